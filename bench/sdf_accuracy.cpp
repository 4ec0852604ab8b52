/// \file
/// implicitizer-sdf-accuracy: how far the distance estimates of lib/sdf are from the
/// true distance, per public surface of shared/bench and per mode, and what that does
/// to sphere tracing. The numbers of docs/sdf.md, "Accuracy table".
///
/// For each surface: its implicit equation (implicitize()), a box that frames it
/// (public_surface_box, tests/sdf/reference_distance.hpp), and the reference distance
/// D of that header (a closed form where the surface is a plane, sphere, cylinder,
/// cone or torus, else a dense cloud on the zero set refined by descents and
/// Lagrange–Newton projections onto it).
/// Then, for each mode, at N sample points (half uniform in the box, half within
/// 1e-3..1e-1 of the box's size of the surface, along its normal), with v the fp32
/// estimate exactly as the GLSL computes it:
///   - over: the fraction of points with |v| > D·(1 + 1e-6) + 1e-7·h, h the box's
///     half side: where sphere tracing may step across the surface (0 for a bound);
///   - the median, 5th percentile and largest |v|/D: how much of each step is lost
///     (a ratio below 1) or overshot (above 1);
///   - a sphere tracer (Hart 1996: t += |v|) over R×R rays from the eye
///     centre + 3h·(3, 3, 5)/|(3, 3, 5)| towards the centre, the field of view just
///     holding the box's corners; each ray that meets the box starts where it
///     enters it (as a renderer that intersects the bounding box first: outside the
///     box both modes return the distance to the box, and inside their margin they
///     draw the surface beyond the box, which D does not describe). A hit is
///     |v| < 1e-4·h, a miss is t beyond the box's far side, a stall 512 steps without
///     either. Reported: mean and largest steps per ray, hits, far hits (hit points
///     farther than 1e-3·h from the zero set: the tracer stepped across the surface,
///     or stopped where v is small but the surface is not), crossed rays (v changed
///     sign between two steps: the tracer stepped across the surface and went on)
///     and stalls;
///   - the time of one evaluation in ns (the same sample points, repeated), of which
///     only the ratio between modes means anything on a shared machine.
///
/// Not a test: nothing here is registered with ctest. Exit status 1 when a mode that
/// claims a bound (safe) is over D at any sample point, 2 on a bad command line.

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "implicitizer/core/errors.hpp"
#include "implicitizer/implicitization/implicitize.hpp"
#include "implicitizer/sdf/fast_sdf.hpp"
#include "implicitizer/sdf/safe_sdf.hpp"
#include "sdf/reference_distance.hpp"
#include "surface_suite.hpp"

#ifndef IMPLICITIZER_BENCH_DIR
#define IMPLICITIZER_BENCH_DIR "../shared/bench"
#endif

