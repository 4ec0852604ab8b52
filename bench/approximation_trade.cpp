/// \file
/// implicitizer-approximation-trade: what a tolerance buys and costs (issue 19; the
/// trade table of docs/sdf.md, "Approximate implicitization: the trade").
///
/// For each surface (default: tp_22, tp_33, tri_quartic, biquadratic_patch, enneper of
/// shared/bench) on D = [0, 1]² and each tolerance EPS (default: exact, 1e-4, 1e-3,
/// 1e-2), the parametric leaf as a request makes it (shape auto: a sheet trimmed to the
/// patch; no box: fitted), in mode fast (--mode safe: safe), at fp32 exactly as the GLSL computes:
///   - degree × pieces and total terms of the equations, lines of the scene's GLSL;
///   - ns per evaluation of the C++ float twin at uniform points of the frame box (one
///     run: compare within a surface, never across runs);
///   - the sphere tracer of sphere_tracer.hpp (R×R rays through the exact leaf's frame
///     box, the same rays for every row): mean steps per ray;
///   - the bound the library reports (relative to the diagonal of the patch's box) and
///     how it was established;
///   - the two-sided error, measured independently of the library, relative to the
///     same diagonal:
///       patch → surface: the largest distance from a point X(s, t), (s, t) uniform in D,
///       to a zero of its piece's equation found by Newton steps along the gradient
///       (in long double; the found zero is a point of the surface, so each distance
///       is at least the true one);
///       surface → patch: the largest distance from a traced hit (a point the user
///       sees, |v| < 1e-4h) to the patch over D widened by a quarter on each side
///       (patch_sample.hpp's projection, again at least the true distance), so that
///       the surface's continuation past the trimmed edge, which the exact equation
///       shows too, does not count as error;
///   - the IoU of the hit mask against the exact equation's (the same rays).
///
/// Not a test: nothing here is registered with ctest. Exit status 1 when a measured
/// error exceeds the reported bound, 2 on a bad command line.

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "command_line.hpp"
#include "implicitizer/approximation/patch_approximation.hpp"
#include "implicitizer/core/errors.hpp"
#include "implicitizer/implicitization/parametrization.hpp"
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
    "usage: implicitizer-approximation-trade [--surface NAME[,NAME...]] [--tolerance EPS[,EPS...]]\n"
    "                                        [--points N] [--rays R] [--samples S] [--mode fast|safe]\n"
    "                                        [--markdown]\n"
    "\n"
    "The trade between exact and approximate implicitization of patches on [0,1]^2:\n"
    "degree x pieces, GLSL lines, ns per fp32 evaluation, sphere-tracing steps, the\n"
    "reported bound, the measured two-sided error and the hit-mask IoU against the\n"
    "exact equation. EPS 0 is the exact equation. Defaults: --surface\n"
    "tp_22,tp_33,tri_quartic,biquadratic_patch,enneper --tolerance 0,1e-4,1e-3,1e-2\n"
    "--points 4000 --rays 96 --samples 512 --mode fast\n";

struct Config {
  std::vector<std::string> surfaces = {"tp_22", "tp_33", "tri_quartic", "biquadratic_patch", "enneper"};
  std::vector<double> tolerances = {0, 1e-4, 1e-3, 1e-2};
  std::size_t points = 4000;
  int rays = 96;
  std::size_t samples = 512;
  bool markdown = false;
  SdfMode mode = SdfMode::fast;
};

std::vector<double> parse_tolerances(const std::string& flag, const std::string& text) {
  std::vector<double> out;
  for (const std::string& part : split_commas(text)) {
    char* end = nullptr;
    const double value = std::strtod(part.c_str(), &end);
    if (end == part.c_str() || *end != '\0' || !std::isfinite(value) || value < 0 || value > 0.5) {
      throw InputError("invalid_argument", "'" + part + "' is not a tolerance in [0, 0.5]").in_field(flag);
    }
    out.push_back(value);
  }
  return out;
}

