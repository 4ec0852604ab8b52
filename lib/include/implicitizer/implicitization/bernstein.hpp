#pragma once
/// \file
/// Dense tensor Bernstein coefficients in exact rational arithmetic: the form in which
/// bound_patch() proves its boxes and approximate_patch() certifies its bounds. On a
/// box B = Π [a_j, b_j], p = Σ_J c_J·B_J with B_J ≥ 0 and Σ_J B_J = 1, so min_J c_J
/// <= p <= max_J c_J on B, and c_J at a corner of B is the value there.

#include <cstddef>
#include <utility>
#include <vector>

#include "implicitizer/core/budget.hpp"
#include "implicitizer/core/rational.hpp"
#include "implicitizer/polynomial/polynomial.hpp"

namespace implicitizer {

/// Exact coefficients, one per entry of a BernsteinLayout.
using BernsteinCoefficients = std::vector<mpq_class>;

/// A box of parameters: [lo, hi] per variable.
using BernsteinBox = std::vector<std::pair<mpq_class, mpq_class>>;

/// The layout of a dense coefficient tensor: one axis per variable with degree + 1
/// entries, the last variable fastest.
struct BernsteinLayout {
  std::vector<std::size_t> extents;  ///< degree + 1 per variable
  std::vector<std::size_t> strides;  ///< of each axis in the flat vector
  std::size_t size = 1;              ///< number of coefficients

  /// The layout of degrees extents[j] − 1.
  explicit BernsteinLayout(std::vector<std::size_t> e);

  /// Calls f(first, stride) for every line of coefficients along `axis`.
  template <class F>
  void for_each_fiber(std::size_t axis, F&& f) const {
    const std::size_t stride = strides[axis];
    const std::size_t block = stride * extents[axis];
    for (std::size_t outer = 0; outer < size; outer += block) {
      for (std::size_t inner = 0; inner < stride; ++inner) f(outer + inner, stride);
    }
  }

  /// The index of corner `mask` (bit j set: the upper end of variable j).
  std::size_t corner(std::size_t mask) const;
};

/// The power-basis coefficients of `p` as a dense tensor of `layout` (p's degree in
/// each variable must fit its extent).
BernsteinCoefficients dense_coefficients(const Polynomial& p, const BernsteinLayout& layout);

/// Rewrites power-basis coefficients in variable `axis` as Bernstein coefficients on
/// [a, b]: p(t) = q(u) with t = a + (b − a)·u (Taylor shift, then scaling), then
/// b_k = Σ_{i ≤ k} C(k,i)/C(n,i)·q_i, the Bernstein form of q on [0, 1]. O(n²) exact
/// operations per line along the axis: `budget` is checked per line (stops name
/// `where`).
void to_bernstein_along(BernsteinCoefficients& c, const BernsteinLayout& layout, std::size_t axis, const mpq_class& a,
                        const mpq_class& b, const Budget& budget, const char* where);

/// The Bernstein coefficients of `p` over `box` in `layout` (every axis converted;
/// checks `budget` per axis).
BernsteinCoefficients bernstein_coefficients(const Polynomial& p, const BernsteinLayout& layout,
                                             const BernsteinBox& box, const Budget& budget, const char* where);

/// Splits Bernstein coefficients at the midpoint of variable `axis` (de Casteljau with
/// weight 1/2): the coefficients of the lower and of the upper half. O(n²) exact
/// operations per line: `budget` is checked per line (stops name `where`).
std::pair<BernsteinCoefficients, BernsteinCoefficients> split_along(const BernsteinCoefficients& c,
                                                                    const BernsteinLayout& layout, std::size_t axis,
                                                                    const Budget& budget, const char* where);

}  // namespace implicitizer
