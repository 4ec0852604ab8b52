#pragma once
/// \file
/// Union, intersection and difference of solids (Def. 1.17 of the seed thesis) and
/// their smooth versions (Def. 1.18): C++ twins and, next to them, the GLSL of the
/// smooth ones (the sharp ones are GLSL's min and max, which the twins call with the
/// same argument order: GLSL's min(x, y) is y < x ? y : x, as std::min).
///
/// Smooth minimum with blend radius k > 0 and integer exponent n ≥ 1:
///     smin(a, b) = min(a, b) − max(k − |a − b|, 0)^n / (2n·k^(n−1))
///                = min(a, b) − k·h^n/(2n),   h = max(k − |a − b|, 0)/k ∈ [0, 1],
/// computed in the second form: h ≤ 1, so h^n cannot overflow for any k, and the
/// power is n − 1 multiplications (no pow(), undefined for negative bases in GLSL).
/// smax(a, b) = −smin(−a, −b) = max(a, b) + k·h^n/(2n) (the same floats: negation is
/// exact and min(−a, −b) = −max(a, b)); smooth difference = smax(a, −b).
///
/// Why smin keeps 1-Lipschitz children 1-Lipschitz: where a < b − k or b < a − k it
/// is min(a, b); for |a − b| < k and a ≤ b, smin = a − w(b − a) with
/// w(t) = (k − t)^n/(2n·k^(n−1)), w'(t) = −(k − t)^(n−1)/(2k^(n−1)) ∈ [−1/2, 0], so
/// ∂smin/∂a = 1 + w' ∈ [1/2, 1] and ∂smin/∂b = −w' ∈ [0, 1/2]; symmetrically for
/// a > b. smin is continuous (w(k) = 0, and the two formulas agree at a = b), so
/// along any segment |Δsmin| ≤ ∂a·|Δa| + ∂b·|Δb| ≤ max(|Δa|, |Δb|) ≤ |Δp| when both
/// children are 1-Lipschitz. A 1-Lipschitz function with the right sign never
/// exceeds the distance to the other side of its zero set. Over children that are
/// only bounds (not Lipschitz) the blend term can exceed the distance: safe mode
/// refuses that (classify_smooth, boolean_operators.cpp).

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

namespace implicitizer {

/// k·h^n/(2n) with h = max(k − |a − b|, 0)/k: the smooth operators' blend term,
/// h^n as h·h·…·h from the left, then ·k, then /(2n) (an exact float for any n < 2^23).
template <typename T>
T smooth_blend(T a, T b, T k, std::int32_t n) {
  const T h = std::max(k - std::abs(a - b), T(0)) / k;
  T power = h;
  for (std::int32_t i = 1; i < n; ++i) power = power * h;
  return power * k / T(2 * n);
}

/// smin(a, b) = min(a, b) − blend.
template <typename T>
T smooth_min(T a, T b, T k, std::int32_t n) {
  return std::min(a, b) - smooth_blend(a, b, k, n);
}

/// smax(a, b) = max(a, b) + blend = −smin(−a, −b).
template <typename T>
T smooth_max(T a, T b, T k, std::int32_t n) {
  return std::max(a, b) + smooth_blend(a, b, k, n);
}

/// `float PREFIX_smin<n>(float a, float b, float k)`, e.g. PREFIX_smin2.
std::string smooth_min_glsl(const std::string& prefix, std::int32_t n);
/// `float PREFIX_smax<n>(float a, float b, float k)`.
std::string smooth_max_glsl(const std::string& prefix, std::int32_t n);

}  // namespace implicitizer