Config parse_config(int argc, char** argv) {
  Config config;
  FlagReader flags(argc, argv);
  while (flags.next()) {
    const std::string& flag = flags.flag();
    if (flag == "--help" || flag == "-h") {
      std::cout << kUsage;
      std::exit(0);
    } else if (flag == "--surface") {
      config.surfaces = split_commas(flags.value());
    } else if (flag == "--tolerance") {
      config.tolerances = parse_tolerances(flag, flags.value());
    } else if (flag == "--points") {
      config.points = static_cast<std::size_t>(parse_count(flag, flags.value(), 10, 10000000));
    } else if (flag == "--rays") {
      config.rays = static_cast<int>(parse_count(flag, flags.value(), 1, 4096));
    } else if (flag == "--samples") {
      config.samples = static_cast<std::size_t>(parse_count(flag, flags.value(), 16, 4096));
    } else if (flag == "--mode") {
      const std::string mode = flags.value();
      if (mode != "fast" && mode != "safe") throw InputError("invalid_argument", "mode fast or safe").in_field(flag);
      config.mode = mode == "safe" ? SdfMode::safe : SdfMode::fast;
    } else if (flag == "--markdown") {
      config.markdown = true;
    } else {
      throw InputError("invalid_argument", "unknown argument '" + flag + "'").in_field(flag);
    }
  }
  return config;
}

using Point = PatchSample::Point;

/// A polynomial in x, y, z in long double, with its gradient: enough for the low
/// degrees of the pieces (the exact row needs no Newton steps).
class DoublePolynomial {
 public:
  explicit DoublePolynomial(const Polynomial& p) {
    for (std::size_t i = 0; i < p.num_terms(); ++i) {
      const std::vector<std::int32_t> e = p.exponents(i);
      terms_.push_back({static_cast<long double>(to_mpq(p.coefficient(i)).get_d()), e[0], e[1], e[2]});
    }
  }
  /// The value at x and, in `gradient`, its partial derivatives.
  long double evaluate(const std::array<long double, 3>& x, std::array<long double, 3>& gradient) const {
    long double value = 0;
    gradient = {0, 0, 0};
    for (const Term& t : terms_) {
      const std::array<long double, 3> power = {power_of(x[0], t.e[0]), power_of(x[1], t.e[1]), power_of(x[2], t.e[2])};
      value += t.c * power[0] * power[1] * power[2];
      for (std::size_t k = 0; k < 3; ++k) {
        if (t.e[k] == 0) continue;
        long double d = t.c * t.e[k] * power_of(x[k], t.e[k] - 1);
        for (std::size_t j = 0; j < 3; ++j) d *= j == k ? 1 : power[j];
        gradient[k] += d;
      }
    }
    return value;
  }

 private:
  struct Term {
    long double c;
    std::array<int, 3> e;
  };
  static long double power_of(long double x, int n) {
    long double r = 1;
    for (int i = 0; i < n; ++i) r *= x;
    return r;
  }
  std::vector<Term> terms_;
};

/// The distance from p to a zero of q found by Newton steps along the gradient
/// (nullopt when they do not converge within 60 steps).
std::optional<double> distance_to_zero(const DoublePolynomial& q, const Point& p, double scale) {
  std::array<long double, 3> x = {p[0], p[1], p[2]}, g;
  for (int step = 0; step < 60; ++step) {
    const long double v = q.evaluate(x, g);
    const long double g2 = g[0] * g[0] + g[1] * g[1] + g[2] * g[2];
    if (g2 == 0) return std::nullopt;
    const long double move = std::fabs(v) / std::sqrt(g2);
    for (std::size_t k = 0; k < 3; ++k) x[k] -= v * g[k] / g2;
    if (move < 1e-12L * scale) {
      const long double d0 = x[0] - p[0], d1 = x[1] - p[1], d2 = x[2] - p[2];
      return static_cast<double>(std::sqrt(d0 * d0 + d1 * d1 + d2 * d2));
    }
  }
  return std::nullopt;
}

