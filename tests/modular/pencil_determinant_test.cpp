// Tests of lib/src/modular/pencil_determinant.cpp and prime_sequence.cpp: the
// modular determinant agrees with a cofactor expansion done with the polynomial
// arithmetic (written independently here), in both stopping modes, with a divisor
// minor, and with primes small enough to be unlucky.

#include "implicitizer/modular/pencil_determinant.hpp"

#include <gtest/gtest.h>

#include <random>

#include "implicitizer/modular/prime_sequence.hpp"
#include "implicitizer/polynomial/parser.hpp"
#include "implicitizer/polynomial/printer.hpp"

namespace implicitizer {
namespace {

RingPtr ring_of(std::size_t k) {
  static const std::vector<std::string> names = {"x", "y", "z", "w"};
  return Ring::make(std::vector<std::string>(names.begin(), names.begin() + static_cast<std::ptrdiff_t>(k)));
}

// The entry (r, c) of the pencil as a polynomial.
Polynomial entry(const MatrixPencil& m, const RingPtr& ring, std::size_t r, std::size_t c) {
  Polynomial e = Polynomial::constant(ring, to_rational(m.at(0, r, c)));
  for (std::size_t v = 0; v < m.num_variables(); ++v) {
    e += Polynomial::variable(ring, v).scaled(to_rational(m.at(v + 1, r, c)));
  }
  return e;
}

// Laplace expansion along the first row of the submatrix rows[..], cols[..].
Polynomial cofactor_determinant(const MatrixPencil& m, const RingPtr& ring, std::vector<std::size_t> rows,
                                std::vector<std::size_t> cols) {
  if (rows.empty()) return Polynomial::constant(ring, Rational(1));
  Polynomial det(ring);
  const std::size_t r = rows.front();
  std::vector<std::size_t> rest_rows(rows.begin() + 1, rows.end());
  for (std::size_t j = 0; j < cols.size(); ++j) {
    std::vector<std::size_t> rest_cols = cols;
    rest_cols.erase(rest_cols.begin() + static_cast<std::ptrdiff_t>(j));
    Polynomial term = entry(m, ring, r, cols[j]) * cofactor_determinant(m, ring, rest_rows, rest_cols);
    det = (j % 2 == 0) ? det + term : det - term;
  }
  return det;
}

std::vector<std::size_t> all(std::size_t n) {
  std::vector<std::size_t> v(n);
  for (std::size_t i = 0; i < n; ++i) v[i] = i;
  return v;
}

MatrixPencil random_pencil(std::size_t n, std::size_t k, std::mt19937_64& rng, int magnitude, double density = 0.7) {
  MatrixPencil m(n, k);
  std::uniform_int_distribution<int> coefficient(-magnitude, magnitude);
  std::uniform_real_distribution<double> keep(0, 1);
  for (std::size_t part = 0; part <= k; ++part) {
    for (std::size_t r = 0; r < n; ++r) {
      for (std::size_t c = 0; c < n; ++c) {
        if (keep(rng) < density) m.at(part, r, c) = coefficient(rng);
      }
    }
  }
  return m;
}

TEST(PrimeSequence, IncreasingPrimesAboveTwoToThe62) {
  PrimeSequence primes;
  std::uint64_t last = 0;
  for (int i = 0; i < 5; ++i) {
    const std::uint64_t p = primes.next();
    EXPECT_GT(p, std::uint64_t{1} << 62);
    EXPECT_GT(p, last);
    last = p;
  }
  EXPECT_EQ(PrimeSequence::from(10).next(), 11u);
}

TEST(ResidueStream, ReproducibleAndBelowModulus) {
  ResidueStream a(42), b(42);
  for (int i = 0; i < 100; ++i) {
    const auto v = a.next(97);
    EXPECT_EQ(v, b.next(97));
    EXPECT_LT(v, 97u);
  }
}

TEST(PencilDeterminant, AgreesWithCofactorExpansionOnRandomPencils) {
  std::mt19937_64 rng(7);
  for (std::size_t k = 1; k <= 3; ++k) {
    for (std::size_t n = 1; n <= 5; ++n) {
      const MatrixPencil m = random_pencil(n, k, rng, 1000);
      const RingPtr ring = ring_of(k);
      const Polynomial expected = cofactor_determinant(m, ring, all(n), all(n));
      PencilDeterminantParams early;
      early.degree_bound = static_cast<std::int32_t>(n);
      PencilDeterminantStats stats;
      EXPECT_EQ(to_string(pencil_determinant(m, ring, early, &stats)), to_string(expected)) << "k=" << k << " n=" << n;
      EXPECT_FALSE(stats.proven);
      PencilDeterminantParams proven = early;
      proven.proven_bits = m.determinant_coefficient_bits();
      EXPECT_EQ(to_string(pencil_determinant(m, ring, proven, &stats)), to_string(expected));
      EXPECT_TRUE(stats.proven);
      EXPECT_GT(stats.modulus_bits, proven.proven_bits + 1);
    }
  }
}

TEST(PencilDeterminant, HugeCoefficientsNeedManyPrimes) {
  // Entries of 300 bits: the determinant's coefficients have about 1500 bits, so
  // the reconstruction must combine some 25 primes of 62 bits.
  std::mt19937_64 rng(3);
  MatrixPencil m(5, 1);
  const Integer big = Integer(1) << 300;
  for (std::size_t r = 0; r < 5; ++r) {
    for (std::size_t c = 0; c < 5; ++c) {
      m.at(0, r, c) = big * static_cast<int>(rng() % 19) - static_cast<int>(rng() % 7);
      m.at(1, r, c) = static_cast<int>(rng() % 5) - 2;
    }
  }
  const RingPtr ring = ring_of(1);
  PencilDeterminantParams options;
  options.degree_bound = 5;
  PencilDeterminantStats stats;
  EXPECT_EQ(pencil_determinant(m, ring, options, &stats), cofactor_determinant(m, ring, all(5), all(5)));
  EXPECT_GE(stats.primes, 24u);
}

TEST(PencilDeterminant, QuotientByADivisorMinor) {
  // Block lower-triangular: det = det(E)·det(F) with E on rows/columns {1, 3}.
  std::mt19937_64 rng(11);
  const RingPtr ring = ring_of(2);
  MatrixPencil m = random_pencil(5, 2, rng, 9, 1.0);
  const std::vector<std::size_t> e = {1, 3};
  const std::vector<std::size_t> f = {0, 2, 4};
  for (std::size_t part = 0; part <= 2; ++part) {
    for (std::size_t i : e) {
      for (std::size_t j : f) m.at(part, i, j) = 0;
    }
  }
  PencilDeterminantParams options;
  options.degree_bound = 3;
  options.divisor_minor = e;
  EXPECT_EQ(pencil_determinant(m, ring, options), cofactor_determinant(m, ring, f, f));
}

TEST(PencilDeterminant, SmallPrimesAreUnluckyAndDropped) {
  // Modulo primes near 20 a random grid of 4 points per variable often meets a
  // zero of the divisor minor; those primes must be dropped, not combined.
  std::mt19937_64 rng(5);
  const RingPtr ring = ring_of(2);
  MatrixPencil m = random_pencil(4, 2, rng, 3, 1.0);
  const std::vector<std::size_t> e = {0, 1};
  for (std::size_t part = 0; part <= 2; ++part) {
    for (std::size_t i : e) {
      m.at(part, i, 2) = 0;
      m.at(part, i, 3) = 0;
    }
  }
  PencilDeterminantParams options;
  options.degree_bound = 2;
  options.divisor_minor = e;
  options.primes = PrimeSequence::from(16);
  options.stable_primes = 4;
  options.threads = 1;
  PencilDeterminantStats stats;
  EXPECT_EQ(pencil_determinant(m, ring, options, &stats), cofactor_determinant(m, ring, {2, 3}, {2, 3}));
  EXPECT_GT(stats.unlucky_primes, 0u);
}

TEST(PencilDeterminant, AWrongDegreeBoundIsCaught) {
  std::mt19937_64 rng(1);
  MatrixPencil m = random_pencil(4, 1, rng, 5, 1.0);
  PencilDeterminantParams options;
  options.degree_bound = 2;  // the determinant has degree 4
  EXPECT_THROW(pencil_determinant(m, ring_of(1), options), std::logic_error);
}

TEST(PencilDeterminant, SingularPencilIsZeroAndProbedAsZero) {
  std::mt19937_64 rng(2);
  MatrixPencil m = random_pencil(4, 3, rng, 5, 1.0);
  for (std::size_t part = 0; part <= 3; ++part) {
    for (std::size_t c = 0; c < 4; ++c) m.at(part, 3, c) = m.at(part, 1, c) * 2;
  }
  PencilDeterminantParams options;
  options.degree_bound = 4;
  EXPECT_TRUE(pencil_determinant(m, ring_of(3), options).is_zero());
  EXPECT_EQ(probe_pencil_determinant(m, {}), PencilProbe::zero);
  m.at(0, 3, 0) += 1;
  EXPECT_EQ(probe_pencil_determinant(m, {}), PencilProbe::nonzero);
  EXPECT_EQ(probe_pencil_determinant(m, {3}), PencilProbe::nonzero);
  MatrixPencil zero_minor = m;
  for (std::size_t part = 0; part <= 3; ++part) zero_minor.at(part, 2, 2) = 0;
  EXPECT_EQ(probe_pencil_determinant(zero_minor, {2}), PencilProbe::minor_zero);
}

TEST(PencilDeterminant, BudgetStopsTheEvaluation) {
  std::mt19937_64 rng(4);
  MatrixPencil m = random_pencil(30, 3, rng, 100, 1.0);
  PencilDeterminantParams options;
  options.degree_bound = 30;
  options.budget = Budget::with_timeout(0.01);
  try {
    pencil_determinant(m, ring_of(3), options);
    FAIL() << "expected the time limit";
  } catch (const LimitExceeded& e) {
    EXPECT_EQ(e.limit(), Limit::time);
  }
}

// One evaluation is a whole determinant, which FLINT cannot interrupt (seconds at
// size 2000): evaluations that would end past the deadline are refused before the
// first, naming the sizes. Those of the curve t^1000 + t^3, t^999 (a 2000 × 2000
// pencil, C(1002, 2) + 1 evaluations) are predicted at about 10^6 s, refused on a
// 1 s budget whatever the machine; without a deadline, or below size 256, never.
TEST(PencilDeterminant, EvaluationsPastTheDeadlineAreRefusedBeforeTheFirst) {
  try {
    refuse_determinants_past_deadline(2000, 501502, Budget::with_timeout(1));
    FAIL() << "expected the time limit";
  } catch (const LimitExceeded& e) {
    EXPECT_EQ(e.limit(), Limit::time);
    EXPECT_NE(std::string(e.what()).find("501502 evaluations of a 2000x2000 matrix"), std::string::npos) << e.what();
  }
  EXPECT_NO_THROW(refuse_determinants_past_deadline(2000, 501502, Budget()));
  EXPECT_NO_THROW(refuse_determinants_past_deadline(100, 501502, Budget::with_timeout(1)));
}

// A cancelled budget stops the probe at the reduction of the pencil modulo its prime.
TEST(PencilDeterminant, TheProbeChecksItsBudget) {
  std::mt19937_64 rng(4);
  const MatrixPencil m = random_pencil(30, 3, rng, 100, 1.0);
  Budget cancelled;
  cancelled.cancel();
  try {
    (void)probe_pencil_determinant(m, {}, 0x5eed, 1, cancelled);
    FAIL() << "expected the cancellation";
  } catch (const LimitExceeded& e) {
    EXPECT_EQ(e.limit(), Limit::cancelled);
  }
}

TEST(PencilDeterminant, RefusesMismatchedRingsAndMinors) {
  MatrixPencil m(2, 2);
  PencilDeterminantParams options;
  options.degree_bound = 2;
  EXPECT_THROW(pencil_determinant(m, ring_of(3), options), std::invalid_argument);
  options.divisor_minor = {1, 0};
  EXPECT_THROW(pencil_determinant(m, ring_of(2), options), std::invalid_argument);
}

}  // namespace
}  // namespace implicitizer
