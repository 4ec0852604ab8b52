/// \file
/// implicitizer-render-accuracy: what each marching method of the preview renderer
/// (lib/include/implicitizer/render/march_ray.hpp) trades in accuracy for speed, the
/// numbers of docs/render.md, "Speed against accuracy". The comparison of the second
/// thesis (001, chapter 5: SDF evaluations per ray, time, squared depth error against a
/// reference), on the public surfaces of shared/bench and on that thesis's scenes
/// (bench/scenes/: a rounded box, a tunnel of four planes, five spheres at
/// increasing distance).
///
/// For each target: the renderer's default camera (default_camera: eye at the box
/// centre + (3, 3, 5)·unit, looking at the centre) and march parameters
/// (default_render_march_params), one primary ray through each pixel centre of a
/// W×H grid (deterministic: no random numbers). The reference is `exact` (root
/// isolation on the algebraic surface) for a target that is one polynomial leaf, else
/// the bisection reference (tests/render/bisection_reference.hpp: steps bounded by the
/// safe value in double, the first sign change bisected to 1e-12 relative); on the
/// algebraic targets the bisection reference is also run and compared with exact, as
/// a check of the reference itself. Then every method (sphere, enhanced, newton,
/// forward_newton; and the two Newton methods unchecked, the second thesis' algorithms,
/// MarchParams::check_newton_steps = false) in both bound modes (fast, safe; float
/// evaluation, as the GLSL), and exact, marches every ray on one thread; per run: mean and largest evaluations per
/// ray, the time of all rays (ms; only ratios mean anything on a shared machine),
/// rays out of steps, hit/miss disagreements with the reference, and on rays both
/// hit the squared depth error Δt² = (t − t_ref)² (mean and max), the largest |Δt|
/// relative to the scene size S (the largest side of the target's box) and the rays
/// with |Δt| > 1 % of S (a different surface or the far side: Newton's failure).
/// Rays whose reference hit is a jump of the scene's value rather than a zero
/// (TargetResult::jumps: entering an open surface's solid through the face of its
/// leaf's far-field cube, or crossing the surface outside the leaf's box) are counted
/// apart: they count for hit/miss, and their mean t − t_ref is reported instead of a
/// depth error.
///
/// Not a test: nothing here is registered with ctest. Exit status 1 when the
/// reference could not decide a ray (bisection out of steps or NaN), 2 on a bad
/// command line.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "command_line.hpp"
#include "implicitizer/codec/scene_json.hpp"
#include "implicitizer/core/errors.hpp"
#include "implicitizer/core/rational.hpp"
#include "implicitizer/render/camera.hpp"
#include "implicitizer/render/march_ray.hpp"
#include "implicitizer/render/render_image.hpp"
#include "implicitizer/render/render_target.hpp"
#include "render/bisection_reference.hpp"
#include "sdf/reference_distance.hpp"
#include "surface_suite.hpp"

#ifndef IMPLICITIZER_BENCH_DIR
#define IMPLICITIZER_BENCH_DIR "../shared/bench"
#endif
#ifndef IMPLICITIZER_SCENES_DIR
#define IMPLICITIZER_SCENES_DIR "bench/scenes"
#endif

