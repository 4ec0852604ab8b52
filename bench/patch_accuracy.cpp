/// \file
/// implicitizer-patch-accuracy: what a parametric leaf with a domain exports, against
/// the patch X(D) it stands for, on every parametric surface of shared/bench (public
/// and hard), in both modes. The numbers of docs/sdf.md, "Patches: measured".
///
/// For each surface, D = [0, 1]² (the files give no domain), the leaf compiled as a
/// one-leaf scene with the default shape (auto) and no box (fitted to the patch), and
/// a dense sample of X(D) (patch_sample.hpp). h is the frame box's largest half side.
/// At fp32, exactly as the GLSL computes:
///   - on patch: points X(s, t), (s, t) uniform in D: how many have |v| > 1e-3h
///     and the largest |v|/h (the issue asks none above 1e-3h);
///   - off patch: points X(s, t) of the same algebraic surface with (s, t) uniform in
///     [−1, 2]² outside D, inside the frame box and farther than 0.1h from X(D) (by
///     the sample's lower bound): how many, how many have v <= 0.01h (the issue asks
///     none), and the smallest v/h;
///   - box points: uniform in the frame box: how many have v < 0 (a sheet: none), and
///     in safe mode how many exceed the distance to X(D) (the sample's upper bound:
///     a certain violation; none allowed);
///   - the sphere tracer of sphere_tracer.hpp (R×R rays through the frame box): mean
///     steps, hits, hits off the patch (farther than 1e-3h from X(D)), and ns per
///     evaluation, beside the same numbers for the solid the library exported before
///     issue 18: the whole algebraic surface F <= 0 clipped to the same box.
///
/// Not a test: nothing here is registered with ctest. Exit status 1 when a safe
/// value exceeds the distance to the patch, 2 on a bad command line.

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "command_line.hpp"
#include "implicitizer/core/errors.hpp"
#include "implicitizer/implicitization/parametrization.hpp"
#include "implicitizer/polynomial/printer.hpp"
#include "implicitizer/scene/compiled_scene.hpp"
#include "patch_sample.hpp"
#include "sphere_tracer.hpp"
#include "surface_suite.hpp"
#include "text_table.hpp"

#ifndef IMPLICITIZER_BENCH_DIR
#define IMPLICITIZER_BENCH_DIR "../shared/bench"
#endif

namespace implicitizer::bench {
namespace {

constexpr const char* kUsage =
    "usage: implicitizer-patch-accuracy [--surface NAME[,NAME...]] [--points N] [--rays R]\n"
    "                                   [--samples S] [--markdown]\n"
    "\n"
    "Measures the distance functions of parametric patches on [0,1]^2 against the\n"
    "patch, for the public and hard surfaces of shared/bench, in modes fast and safe:\n"
    "N points on the patch, off the patch and in the box; an RxR-ray sphere tracer\n"
    "beside the box-clipped solid of the whole surface; an SxS sample of the patch as\n"
    "the reference. Defaults: --points 2000 --rays 48 --samples 512\n";

struct Config {
  std::vector<std::string> surfaces;
  std::size_t points = 2000;
  int rays = 48;
  std::size_t samples = 512;
  bool markdown = false;
};

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
    } else if (flag == "--samples") {
      config.samples = static_cast<std::size_t>(parse_count(flag, take_value(), 16, 4096));
    } else if (flag == "--markdown") {
      config.markdown = true;
    } else {
      throw InputError("invalid_argument", "unknown argument '" + flag + "'").in_field(flag);
    }
  }
  return config;
}

/// One mode on one surface.
struct ModeResult {
  std::string mode, shape;
  double h = 0;
  double on_patch_max = 0;       ///< max |v|/h on the patch
  std::size_t on_points = 0;     ///< on-patch points tested
  std::size_t on_failures = 0;   ///< of which |v| > 1e-3h
  std::size_t off_points = 0;    ///< off-patch points tested
  std::size_t off_failures = 0;  ///< of which v <= 0.01h
  double off_min = 0;            ///< min v/h over them
  std::size_t box_points = 0;    ///< box points tested
  std::size_t negative = 0;      ///< box points with v < 0
  std::size_t over = 0;          ///< safe: box points with v above the distance to X(D)
  TraceStatistics patch, solid;  ///< the tracer on the patch and on the box-clipped solid
  double ns_patch = 0, ns_solid = 0;
};

using Point = PatchSample::Point;

Vec3<float> to_float(const Point& p) {
  return {static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2])};
}

