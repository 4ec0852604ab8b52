// F4's echelon step (lib/src/groebner/f4_row_echelon.hpp) on threads against one
// thread: random sparse matrices large enough to be shared among threads, modulo a
// prime below 2^31 (the delayed path) and a 62-bit one, must give the same new rows,
// from the same rows to reduce.
#include "f4_row_echelon.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <set>
#include <vector>

#include "implicitizer/core/budget.hpp"

namespace implicitizer::detail {
namespace {

// A row leading at `lead` with `terms` random columns after it and random non-zero
// coefficients; monic when `monic` (a pivot).
MatrixRow random_row(std::mt19937_64& engine, std::uint32_t lead, std::size_t columns, std::size_t terms,
                     std::uint64_t prime, bool monic) {
  std::set<std::uint32_t> tail;
  while (tail.size() < terms && tail.size() + lead + 1 < columns) {
    tail.insert(static_cast<std::uint32_t>(lead + 1 + engine() % (columns - lead - 1)));
  }
  MatrixRow row;
  row.columns.push_back(lead);
  row.columns.insert(row.columns.end(), tail.begin(), tail.end());
  for (std::size_t i = 0; i < row.columns.size(); ++i) {
    row.owned.push_back(i == 0 && monic ? 1 : 1 + engine() % (prime - 1));
  }
  row.coefficients = row.owned.data();
  return row;
}

// Pivots on two columns in three, and rows to reduce leading at pivot columns (as
// F4's pairs do) and at free ones.
MacaulayMatrix random_matrix(std::mt19937_64& engine, std::uint64_t prime) {
  MacaulayMatrix matrix;
  matrix.columns = 600;
  for (std::uint32_t c = 0; c < matrix.columns; ++c) {
    if (c % 3 != 2) matrix.pivots.push_back(random_row(engine, c, matrix.columns, 20, prime, true));
  }
  // More rows than free columns: some reduce to zero.
  for (std::size_t k = 0; k < 300; ++k) {
    const auto lead = static_cast<std::uint32_t>(engine() % (matrix.columns / 2));
    matrix.to_reduce.push_back(random_row(engine, lead, matrix.columns, 30, prime, false));
  }
  return matrix;
}

TEST(F4RowEchelonTest, ThreadsGiveTheRowsOneThreadGives) {
  std::mt19937_64 engine(20261204);
  for (const std::uint64_t prime : {std::uint64_t{2147483629}, std::uint64_t{4611686018427387847}}) {
    nmod_t modulus;
    nmod_init(&modulus, prime);
    for (int round = 0; round < 3; ++round) {
      const MacaulayMatrix matrix = random_matrix(engine, prime);
      const Budget budget;
      const EchelonResult one = reduce_to_row_echelon(matrix, modulus, budget, 1);
      const EchelonResult two = reduce_to_row_echelon(matrix, modulus, budget, 2);
      ASSERT_FALSE(one.new_rows.empty());
      // Not every row is new: the elimination by the new rows is exercised.
      ASSERT_LT(one.new_rows.size(), matrix.to_reduce.size());
      EXPECT_EQ(one.sources, two.sources);
      ASSERT_EQ(one.new_rows.size(), two.new_rows.size());
      for (std::size_t k = 0; k < one.new_rows.size(); ++k) {
        EXPECT_EQ(one.new_rows[k].columns, two.new_rows[k].columns) << "row " << k;
        EXPECT_EQ(one.new_rows[k].owned, two.new_rows[k].owned) << "row " << k;
      }
    }
  }
}

}  // namespace
}  // namespace implicitizer::detail
