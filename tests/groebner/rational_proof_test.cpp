// The proof over ℚ (lib/src/groebner/rational_proof.hpp) with each accumulator row:
// Buchberger's reduced basis is proven, a basis with one coefficient changed is
// refuted, with small coefficients and with coefficients past the size where the
// automatic choice switches rows.
#include "rational_proof.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "groebner/groebner_support.hpp"
#include "implicitizer/groebner/buchberger.hpp"
#include "int_polynomial.hpp"

namespace implicitizer::detail {
namespace {

using implicitizer::testing::parse_all;

std::vector<IntPolynomial> integer_polynomials(const std::vector<Polynomial>& ps) {
  std::vector<IntPolynomial> out;
  for (const Polynomial& p : ps) out.push_back(to_int_polynomial(p));
  return out;
}

// The generators and their reduced basis (Buchberger's, over ℚ), as integer polynomials.
struct Case {
  RingPtr ring;
  std::vector<IntPolynomial> generators;
  std::vector<IntPolynomial> basis;
};

Case make_case(const std::vector<std::string>& variables, const std::vector<std::string>& texts) {
  Case c;
  c.ring = Ring::make(variables);
  const std::vector<Polynomial> generators = parse_all(texts, c.ring);
  c.generators = integer_polynomials(generators);
  c.basis = integer_polynomials(compute_groebner_basis(generators).basis);
  return c;
}

Case katsura4() {
  return make_case({"u0", "u1", "u2", "u3", "u4"}, {"u0+2*u1+2*u2+2*u3+2*u4-1", "u0^2+2*u1^2+2*u2^2+2*u3^2+2*u4^2-u0",
                                                    "2*u0*u1+2*u1*u2+2*u2*u3+2*u3*u4-u1",
                                                    "u1^2+2*u0*u2+2*u1*u3+2*u2*u4-u2", "2*u1*u2+2*u0*u3+2*u1*u4-u3"});
}

// A 150-digit constant makes the reduced basis's coefficients pass
// kLimbRowCoefficientBits.
Case large_coefficients() {
  std::string big = "1";
  for (int i = 0; i < 15; ++i) big += "234567890";
  big += "1234567891";
  return make_case({"x", "y", "z"}, {"x^2-" + big + "*y*z+z^2", "x*y-" + big + "/7*z^2+y", "y^2-x*z+" + big});
}

std::size_t largest_coefficient_bits(const std::vector<IntPolynomial>& basis) {
  std::size_t bits = 0;
  for (const IntPolynomial& g : basis) {
    for (const Integer& c : g.coefficients) bits = std::max(bits, mpz_sizeinbase(c.get_mpz_t(), 2));
  }
  return bits;
}

// The basis with one tail coefficient of its last element increased by one: no longer
// a Gröbner basis of the ideal (or not of one containing the generators).
std::vector<IntPolynomial> perturbed(std::vector<IntPolynomial> basis) {
  IntPolynomial& g = basis.back();
  EXPECT_GE(g.size(), 2u);
  g.coefficients.back() += 1;
  return basis;
}

class RationalProofTest : public ::testing::TestWithParam<ProofRows> {};

TEST_P(RationalProofTest, TheReducedBasisIsProven) {
  for (const Case& c : {katsura4(), large_coefficients()}) {
    const ProofOutcome outcome = prove_groebner_basis(*c.ring, c.generators, c.basis, {}, 2, GetParam());
    EXPECT_TRUE(outcome.proven);
    EXPECT_GT(outcome.pairs, 0u);
  }
}

TEST_P(RationalProofTest, AChangedCoefficientIsRefuted) {
  for (const Case& c : {katsura4(), large_coefficients()}) {
    EXPECT_FALSE(prove_groebner_basis(*c.ring, c.generators, perturbed(c.basis), {}, 2, GetParam()).proven);
  }
}

INSTANTIATE_TEST_SUITE_P(Rows, RationalProofTest,
                         ::testing::Values(ProofRows::by_coefficient_size, ProofRows::limbs, ProofRows::gmp));

// The cases above do reach both sides of the automatic choice.
TEST(RationalProofCasesTest, OneSmallOneLarge) {
  EXPECT_LE(largest_coefficient_bits(katsura4().basis), kLimbRowCoefficientBits);
  EXPECT_GT(largest_coefficient_bits(large_coefficients().basis), kLimbRowCoefficientBits);
}

}  // namespace
}  // namespace implicitizer::detail
