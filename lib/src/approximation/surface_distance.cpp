#include "surface_distance.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <random>
#include <vector>

namespace implicitizer::approximation {
namespace {

const char* const kWhere = "approximation: surface to patch";
constexpr std::size_t kSampleSide = 25;
constexpr std::size_t kSeedSide = 25;

// Newton's projection of p onto {q = 0} along ∇q; none when it does not converge.
std::optional<Point> project_onto_surface(const FramedPolynomial& q, Point p, double scale) {
  for (int iteration = 0; iteration < 40; ++iteration) {
    Point g;
    const double value = q.value_and_gradient(p, g);
    const double g2 = g[0] * g[0] + g[1] * g[1] + g[2] * g[2];
    if (!(g2 > 0) || !std::isfinite(value)) return std::nullopt;
    const double step = value / g2;
    for (std::size_t i = 0; i < 3; ++i) p[i] -= step * g[i];
    if (std::abs(step) * std::sqrt(g2) <= 1e-11 * scale) return p;
  }
  return std::nullopt;
}

void add_seed_grid(const PatchEvaluator& patch, const ParameterRect& rect, SeedGrid& seeds) {
  for (std::size_t i = 0; i < kSeedSide; ++i) {
    for (std::size_t j = 0; j < kSeedSide; ++j) {
      const double s = rect[0] + (rect[1] - rect[0]) * double(i) / double(kSeedSide - 1);
      const double t = rect[2] + (rect[3] - rect[2]) * double(j) / double(kSeedSide - 1);
      Point x;
      if (!patch.point(s, t, x)) continue;
      seeds.points.push_back(x);
      seeds.parameters.push_back({s, t});
    }
  }
}

// |X(s*, t*) − y| after Gauss–Newton on |X(s, t) − y|² from the nearest seed, clamped
// to `rect`; the smallest distance met on the way.
double distance_to_patch(const PatchEvaluator& patch, const SeedGrid& seeds, const ParameterRect& rect, const Point& y) {
  // The nearest seed by squared distance: one square root, not one per seed (the scan
  // runs for every sample against every seed).
  std::size_t nearest = 0;
  double best_squared = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < seeds.points.size(); ++k) {
    const Point& x = seeds.points[k];
    const double d0 = x[0] - y[0], d1 = x[1] - y[1], d2 = x[2] - y[2];
    const double d = d0 * d0 + d1 * d1 + d2 * d2;
    if (d < best_squared) best_squared = d, nearest = k;
  }
  double best = std::sqrt(best_squared);
  double s = seeds.parameters[nearest][0], t = seeds.parameters[nearest][1];
  for (int iteration = 0; iteration < 12; ++iteration) {
    Point x, xs, xt;
    if (!patch.point_and_derivatives(s, t, x, xs, xt)) break;
    best = std::min(best, distance(x, y));
    double a = 0, b = 0, c = 0, rs = 0, rt = 0;
    for (std::size_t i = 0; i < 3; ++i) {
      a += xs[i] * xs[i], b += xs[i] * xt[i], c += xt[i] * xt[i];
      rs += xs[i] * (y[i] - x[i]), rt += xt[i] * (y[i] - x[i]);
    }
    const double det = a * c - b * b;
    if (!(std::abs(det) > 0)) break;
    s = std::clamp(s + (c * rs - b * rt) / det, rect[0], rect[1]);
    t = std::clamp(t + (a * rt - b * rs) / det, rect[2], rect[3]);
  }
  Point x;
  if (patch.point(s, t, x)) best = std::min(best, distance(x, y));
  return best;
}

// Zeros of q on the normal segment X + λ·ν, |λ| <= reach: every sign change between
// 17 equally spaced λ, bisected.
void normal_line_zeros(const FramedPolynomial& q, const Point& x, const Point& xs, const Point& xt, double reach,
                       std::vector<Point>& zeros) {
  Point nu{xs[1] * xt[2] - xs[2] * xt[1], xs[2] * xt[0] - xs[0] * xt[2], xs[0] * xt[1] - xs[1] * xt[0]};
  const double length = distance(nu, Point{});
  if (!(length > 0)) return;
  const auto at = [&](double lambda) {
    return Point{x[0] + lambda * nu[0] / length, x[1] + lambda * nu[1] / length, x[2] + lambda * nu[2] / length};
  };
  constexpr int kSteps = 16;
  double previous_lambda = -reach, previous = q.value(at(-reach));
  for (int k = 1; k <= kSteps; ++k) {
    const double lambda = -reach + 2 * reach * k / kSteps, value = q.value(at(lambda));
    if ((value > 0) != (previous > 0)) {
      double a = previous_lambda, b = lambda;
      for (int halving = 0; halving < 60; ++halving) {
        const double middle = (a + b) / 2;
        ((q.value(at(middle)) > 0) == (previous > 0) ? a : b) = middle;
      }
      zeros.push_back(at((a + b) / 2));
    }
    previous_lambda = lambda, previous = value;
  }
}

// Newton projections of X moved by a random length up to `reach` and by `reach`, in
// random directions; kept when they moved at most `reach`.
void projected_zeros(const FramedPolynomial& q, const Point& x, double reach, std::mt19937_64& random,
                     std::vector<Point>& zeros) {
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (const double fraction : {uniform(random), 1.0}) {
    Point p = x, direction{normal(random), normal(random), normal(random)};
    const double length = reach * fraction / std::max(distance(direction, Point{}), 1e-300);
    for (std::size_t k = 0; k < 3; ++k) p[k] += length * direction[k];
    const std::optional<Point> y = project_onto_surface(q, p, reach * 10);
    if (y && distance(*y, p) <= reach) zeros.push_back(*y);
  }
}

// The zeros of q near X(S): on the normal segments of reach `reach` and by Newton
// from random points within `reach`, from a 25×25 grid of S widened by an eighth of
// its sides (for the caps of the tube beyond S's edges).
void collect_tube_zeros(const PatchEvaluator& patch, const FramedPolynomial& q, const ParameterRect& piece,
                        double reach, const Budget& budget, std::vector<Point>& zeros) {
  std::mt19937_64 random(19);
  const double es = (piece[1] - piece[0]) / 8, et = (piece[3] - piece[2]) / 8;
  const ParameterRect scan{piece[0] - es, piece[1] + es, piece[2] - et, piece[3] + et};
  for (std::size_t i = 0; i < kSampleSide; ++i) {
    budget.check(kWhere);
    for (std::size_t j = 0; j < kSampleSide; ++j) {
      const double s = scan[0] + (scan[1] - scan[0]) * double(i) / double(kSampleSide - 1);
      const double t = scan[2] + (scan[3] - scan[2]) * double(j) / double(kSampleSide - 1);
      Point x, xs, xt;
      if (!patch.point_and_derivatives(s, t, x, xs, xt)) continue;
      normal_line_zeros(q, x, xs, xt, reach, zeros);
      projected_zeros(q, x, reach, random, zeros);
    }
  }
}

}  // namespace

