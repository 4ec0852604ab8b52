#include "implicitizer/polynomial/gcd.hpp"

#include <flint/fmpz.h>
#include <flint/fmpz_mpoly.h>

#include <map>
#include <stdexcept>
#include <utility>
#include <vector>

namespace implicitizer {

namespace {

constexpr const char* kGcd = "the greatest common divisor";

// RAII context + polynomial for FLINT's fmpz_mpoly in the variables of one ring.
class FlintContext {
 public:
  explicit FlintContext(std::size_t num_variables) { fmpz_mpoly_ctx_init(ctx_, static_cast<slong>(num_variables), ORD_LEX); }
  ~FlintContext() { fmpz_mpoly_ctx_clear(ctx_); }
  FlintContext(const FlintContext&) = delete;
  FlintContext& operator=(const FlintContext&) = delete;
  fmpz_mpoly_ctx_struct* get() { return ctx_; }

 private:
  fmpz_mpoly_ctx_t ctx_;
};

class FlintPolynomial {
 public:
  explicit FlintPolynomial(FlintContext& ctx) : ctx_(ctx) { fmpz_mpoly_init(p_, ctx_.get()); }
  ~FlintPolynomial() { fmpz_mpoly_clear(p_, ctx_.get()); }
  FlintPolynomial(const FlintPolynomial&) = delete;
  FlintPolynomial& operator=(const FlintPolynomial&) = delete;
  fmpz_mpoly_struct* get() { return p_; }