namespace implicitizer::bench {
namespace {

using Clock = std::chrono::steady_clock;

/// The second thesis's scenes, in bench/scenes/NAME.json, in the order reported.
constexpr const char* kThesisScenes[] = {"rounded_box", "tunnel", "five_spheres"};

constexpr const char* kUsage =
    "usage: implicitizer-render-accuracy [--surface NAME[,NAME...]] [--size WxH]\n"
    "                                    [--surfaces FILE] [--scenes DIR] [--omega W]\n"
    "\n"
    "Marches one primary ray per pixel of a WxH grid (the renderer's default camera)\n"
    "through every public surface of shared/bench and the second thesis's scenes\n"
    "(rounded_box, tunnel, five_spheres) with each method (sphere, enhanced, newton,\n"
    "forward_newton, and both Newton methods unchecked, in modes fast and safe, and\n"
    "exact), and compares the hits with the\n"
    "reference (exact, or bisection where exact does not apply). Prints Markdown.\n"
    "--omega W sets enhanced sphere tracing's relaxation (default the renderer's, 1.2).\n"
    "Defaults: --size 128x128 --surfaces " IMPLICITIZER_BENCH_DIR
    "/surfaces_public.json\n"
    "--scenes " IMPLICITIZER_SCENES_DIR "\n";

/// The command line.
struct Config {
  std::vector<std::string> targets;  ///< when non-empty, only these (surface or scene names)
  std::size_t width = 128;
  std::size_t height = 128;
  std::string surfaces_file = std::string(IMPLICITIZER_BENCH_DIR) + "/surfaces_public.json";
  std::string scenes_dir = IMPLICITIZER_SCENES_DIR;
  std::optional<double> omega;  ///< enhanced's ω; absent: MarchParams' default
};

/// A whole number in [1, 4096] from `text`; InputError `invalid_argument` naming `flag`.
std::size_t parse_side(const std::string& flag, const std::string& text) {
  try {
    std::size_t used = 0;
    const long value = std::stol(text, &used);
    if (used == text.size() && value >= 1 && value <= 4096) return static_cast<std::size_t>(value);
  } catch (const std::exception&) {
  }
  throw InputError("invalid_argument", flag + " needs WxH with W and H in [1, 4096], not '" + text + "'")
      .in_field(flag);
}

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
      config.targets = split_commas(take_value());
    } else if (flag == "--size") {
      const std::string size = take_value();
      const auto x = size.find('x');
      if (x == std::string::npos) {
        throw InputError("invalid_argument", "--size needs WxH, e.g. 128x128, not '" + size + "'").in_field(flag);
      }
      config.width = parse_side(flag, size.substr(0, x));
      config.height = parse_side(flag, size.substr(x + 1));
    } else if (flag == "--surfaces") {
      config.surfaces_file = take_value();
    } else if (flag == "--scenes") {
      config.scenes_dir = take_value();
    } else if (flag == "--omega") {
      const std::string text = take_value();
      char* end = nullptr;
      const double omega = std::strtod(text.c_str(), &end);
      if (end != text.c_str() + text.size() || !(omega >= 1 && omega < 2)) {
        throw InputError("invalid_argument", "--omega needs a number in [1, 2), not '" + text + "'").in_field(flag);
      }
      config.omega = omega;
    } else {
      throw InputError("invalid_argument", "unknown argument '" + flag + "'").in_field(flag);
    }
  }
  return config;
}

// ---------------------------------------------------------------- targets

/// One thing to march through.
struct Target {
  std::string name;
  std::string kind;  ///< "surface" (a public surface, parametric) or "scene" (bench/scenes)
  SceneNode root;
  SceneBox box = SceneBox::default_box();
};

std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + file.string());
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// The public surfaces (parametric leaves, framed by public_surface_box as in the
/// SDF accuracy table) and the thesis scenes, restricted to config.targets.
std::vector<Target> load_targets(const Config& config) {
  std::vector<Target> all;
  for (const Surface& s : read_surface_suite(config.surfaces_file, "public")) {
    Target t;
    t.name = s.name;
    t.kind = "surface";
    t.root.kind = NodeKind::parametric;
    t.root.leaf.coordinates = {s.x, s.y, s.z};
    t.box = testing::public_surface_box(s.name);
    all.push_back(std::move(t));
  }
  for (const char* name : kThesisScenes) {
    const std::filesystem::path file = std::filesystem::path(config.scenes_dir) / (std::string(name) + ".json");
    Target t;
    t.name = name;
    t.kind = "scene";
    t.root = parse_scene_json(read_text(file), "scene");
    all.push_back(std::move(t));
  }
  if (config.targets.empty()) return all;
  std::vector<Target> chosen;
  for (const std::string& name : config.targets) {
    const auto it = std::find_if(all.begin(), all.end(), [&](const Target& t) { return t.name == name; });
    if (it == all.end()) {
      throw InputError("invalid_argument", "no surface or scene '" + name + "'").in_field("--surface");
    }
    chosen.push_back(*it);
  }
  return chosen;
}

// ---------------------------------------------------------------- measurements

/// The reference's answer on one ray.
struct ReferenceRay {
  bool hit = false;
  double t = 0;
};

