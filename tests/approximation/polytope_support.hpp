#pragma once
// What the approximation and scene tests share about tp_33 and trimming polytopes:
// the patch evaluated by the test itself (not the library), and a polytope's excess
// in the test's own arithmetic.

#include <algorithm>
#include <array>
#include <limits>

#include "implicitizer/approximation/trim_polytope.hpp"

namespace implicitizer::testing {

/// max_i (n_i·y − c_i) of `polytope` in long double: <= 0 inside.
template <typename T>
long double polytope_excess(const TrimPolytope& polytope, const std::array<T, 3>& y) {
  long double worst = -std::numeric_limits<long double>::infinity();
  for (std::size_t i = 0; i < polytope.normals.size(); ++i) {
    long double sum = -static_cast<long double>(polytope.offsets[i]);
    for (std::size_t j = 0; j < 3; ++j) sum += static_cast<long double>(polytope.normals[i][j]) * y[j];
    worst = std::max(worst, sum);
  }
  return worst;
}

/// tp_33 of ../shared/bench/surfaces_hard.json (a bicubic patch) at (s, t), in T.
template <typename T>
std::array<T, 3> tp33_point(T s, T t) {
  const T s2 = s * s, s3 = s2 * s, t2 = t * t, t3 = t2 * t;
  return {3 + 2 * t2 + t3 - 3 * s - 5 * s * t + s2 - 2 * s2 * t - 3 * s2 * t2 - 3 * s2 * t3 + 4 * s3 - 3 * s3 * t +
              3 * s3 * t2 - s3 * t3,
          3 + t - 2 * t2 - 4 * t3 - 3 * s + s * t + 5 * s * t2 + 2 * s * t3 + 4 * s2 - s2 * t - 5 * s2 * t2 + s2 * t3 -
              5 * s3 - 3 * s3 * t - 5 * s3 * t2 + 3 * s3 * t3,
          -2 - 2 * t - 4 * t2 - 5 * t3 + 3 * s - 3 * s * t - 4 * s * t2 - 4 * s * t3 - s2 + 3 * s2 * t - 3 * s2 * t2 -
              2 * s2 * t3 + 3 * s3 + 5 * s3 * t - 2 * s3 * t2 + 2 * s3 * t3};
}

}  // namespace implicitizer::testing
