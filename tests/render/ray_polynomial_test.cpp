// Tests of lib/src/render/ray_polynomial.cpp against the library's exact rational
// composition: the double expansion stays within its stated error bound (random
// polynomials and rays, fixed seed, far origins included), the exact expansion is a
// positive multiple of q, and q is F along the segment.

#include "implicitizer/render/ray_polynomial.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "implicitizer/core/errors.hpp"
#include "implicitizer/polynomial/parser.hpp"
#include "sdf/sdf_support.hpp"

namespace implicitizer {
namespace {

RingPtr xyz_ring() {
  static const RingPtr ring = Ring::make({"x", "y", "z"});
  return ring;
}

Polynomial parse_xyz(const std::string& text) { return parse_polynomial(text, xyz_ring()); }

// q(s) = F(o + (t_begin + s(t_end − t_begin))·d) by the library's exact composition,
// coefficient k at index k.
std::vector<Rational> exact_q(const Polynomial& f, const RaySegment& segment) {
  const RingPtr ring = Ring::make({"s"});
  const Rational t0(segment.t_begin);
  const Rational width = Rational(segment.t_end) - t0;
  std::vector<Polynomial> values;
  for (std::size_t i = 0; i < 3; ++i) {
    const Rational o(segment.origin[i]), d(segment.direction[i]);
    values.push_back(Polynomial::constant(ring, o + t0 * d) + Polynomial::variable(ring, 0).scaled(width * d));
  }
  const Polynomial q = f.compose(ring, values);
  std::vector<Rational> out(static_cast<std::size_t>(f.total_degree()) + 1, Rational(0));
  for (std::size_t t = 0; t < q.num_terms(); ++t) out[static_cast<std::size_t>(q.exponents(t)[0])] = q.coefficient(t);
  return out;
}

// 1 / (|c|·2^e): the factor between F and the polynomial the double expansion uses.
Rational double_scale(const Polynomial& f) {
  long largest = std::numeric_limits<long>::min();
  for (const Integer& c : f.integer_coefficients()) {
    long e = 0;
    mpz_get_d_2exp(&e, c.get_mpz_t());
    largest = std::max(largest, e);
  }
  Integer power = 1;
  mpz_mul_2exp(power.get_mpz_t(), power.get_mpz_t(), static_cast<mp_bitcnt_t>(largest));
  const Rational c = f.content() < Rational(0) ? -f.content() : f.content();
  return Rational(1) / (c * to_rational(power));
}

double magnitude(const Rational& q) { return std::fabs(to_mpq(q).get_d()); }

// A random polynomial of total degree `degree` with up to `terms` terms and integer
// coefficients in [−1000, 1000] (the monomial of full degree is always present).
Polynomial random_polynomial(std::mt19937_64& rng, int degree, int terms) {
  std::uniform_int_distribution<int> coefficient(-1000, 1000);
  Polynomial f(xyz_ring());
  for (int t = 0; t < terms; ++t) {
    std::uniform_int_distribution<int> total(0, degree);
    const int d = t == 0 ? degree : total(rng);
    std::uniform_int_distribution<int> split(0, d);
    const int i = split(rng);
    std::uniform_int_distribution<int> rest(0, d - i);
    const int j = rest(rng);
    const std::int32_t e[3] = {i, j, d - i - j};
    int c = coefficient(rng);
    if (c == 0) c = 1;
    f += Polynomial::term(xyz_ring(), Rational(c), e);
  }
  return f.is_constant() ? f + Polynomial::variable(xyz_ring(), 0) : f;
}

// Every computed coefficient within relative_error·majorant + band of the exact one,
// and the majorant above |q_k| up to the same slack: 300 random cases, degrees 1 to 9,
// origins at distance up to 1e6 (where the terms of q cancel by many digits),
// segments not starting at 0 (so that o + t_begin·d is rounded).
TEST(RayPolynomial, DoubleExpansionStaysWithinItsBound) {
  std::mt19937_64 rng(20261123);
  std::uniform_real_distribution<double> unit(-1, 1);
  double worst = 0;  // max |q̃_k − q_k| / (relative_error·q̂̃_k)
  for (int trial = 0; trial < 300; ++trial) {
    const int degree = 1 + trial % 9;
    const Polynomial f = random_polynomial(rng, degree, 2 + trial % 12);
    const double far = trial % 3 == 0 ? 1e6 : (trial % 3 == 1 ? 10 : 1);
    RaySegment segment{{far * unit(rng), far * unit(rng), far * unit(rng)},
                       {unit(rng), unit(rng), unit(rng)},
                       trial % 2 == 0 ? 0.0 : 3 * std::fabs(unit(rng)),
                       0};
    segment.t_end = segment.t_begin + 20 * std::fabs(unit(rng));
    const RayPolynomialContext context(f);
    DoubleRayPolynomial q;
    context.expand_double(segment, q);
    ASSERT_TRUE(q.finite);
    ASSERT_EQ(q.coefficients.size(), static_cast<std::size_t>(degree) + 1);
    const std::vector<Rational> exact = exact_q(f, segment);
    const Rational scale = double_scale(f);
    for (std::size_t k = 0; k < exact.size(); ++k) {
      const Rational scaled = exact[k] * scale;
      const double error = magnitude(Rational(q.coefficients[k]) - scaled);
      const double bound = q.relative_error * q.majorant[k] + q.band;
      EXPECT_LE(error, bound) << "trial " << trial << " k " << k;
      EXPECT_LE(magnitude(scaled), (1 + q.relative_error) * q.majorant[k] + q.band) << "trial " << trial << " k " << k;
      if (bound > 0) worst = std::max(worst, error / bound);
    }
  }
  std::printf("[ray_polynomial] worst error / bound over 300 random expansions: %.3g\n", worst);
}

// expand_exact is a positive rational multiple of q, with the same zero coefficients.
TEST(RayPolynomial, ExactExpansionIsAPositiveMultipleOfQ) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(-1, 1);
  for (int trial = 0; trial < 100; ++trial) {
    const Polynomial f = random_polynomial(rng, 1 + trial % 8, 2 + trial % 10);
    const RaySegment segment{{5 * unit(rng), 5 * unit(rng), 1e-3 * unit(rng)},
                             {unit(rng), unit(rng), unit(rng)},
                             std::fabs(unit(rng)),
                             2 + std::fabs(unit(rng))};
    const RayPolynomialContext context(f);
    const std::vector<Integer> integer = context.expand_exact(segment);
    const std::vector<Rational> exact = exact_q(f, segment);
    std::optional<Rational> ratio;
    for (std::size_t k = 0; k < exact.size(); ++k) {
      const Rational a = k < integer.size() ? to_rational(integer[k]) : Rational(0);
      ASSERT_EQ(a == Rational(0), exact[k] == Rational(0)) << "trial " << trial << " k " << k;
      if (a == Rational(0)) continue;
      if (!ratio) ratio = a / exact[k];
      EXPECT_EQ(a / exact[k], *ratio) << "trial " << trial << " k " << k;
    }
    ASSERT_TRUE(ratio.has_value());
    EXPECT_GT(*ratio, Rational(0));
  }
}

// The segment [0, 1] is g(t) = F(o + t·d): Σ q_k t^k equals F at o + t·d exactly.
TEST(RayPolynomial, UnitSegmentIsFAlongTheRay) {
  const Polynomial f = parse_xyz("(x^2+y^2+z^2+3)^2-16*(x^2+y^2)");
  const RaySegment segment{{-5, 0.5, 0.25}, {1, 0.125, -0.0625}, 0, 1};
  const std::vector<Integer> q = RayPolynomialContext(f).expand_exact(segment);
  const std::vector<Rational> exact = exact_q(f, segment);
  const Rational ratio = to_rational(q[0]) / exact[0];
  for (const Rational& t : {Rational(0), Rational(1, 3), Rational(7, 2), Rational(-2)}) {
    Rational sum(0), power(1);
    for (const Integer& c : q) {
      sum += to_rational(c) * power;
      power *= t;
    }
    const Rational point[3] = {Rational(-5) + t, Rational(0.5) + t * Rational(0.125),
                               Rational(0.25) - t * Rational(0.0625)};
    EXPECT_EQ(sum, ratio * f.evaluate(point));
  }
}

// A segment lying in the surface gives q ≡ 0 (empty); a line of the cone does.
TEST(RayPolynomial, SegmentInsideTheSurfaceIsZero) {
  const RayPolynomialContext context(parse_xyz("x^2+y^2-z^2"));
  EXPECT_TRUE(context.expand_exact(RaySegment{{3, 0, 3}, {-1, 0, -1}, 0, 10}).empty());
  EXPECT_FALSE(context.expand_exact(RaySegment{{3, 0, 4}, {-1, 0, -1}, 0, 10}).empty());
}

// Why the double path re-expands: for tp_33 (degree 18) seen from 55 units away, the
// majorant of the whole segment [0, 100] is driven by |o| + 100, far above the size
// of F's terms near the hit; on the piece [25, 50] around the hit it is local. The
// local expansion's bound (relative_error·majorant + band, band from rounding the
// piece's start) is what lets Descartes' rule decide there.
TEST(RayPolynomial, ExpansionOnAPieceHasALocalMajorant) {
  const RayPolynomialContext context(testing::tp33_implicit());
  const std::array<double, 3> o{30, 25, 40}, d{-0.6, -0.5, -0.62};
  DoubleRayPolynomial whole, piece;
  context.expand_double(RaySegment{o, d, 0, 100}, whole);
  context.expand_double(RaySegment{o, d, 25, 50}, piece);
  ASSERT_TRUE(whole.finite && piece.finite);
  const double whole_majorant = *std::max_element(whole.majorant.begin(), whole.majorant.end());
  const double piece_majorant = *std::max_element(piece.majorant.begin(), piece.majorant.end());
  std::printf("[ray_polynomial] tp_33 majorant on [0, 100]: %.3g; on [25, 50]: %.3g, band %.3g\n", whole_majorant,
              piece_majorant, piece.band);
  EXPECT_GT(whole_majorant, 1e4 * piece_majorant);
  EXPECT_EQ(whole.band, 0.0);
  EXPECT_GT(piece.band, 0.0);
  EXPECT_LT(piece.band, 10 * piece.relative_error * piece_majorant);
}

// Out of double's range the expansion says so instead of returning inf.
TEST(RayPolynomial, ReportsCoefficientsOutOfRange) {
  const RayPolynomialContext context(parse_xyz("x^9+y^9+z^9-1"));
  DoubleRayPolynomial q;
  context.expand_double(RaySegment{{1e40, 0, 0}, {1, 0, 0}, 0, 1}, q);
  EXPECT_FALSE(q.finite);
  context.expand_double(RaySegment{{1e4, 0, 0}, {1, 0, 0}, 0, 1}, q);
  EXPECT_TRUE(q.finite);
}

TEST(RayPolynomial, RefusesConstantsAndOtherRings) {
  try {
    RayPolynomialContext context(parse_xyz("7"));
    FAIL() << "a constant was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.code(), "constant_polynomial");
    EXPECT_EQ(e.field(), "equation");
  }
  try {
    RayPolynomialContext context(parse_polynomial("x^2+y^2-1", Ring::make({"x", "y"})));
    FAIL() << "a polynomial in two variables was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.code(), "invalid_variables");
  }
}

}  // namespace
}  // namespace implicitizer