/// One surface at one tolerance.
struct Row {
  std::string degree_pieces, terms, bound = "0 (exact)";
  std::size_t glsl_lines = 0;
  double ns = 0, steps = 0, iou = 1;
  double patch_to_surface = 0, surface_to_patch = 0;  // measured, / diagonal
  std::size_t unconverged = 0;                        // patch points whose Newton steps found no zero
  double reported = 0;                                // the larger of the reported bounds (0: exact)
};

SceneNode patch_node(const Surface& surface, double tolerance) {
  SceneNode node;
  node.kind = NodeKind::parametric;
  node.leaf.coordinates = {surface.x, surface.y, surface.z};
  node.leaf.domain = {{Rational(0), Rational(1)}, {Rational(0), Rational(1)}};
  if (tolerance > 0) node.leaf.tolerance = tolerance;
  return node;
}

/// The largest distance from X(s, t), (s, t) uniform in D, to its piece's surface.
void measure_patch_to_surface(const PatchApproximation& approximation, const PatchSample& sample, const Config& config,
                              double diagonal, Row& row) {
  std::vector<DoublePolynomial> pieces;
  for (const ApproximationPiece& piece : approximation.pieces) pieces.emplace_back(piece.equation);
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> unit(0, 1);
  for (std::size_t k = 0; k < config.points; ++k) {
    const double s = unit(random), t = unit(random);
    Point x;
    if (!sample.evaluate(s, t, x)) continue;
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      const auto& d = approximation.pieces[i].domain.intervals;
      if (s < to_mpq(d[0].first).get_d() || s > to_mpq(d[0].second).get_d() || t < to_mpq(d[1].first).get_d() ||
          t > to_mpq(d[1].second).get_d()) {
        continue;
      }
      const std::optional<double> distance = distance_to_zero(pieces[i], x, diagonal);
      if (distance) {
        row.patch_to_surface = std::max(row.patch_to_surface, *distance / diagonal);
      } else {
        ++row.unconverged;
      }
      break;
    }
  }
}

Row measure(const Surface& surface, double tolerance, const PatchSample& wide, const PatchSample& sample,
            const Config& config, const Point& lo, const Point& hi, const std::vector<std::uint8_t>& exact_mask) {
  Row row;
  const CompiledScene scene =
      compile_scene(patch_node(surface, tolerance), SceneParams{config.mode, SceneBox::default_box(), "trade"});
  const PolynomialLeaf& leaf = scene.leaves().front();
  const std::string glsl = scene.to_glsl();
  row.glsl_lines = static_cast<std::size_t>(std::count(glsl.begin(), glsl.end(), '\n'));
  const double diagonal = std::sqrt((sample.hi()[0] - sample.lo()[0]) * (sample.hi()[0] - sample.lo()[0]) +
                                    (sample.hi()[1] - sample.lo()[1]) * (sample.hi()[1] - sample.lo()[1]) +
                                    (sample.hi()[2] - sample.lo()[2]) * (sample.hi()[2] - sample.lo()[2]));
  if (const PatchApproximation* approximation = leaf.approximation()) {
    std::size_t terms = 0;
    for (const ApproximationPiece& piece : approximation->pieces) terms += piece.equation.num_terms();
    row.degree_pieces =
        std::to_string(approximation->max_degree) + " × " + std::to_string(approximation->pieces.size());
    row.terms = std::to_string(terms);
    row.reported = std::max(approximation->patch_to_surface, approximation->surface_to_patch);
    row.bound = format("%.2g", approximation->patch_to_surface) + " " +
                to_string(approximation->patch_to_surface_method) + " / " +
                format("%.2g", approximation->surface_to_patch) + " " +
                to_string(approximation->surface_to_patch_method);
    measure_patch_to_surface(*approximation, sample, config, diagonal, row);
  } else {
    // A tolerance the exact equation answers more cheaply (or alone) keeps it.
    row.degree_pieces =
        std::to_string(leaf.equation().total_degree()) + " × 1" + (tolerance > 0 ? " (exact kept)" : "");
    row.terms = std::to_string(leaf.equation().num_terms());
  }
  const auto value = [&](float x, float y, float z) { return scene.evaluate<float>(Vec3<float>{x, y, z}); };
  const auto hit_error = [&](const TracePoint& p) {
    const double d = wide.upper_bound(p) / diagonal;
    row.surface_to_patch = std::max(row.surface_to_patch, d);
    return d;
  };
  const TraceStatistics traced = trace_rays(lo, hi, config.rays, value, hit_error);
  row.steps = traced.mean_steps;
  std::size_t both = 0, either = 0;
  for (std::size_t i = 0; i < exact_mask.size(); ++i) {
    both += exact_mask[i] && traced.hit_mask[i];
    either += exact_mask[i] || traced.hit_mask[i];
  }
  row.iou = either == 0 ? 1 : double(both) / double(either);
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> unit(0, 1);
  std::vector<std::array<float, 3>> points;
  for (std::size_t k = 0; k < config.points; ++k) {
    points.push_back({static_cast<float>(lo[0] + (hi[0] - lo[0]) * unit(random)),
                      static_cast<float>(lo[1] + (hi[1] - lo[1]) * unit(random)),
                      static_cast<float>(lo[2] + (hi[2] - lo[2]) * unit(random))});
  }
  row.ns = time_evaluation(value, points);
  return row;
}

