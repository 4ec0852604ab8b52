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

#include "command_line.hpp"
#include "implicitizer/core/errors.hpp"
#include "implicitizer/implicitization/implicitize.hpp"
#include "implicitizer/sdf/fast_sdf.hpp"
#include "implicitizer/sdf/safe_sdf.hpp"
#include "sdf/reference_distance.hpp"
#include "sphere_tracer.hpp"
#include "surface_suite.hpp"
#include "text_table.hpp"

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

/// Reads the command line. Throws InputError `invalid_argument` (field: the flag).
Config parse_config(int argc, char** argv) {
  Config config;
  FlagReader flags(argc, argv);
  while (flags.next()) {
    const std::string& flag = flags.flag();
    const auto take_value = [&flags] { return flags.value(); };
    if (flag == "--help" || flag == "-h") {
      std::cout << kUsage;
      std::exit(0);
    } else if (flag == "--surface") {
      config.surfaces = split_commas(take_value());
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

/// One mode on one surface.
struct ModeResult {
  std::string mode;
  EstimateStatistics estimates;
  TraceStatistics trace;
  double ns_per_evaluation = 0;
};

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
  const testing::DistanceBox& box = reference.box();
  const double h = box.half_extent();
  const auto evaluate = [&sdf](float x, float y, float z) { return sdf.template evaluate<float>(x, y, z); };
  result.trace = trace_rays(box.lo, box.hi, rays, evaluate, [&](const TracePoint& p) {
    // The cloud distance is an upper bound: below the tolerance, no need to refine.
    return reference.cloud_distance(p) > kFarHitTolerance * h ? reference.distance(p) : 0.0;
  });
  std::vector<std::array<float, 3>> floats;
  for (const Point3& p : points) {
    floats.push_back({static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2])});
  }
  result.ns_per_evaluation = time_evaluation(evaluate, floats);
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
  using namespace implicitizer::bench;
  return run_bench("implicitizer-sdf-accuracy", kUsage, [&] { return run(parse_config(argc, argv)); });
}