/// One method in one mode over all rays, compared with the reference.
struct RunResult {
  std::string method, mode;
  bool is_reference = false;
  double mean_evaluations = 0;
  std::uint64_t max_evaluations = 0;
  double ms = 0;
  std::size_t out_of_steps = 0;
  std::size_t hits = 0;
  std::size_t false_hits = 0;    ///< hit where the reference misses
  std::size_t false_misses = 0;  ///< miss where the reference hits on the surface (not a jump)
  std::size_t both = 0;          ///< rays both hit
  double mean_square = 0;        ///< mean Δt² over `both`
  double max_square = 0;         ///< max Δt²
  double max_relative = 0;       ///< max |Δt| / S
  std::size_t off = 0;           ///< rays with |Δt| > 1 % of S
  std::size_t jump_misses = 0;   ///< jump rays (see TargetResult::jumps) the method misses; not in false_misses
  std::size_t jump_both = 0;     ///< jump rays both hit; not in the Δt statistics
  double jump_mean_dt = 0;       ///< mean t − t_ref over them: how far past the jump the method stopped
};

/// One target: setup, reference, runs.
struct TargetResult {
  std::string name, kind, box, reference;
  double size = 0;  ///< S: the largest side of the box
  double reference_ms = 0;
  std::size_t rays = 0, reference_hits = 0, undecided = 0;
  /// Reference hits where the scene's value does not pass through 0 but jumps from
  /// positive to negative ("jump rays"). A polynomial leaf's value is a bound (or
  /// estimate) of the distance to the part of F = 0 inside its box, with the sign of
  /// F up to its far-field cube (|u_i| ≤ 2 of its frame, twice the box) and the
  /// distance to the box beyond. So it jumps (a) where the ray enters the solid
  /// {F < 0} through a face of the far-field cube (open surfaces whose negative side
  /// reaches the cube, e.g. a plane with the eye on its negative side), and (b) where
  /// the ray crosses F = 0 between the box and the far-field cube: |value| there is
  /// about the distance to the box, not to that part of the surface. Exact stops at
  /// the jump (the first root of F, or the segment's start inside the solid); the
  /// value-based methods step across it and stop at their first point beyond. These
  /// rays count for hit/miss but not for the depth errors.
  std::vector<bool> jumps;
  std::size_t jump_rays = 0;
  std::uint64_t reference_max_steps = 0;
  std::vector<RunResult> runs;
  std::optional<RunResult> bisection_check;  ///< the bisection reference against exact (algebraic targets)
};

/// Compares `hits` (one per ray) with the reference.
void compare(const std::vector<ReferenceRay>& reference, const std::vector<ReferenceRay>& hits,
             const std::vector<bool>& jumps, double size, RunResult& run) {
  double sum = 0, jump_sum = 0;
  for (std::size_t i = 0; i < hits.size(); ++i) {
    if (hits[i].hit) ++run.hits;
    if (jumps[i]) {
      if (!hits[i].hit) {
        ++run.jump_misses;
        continue;
      }
      ++run.jump_both;
      jump_sum += hits[i].t - reference[i].t;
      continue;
    }
    if (hits[i].hit && !reference[i].hit) ++run.false_hits;
    if (!hits[i].hit && reference[i].hit) ++run.false_misses;
    if (!hits[i].hit || !reference[i].hit) continue;
    const double dt = hits[i].t - reference[i].t;
    ++run.both;
    sum += dt * dt;
    run.max_square = std::max(run.max_square, dt * dt);
    run.max_relative = std::max(run.max_relative, std::fabs(dt) / size);
    if (std::fabs(dt) > 0.01 * size) ++run.off;
  }
  run.mean_square = run.both ? sum / static_cast<double>(run.both) : 0;
  run.jump_mean_dt = run.jump_both ? jump_sum / static_cast<double>(run.jump_both) : 0;
}

/// Marches every ray with `method` on `target` (one thread), timed.
RunResult run_method(const RenderTarget& target, const std::vector<Ray>& rays, MarchMethod method,
                     const MarchParams& params, std::vector<ReferenceRay>& out) {
  RunResult run;
  run.method = to_string(method);
  run.mode = method == MarchMethod::exact ? "—" : (target.mode() == SdfMode::safe ? "safe" : "fast");
  out.assign(rays.size(), {});
  std::uint64_t evaluations = 0;
  const auto start = Clock::now();
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const MarchResult r = march_ray(target, rays[i], method, params);
    out[i] = {r.hit, r.t};
    evaluations += r.evaluations;
    run.max_evaluations = std::max<std::uint64_t>(run.max_evaluations, r.evaluations);
    if (r.out_of_steps) ++run.out_of_steps;
  }
  run.ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  run.mean_evaluations = static_cast<double>(evaluations) / static_cast<double>(rays.size());
  return run;
}