int run(const Config& config) {
  std::vector<std::vector<std::string>> table = {{"surface", "EPS", "degree × pieces", "terms", "GLSL lines",
                                                  "ns / eval", "steps / ray", "bound (p→s / s→p)", "measured p→s",
                                                  "measured s→p", "IoU"}};
  int status = 0;
  for (const Surface& surface : read_public_and_hard(IMPLICITIZER_BENCH_DIR, config.surfaces)) {
    std::cerr << "measuring " << surface.name << "...\n";
    const Parametrization parametrization = parse_parametrization(surface.x, surface.y, surface.z);
    const PatchSample sample(parametrization, {0, 1, 0, 1}, config.samples);
    const PatchSample wide(parametrization, {-0.25, 1.25, -0.25, 1.25}, config.samples * 3 / 2);
    // The rays of every row: through the exact leaf's frame box, fitted to X(D).
    const CompiledScene exact =
        compile_scene(patch_node(surface, 0), SceneParams{config.mode, SceneBox::default_box(), "exact"});
    Point lo, hi;
    for (std::size_t i = 0; i < 3; ++i) {
      lo[i] = to_mpq(exact.leaves().front().frame_box().lo[i]).get_d();
      hi[i] = to_mpq(exact.leaves().front().frame_box().hi[i]).get_d();
    }
    const auto exact_value = [&](float x, float y, float z) { return exact.evaluate<float>(Vec3<float>{x, y, z}); };
    const TraceStatistics exact_traced =
        trace_rays(lo, hi, config.rays, exact_value, [](const TracePoint&) { return 0.0; });
    for (double tolerance : config.tolerances) {
      const std::string eps = tolerance == 0 ? "exact" : format("%.0e", tolerance);
      try {
        const Row r = measure(surface, tolerance, wide, sample, config, lo, hi, exact_traced.hit_mask);
        if (r.reported > 0 && r.patch_to_surface > r.reported) status = 1;
        table.push_back({surface.name, eps, r.degree_pieces, r.terms, std::to_string(r.glsl_lines),
                         format("%.0f", r.ns), format("%.1f", r.steps), r.bound,
                         format("%.2g", r.patch_to_surface) +
                             (r.unconverged ? " (" + std::to_string(r.unconverged) + " no zero)" : ""),
                         format("%.2g", r.surface_to_patch), format("%.3f", r.iou)});
      } catch (const ToleranceNotMet& e) {
        table.push_back({surface.name, eps, "tolerance_not_met: best " + format("%.2g", e.best())});
      }
    }
  }
  print_table(table, config.markdown);
  return status;
}

}  // namespace
}  // namespace implicitizer::bench

int main(int argc, char** argv) {
  using namespace implicitizer::bench;
  return run_bench("implicitizer-approximation-trade", kUsage, [&] { return run(parse_config(argc, argv)); });
}
