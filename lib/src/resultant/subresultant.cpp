#include "implicitizer/resultant/subresultant.hpp"

#include <flint/fmpz.h>
#include <flint/fmpz_mpoly.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "implicitizer/core/errors.hpp"
#include "implicitizer/polynomial/gcd.hpp"
#include "implicitizer/resultant/sylvester.hpp"

namespace implicitizer {
namespace {

constexpr const char* kWhere = "resultant (subresultant PRS)";

// ---- coefficients: FLINT's fmpz_mpoly ---------------------------------------
//
// The algorithm below is ours; the arithmetic of its coefficients (products and
// exact divisions of polynomials in the other variables) is FLINT's, as for gcd():
// it is where all the time goes (80 % in products), and fmpz_mpoly's packed
// monomials multiply about 30 times faster than Polynomial::multiply (degree 7 and
// 7 in t, coefficients in three more variables: 36 s against 1.2 s; Singular 12.7 s).
// Over ℚ the contents factor out (Res(a·F, b·G) = a^n·b^m·Res(F, G)), so the
// chain runs on the primitive integer parts, in ℤ[other variables].

class FlintContext {
 public:
  explicit FlintContext(std::size_t num_variables) {
    fmpz_mpoly_ctx_init(ctx_, static_cast<slong>(num_variables), ORD_LEX);
  }
  ~FlintContext() { fmpz_mpoly_ctx_clear(ctx_); }
  FlintContext(const FlintContext&) = delete;
  FlintContext& operator=(const FlintContext&) = delete;
  const fmpz_mpoly_ctx_struct* get() const { return ctx_; }

 private:
  fmpz_mpoly_ctx_t ctx_;
};

// One coefficient: an fmpz_mpoly of a FlintContext that outlives it. A value type
// (copies copy, moves swap), so that vectors of them behave.
class Coefficient {
 public:
  explicit Coefficient(const FlintContext& context) : context_(&context) { fmpz_mpoly_init(p_, ctx()); }
  Coefficient(const Coefficient& other) : context_(other.context_) {
    fmpz_mpoly_init(p_, ctx());
    fmpz_mpoly_set(p_, other.p_, ctx());
  }
  Coefficient(Coefficient&& other) noexcept : context_(other.context_) {
    fmpz_mpoly_init(p_, ctx());
    fmpz_mpoly_swap(p_, other.p_, ctx());
  }
  Coefficient& operator=(const Coefficient& other) {
    if (this != &other) fmpz_mpoly_set(p_, other.p_, ctx());
    return *this;
  }
  Coefficient& operator=(Coefficient&& other) noexcept {
    fmpz_mpoly_swap(p_, other.p_, ctx());
    return *this;
  }
  ~Coefficient() { fmpz_mpoly_clear(p_, ctx()); }

  const FlintContext& context() const { return *context_; }
  const fmpz_mpoly_ctx_struct* ctx() const { return context_->get(); }
  fmpz_mpoly_struct* get() { return p_; }
  const fmpz_mpoly_struct* get() const { return p_; }
  bool is_zero() const { return fmpz_mpoly_is_zero(p_, ctx()) != 0; }
  std::size_t num_terms() const { return static_cast<std::size_t>(fmpz_mpoly_length(p_, ctx())); }