double to_double(const Rational& q) { return to_mpq(q).get_d(); }

std::string format(const char* pattern, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, pattern, value);
  return buffer;
}

std::string describe_box(const SceneBox& box) {
  double lo[3], hi[3];
  for (std::size_t i = 0; i < 3; ++i) lo[i] = to_double(box.lo[i]), hi[i] = to_double(box.hi[i]);
  char buffer[160];
  if (lo[0] == lo[1] && lo[1] == lo[2] && hi[0] == hi[1] && hi[1] == hi[2]) {
    std::snprintf(buffer, sizeof buffer, "[%g, %g]³", lo[0], hi[0]);
  } else {
    std::snprintf(buffer, sizeof buffer, "[%g, %g]×[%g, %g]×[%g, %g]", lo[0], hi[0], lo[1], hi[1], lo[2], hi[2]);
  }
  return buffer;
}

/// Compiles `target` in both modes and measures every method against the reference.
TargetResult measure_target(const Target& target, const Config& config) {
  TargetResult out;
  out.name = target.name;
  out.kind = target.kind;
  out.box = describe_box(target.box);
  const RenderTarget fast =
      RenderTarget::compile(target.root, SceneParams{SdfMode::fast, target.box, "scene", "scene"});
  const RenderTarget safe =
      RenderTarget::compile(target.root, SceneParams{SdfMode::safe, target.box, "scene", "scene"});
  for (std::size_t i = 0; i < 3; ++i) {
    out.size = std::max(out.size, to_double(target.box.hi[i]) - to_double(target.box.lo[i]));
  }
  const CameraSpec camera_spec = default_camera(safe);
  MarchParams params = default_render_march_params(safe, camera_spec);
  if (config.omega) params.omega = *config.omega;
  const Camera camera(camera_spec, config.width, config.height);
  std::vector<Ray> rays;
  for (std::size_t j = 0; j < config.height; ++j) {
    for (std::size_t i = 0; i < config.width; ++i) {
      rays.push_back(camera.ray_through(static_cast<double>(i) + 0.5, static_cast<double>(j) + 0.5));
    }
  }
  out.rays = rays.size();

  // The bisection reference on the safe scene in double.
  testing::BisectionReferenceOptions bisection;
  bisection.t_min = params.t_min;
  bisection.t_max = params.t_max;
  bisection.scale = safe.length_unit();
  bisection.min_step = 1e-6 * safe.length_unit();
  bisection.max_steps = 1'000'000;
  std::vector<ReferenceRay> bisected(rays.size());
  std::uint64_t bisection_evaluations = 0, bisection_max = 0;
  const auto bisection_start = Clock::now();
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const testing::BisectionReferenceHit h = testing::march_bisection_reference(safe.scene(), rays[i], bisection);
    bisected[i] = {h.hit, h.t};
    bisection_evaluations += h.evaluations;
    bisection_max = std::max(bisection_max, h.evaluations);
    out.reference_max_steps = std::max(out.reference_max_steps, h.steps);
    if (h.exhausted || h.undefined) ++out.undecided;
  }
  const double bisection_ms = std::chrono::duration<double, std::milli>(Clock::now() - bisection_start).count();

  std::vector<ReferenceRay> reference;
  RunResult exact;
  if (safe.algebraic()) {
    exact = run_method(safe, rays, MarchMethod::exact, params, reference);
    exact.is_reference = true;
    out.reference = "exact";
    out.reference_ms = exact.ms;
  } else {
    reference = bisected;
    out.reference = "bisection";
    out.reference_ms = bisection_ms;
  }
  // Jump rays (TargetResult::jumps): the value is a bound of the distance to the part
  // of F = 0 inside the leaf's frame cube |u_i| ≤ 1 (u = (p − c)·s), continuous
  // there; a reference hit outside that cube is a jump (a far-field face, or F = 0
  // crossed where the value is about the distance to the cube).
  out.jumps.assign(rays.size(), false);
  for (std::size_t i = 0; i < rays.size(); ++i) {
    if (!reference[i].hit) continue;
    ++out.reference_hits;
    if (!safe.algebraic()) continue;
    const AlgebraicSurface& a = *safe.algebraic();
    double u = 0;
    for (std::size_t k = 0; k < 3; ++k) {
      const double p = rays[i].origin[k] + reference[i].t * rays[i].direction[k];
      u = std::max(u, std::fabs((p - a.centre[k]) * a.scale));
    }
    if (u > 1 + 1e-9) {
      out.jumps[i] = true;
      ++out.jump_rays;
    }
  }
  if (safe.algebraic()) {
    compare(reference, reference, out.jumps, out.size, exact);
    out.runs.push_back(exact);
    RunResult check;
    check.method = "bisection";
    check.mode = "safe, double";
    check.ms = bisection_ms;
    check.mean_evaluations = static_cast<double>(bisection_evaluations) / static_cast<double>(rays.size());
    check.max_evaluations = bisection_max;
    compare(reference, bisected, out.jumps, out.size, check);
    out.bisection_check = check;
  }

  std::vector<ReferenceRay> hits;
  for (MarchMethod method :
       {MarchMethod::sphere, MarchMethod::enhanced, MarchMethod::newton, MarchMethod::forward_newton}) {
    for (const RenderTarget* t : {&fast, &safe}) {
      RunResult run = run_method(*t, rays, method, params, hits);
      compare(reference, hits, out.jumps, out.size, run);
      out.runs.push_back(run);
    }
  }
  // The second thesis' Newton algorithms, without the step check: what the check buys.
  MarchParams unchecked = params;
  unchecked.check_newton_steps = false;
  for (MarchMethod method : {MarchMethod::newton, MarchMethod::forward_newton}) {
    for (const RenderTarget* t : {&fast, &safe}) {
      RunResult run = run_method(*t, rays, method, unchecked, hits);
      run.method += " (unchecked)";
      compare(reference, hits, out.jumps, out.size, run);
      out.runs.push_back(run);
    }
  }
  return out;
}