namespace implicitizer::bench {
namespace {

using testing::EstimateStatistics;
using testing::Point3;
using testing::ReferenceDistance;

constexpr const char* kUsage =
    "usage: implicitizer-sdf-accuracy [--surface NAME[,NAME...]] [--points N] [--rays R]\n"
    "                                 [--markdown] [--check-reference] [--surfaces FILE]\n"
    "\n"
    "Compares the fp32 distance estimates of every SDF mode with the true distance to\n"
    "the zero set inside the box, on the public surfaces of shared/bench: --points N\n"
    "sample points per surface (half uniform, half near the surface), and an R×R-ray\n"
    "sphere tracer (--rays R). --check-reference also builds a reference with twice\n"
    "the grid lines and parameter samples and four times the starts, and reports the\n"
    "largest relative difference at the sample points (and from the closed form, where\n"
    "there is one). Defaults: --points 2000 --rays 64\n"
    "--surfaces " IMPLICITIZER_BENCH_DIR "/surfaces_public.json\n";

/// The command line.
struct Config {
  std::vector<std::string> surfaces;  ///< when non-empty, only these
  std::size_t points = 2000;          ///< sample points per surface
  int rays = 64;                      ///< rays per side of the image
  bool markdown = false;              ///< Markdown tables instead of aligned text
  bool check_reference = false;       ///< compare the reference with a denser one
  std::string surfaces_file = std::string(IMPLICITIZER_BENCH_DIR) + "/surfaces_public.json";
};

/// A whole number in [low, high] from `text`; InputError `invalid_argument` naming
/// the flag otherwise.
long parse_count(const std::string& flag, const std::string& text, long low, long high) {
  try {
    std::size_t used = 0;
    const long value = std::stol(text, &used);
    if (used == text.size() && value >= low && value <= high) return value;
  } catch (const std::exception&) {
  }
  throw InputError("invalid_argument", flag + " needs a whole number in [" + std::to_string(low) + ", " +
                                           std::to_string(high) + "], not '" + text + "'")
      .in_field(flag);
}

/// Reads the command line. Throws InputError `invalid_argument` (field: the flag).
Config parse_config(int argc, char** argv) {
  Config config;
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    const auto take_value = [&]() -> std::string {
      if (i + 1 >= argc) throw InputError("invalid_argument", flag + " needs a value").in_field(flag);
      return argv[++i];
    };
    if (flag == "--help" || flag == "-h") {
      std::cout << kUsage;
      std::exit(0);
    } else if (flag == "--surface") {
      std::istringstream in(take_value());
      for (std::string name; std::getline(in, name, ',');) {
        if (!name.empty()) config.surfaces.push_back(name);
      }
    } else if (flag == "--points") {
      config.points = static_cast<std::size_t>(parse_count(flag, take_value(), 10, 10000000));
    } else if (flag == "--rays") {
      config.rays = static_cast<int>(parse_count(flag, take_value(), 1, 4096));
    } else if (flag == "--markdown") {
      config.markdown = true;
    } else if (flag == "--check-reference") {
      config.check_reference = true;
    } else if (flag == "--surfaces") {
      config.surfaces_file = take_value();
    } else {
      throw InputError("invalid_argument", "unknown argument '" + flag + "'").in_field(flag);
    }
  }
  return config;
}

// ---------------------------------------------------------------- measurements

/// What the sphere tracer did over all rays.
struct TraceStatistics {
  std::size_t rays = 0;      ///< rays traced: those that meet the box
  std::size_t hits = 0;      ///< |v| < 1e-4·h reached
  std::size_t far_hits = 0;  ///< hits farther than 1e-3·h from the zero set
  std::size_t crossed = 0;   ///< rays on which v changed sign between two steps
  double farthest_hit = 0;   ///< the largest D at a far hit, in units of h (0 without far hits)
  std::size_t stalled = 0;   ///< 512 steps without a hit or a miss
  double mean_steps = 0;     ///< evaluations per ray
  int max_steps = 0;         ///< the most evaluations of one ray
};

/// One mode on one surface.
struct ModeResult {
  std::string mode;
  EstimateStatistics estimates;
  TraceStatistics trace;
  double ns_per_evaluation = 0;
};

constexpr double kHitTolerance = 1e-4;     ///< × h: the tracer stops below this |v|
constexpr double kFarHitTolerance = 1e-3;  ///< × h: a hit farther than this from the zero set is wrong
constexpr int kMaxSteps = 512;

/// Sphere tracing with the fp32 estimate (positions in double, rounded to float for
/// each evaluation, as a shader receives them; the step sum in double so that the
/// tracer's own rounding does not enter the comparison).
template <typename Sdf>
TraceStatistics trace_rays(const Sdf& sdf, const ReferenceDistance& reference, int side) {
  const testing::DistanceBox& box = reference.box();
  const double h = box.half_extent();
  const Point3 c = box.centre();
  const double n43 = std::sqrt(43.0);  // |(3, 3, 5)|
  const Point3 eye = {c[0] + 3 * h * 3 / n43, c[1] + 3 * h * 3 / n43, c[2] + 3 * h * 5 / n43};
  auto normalise = [](Point3 v) {
    const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    return Point3{v[0] / n, v[1] / n, v[2] / n};
  };
  auto cross = [](const Point3& a, const Point3& b) {
    return Point3{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  };
  const Point3 forward = normalise({c[0] - eye[0], c[1] - eye[1], c[2] - eye[2]});
  const Point3 right = normalise(cross(forward, {0, 0, 1}));
  const Point3 up = cross(right, forward);
  // The field of view frames the box: the largest tangent under which a corner is seen.
  double tan_half = 0;
  for (int k = 0; k < 8; ++k) {
    const Point3 corner = {(k & 1) ? box.hi[0] : box.lo[0], (k & 2) ? box.hi[1] : box.lo[1],
                           (k & 4) ? box.hi[2] : box.lo[2]};
    const Point3 r = {corner[0] - eye[0], corner[1] - eye[1], corner[2] - eye[2]};
    auto dot = [&r](const Point3& e) { return r[0] * e[0] + r[1] * e[1] + r[2] * e[2]; };
    tan_half = std::max({tan_half, std::fabs(dot(right)) / dot(forward), std::fabs(dot(up)) / dot(forward)});
  }
  TraceStatistics stats;
  double total_steps = 0;
  for (int j = 0; j < side; ++j) {
    for (int i = 0; i < side; ++i) {
      const double a = (2 * (i + 0.5) / side - 1) * tan_half, b = (2 * (j + 0.5) / side - 1) * tan_half;
      const Point3 d = normalise({forward[0] + a * right[0] + b * up[0], forward[1] + a * right[1] + b * up[1],
                                  forward[2] + a * right[2] + b * up[2]});
      // The ray's span in the box (slabs); a ray that misses the box is not traced.
      double t = 0, t_exit = std::numeric_limits<double>::infinity();
      for (std::size_t axis = 0; axis < 3; ++axis) {
        if (d[axis] == 0) {
          if (eye[axis] < box.lo[axis] || eye[axis] > box.hi[axis]) t = t_exit = 0;
          continue;
        }
        const double t0 = (box.lo[axis] - eye[axis]) / d[axis], t1 = (box.hi[axis] - eye[axis]) / d[axis];
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
        const float v = sdf.template evaluate<float>(px, py, pz);
        ++steps;
        if (std::fabs(v) < kHitTolerance * h) {
          ++stats.hits;
          const Point3 p = {px, py, pz};
          // The cloud distance is an upper bound: below the tolerance, no need to refine.
          if (reference.cloud_distance(p) > kFarHitTolerance * h) {
            const double distance = reference.distance(p);
            if (distance > kFarHitTolerance * h) {
              ++stats.far_hits;
              stats.farthest_hit = std::max(stats.farthest_hit, distance / h);
            }
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
  stats.mean_steps = total_steps / static_cast<double>(stats.rays);
  return stats;
}

/// ns per fp32 evaluation at the sample points: the best of 5 batches, each
/// repeating the points until it lasts at least 20 ms.
template <typename Sdf>
double time_evaluation(const Sdf& sdf, const std::vector<Point3>& points) {
  std::vector<std::array<float, 3>> floats;
  for (const Point3& p : points) {
    floats.push_back({static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2])});
  }
  using Clock = std::chrono::steady_clock;
  double best = 1e300;
  volatile float sink = 0;
  for (int batch = 0; batch < 5; ++batch) {
    std::size_t evaluations = 0;
    float sum = 0;
    const auto start = Clock::now();
    double seconds = 0;
    do {
      for (const auto& p : floats) sum += sdf.template evaluate<float>(p[0], p[1], p[2]);
      evaluations += floats.size();
      seconds = std::chrono::duration<double>(Clock::now() - start).count();
    } while (seconds < 0.02);
    sink = sink + sum;
    best = std::min(best, seconds * 1e9 / static_cast<double>(evaluations));
  }
  return best;
}

/// One mode on one surface: the estimates at the sample points against their
/// reference distances, the tracer, the timing.
template <typename Sdf>
ModeResult measure_mode(const std::string& mode, const Sdf& sdf, const ReferenceDistance& reference,
                        const std::vector<Point3>& points, const std::vector<double>& distances, int rays) {
  ModeResult result;
  result.mode = mode;
  std::vector<double> values;
  for (const Point3& p : points) {
    values.push_back(
        sdf.template evaluate<float>(static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2])));
  }
  result.estimates = testing::summarise_estimates(values, distances, reference.box().half_extent());
  result.trace = trace_rays(sdf, reference, rays);
  result.ns_per_evaluation = time_evaluation(sdf, points);
  return result;
}

/// One surface: its setup and every mode.
struct SurfaceResult {
  std::string name;
  std::int32_t degree = 0;
  std::string box;        ///< e.g. "[-2, 2]^3"
  std::string reference;  ///< "closed form (sphere r=1)" or the cloud's size
  double reference_seconds = 0;
  std::string denser;  ///< with --check-reference: the largest relative difference
  std::vector<ModeResult> modes;
};

/// `value` printed with a printf pattern.
std::string format(const char* pattern, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, pattern, value);
  return buffer;
}

/// "[lo, hi]³" for a cube, else the three intervals.
std::string describe_box(const testing::DistanceBox& box) {
  char buffer[160];
  if (box.lo[0] == box.lo[1] && box.lo[1] == box.lo[2] && box.hi[0] == box.hi[1] && box.hi[1] == box.hi[2]) {
    std::snprintf(buffer, sizeof buffer, "[%g, %g]³", box.lo[0], box.hi[0]);
  } else {
    std::snprintf(buffer, sizeof buffer, "[%g, %g]×[%g, %g]×[%g, %g]", box.lo[0], box.hi[0], box.lo[1], box.hi[1],
                  box.lo[2], box.hi[2]);
  }
  return buffer;
}

/// Implicitizes `surface`, builds its reference and measures every mode; `seed`
/// fixes the sample points.
SurfaceResult measure_surface(const Surface& surface, const Config& config, unsigned seed) {
  SurfaceResult out;
  out.name = surface.name;
  const Parametrization parametrization = parse_parametrization(surface.x, surface.y, surface.z);
  const Polynomial f = implicitize(parametrization).implicit;
  out.degree = f.total_degree();
  const SceneBox box = testing::public_surface_box(surface.name);
  const auto start = std::chrono::steady_clock::now();
  const ReferenceDistance reference = ReferenceDistance::build(f, &parametrization, box);
  out.box = describe_box(reference.box());
  if (reference.closed_form()) {
    out.reference = "closed form: " + reference.closed_form()->describe();
  } else {
    out.reference = "cloud: " + std::to_string(reference.line_points()) + " line roots, " +
                    std::to_string(reference.parameter_points()) + " parameter points";
    if (!reference.singular_points().empty()) {
      out.reference += ", " + std::to_string(reference.singular_points().size()) + " singular points";
    }
    if (!reference.zero_lines().empty()) {
      out.reference += ", " + std::to_string(reference.zero_lines().size()) + " zero lines";
    }
  }
  const std::vector<Point3> points = testing::accuracy_samples(reference, config.points, seed);
  std::vector<double> distances;
  for (const Point3& p : points) distances.push_back(reference.distance(p));
  out.reference_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (config.check_reference) {
    // Both are upper bounds of D; a difference shows where one missed the nearest
    // point. Relative to max(D, 1e-3·h), as in the test against closed forms.
    testing::ReferenceOptions options;
    options.lines_per_axis = 2 * options.lines_per_axis - 1;
    options.parameter_samples *= 2;
    options.starts *= 4;
    const ReferenceDistance denser = ReferenceDistance::build(f, &parametrization, box, options);
    const double h = reference.box().half_extent();
    double worst = 0, worst_closed = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
      const double other = denser.refined_distance(points[i]);
      const double mine = reference.refined_distance(points[i]);
      worst = std::max(worst, std::fabs(mine - other) / std::max(other, 1e-3 * h));
      if (reference.closed_form()) {
        const double exact = reference.closed_form()->distance(points[i]);
        worst_closed = std::max(worst_closed, std::fabs(mine - exact) / std::max(exact, 1e-3 * h));
      }
    }
    out.denser = format("%.2g", worst);
    if (reference.closed_form()) out.denser += format(" (closed form: %.2g)", worst_closed);
  }
  out.modes.push_back(measure_mode("fast", FastSdf::build(f, box), reference, points, distances, config.rays));
  out.modes.push_back(measure_mode("safe", SafeSdf::build(f, box), reference, points, distances, config.rays));
  return out;
}

// ---------------------------------------------------------------- output

/// Rows as a Markdown table (the first row the header) or aligned columns.
void print_table(const std::vector<std::vector<std::string>>& rows, bool markdown) {
  std::vector<std::size_t> widths;
  for (const auto& row : rows) {
    widths.resize(std::max(widths.size(), row.size()));
    for (std::size_t i = 0; i < row.size(); ++i) widths[i] = std::max(widths[i], row[i].size());
  }
  for (std::size_t r = 0; r < rows.size(); ++r) {
    std::string line = markdown ? "|" : "";
    for (std::size_t i = 0; i < rows[r].size(); ++i) {
      line += markdown ? " " + rows[r][i] + " |" : rows[r][i] + std::string(widths[i] - rows[r][i].size() + 2, ' ');
    }
    std::cout << line << '\n';
    if (markdown && r == 0) {
      std::string rule = "|";
      for (std::size_t i = 0; i < rows[r].size(); ++i) rule += "---|";
      std::cout << rule << '\n';
    }
  }
}

/// Measures the surfaces of the command line and prints both tables. Returns the
/// exit status (file comment).
int run(const Config& config) {
  std::vector<Surface> surfaces = read_surface_suite(config.surfaces_file, "public");
  if (!config.surfaces.empty()) {
    std::vector<Surface> chosen;
    for (const std::string& name : config.surfaces) {
      const auto it = std::find_if(surfaces.begin(), surfaces.end(), [&](const Surface& s) { return s.name == name; });
      if (it == surfaces.end()) {
        throw InputError("invalid_argument", "no surface '" + name + "' in " + config.surfaces_file)
            .in_field("--surface");
      }
      chosen.push_back(*it);
    }
    surfaces = chosen;
  }
  std::vector<SurfaceResult> results;
  unsigned seed = 1;
  for (const Surface& s : surfaces) {
    std::cerr << "measuring " << s.name << "...\n";
    results.push_back(measure_surface(s, config, seed++));
  }
  std::vector<std::vector<std::string>> setup = {{"surface", "degree", "box", "reference", "reference s"}};
  if (config.check_reference) setup[0].push_back("vs denser");
  for (const SurfaceResult& r : results) {
    setup.push_back({r.name, std::to_string(r.degree), r.box, r.reference, format("%.2f", r.reference_seconds)});
    if (config.check_reference) setup.back().push_back(r.denser);
  }
  print_table(setup, config.markdown);
  std::cout << '\n';
  std::vector<std::vector<std::string>> table = {{"surface", "mode", "over D", "median |v|/D", "p5 |v|/D", "max |v|/D",
                                                  "steps mean", "steps max", "hits", "far hits", "crossed", "stalled",
                                                  "ns/eval"}};
  if (config.markdown) {
    for (std::string& cell : table[0]) {
      for (std::size_t at = cell.find('|'); at != std::string::npos; at = cell.find('|', at + 2)) {
        cell.replace(at, 1, "\\|");
      }
    }
  }
  int status = 0;
  for (const SurfaceResult& r : results) {
    for (const ModeResult& m : r.modes) {
      const EstimateStatistics& e = m.estimates;
      table.push_back({r.name, m.mode,
                       std::to_string(e.over) + "/" + std::to_string(e.points) +
                           format(" (%.1f%%)", 100.0 * static_cast<double>(e.over) / static_cast<double>(e.points)),
                       format("%.3g", e.median_ratio), format("%.3g", e.p5_ratio), format("%.3g", e.max_ratio),
                       format("%.1f", m.trace.mean_steps), std::to_string(m.trace.max_steps),
                       std::to_string(m.trace.hits) + "/" + std::to_string(m.trace.rays),
                       std::to_string(m.trace.far_hits) +
                           (m.trace.far_hits > 0 ? format(" (D <= %.2gh)", m.trace.farthest_hit) : ""),
                       std::to_string(m.trace.crossed), std::to_string(m.trace.stalled),
                       format("%.0f", m.ns_per_evaluation)});
      if (m.mode == "safe" && e.over > 0) status = 1;
    }
  }
  print_table(table, config.markdown);
  return status;
}

}  // namespace
}  // namespace implicitizer::bench

int main(int argc, char** argv) {
  try {
    return implicitizer::bench::run(implicitizer::bench::parse_config(argc, argv));
  } catch (const implicitizer::InputError& e) {
    std::cerr << "implicitizer-sdf-accuracy: " << e.field() << ": " << e.what() << "\n\n"
              << implicitizer::bench::kUsage;
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "implicitizer-sdf-accuracy: " << e.what() << '\n';
    return 1;
  }
}
