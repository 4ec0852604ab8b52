#pragma once
/// \file
/// The sphere tracer and the evaluation timer of the accuracy benches (sdf_accuracy.cpp,
/// patch_accuracy.cpp), so that both measure tracing the same way.
///
/// Rays: R×R rays from the eye centre + 3h·(3, 3, 5)/|(3, 3, 5)| towards the box's
/// centre, h the box's largest half side, the field of view just holding the box's
/// corners. Each ray that meets the box starts where it enters it (as a renderer that
/// intersects the bounding box first) and steps t += |v| (Hart 1996) with v the fp32
/// value at the point rounded to float, as a shader receives it; the step sum is kept
/// in double so that the tracer's own rounding does not enter the comparison. A hit is
/// |v| < kHitTolerance·h, a miss t beyond the box's far side, a stall kMaxSteps steps
/// without either.

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace implicitizer::bench {

/// A point in double.
using TracePoint = std::array<double, 3>;

/// What the sphere tracer did over all rays.
struct TraceStatistics {
  std::size_t rays = 0;      ///< rays traced: those that meet the box
  std::size_t hits = 0;      ///< |v| < kHitTolerance·h reached
  std::size_t far_hits = 0;  ///< hits farther than kFarHitTolerance·h from what should be hit
  std::size_t crossed = 0;   ///< rays on which v changed sign between two steps
  double farthest_hit = 0;   ///< the largest such distance at a far hit, in units of h (0 without far hits)
  std::size_t stalled = 0;   ///< kMaxSteps steps without a hit or a miss
  double mean_steps = 0;     ///< evaluations per ray
  int max_steps = 0;         ///< the most evaluations of one ray
  /// Per ray, row by row (side × side entries): 1 where the ray hit, 0 where it missed
  /// the box, left it or stalled: the hit mask two functions are compared by.
  std::vector<std::uint8_t> hit_mask;
};

inline constexpr double kHitTolerance = 1e-4;     ///< × h: the tracer stops below this |v|
inline constexpr double kFarHitTolerance = 1e-3;  ///< × h: a hit farther than this from its target is wrong
inline constexpr int kMaxSteps = 512;

/// Traces side×side rays through the box [lo, hi] (file comment). `evaluate(x, y, z)`
/// returns the fp32 value at a float point; `hit_error(p)` returns an upper bound of
/// the distance from the hit point p to what the function should draw, only called
/// for hits (the caller may return 0 early when a cheap bound is below
/// kFarHitTolerance·h).
template <typename Evaluate, typename HitError>
TraceStatistics trace_rays(const TracePoint& lo, const TracePoint& hi, int side, const Evaluate& evaluate,
                           const HitError& hit_error) {
  const double h = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]}) / 2;
  const TracePoint c = {(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2};
  const double n43 = std::sqrt(43.0);  // |(3, 3, 5)|
  const TracePoint eye = {c[0] + 3 * h * 3 / n43, c[1] + 3 * h * 3 / n43, c[2] + 3 * h * 5 / n43};
  auto normalise = [](TracePoint v) {
    const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    return TracePoint{v[0] / n, v[1] / n, v[2] / n};
  };
  auto cross = [](const TracePoint& a, const TracePoint& b) {
    return TracePoint{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  };
  const TracePoint forward = normalise({c[0] - eye[0], c[1] - eye[1], c[2] - eye[2]});
  const TracePoint right = normalise(cross(forward, {0, 0, 1}));
  const TracePoint up = cross(right, forward);
  // The field of view frames the box: the largest tangent under which a corner is seen.
  double tan_half = 0;
  for (int k = 0; k < 8; ++k) {
    const TracePoint corner = {(k & 1) ? hi[0] : lo[0], (k & 2) ? hi[1] : lo[1], (k & 4) ? hi[2] : lo[2]};
    const TracePoint r = {corner[0] - eye[0], corner[1] - eye[1], corner[2] - eye[2]};
    auto dot = [&r](const TracePoint& e) { return r[0] * e[0] + r[1] * e[1] + r[2] * e[2]; };
    tan_half = std::max({tan_half, std::fabs(dot(right)) / dot(forward), std::fabs(dot(up)) / dot(forward)});
  }
  TraceStatistics stats;
  stats.hit_mask.assign(static_cast<std::size_t>(side) * static_cast<std::size_t>(side), 0);
  double total_steps = 0;
  for (int j = 0; j < side; ++j) {
    for (int i = 0; i < side; ++i) {
      const double a = (2 * (i + 0.5) / side - 1) * tan_half, b = (2 * (j + 0.5) / side - 1) * tan_half;
      const TracePoint d = normalise({forward[0] + a * right[0] + b * up[0], forward[1] + a * right[1] + b * up[1],
                                      forward[2] + a * right[2] + b * up[2]});
      // The ray's span in the box (slabs); a ray that misses the box is not traced.
      double t = 0, t_exit = std::numeric_limits<double>::infinity();
      for (std::size_t axis = 0; axis < 3; ++axis) {
        if (d[axis] == 0) {
          if (eye[axis] < lo[axis] || eye[axis] > hi[axis]) t = t_exit = 0;
          continue;
        }
        const double t0 = (lo[axis] - eye[axis]) / d[axis], t1 = (hi[axis] - eye[axis]) / d[axis];
        t = std::max(t, std::min(t0, t1));
        t_exit = std::min(t_exit, std::max(t0, t1));
      }
      if (!(t < t_exit)) continue;
      int steps = 0;
      bool done = false, crossed = false;
      float previous = 0;
      while (steps < kMaxSteps) {
        const float px = static_cast<float>(eye[0] + t * d[0]), py = static_cast<float>(eye[1] + t * d[1]),
                    pz = static_cast<float>(eye[2] + t * d[2]);
        const float v = evaluate(px, py, pz);
        ++steps;
        if (std::fabs(v) < kHitTolerance * h) {
          ++stats.hits;
          stats.hit_mask[static_cast<std::size_t>(j) * static_cast<std::size_t>(side) + static_cast<std::size_t>(i)] = 1;
          const double error = hit_error(TracePoint{px, py, pz});
          if (error > kFarHitTolerance * h) {
            ++stats.far_hits;
            stats.farthest_hit = std::max(stats.farthest_hit, error / h);
          }
          done = true;
          break;
        }
        crossed = crossed || (previous < 0 && v > 0) || (previous > 0 && v < 0);
        previous = v;
        t += std::fabs(v);
        if (t > t_exit) {
          done = true;
          break;
        }
      }
      if (!done) ++stats.stalled;
      if (crossed) ++stats.crossed;
      ++stats.rays;
      total_steps += steps;
      stats.max_steps = std::max(stats.max_steps, steps);
    }
  }
  stats.mean_steps = stats.rays == 0 ? 0 : total_steps / static_cast<double>(stats.rays);
  return stats;
}

/// ns per fp32 evaluation of `evaluate(x, y, z)` at `points`: the best of 5 batches,
/// each repeating the points until it lasts at least 20 ms. Only ratios between
/// functions timed in one run mean anything on a shared machine.
template <typename Evaluate>
double time_evaluation(const Evaluate& evaluate, const std::vector<std::array<float, 3>>& points) {
  using Clock = std::chrono::steady_clock;
  double best = 1e300;
  volatile float sink = 0;
  for (int batch = 0; batch < 5; ++batch) {
    std::size_t evaluations = 0;
    float sum = 0;
    const auto start = Clock::now();
    double seconds = 0;
    do {
      for (const auto& p : points) sum += evaluate(p[0], p[1], p[2]);
      evaluations += points.size();
      seconds = std::chrono::duration<double>(Clock::now() - start).count();
    } while (seconds < 0.02);
    sink = sink + sum;
    best = std::min(best, seconds * 1e9 / static_cast<double>(evaluations));
  }
  return best;
}

}  // namespace implicitizer::bench