// ---------------------------------------------------------------- output

void print_table(const std::vector<std::vector<std::string>>& rows) {
  for (std::size_t r = 0; r < rows.size(); ++r) {
    std::string line = "|";
    for (const std::string& cell : rows[r]) line += " " + cell + " |";
    std::cout << line << '\n';
    if (r == 0) {
      std::string rule = "|";
      for (std::size_t i = 0; i < rows[r].size(); ++i) rule += "---|";
      std::cout << rule << '\n';
    }
  }
}

std::string count_and_percent(std::size_t count, std::size_t of) {
  if (of == 0) return std::to_string(count) + " (of 0)";
  return std::to_string(count) + format(" (%.2f%%)", 100.0 * static_cast<double>(count) / static_cast<double>(of));
}

std::string square(double v) { return v == 0 ? "0" : format("%.2e", v); }

std::vector<std::string> run_row(const std::string& name, const RunResult& r, std::size_t rays) {
  if (r.is_reference) {
    // exact's `evaluations` count sign evaluations of F, not scene evaluations: its
    // cost is its time.
    return {name,
            r.method,
            r.mode,
            "n/a",
            "n/a",
            format("%.0f", r.ms),
            std::to_string(r.out_of_steps),
            std::to_string(r.hits),
            "reference",
            "—",
            "—",
            "—",
            "—",
            "—"};
  }
  return {name,
          r.method,
          r.mode,
          format("%.1f", r.mean_evaluations),
          std::to_string(r.max_evaluations),
          format("%.0f", r.ms),
          std::to_string(r.out_of_steps),
          std::to_string(r.hits),
          count_and_percent(r.false_hits + r.false_misses, rays) +
              (r.false_hits + r.false_misses ? " " + std::to_string(r.false_hits) + "/" + std::to_string(r.false_misses)
                                             : ""),
          square(r.mean_square),
          square(r.max_square),
          square(r.max_relative),
          std::to_string(r.off),
          r.jump_both + r.jump_misses ? std::to_string(r.jump_misses) + " / " +
                                            (r.jump_both ? format("%.3g", r.jump_mean_dt) : std::string("—"))
                                      : "—"};
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

int run(const Config& config) {
  const std::vector<Target> targets = load_targets(config);
  std::vector<TargetResult> results;
  for (const Target& t : targets) {
    std::cerr << "measuring " << t.name << "...\n";
    results.push_back(measure_target(t, config));
  }
  int status = 0;
  std::cout << "Rays: " << config.width << "×" << config.height
            << " pixel centres per target, the renderer's default camera, one thread.\n\n";
  std::vector<std::vector<std::string>> setup = {
      {"target", "kind", "box", "S", "reference", "reference ms", "reference hits", "of which jumps", "undecided"}};
  for (const TargetResult& r : results) {
    setup.push_back({r.name, r.kind, r.box, format("%g", r.size), r.reference, format("%.0f", r.reference_ms),
                     std::to_string(r.reference_hits) + "/" + std::to_string(r.rays), std::to_string(r.jump_rays),
                     r.reference == "bisection" ? std::to_string(r.undecided) : "—"});
    if (r.reference == "bisection" && r.undecided > 0) status = 1;
  }
  print_table(setup);
  std::cout << '\n';

  const std::vector<std::string> header = {"target",
                                           "method",
                                           "mode",
                                           "evals/ray",
                                           "max evals",
                                           "ms",
                                           "out of steps",
                                           "hits",
                                           "hit/miss ≠ ref, other rays (false hit/false miss)",
                                           "mean Δt²",
                                           "max Δt²",
                                           "max \\|Δt\\|/S",
                                           "\\|Δt\\| > 1% S",
                                           "jump rays: missed / mean t − t_ref"};
  std::vector<std::vector<std::string>> table = {header};
  for (const TargetResult& r : results) {
    for (const RunResult& run : r.runs) table.push_back(run_row(r.name, run, r.rays - r.jump_rays));
  }
  print_table(table);
  std::cout << '\n';

  // The bisection reference against exact, where both apply.
  std::vector<std::vector<std::string>> check = {header};
  for (const TargetResult& r : results) {
    if (r.bisection_check) check.push_back(run_row(r.name, *r.bisection_check, r.rays - r.jump_rays));
  }
  if (check.size() > 1) {
    std::cout << "The bisection reference (safe value in double, min step 1e-6·unit) against exact, on the "
                 "algebraic targets:\n\n";
    print_table(check);
    std::cout << '\n';
  }

  // Per method and mode over all targets (the thesis' Table 5.4 takes medians).
  std::vector<std::vector<std::string>> summary = {
      {"method", "mode", "targets", "median evals/ray", "median ms", "out of steps (all targets)",
       "hit/miss ≠ ref, other rays (all targets)", "median mean Δt²", "worst max \\|Δt\\|/S", "\\|Δt\\| > 1% S (all)",
       "jump rays missed (all)"}};
  std::vector<std::pair<std::string, std::string>> keys;
  for (const TargetResult& r : results) {
    for (const RunResult& run : r.runs) {
      if (std::find(keys.begin(), keys.end(), std::pair{run.method, run.mode}) == keys.end()) {
        keys.emplace_back(run.method, run.mode);
      }
    }
  }
  for (const auto& [method, mode] : keys) {
    std::vector<double> evaluations, ms, squares;
    std::size_t n = 0, out_of_steps = 0, wrong = 0, rays = 0, off = 0, jump_misses = 0, jump_rays = 0;
    double worst = 0;
    bool reference = false;
    for (const TargetResult& r : results) {
      for (const RunResult& run : r.runs) {
        if (run.method != method || run.mode != mode) continue;
        ++n;
        reference = run.is_reference;
        evaluations.push_back(run.mean_evaluations);
        ms.push_back(run.ms);
        squares.push_back(run.mean_square);
        out_of_steps += run.out_of_steps;
        wrong += run.false_hits + run.false_misses;
        rays += r.rays - r.jump_rays;
        off += run.off;
        jump_misses += run.jump_misses;
        jump_rays += r.jump_rays;
        worst = std::max(worst, run.max_relative);
      }
    }
    summary.push_back({method, mode, std::to_string(n), reference ? "n/a" : format("%.1f", median(evaluations)),
                       format("%.0f", median(ms)), std::to_string(out_of_steps),
                       reference ? "reference" : count_and_percent(wrong, rays),
                       reference ? "—" : square(median(squares)), reference ? "—" : square(worst),
                       reference ? "—" : std::to_string(off),
                       reference ? "—" : count_and_percent(jump_misses, jump_rays)});
  }
  print_table(summary);
  return status;
}

}  // namespace
}  // namespace implicitizer::bench

int main(int argc, char** argv) {
  using namespace implicitizer::bench;
  return run_bench("implicitizer-render-accuracy", kUsage, [&] { return run(parse_config(argc, argv)); });
}
