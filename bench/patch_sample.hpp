#pragma once
/// \file
/// A dense sample of a patch X(D), D = [s0, s1]×[t0, t1], evaluated in double, with
/// the distance queries the patch benchmark needs (patch_accuracy.cpp):
///   - upper_bound(p): the distance from p to a point of X(D) found by projecting p
///     onto the patch (Gauss–Newton on (s, t), clamped to D, from the nearest
///     samples). It is the distance to an actual patch point, so never below the true
///     distance: a value above it is certainly above the true distance.
///   - lower_bound(p): the distance to the nearest sample minus the sample's covering
///     radius (the largest distance between neighbouring samples): every patch point
///     of a grid cell is within that radius of one of the cell's corners when the
///     grid is fine enough for the cell's image to be nearly flat, which the default
///     grid (512² samples on patches whose box is ~1) makes true up to rounding.

#include <array>
#include <cstddef>
#include <unordered_map>
#include <vector>

#include "implicitizer/implicitization/parametrization.hpp"

namespace implicitizer::bench {

/// A patch's dense sample.
class PatchSample {
 public:
  using Point = std::array<double, 3>;

  /// Samples `parametrization` (two parameters, three coordinates) on a side×side
  /// grid of D = domain (s0, s1, t0, t1). Grid points where a denominator is 0 are
  /// skipped.
  PatchSample(const Parametrization& parametrization, const std::array<double, 4>& domain, std::size_t side);

  /// X(s, t) in double; false when a denominator is 0 there.
  bool evaluate(double s, double t, Point& out) const;
  /// See the file comment.
  double upper_bound(const Point& p) const;
  /// See the file comment (never negative).
  double lower_bound(const Point& p) const;
  /// The box of the samples.
  const Point& lo() const { return lo_; }
  /// See lo().
  const Point& hi() const { return hi_; }
  /// The largest distance between neighbouring samples.
  double spacing() const { return spacing_; }

 private:
  struct Term {
    double coefficient;
    int s, t;
  };
  using Terms = std::vector<Term>;
  static double evaluate_terms(const Terms& terms, double s, double t);
  // The indices of the samples nearest p (up to `count`), nearest first.
  std::vector<std::size_t> nearest(const Point& p, std::size_t count) const;
  std::array<long, 3> cell_of(const Point& p) const;
  static std::size_t cell_key(const std::array<long, 3>& c);

  std::array<Terms, 3> numerators_, denominators_;
  std::array<double, 4> domain_{};
  std::vector<Point> points_;
  std::vector<std::array<double, 2>> parameters_;
  Point lo_{}, hi_{};
  double spacing_ = 0, cell_ = 1;
  std::unordered_map<std::size_t, std::vector<std::size_t>> cells_;
};

}  // namespace implicitizer::bench