 private:
  const FlintContext* context_;
  fmpz_mpoly_t p_;
};

Coefficient product(const Coefficient& a, const Coefficient& b, const Budget& budget) {
  Coefficient r(a.context());
  fmpz_mpoly_mul(r.get(), a.get(), b.get(), a.ctx());
  budget.check_terms(r.num_terms(), kWhere);
  return r;
}

// a / b, which the theory says is exact; anything else is a bug.
Coefficient quotient(const Coefficient& a, const Coefficient& b, const Budget& budget) {
  Coefficient q(a.context());
  if (!fmpz_mpoly_divides(q.get(), a.get(), b.get(), a.ctx())) {
    throw std::logic_error("subresultant PRS: a division that must be exact is not");
  }
  budget.check_terms(q.num_terms(), kWhere);
  return q;
}

Coefficient power(const Coefficient& a, unsigned e, const Budget& budget) {
  Coefficient r(a.context());
  if (!fmpz_mpoly_pow_ui(r.get(), a.get(), e, a.ctx()))
    throw LimitExceeded(Limit::size, "exponent overflow in a power");
  budget.check_terms(r.num_terms(), kWhere);
  return r;
}

// ---- univariate polynomials over those coefficients ---------------------------

// A polynomial in x: entry i is the coefficient of x^i. Invariant: the last entry
// is non-zero; the zero polynomial is empty.
using Univariate = std::vector<Coefficient>;

int degree(const Univariate& a) { return static_cast<int>(a.size()) - 1; }
const Coefficient& leading(const Univariate& a) { return a.back(); }

void trim(Univariate& a) {
  while (!a.empty() && a.back().is_zero()) a.pop_back();
}

Univariate scaled(const Univariate& a, const Coefficient& c, const Budget& budget) {
  Univariate out;
  out.reserve(a.size());
  for (const Coefficient& ai : a) out.push_back(product(ai, c, budget));
  trim(out);
  return out;
}

// a / c coefficient-wise; c divides every coefficient (the caller knows why).
Univariate divided(const Univariate& a, const Coefficient& c, const Budget& budget) {
  Univariate out;
  out.reserve(a.size());
  for (const Coefficient& ai : a) out.push_back(quotient(ai, c, budget));
  return out;
}

Univariate negated(Univariate a) {
  for (Coefficient& ai : a) fmpz_mpoly_neg(ai.get(), ai.get(), ai.ctx());
  return a;
}

// a + b·x^shift when add, else a − b·x^shift.
Univariate combined(const Univariate& a, const Univariate& b, std::size_t shift, bool add, const FlintContext& ctx) {
  Univariate out(std::max(a.size(), b.size() + shift), Coefficient(ctx));
  for (std::size_t i = 0; i < a.size(); ++i) out[i] = a[i];
  for (std::size_t i = 0; i < b.size(); ++i) {
    Coefficient& o = out[i + shift];
    if (add) {
      fmpz_mpoly_add(o.get(), o.get(), b[i].get(), ctx.get());
    } else {
      fmpz_mpoly_sub(o.get(), o.get(), b[i].get(), ctx.get());
    }
  }
  trim(out);
  return out;
}

Univariate sum(const Univariate& a, const Univariate& b, const FlintContext& ctx) {
  return combined(a, b, 0, true, ctx);
}
Univariate difference(const Univariate& a, const Univariate& b, const FlintContext& ctx) {
  return combined(a, b, 0, false, ctx);
}

// x·a.
Univariate shifted(Univariate a, const FlintContext& ctx) {
  if (!a.empty()) a.insert(a.begin(), Coefficient(ctx));
  return a;
}

// The coefficient of x^i (zero beyond the degree).
Coefficient coefficient(const Univariate& a, int i, const FlintContext& ctx) {
  return i >= 0 && i < static_cast<int>(a.size()) ? a[static_cast<std::size_t>(i)] : Coefficient(ctx);
}

// ---- the subresultant chain ---------------------------------------------------

// The pseudo-remainder prem(p, q) = lc(q)^(deg p − deg q + 1)·p mod q, with
// deg p ≥ deg q ≥ 0 and q ≠ 0: what remains of lc(q)^(δ+1)·p after dividing by q
// in R[x], where the power makes every quotient coefficient land in R.
Univariate pseudo_remainder(Univariate p, const Univariate& q, const FlintContext& ctx, const Budget& budget) {
  const int dq = degree(q);
  int powers_left = degree(p) - dq + 1;
  while (!p.empty() && degree(p) >= dq) {
    const auto shift = static_cast<std::size_t>(degree(p) - dq);
    const Coefficient lead = leading(p);
    p = combined(scaled(p, leading(q), budget), scaled(q, lead, budget), shift, false, ctx);
    --powers_left;
    budget.check(kWhere);
  }
  // A remainder whose degree fell by more than one per step still owes the
  // missing powers of lc(q) (prem is defined with the full exponent δ + 1).
  if (!p.empty() && powers_left > 0) {
    p = scaled(p, power(leading(q), static_cast<unsigned>(powers_left), budget), budget);
  }
  return p;
}

// Lazard's optimisation: x^n / y^(n−1) for n ≥ 1, by square-and-multiply where
// every intermediate c = x^k / y^(k−1) is in R (Ducos 2000, §2), so each step
// divides exactly and no power of x or y is ever formed in full.
Coefficient lazard_power(const Coefficient& x, const Coefficient& y, unsigned n, const Budget& budget) {
  unsigned high = 1;
  while (high * 2 <= n) high *= 2;
  Coefficient c = x;
  n -= high;
  while (high > 1) {
    high /= 2;
    c = quotient(product(c, c, budget), y, budget);
    if (n >= high) {
      c = quotient(product(c, x, budget), y, budget);
      n -= high;
    }
  }
  return c;
}

// Ducos' reduction (Ducos 2000, Algorithm "Reduction"; the formula of Lickteig and
// Roy): the subresultant S_(e−1) of the chain from
//   a = S_d (degree d, regular), b = S_(d−1) (degree e < d), c = S_e (degree e,
//   c = lc(b)^(d−e−1)·b / s^(d−e−1)), s = lc(S_d),
// without pseudo-division. With H_j = lc(c)·x^j for j < e, H_e = lc(c)·x^e − c and
// H_(j+1) = x·H_j − coef_e(x·H_j)·b / lc(b) (reduced below degree e):
//   S_(e−1) = (−1)^(d−e+1)·(lc(b)·(x·H_(d−1) + D) − coef_e(x·H_(d−1))·b) / s,
//   D = Σ_(j<d) coef_j(a)·H_j / lc(a).
// Every division is exact in R. Against the classic S_(e−1) = prem(a, c) /
// (s^(d−e)·lc(a)) (Brown–Traub), the products are of size d·e instead of d², and
// the power s^(d−e) is never built.
Univariate ducos_reduction(const Univariate& a, const Univariate& b, const Univariate& c, const Coefficient& s,
                           const FlintContext& ctx, const Budget& budget) {
  const int d = degree(a);
  const int e = degree(b);
  const Coefficient& lc_b = leading(b);
  const Coefficient& lc_c = leading(c);

  // D's share of the H_j = lc(c)·x^j, j < e: lc(c) times the low part of a.
  Univariate total;
  for (int j = 0; j < e; ++j) total.push_back(product(a[static_cast<std::size_t>(j)], lc_c, budget));
  trim(total);

  Univariate h = negated(Univariate(c.begin(), c.end() - 1));  // H_e = lc(c)·x^e − c
  trim(h);
  for (int j = e; j < d; ++j) {
    if (j > e) {
      Univariate xh = shifted(std::move(h), ctx);
      const Coefficient top = coefficient(xh, e, ctx);
      h = top.is_zero() ? std::move(xh) : difference(xh, divided(scaled(b, top, budget), lc_b, budget), ctx);
    }
    total = sum(total, scaled(h, a[static_cast<std::size_t>(j)], budget), ctx);
    budget.check(kWhere);
  }
  const Univariate dd = divided(total, leading(a), budget);

  Univariate xh = shifted(std::move(h), ctx);  // x·H_(d−1), degree ≤ e
  const Coefficient top = coefficient(xh, e, ctx);
  const Univariate numerator = difference(scaled(sum(xh, dd, ctx), lc_b, budget), scaled(b, top, budget), ctx);
  Univariate next = divided(numerator, s, budget);
  return (d - e) % 2 == 0 ? negated(std::move(next)) : next;
}

// Res(p, q) for deg p ≥ deg q ≥ 1 (Ducos 2000, Algorithm "Subresultant"): walks
// the subresultant chain keeping only the last regular subresultant a, the next
// one b and s = lc(a), and returns S_0.
Coefficient resultant_ducos(const Univariate& p, const Univariate& q, const FlintContext& ctx, const Budget& budget) {
  const int delta = degree(p) - degree(q);
  Coefficient s = power(leading(q), static_cast<unsigned>(delta), budget);
  Univariate a = q;
  // S_(q−1) = prem(p, −q) = (−1)^(δ+1)·prem(p, q).
  Univariate b = pseudo_remainder(p, q, ctx, budget);
  if (delta % 2 == 0) b = negated(std::move(b));
  while (true) {
    budget.check(kWhere);
    if (b.empty()) return Coefficient(ctx);  // a common factor of positive degree
    const int d = degree(a);
    const int e = degree(b);
    // Between degrees d−1 and e the chain is defective: S_e is a multiple of S_(d−1)
    // (structure theorem), c = lc(b)^(d−e−1)·b / s^(d−e−1).
    Univariate c = b;
    if (d - e > 1) {
      const Coefficient factor = lazard_power(leading(b), s, static_cast<unsigned>(d - e - 1), budget);
      c = divided(scaled(b, factor, budget), s, budget);
    }
    if (e == 0) return c.front();
    b = ducos_reduction(a, b, c, s, ctx, budget);
    a = std::move(c);
    s = leading(a);
  }
}

// ---- conversions --------------------------------------------------------------

// The coefficients in x_var of f's primitive part (f ≠ 0).
Univariate split_primitive_part(const Polynomial& f, std::size_t var, const FlintContext& ctx) {
  const Ring& ring = *f.ring();
  const std::size_t n = ring.num_variables();
  Univariate out(static_cast<std::size_t>(f.degree_in(var)) + 1, Coefficient(ctx));
  std::vector<ulong> e(n);
  fmpz_t c;
  fmpz_init(c);
  for (std::size_t t = 0; t < f.num_terms(); ++t) {
    const std::int32_t* ex = ring.exponents(f.monomial(t));
    for (std::size_t i = 0; i < n; ++i) e[i] = static_cast<ulong>(ex[i]);
    const auto power_of_x = static_cast<std::size_t>(e[var]);
    e[var] = 0;
    fmpz_set_mpz(c, f.integer_coefficients()[t].get_mpz_t());
    fmpz_mpoly_push_term_fmpz_ui(out[power_of_x].get(), c, e.data(), ctx.get());
  }
  fmpz_clear(c);
  for (Coefficient& ci : out) {
    fmpz_mpoly_sort_terms(ci.get(), ctx.get());
    fmpz_mpoly_combine_like_terms(ci.get(), ctx.get());
  }
  return out;
}

// content·r in `ring`. Throws LimitExceeded (size) when r's degrees do not fit the
// ring's monomials (kMaxTotalDegree).
Polynomial to_polynomial(const Coefficient& r, const RingPtr& ring, const Rational& content) {
  const std::size_t n = ring->num_variables();
  if (!r.is_zero() && (!fmpz_mpoly_total_degree_fits_si(r.get(), r.ctx()) ||
                       fmpz_mpoly_total_degree_si(r.get(), r.ctx()) > kMaxTotalDegree)) {
    throw LimitExceeded(Limit::size, "degree limit exceeded in a resultant");
  }
  const std::size_t len = r.num_terms();
  const std::size_t w = ring->monomial_size();
  std::vector<Integer> coefficients(len);
  std::vector<std::int32_t> monomials(len * w);
  std::vector<ulong> e(n);
  std::vector<std::int32_t> e32(n);
  fmpz_t c;
  fmpz_init(c);
  for (std::size_t t = 0; t < len; ++t) {
    fmpz_mpoly_get_term_coeff_fmpz(c, r.get(), static_cast<slong>(t), r.ctx());
    fmpz_get_mpz(coefficients[t].get_mpz_t(), c);
    fmpz_mpoly_get_term_exp_ui(e.data(), r.get(), static_cast<slong>(t), r.ctx());
    for (std::size_t i = 0; i < n; ++i) e32[i] = static_cast<std::int32_t>(e[i]);
    ring->encode(e32.data(), monomials.data() + t * w);
  }
  fmpz_clear(c);
  return Polynomial::from_terms(ring, content, std::move(coefficients), std::move(monomials));
}

Rational rational_power(const Rational& q, unsigned e) {
  mpq_class base = to_mpq(q);
  mpq_class r(1);
  mpz_pow_ui(r.get_num_mpz_t(), base.get_num_mpz_t(), e);
  mpz_pow_ui(r.get_den_mpz_t(), base.get_den_mpz_t(), e);
  return to_rational(r);  // lowest terms: powers of coprime integers are coprime
}

void require_variable(const Polynomial& f, std::size_t var, const char* who) {
  if (var >= f.ring()->num_variables()) {
    throw std::invalid_argument(std::string(who) + ": no variable with index " + std::to_string(var));
  }
}

}  // namespace

Polynomial resultant(const Polynomial& f, const Polynomial& g, std::size_t var, const Budget& budget) {
  if (!(*f.ring() == *g.ring())) throw std::invalid_argument("resultant: polynomials from different rings");
  require_variable(f, var, "resultant");
  const RingPtr& ring = f.ring();
  if (f.is_zero() || g.is_zero()) return Polynomial(ring);
  const int m = f.degree_in(var);
  const int n = g.degree_in(var);
  // A factor free of x: the Sylvester matrix is that factor times the identity.
  if (m == 0) return f.pow(static_cast<unsigned>(n), budget);
  if (n == 0) return g.pow(static_cast<unsigned>(m), budget);

  const FlintContext ctx(ring->num_variables());
  const Univariate fc = split_primitive_part(f, var, ctx);
  const Univariate gc = split_primitive_part(g, var, ctx);
  // Exchanging f and g permutes the Sylvester matrix's rows by m·n transpositions.
  const bool swap = m < n;
  const Coefficient r = swap ? resultant_ducos(gc, fc, ctx, budget) : resultant_ducos(fc, gc, ctx, budget);
  Rational content =
      rational_power(f.content(), static_cast<unsigned>(n)) * rational_power(g.content(), static_cast<unsigned>(m));
  if (swap && (m * n) % 2 != 0) content = -content;
  return to_polynomial(r, ring, content);
}

Polynomial discriminant(const Polynomial& f, std::size_t var, const Budget& budget) {
  require_variable(f, var, "discriminant");
  if (f.is_zero()) return f;
  const int n = f.degree_in(var);
  if (n < 1) throw std::invalid_argument("discriminant: the polynomial does not involve the variable");
  const Polynomial r = resultant(f, f.derivative(var), var, budget);
  const Polynomial d = divide_exact(r, coefficients_in(f, var).back());
  return (n * (n - 1) / 2) % 2 == 0 ? d : -d;
}

}  // namespace implicitizer