ParameterRect widened(const ParameterRect& r) {
  const double ws = (r[1] - r[0]) / 4, wt = (r[3] - r[2]) / 4;
  return {r[0] - ws, r[1] + ws, r[2] - wt, r[3] + wt};
}

TubeSample::TubeSample(const PatchEvaluator& patch, const FramedPolynomial& q, const ParameterRect& piece,
                       const ParameterRect& domain, double reach, const Budget& budget)
    : patch_(patch), piece_(piece), whole_(widened(domain)), reach_(reach) {
  // Seeds: grids of S, S' and D' (S ⊂ S' ⊂ D'); projections stay in D'.
  add_seed_grid(patch, piece, own_);
  add_seed_grid(patch, widened(piece), near_);
  add_seed_grid(patch, whole_, far_);
  if (!seeded()) return;
  collect_tube_zeros(patch, q, piece, reach, budget, zeros_);
  to_piece_.assign(zeros_.size(), std::numeric_limits<double>::quiet_NaN());
  to_patch_.assign(zeros_.size(), std::numeric_limits<double>::quiet_NaN());
}

bool TubeSample::seeded() const { return !own_.points.empty() && !near_.points.empty() && !far_.points.empty(); }

double TubeSample::to_piece(const Point& y) const { return distance_to_patch(patch_, own_, piece_, y); }

double TubeSample::to_patch(const Point& y) const {
  // Two starts: a folded patch brings another part of X(D') close, where a single
  // projection can stop in a local minimum.
  return std::min(distance_to_patch(patch_, near_, whole_, y), distance_to_patch(patch_, far_, whole_, y));
}

double TubeSample::zero_to_piece(std::size_t k) {
  if (std::isnan(to_piece_[k])) to_piece_[k] = to_piece(zeros_[k]);
  return to_piece_[k];
}

