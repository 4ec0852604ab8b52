#include "implicitizer/polynomial/gcd.hpp"

#include <flint/fmpz.h>
#include <flint/fmpz_mpoly.h>

#include <stdexcept>

namespace implicitizer {

namespace {

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

}  // namespace

Polynomial gcd(const Polynomial& a, const Polynomial& b) {
  if (a.is_zero()) return b.primitive_part();
  if (b.is_zero()) return a.primitive_part();
  if (a.is_constant() || b.is_constant()) return Polynomial::constant(a.ring(), Rational(1));
  // A common factor would have to be free of every variable of both: a constant. Saves
  // FLINT's conversion of the large denominators of products of separate parameters.
  if (!share_a_variable(a, b)) return Polynomial::constant(a.ring(), Rational(1));
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
  const Polynomial g = gcd(pa, pb);
  budget.check("the least common multiple");
  return pa.multiply(g.is_constant() ? pb : divide_exact(pb, g), budget).primitive_part();
}

Polynomial square_free_part(const Polynomial& a, std::size_t var) {
  if (a.is_zero() || !a.involves(var)) return a.primitive_part();
  return divide_exact(a, gcd(a, a.derivative(var))).primitive_part();
}

Polynomial divide_exact(const Polynomial& a, const Polynomial& b) {
  if (b.is_zero()) throw std::logic_error("divide_exact by zero");
  if (a.is_zero()) return a;
  if (b.is_constant()) return a.divided_by(b.coefficient(0));
  // a = c·b (a common denominator divided by one of its factors, often itself).
  if (a.num_terms() == b.num_terms() && a.primitive_part() == b.primitive_part()) {
    return Polynomial::constant(a.ring(), a.coefficient(0) / b.coefficient(0));
  }
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
