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
constexpr std::size_t kSampleSide = 17;
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

struct Seeds {
  std::vector<Point> points;
  std::vector<std::array<double, 2>> parameters;
};

Seeds seed_grid(const PatchEvaluator& patch, const ParameterRect& rect) {
  Seeds seeds;
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
  return seeds;
}

// |X(s*, t*) − y| after Gauss–Newton on |X(s, t) − y|² from the nearest seed, clamped
// to `rect`; the smallest distance met on the way.
double distance_to_patch(const PatchEvaluator& patch, const Seeds& seeds, const ParameterRect& rect, const Point& y) {
  std::size_t nearest = 0;
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < seeds.points.size(); ++k) {
    const double d = distance(seeds.points[k], y);
    if (d < best) best = d, nearest = k;
  }
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

}  // namespace

SurfaceToPatch measure_surface_to_patch(const PatchEvaluator& patch, const FramedPolynomial& q,
                                        const ParameterRect& piece, double reach, const Budget& budget) {
  const double ws = (piece[1] - piece[0]) / 4, wt = (piece[3] - piece[2]) / 4;
  const ParameterRect widened{piece[0] - ws, piece[1] + ws, piece[2] - wt, piece[3] + wt};
  const Seeds seeds = seed_grid(patch, widened);
  std::mt19937_64 random(19);
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  SurfaceToPatch result;
  if (seeds.points.empty()) return result;
  for (std::size_t i = 0; i < kSampleSide; ++i) {
    budget.check(kWhere);
    for (std::size_t j = 0; j < kSampleSide; ++j) {
      const double s = piece[0] + (piece[1] - piece[0]) * double(i) / double(kSampleSide - 1);
      const double t = piece[2] + (piece[3] - piece[2]) * double(j) / double(kSampleSide - 1);
      Point x;
      if (!patch.point(s, t, x)) continue;
      // Two offsets per grid point: one of random length, one of the full reach (the
      // farthest points of {q = 0} the trimming keeps).
      for (const double fraction : {uniform(random), 1.0}) {
        Point p = x, direction{normal(random), normal(random), normal(random)};
        const double length = reach * fraction / std::max(distance(direction, Point{}), 1e-300);
        for (std::size_t k = 0; k < 3; ++k) p[k] += length * direction[k];
        const std::optional<Point> y = project_onto_surface(q, p, reach * 10);
        if (!y || distance(*y, p) > reach) continue;
        ++result.samples;
        result.distance = std::max(result.distance, distance_to_patch(patch, seeds, widened, *y));
      }
    }
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