double TubeSample::zero_to_patch(std::size_t k) {
  if (std::isnan(to_patch_[k])) to_patch_[k] = to_patch(zeros_[k]);
  return to_patch_[k];
}

SurfaceToPatch measure_surface_to_patch(TubeSample& tube) {
  SurfaceToPatch result;
  if (!tube.seeded()) return result;
  // The zeros farther than `reach` from X(S) are dropped (the trimming removes them).
  for (std::size_t k = 0; k < tube.zeros().size(); ++k) {
    if (tube.zero_to_piece(k) > tube.reach()) continue;
    result.distance = std::max(result.distance, tube.zero_to_patch(k));
    ++result.samples;
  }
  return result;
}

namespace {

// Zeros of q on the segment from `a` along axis `axis` over [from, to]: every sign
// change between kLineSamples equally spaced points, bisected.
void axis_line_zeros(const FramedPolynomial& q, Point a, std::size_t axis, double from, double to,
                     std::vector<Point>& zeros) {
  constexpr int kLineSamples = 48;
  const auto at = [&](double c) {
    a[axis] = c;
    return a;
  };
  double previous_c = from, previous = q.value(at(from));
  for (int k = 1; k < kLineSamples; ++k) {
    const double c = from + (to - from) * k / (kLineSamples - 1), value = q.value(at(c));
    if ((value > 0) != (previous > 0)) {
      double lo = previous_c, hi = c;
      for (int halving = 0; halving < 60; ++halving) {
        const double middle = (lo + hi) / 2;
        ((q.value(at(middle)) > 0) == (previous > 0) ? lo : hi) = middle;
      }
      zeros.push_back(at((lo + hi) / 2));
    }
    previous_c = c, previous = value;
  }
}

}  // namespace

SurfaceToPatch measure_polytope_to_patch(TubeSample& tube, const FramedPolynomial& q, const TrimPolytope& polytope,
                                         const Point& lo, const Point& hi, const Budget& budget) {
  constexpr std::size_t kGrid = 48;
  SurfaceToPatch result;
  if (!tube.seeded()) return result;
  const auto inside = [&](const Point& y) {
    const bool in_box =
        y[0] >= lo[0] && y[0] <= hi[0] && y[1] >= lo[1] && y[1] <= hi[1] && y[2] >= lo[2] && y[2] <= hi[2];
    return in_box && !(polytope.excess(y) > 0);
  };
  const auto measure = [&](double to_piece, double to_patch) {
    result.beyond_piece = std::max(result.beyond_piece, to_piece);
    result.distance = std::max(result.distance, to_patch);
    ++result.samples;
  };
  // Near the patch as the tube's measurement samples, then across the whole box.
  for (std::size_t k = 0; k < tube.zeros().size(); ++k) {
    if (inside(tube.zeros()[k])) measure(tube.zero_to_piece(k), tube.zero_to_patch(k));
  }
  std::vector<Point> zeros;
  for (std::size_t axis = 0; axis < 3; ++axis) {
    const std::size_t a = (axis + 1) % 3, b = (axis + 2) % 3;
    for (std::size_t i = 0; i < kGrid; ++i) {
      budget.check(kWhere);
      for (std::size_t j = 0; j < kGrid; ++j) {
        Point start{};
        start[a] = lo[a] + (hi[a] - lo[a]) * (double(i) + 0.5) / double(kGrid);
        start[b] = lo[b] + (hi[b] - lo[b]) * (double(j) + 0.5) / double(kGrid);
        axis_line_zeros(q, start, axis, lo[axis], hi[axis], zeros);
      }
    }
  }
  for (const Point& y : zeros) {
    if (inside(y)) measure(tube.to_piece(y), tube.to_patch(y));
  }
  return result;
}

double estimate_patch_to_surface(const PatchEvaluator& patch, const FramedPolynomial& q, const ParameterRect& piece,
                                 std::size_t side) {
  double worst = 0;
  for (std::size_t i = 0; i < side; ++i) {
    for (std::size_t j = 0; j < side; ++j) {
      const double s = piece[0] + (piece[1] - piece[0]) * double(i) / double(side - 1);
      const double t = piece[2] + (piece[3] - piece[2]) * double(j) / double(side - 1);
      Point x, g;
      if (!patch.point(s, t, x)) continue;
      const double value = q.value_and_gradient(x, g);
      const double norm = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
      worst = std::max(worst, norm > 0 ? std::abs(value) / norm : std::numeric_limits<double>::infinity());
    }
  }
  return worst;
}

}  // namespace implicitizer::approximation