ModeResult measure_mode(const Surface& surface, SdfMode mode, const PatchSample& sample, const Config& config,
                        unsigned seed) {
  ModeResult out;
  out.mode = mode == SdfMode::safe ? "safe" : "fast";
  SceneNode node;
  node.kind = NodeKind::parametric;
  node.leaf.coordinates = {surface.x, surface.y, surface.z};
  node.leaf.domain = {{Rational(0), Rational(1)}, {Rational(0), Rational(1)}};
  const CompiledScene scene = compile_scene(node, SceneParams{mode, SceneBox::default_box(), "trimmed", "scene"});
  const PolynomialLeaf& leaf = scene.leaves().front();
  out.shape = to_string(leaf.shape());
  const SceneBox& frame = leaf.frame_box();
  Point lo, hi;
  for (std::size_t i = 0; i < 3; ++i) {
    lo[i] = to_mpq(frame.lo[i]).get_d();
    hi[i] = to_mpq(frame.hi[i]).get_d();
  }
  const double h = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]}) / 2;
  out.h = h;
  // The solid exported before issue 18: the whole surface F <= 0 in the same box.
  SceneNode whole;
  whole.kind = NodeKind::implicit;
  whole.leaf.equation = to_string(leaf.equation());
  whole.leaf.box = frame;
  whole.leaf.shape = SdfShape::solid;
  const CompiledScene solid = compile_scene(whole, SceneParams{mode, SceneBox::default_box(), "solid", "scene"});

  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> unit(0, 1), wide(-1, 2);
  for (std::size_t k = 0; k < config.points; ++k) {
    Point x;
    if (!sample.evaluate(unit(random), unit(random), x)) continue;
    const float v = scene.evaluate<float>(to_float(x));
    out.on_patch_max = std::max(out.on_patch_max, std::fabs(double(v)) / h);
    ++out.on_points;
    if (std::fabs(double(v)) > 1e-3 * h) ++out.on_failures;
  }
  out.off_min = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < 40 * config.points && out.off_points < config.points; ++k) {
    const double s = wide(random), t = wide(random);
    if (s >= 0 && s <= 1 && t >= 0 && t <= 1) continue;
    Point x;
    if (!sample.evaluate(s, t, x)) continue;
    bool inside = true;
    for (std::size_t i = 0; i < 3; ++i) inside = inside && x[i] >= lo[i] && x[i] <= hi[i];
    if (!inside || sample.lower_bound(x) <= 0.1 * h) continue;
    ++out.off_points;
    const double v = scene.evaluate<float>(to_float(x)) / h;
    out.off_min = std::min(out.off_min, v);
    if (v <= 0.01) ++out.off_failures;
  }
  std::vector<std::array<float, 3>> box_points;
  for (std::size_t k = 0; k < config.points; ++k) {
    const Point x = {lo[0] + (hi[0] - lo[0]) * unit(random), lo[1] + (hi[1] - lo[1]) * unit(random),
                     lo[2] + (hi[2] - lo[2]) * unit(random)};
    const Vec3<float> f = to_float(x);
    box_points.push_back({f.x, f.y, f.z});
    const float v = scene.evaluate<float>(f);
    ++out.box_points;
    if (v < 0) ++out.negative;
    if (mode == SdfMode::safe && double(v) > sample.upper_bound({double(f.x), double(f.y), double(f.z)})) ++out.over;
  }
  const auto on_patch = [&](const TracePoint& p) { return sample.upper_bound(p); };
  const auto patch_value = [&](float x, float y, float z) { return scene.evaluate<float>(Vec3<float>{x, y, z}); };
  const auto solid_value = [&](float x, float y, float z) { return solid.evaluate<float>(Vec3<float>{x, y, z}); };
  out.patch = trace_rays(lo, hi, config.rays, patch_value, on_patch);
  out.solid = trace_rays(lo, hi, config.rays, solid_value, on_patch);
  out.ns_patch = time_evaluation(patch_value, box_points);
  out.ns_solid = time_evaluation(solid_value, box_points);
  return out;
}

int run(const Config& config) {
  const std::vector<Surface> surfaces = read_public_and_hard(IMPLICITIZER_BENCH_DIR, config.surfaces);
  std::vector<std::vector<std::string>> table = {
      {"surface", "mode", "shape", "on patch |v| > 1e-3h", "on patch max |v|/h", "off patch v <= 0.01h", "off min v/h",
       "v < 0", "safe over", "steps patch / solid", "off-patch hits patch / solid", "ns patch / solid"}};
  int status = 0;
  unsigned seed = 1;
  for (const Surface& surface : surfaces) {
    std::cerr << "measuring " << surface.name << "...\n";
    const Parametrization parametrization = parse_parametrization(surface.x, surface.y, surface.z);
    const PatchSample sample(parametrization, {0, 1, 0, 1}, config.samples);
    for (SdfMode mode : {SdfMode::fast, SdfMode::safe}) {
      ModeResult r;
      try {
        r = measure_mode(surface, mode, sample, config, seed++);
      } catch (const std::exception& e) {
        table.push_back({surface.name, mode == SdfMode::safe ? "safe" : "fast", std::string("error: ") + e.what()});
        continue;
      }
      if (r.over > 0) status = 1;
      table.push_back({surface.name, r.mode, r.shape, std::to_string(r.on_failures) + "/" + std::to_string(r.on_points),
                       format("%.2g", r.on_patch_max),
                       std::to_string(r.off_failures) + "/" + std::to_string(r.off_points),
                       r.off_points == 0 ? "-" : format("%.3g", r.off_min),
                       std::to_string(r.negative) + "/" + std::to_string(r.box_points),
                       r.mode == "safe" ? std::to_string(r.over) : "-",
                       format("%.1f", r.patch.mean_steps) + " / " + format("%.1f", r.solid.mean_steps),
                       std::to_string(r.patch.far_hits) + "/" + std::to_string(r.patch.hits) + " / " +
                           std::to_string(r.solid.far_hits) + "/" + std::to_string(r.solid.hits),
                       format("%.0f", r.ns_patch) + " / " + format("%.0f", r.ns_solid)});
    }
  }
  print_table(table, config.markdown);
  return status;
}

}  // namespace
}  // namespace implicitizer::bench

int main(int argc, char** argv) {
  using namespace implicitizer::bench;
  return run_bench("implicitizer-patch-accuracy", kUsage, [&] { return run(parse_config(argc, argv)); });
}
