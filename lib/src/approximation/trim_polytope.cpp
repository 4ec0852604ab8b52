#include "implicitizer/approximation/trim_polytope.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "implicitizer/core/rational.hpp"
#include "patch_evaluator.hpp"

namespace implicitizer {

using approximation::Point;

double TrimPolytope::excess(const std::array<double, 3>& x) const {
  double worst = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < normals.size(); ++i) {
    const std::array<double, 3>& n = normals[i];
    worst = std::max(worst, n[0] * x[0] + n[1] * x[1] + n[2] * x[2] - offsets[i]);
  }
  return worst;
}

namespace {

Point cross(const Point& a, const Point& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

Point minus(const Point& a, const Point& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }

double dot(const Point& a, const Point& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

std::optional<Point> unit(const Point& v) {
  const double length = std::sqrt(dot(v, v));
  if (!(length > 0) || !std::isfinite(length)) return std::nullopt;
  return Point{v[0] / length, v[1] / length, v[2] / length};
}

// The directions of the file comment: ±ν, then two per edge (s = s0, s = s1, t = t0,
// t = t1), one per half of it, facing away from X at the centre.
std::optional<std::vector<Point>> plane_directions(const approximation::PatchEvaluator& patch,
                                                   const ParameterDomain& piece) {
  const double s0 = to_mpq(piece.intervals[0].first).get_d(), s1 = to_mpq(piece.intervals[0].second).get_d();
  const double t0 = to_mpq(piece.intervals[1].first).get_d(), t1 = to_mpq(piece.intervals[1].second).get_d();
  Point centre, xs, xt;
  if (!patch.point_and_derivatives((s0 + s1) / 2, (t0 + t1) / 2, centre, xs, xt)) return std::nullopt;
  const std::optional<Point> normal = unit(cross(xs, xt));
  if (!normal) return std::nullopt;
  std::vector<Point> directions{*normal, {-(*normal)[0], -(*normal)[1], -(*normal)[2]}};
  const std::array<std::array<double, 4>, 4> edges{
      {{s0, t0, s0, t1}, {s1, t0, s1, t1}, {s0, t0, s1, t0}, {s0, t1, s1, t1}}};
  for (const auto& e : edges) {
    Point a, m, b;
    if (!patch.point(e[0], e[1], a) || !patch.point((e[0] + e[2]) / 2, (e[1] + e[3]) / 2, m) ||
        !patch.point(e[2], e[3], b)) {
      return std::nullopt;
    }
    for (const auto& [from, to] : {std::pair{a, m}, std::pair{m, b}}) {
      std::optional<Point> side = unit(cross(minus(to, from), *normal));
      if (!side) return std::nullopt;
      const Point middle{(from[0] + to[0]) / 2, (from[1] + to[1]) / 2, (from[2] + to[2]) / 2};
      if (dot(*side, minus(middle, centre)) < 0) side = Point{-(*side)[0], -(*side)[1], -(*side)[2]};
      directions.push_back(*side);
    }
  }
  return directions;
}

// n·X as a rational function: (Σ n_j ξ_j) / ω, the n_j read exactly.
RationalFunction linear_form(const std::vector<Polynomial>& forms, const Point& n, const RingPtr& ring) {
  Polynomial numerator(ring);
  for (std::size_t j = 0; j < 3; ++j) {
    numerator += forms[j + 1] * Polynomial::constant(ring, Rational(n[j]));
  }
  return RationalFunction(numerator, forms[0]);
}

}  // namespace

std::optional<TrimPolytope> bound_piece_polytope(const Parametrization& parametrization, const ParameterDomain& piece,
                                                 const Budget& budget) {
  const std::vector<Polynomial> forms = common_denominator_form(parametrization, budget);
  const approximation::PatchEvaluator patch(forms);
  const std::optional<std::vector<Point>> directions = plane_directions(patch, piece);
  if (!directions) return std::nullopt;
  TrimPolytope polytope;
  // Three directions per bound_patch() call: it bounds every coordinate of the patch
  // it is given.
  for (std::size_t first = 0; first < directions->size(); first += 3) {
    const std::size_t end = std::min(first + 3, directions->size());
    Parametrization projected{parametrization.parameter_ring, {}, {}, {}};
    for (std::size_t i = first; i < end; ++i) {
      projected.coordinates.push_back(linear_form(forms, (*directions)[i], parametrization.parameter_ring));
      projected.sources.emplace_back();
    }
    const PatchBounds bounds = bound_patch(projected, piece, budget);
    for (std::size_t i = first; i < end; ++i) {
      polytope.normals.push_back((*directions)[i]);
      polytope.offsets.push_back(round_up<double>(bounds.hi[i - first]));
    }
  }
  return polytope;
}

}  // namespace implicitizer