 private:
  FlintContext& ctx_;
  fmpz_mpoly_t p_;
};

// The primitive part of `p` as a FLINT polynomial.
void to_flint(const Polynomial& p, FlintPolynomial& out, FlintContext& ctx) {
  const Ring& ring = *p.ring();
  const std::size_t n = ring.num_variables();
  std::vector<ulong> e(n);
  fmpz_t c;
  fmpz_init(c);
  for (std::size_t t = 0; t < p.num_terms(); ++t) {
    const std::int32_t* ex = ring.exponents(p.monomial(t));
    for (std::size_t i = 0; i < n; ++i) e[i] = static_cast<ulong>(ex[i]);
    fmpz_set_mpz(c, p.integer_coefficients()[t].get_mpz_t());
    fmpz_mpoly_push_term_fmpz_ui(out.get(), c, e.data(), ctx.get());
  }
  fmpz_clear(c);
  fmpz_mpoly_sort_terms(out.get(), ctx.get());
  fmpz_mpoly_combine_like_terms(out.get(), ctx.get());
}

Polynomial from_flint(FlintPolynomial& f, FlintContext& ctx, const RingPtr& ring, const Rational& content) {
  const std::size_t n = ring->num_variables();
  const std::size_t w = ring->monomial_size();
  const slong len = fmpz_mpoly_length(f.get(), ctx.get());
  std::vector<Integer> coefficients(static_cast<std::size_t>(len));
  std::vector<std::int32_t> monomials(static_cast<std::size_t>(len) * w);
  std::vector<ulong> e(n);
  std::vector<std::int32_t> e32(n);
  fmpz_t c;
  fmpz_init(c);
  for (slong t = 0; t < len; ++t) {
    fmpz_mpoly_get_term_coeff_fmpz(c, f.get(), t, ctx.get());
    fmpz_get_mpz(coefficients[t].get_mpz_t(), c);
    fmpz_mpoly_get_term_exp_ui(e.data(), f.get(), t, ctx.get());
    for (std::size_t i = 0; i < n; ++i) e32[i] = static_cast<std::int32_t>(e[i]);
    ring->encode(e32.data(), monomials.data() + static_cast<std::size_t>(t) * w);
  }
  fmpz_clear(c);
  return Polynomial::from_terms(ring, content, std::move(coefficients), std::move(monomials));
}

// Whether every variable of `inner` occurs in `outer`, and `outer` has more.
bool is_proper_subset(const std::vector<bool>& inner, const std::vector<bool>& outer) {
  bool more = false;
  for (std::size_t v = 0; v < inner.size(); ++v) {
    if (inner[v] && !outer[v]) return false;
    more = more || (outer[v] && !inner[v]);
  }
  return more;
}

// `p` as Σ c_k·m_k with m_k distinct monomials free of the variables `in` and each c_k
// a polynomial in those variables only (the primitive part's coefficients): the
// coefficients of p seen as a polynomial in the other variables.
struct CoefficientSplit {
  std::vector<std::vector<std::int32_t>> outside;  // the exponents of m_k
  std::vector<Polynomial> coefficients;            // c_k
};

CoefficientSplit split_coefficients(const Polynomial& p, const std::vector<bool>& in, const Budget& budget) {
  const Ring& ring = *p.ring();
  const std::size_t n = ring.num_variables(), w = ring.monomial_size();
  std::map<std::vector<std::int32_t>, std::pair<std::vector<Integer>, std::vector<std::int32_t>>> groups;
  std::vector<std::int32_t> outside(n), inside(n);
  for (std::size_t t = 0; t < p.num_terms(); ++t) {
    const std::int32_t* e = ring.exponents(p.monomial(t));
    for (std::size_t v = 0; v < n; ++v) {
      outside[v] = in[v] ? 0 : e[v];
      inside[v] = in[v] ? e[v] : 0;
    }
    auto& [c, m] = groups[outside];
    c.push_back(p.integer_coefficients()[t]);
    m.resize(m.size() + w);
    ring.encode(inside.data(), m.data() + m.size() - w);
    if ((t & 0xfff) == 0) budget.check(kGcd);
  }
  CoefficientSplit split;
  for (auto& [key, part] : groups) {
    split.outside.push_back(key);
    split.coefficients.push_back(
        Polynomial::from_terms(p.ring(), Rational(1), std::move(part.first), std::move(part.second)));
  }
  return split;
}

// gcd(big, small) when the variables V of `small` are a proper subset of big's: a
// common factor divides small, so involves V only, and such a polynomial divides big
// iff it divides each coefficient c_k of big in the other variables. So gcd(big,
// small) = gcd(small, c_1, c_2, ...): gcds of polynomials of the size of small, with
// the budget checked between them, instead of one FLINT call on big, which cannot be
// interrupted (a million terms in issue 41's common denominators). It stops once the
// gcd is a constant, and skips a coefficient that is a multiple of the gcd so far.
Polynomial gcd_through_coefficients(const Polynomial& big, const Polynomial& small, const std::vector<bool>& in_small,
                                    const Budget& budget) {
  Polynomial g = small.primitive_part();
  for (const Polynomial& c : split_coefficients(big, in_small, budget).coefficients) {
    if (c.num_terms() == g.num_terms() && c.primitive_part() == g) continue;
    g = gcd(g, c, budget);
    if (g.is_constant()) break;
    budget.check(kGcd);
  }
  return g;
}

// a / b when b's variables are a proper subset of a's: Σ (c_k / b)·m_k, one division of
// the size of b per coefficient, for the same reason.
Polynomial divide_through_coefficients(const Polynomial& a, const Polynomial& b, const std::vector<bool>& in_b,
                                       const Budget& budget) {
  const Ring& ring = *a.ring();
  const std::size_t n = ring.num_variables(), w = ring.monomial_size();
  const CoefficientSplit split = split_coefficients(a, in_b, budget);
  std::vector<Integer> coefficients;
  std::vector<std::int32_t> monomials;
  std::vector<std::int32_t> e(n);
  const Polynomial primitive_b = b.primitive_part();
  for (std::size_t k = 0; k < split.coefficients.size(); ++k) {
    // An integer polynomial divided by a primitive one is an integer polynomial (Gauss's
    // lemma): the quotient's content is an integer.
    const Polynomial q = divide_exact(split.coefficients[k], primitive_b, budget);
    const Integer content = to_mpq(q.content()).get_num();
    for (std::size_t t = 0; t < q.num_terms(); ++t) {
      const std::int32_t* qe = ring.exponents(q.monomial(t));
      for (std::size_t v = 0; v < n; ++v) e[v] = in_b[v] ? qe[v] : split.outside[k][v];
      coefficients.push_back(content * q.integer_coefficients()[t]);
      monomials.resize(monomials.size() + w);
      ring.encode(e.data(), monomials.data() + monomials.size() - w);
    }
    budget.check(kGcd);
  }
  return Polynomial::from_terms(a.ring(), a.content() / b.content(), std::move(coefficients), std::move(monomials));
}

}  // namespace

Polynomial gcd(const Polynomial& a, const Polynomial& b, const Budget& budget) {
  if (a.is_zero()) return b.primitive_part();
  if (b.is_zero()) return a.primitive_part();
  if (a.is_constant() || b.is_constant()) return Polynomial::constant(a.ring(), Rational(1));
  // A common factor would have to be free of every variable of both: a constant. Saves
  // FLINT's conversion of the large denominators of products of separate parameters.
  if (!share_a_variable(a, b)) return Polynomial::constant(a.ring(), Rational(1));
  const std::vector<bool> in_a = a.occurring_variables(), in_b = b.occurring_variables();
  if (is_proper_subset(in_b, in_a)) return gcd_through_coefficients(a, b, in_b, budget);
  if (is_proper_subset(in_a, in_b)) return gcd_through_coefficients(b, a, in_a, budget);
  budget.check(kGcd);
  FlintContext ctx(a.ring()->num_variables());
  FlintPolynomial fa(ctx), fb(ctx), g(ctx);
  to_flint(a, fa, ctx);
  to_flint(b, fb, ctx);
  if (!fmpz_mpoly_gcd(g.get(), fa.get(), fb.get(), ctx.get())) {
    throw std::runtime_error("FLINT could not compute a gcd");
  }
  return from_flint(g, ctx, a.ring(), Rational(1)).primitive_part();
}

Polynomial lcm(const Polynomial& a, const Polynomial& b, const Budget& budget) {
  if (a.is_zero() || b.is_zero()) return Polynomial(a.ring());
  // The common cases of a common denominator (polynomial coordinates, one shared
  // denominator) without FLINT's context, which costs more than these answers: tens
  // of microseconds per call on the benchmark's rational patches.
  if (a.is_constant()) return b.primitive_part();
  if (b.is_constant()) return a.primitive_part();
  Polynomial pa = a.primitive_part();
  const Polynomial pb = b.primitive_part();
  if (pa == pb) return pa;
  // a·(b/g), not (a·b)/g: the only large polynomial is the lcm itself, built once by a
  // multiplication that `budget` can refuse before or while it grows; FLINT, which
  // cannot be interrupted, sees only the factors.
  const Polynomial g = gcd(pa, pb, budget);
  return pa.multiply(g.is_constant() ? pb : divide_exact(pb, g, budget), budget).primitive_part();
}

Polynomial square_free_part(const Polynomial& a, std::size_t var) {
  if (a.is_zero() || !a.involves(var)) return a.primitive_part();
  return divide_exact(a, gcd(a, a.derivative(var))).primitive_part();
}

Polynomial divide_exact(const Polynomial& a, const Polynomial& b, const Budget& budget) {
  if (b.is_zero()) throw std::logic_error("divide_exact by zero");
  if (a.is_zero()) return a;
  if (b.is_constant()) return a.divided_by(b.coefficient(0));
  // a = c·b (a common denominator divided by one of its factors, often itself).
  if (a.num_terms() == b.num_terms() && a.primitive_part() == b.primitive_part()) {
    return Polynomial::constant(a.ring(), a.coefficient(0) / b.coefficient(0));
  }
  const std::vector<bool> in_b = b.occurring_variables();
  if (is_proper_subset(in_b, a.occurring_variables())) return divide_through_coefficients(a, b, in_b, budget);
  budget.check(kGcd);
  // Gauss's lemma: if b | a over ℚ then prim(b) | prim(a) over ℤ.
  FlintContext ctx(a.ring()->num_variables());
  FlintPolynomial fa(ctx), fb(ctx), q(ctx);
  to_flint(a, fa, ctx);
  to_flint(b, fb, ctx);
  if (!fmpz_mpoly_divides(q.get(), fa.get(), fb.get(), ctx.get())) {
    throw std::logic_error("divide_exact: the division is not exact");
  }
  return from_flint(q, ctx, a.ring(), a.content() / b.content());
}

}  // namespace implicitizer
