#include "implicitizer/approximation/patch_approximation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "certificate.hpp"
#include "dokken_matrix.hpp"
#include "implicitizer/core/errors.hpp"
#include "implicitizer/polynomial/ring.hpp"
#include "surface_distance.hpp"

// The driver (docs/sdf.md, "Approximate implicitization"): per piece S of the domain,
// degrees 1, 2, … are tried in order, each through four gates from the cheapest: the
// Dokken equation (dokken_matrix.cpp), a double estimate of patch → surface on a grid
// (skips hopeless degrees without exact work), the measured surface → patch distance
// (surface_distance.cpp), and the exact certificate of patch → surface
// (certificate.cpp). The first degree through all four is kept; when none is, S is
// bisected at the midpoint of its longer parameter side.

namespace implicitizer {

std::string to_string(BoundMethod method) { return method == BoundMethod::certified ? "certified" : "measured"; }

namespace {

using namespace approximation;

const char* const kWhere = "approximation";
constexpr std::size_t kScreenSide = 13;
constexpr std::size_t kCertificateDepth = 6;
// A measured maximum under-estimates the true one: the measured half is accepted only
// at <= 0.8·EPS·diagonal (the tests' independent samples found up to 1.15× the
// library's value before this margin; docs/sdf.md).
constexpr double kMeasuredMargin = 0.8;

InputError tolerance_error(const std::string& message) {
  return InputError("invalid_tolerance", message).in_field("tolerance");
}

void validate(const Parametrization& parametrization, const ParameterDomain& domain,
              const ApproximationParams& params) {
  const double eps = params.tolerance;
  if (!std::isfinite(eps) || eps <= 0 || eps > 0.5) {
    std::ostringstream text;
    text << "the tolerance must be a finite number in (0, 0.5] (relative to the patch box's diagonal), not " << eps;
    throw tolerance_error(text.str());
  }
  if (parametrization.coordinates.size() != 3 || parametrization.parameter_ring->num_variables() != 2) {
    throw InputError("method_not_applicable",
                     "approximate implicitization needs a surface patch: three coordinates in two parameters")
        .in_field("tolerance");
  }
  if (domain.intervals.size() != 2) {
    throw InputError("invalid_domain", "the domain needs one interval per parameter (two)").in_field("domain");
  }
  for (const auto& [lo, hi] : domain.intervals) {
    if (!(lo < hi)) {
      throw InputError("invalid_domain", "approximation needs a bounded domain with lo < hi on every parameter, not [" +
                                             to_string(lo) + ", " + to_string(hi) + "]")
          .in_field("domain");
    }
  }
  if (params.max_degree < 1) throw std::invalid_argument("approximate_patch: max_degree must be at least 1");
  if (params.max_pieces < 1) throw std::invalid_argument("approximate_patch: max_pieces must be at least 1");
}

// What every piece shares.
struct Context {
  const Parametrization& parametrization;
  const ApproximationParams& params;
  const Budget& budget;
  std::vector<Polynomial> forms;  // ω, ξ_x, ξ_y, ξ_z
  PatchEvaluator patch;
  RingPtr space;
  double target = 0;     // EPS·diagonal, absolute
  ParameterRect domain;  // D
};

// One piece's outcome: the accepted piece, or the best two-sided distance reached.
struct PieceResult {
  std::optional<ApproximationPiece> piece;
  double best = std::numeric_limits<double>::infinity();  // absolute
};

ParameterRect rect_of(const ParameterDomain& d) {
  return {round_down<double>(d.intervals[0].first), round_up<double>(d.intervals[0].second),
          round_down<double>(d.intervals[1].first), round_up<double>(d.intervals[1].second)};
}

BernsteinBox box_of(const ParameterDomain& d) {
  BernsteinBox box;
  for (const auto& [lo, hi] : d.intervals) box.emplace_back(to_mpq(lo), to_mpq(hi));
  return box;
}

// The frame of a box: dyadic centre, half = the largest half side rounded up.
Frame frame_of(const PatchBounds& box) {
  Frame frame;
  double half = 0;
  for (std::size_t i = 0; i < 3; ++i) {
    const double lo = round_down<double>(box.lo[i]), hi = round_up<double>(box.hi[i]);
    frame.center[i] = lo / 2 + hi / 2;
    half = std::max({half, hi - frame.center[i], frame.center[i] - lo});
  }
  frame.half = half > 0 ? half : 1;
  return frame;
}

// A 24×24 grid of the piece: points and unit normals X_s × X_t, in frame coordinates.
PatchSamples patch_samples(const PatchEvaluator& patch, const ParameterRect& rect, const Frame& frame) {
  constexpr int kSide = 24;
  PatchSamples samples;
  for (int i = 0; i < kSide; ++i) {
    for (int j = 0; j < kSide; ++j) {
      const double s = rect[0] + (rect[1] - rect[0]) * i / (kSide - 1),
                   t = rect[2] + (rect[3] - rect[2]) * j / (kSide - 1);
      Point x, xs, xt;
      if (!patch.point_and_derivatives(s, t, x, xs, xt)) continue;
      const Point n{xs[1] * xt[2] - xs[2] * xt[1], xs[2] * xt[0] - xs[0] * xt[2], xs[0] * xt[1] - xs[1] * xt[0]};
      const double length = distance(n, Point{});
      if (!(length > 0)) continue;
      samples.points.push_back({(x[0] - frame.center[0]) / frame.half, (x[1] - frame.center[1]) / frame.half,
                                (x[2] - frame.center[2]) / frame.half});
      samples.normals.push_back({n[0] / length, n[1] / length, n[2] / length});
    }
  }
  return samples;
}

// What a piece is measured and trimmed against: its polytope (when one exists) and
// its box, the corners rounded outwards to float as the scene states them.
struct PieceTrimRegion {
  std::optional<TrimPolytope> polytope;
  Point lo{}, hi{};
};

PieceTrimRegion trim_region(const Context& ctx, const ParameterDomain& domain, const PatchBounds& box) {
  PieceTrimRegion region{bound_piece_polytope(ctx.parametrization, domain, ctx.budget), {}, {}};
  for (std::size_t i = 0; i < 3; ++i) {
    region.lo[i] = round_down<float>(box.lo[i]);
    region.hi[i] = round_up<float>(box.hi[i]);
  }
  return region;
}

// The surface → patch distance of q's zeros that the trimming keeps: those in the
// polytope when they all lie within the margin and within the tube of reach 0.1·h
// around X(S) (a curved piece's polytope can hold far more of q's continuation past
// S's edges than the tube: measured on Enneper's surface, the drawn patch then
// differed from the exact one's by a quarter of its pixels), else (kept: none) those
// in the tube, which a box cover keeps.
SurfaceToPatch measure_kept_zeros(const Context& ctx, const FramedPolynomial& q, const ParameterRect& rect,
                                  const Frame& frame, const PieceTrimRegion& region, bool& polytope_kept) {
  polytope_kept = false;
  const double reach = 0.1 * frame.half;
  TubeSample tube(ctx.patch, q, rect, ctx.domain, reach, ctx.budget);
  SurfaceToPatch in_polytope;
  if (region.polytope) {
    in_polytope = measure_polytope_to_patch(tube, q, *region.polytope, region.lo, region.hi, ctx.budget);
    polytope_kept = in_polytope.samples > 0 && in_polytope.distance <= kMeasuredMargin * ctx.target &&
                    in_polytope.beyond_piece <= reach;
    if (polytope_kept) return in_polytope;
  }
  SurfaceToPatch in_tube = measure_surface_to_patch(tube);
  // Reported when neither is kept: the nearer miss.
  if (!(in_tube.distance <= kMeasuredMargin * ctx.target) && in_polytope.samples > 0 &&
      in_polytope.distance < in_tube.distance) {
    return in_polytope;
  }
  return in_tube;
}

// Tries one degree on the piece: the accepted piece, or the distance it reached.
PieceResult try_degree(const Context& ctx, const ParameterDomain& domain, const PatchBounds& box, const Frame& frame,
                       const DokkenChoice& choice, const PieceTrimRegion& region, int degree) {
  const ParameterRect rect = rect_of(domain);
  DokkenEquation dokken = dokken_equation(ctx.forms, box_of(domain), frame, degree, choice, ctx.space, ctx.budget);
  const FramedPolynomial q(dokken.equation, frame);
  PieceResult result;
  const double estimate = estimate_patch_to_surface(ctx.patch, q, rect, kScreenSide);
  result.best = estimate;
  if (!(estimate <= ctx.target)) return result;
  bool polytope_kept = false;
  const SurfaceToPatch measured = measure_kept_zeros(ctx, q, rect, frame, region, polytope_kept);
  result.best = std::max(estimate, measured.distance);
  if (measured.samples == 0 || !(measured.distance <= kMeasuredMargin * ctx.target)) return result;
  const Certificate certificate =
      certify_patch_to_surface(dokken.equation, ctx.forms, box_of(domain), ctx.target, kCertificateDepth, ctx.budget);
  if (!certificate.proven || !(certificate.bound <= ctx.target)) return result;
  result.best = std::max(certificate.bound, measured.distance);
  // q's sign is arbitrary; oriented along X_s × X_t at S's centre, every piece puts its
  // positive side where its neighbours do, so that a renderer colours the sides of the
  // union consistently (scene/sheet_side.hpp).
  Point x, xs, xt, gradient;
  const double sc = (rect[0] + rect[1]) / 2, tc = (rect[2] + rect[3]) / 2;
  if (ctx.patch.point_and_derivatives(sc, tc, x, xs, xt)) {
    q.value_and_gradient(x, gradient);
    const Point n{xs[1] * xt[2] - xs[2] * xt[1], xs[2] * xt[0] - xs[0] * xt[2], xs[0] * xt[1] - xs[1] * xt[0]};
    if (gradient[0] * n[0] + gradient[1] * n[1] + gradient[2] * n[2] < 0) dokken.equation = -dokken.equation;
  }
  const int degree_reached = int(dokken.equation.total_degree());
  result.piece = ApproximationPiece{domain,
                                    box,
                                    std::move(dokken.equation),
                                    degree_reached,
                                    certificate.bound,
                                    BoundMethod::certified,
                                    measured.distance,
                                    BoundMethod::measured,
                                    measured.samples,
                                    polytope_kept ? region.polytope : std::nullopt};
  return result;
}

// Degrees 1 … max_degree on one piece; the first accepted, else the best reached.
PieceResult approximate_piece(const Context& ctx, const ParameterDomain& domain) {
  const PatchBounds box = bound_patch(ctx.parametrization, domain, ctx.budget);
  const Frame frame = frame_of(box);
  // Near null: an algebraic error bound below a tenth of the tolerance in frame units.
  const DokkenChoice choice{0.1 * ctx.target / frame.half, patch_samples(ctx.patch, rect_of(domain), frame)};
  const PieceTrimRegion region = trim_region(ctx, domain, box);
  PieceResult best;
  for (int degree = 1; degree <= ctx.params.max_degree; ++degree) {
    ctx.budget.check(kWhere);
    PieceResult r = try_degree(ctx, domain, box, frame, choice, region, degree);
    if (r.piece) return r;
    best.best = std::min(best.best, r.best);
  }
  return best;
}

// S split at the midpoint of its longer parameter side.
std::pair<ParameterDomain, ParameterDomain> split(const ParameterDomain& d) {
  const std::size_t axis =
      d.intervals[1].second - d.intervals[1].first > d.intervals[0].second - d.intervals[0].first ? 1 : 0;
  ParameterDomain lower = d, upper = d;
  const Rational middle = (d.intervals[axis].first + d.intervals[axis].second) / Rational(2);
  lower.intervals[axis].second = middle;
  upper.intervals[axis].first = middle;
  return {lower, upper};
}

double diagonal_of(const PatchBounds& box) {
  double sum = 0;
  for (std::size_t i = 0; i < box.lo.size(); ++i) {
    const double side = round_up<double>(box.hi[i] - box.lo[i]);
    sum += side * side;
  }
  return std::sqrt(sum);
}

PatchApproximation summarise(std::vector<ApproximationPiece> pieces, double diagonal, double tolerance) {
  PatchApproximation out;
  out.diagonal = diagonal;
  out.tolerance = tolerance;
  for (const ApproximationPiece& p : pieces) {
    out.patch_to_surface = std::max(out.patch_to_surface, p.patch_to_surface / diagonal);
    out.surface_to_patch = std::max(out.surface_to_patch, p.surface_to_patch / diagonal);
    if (p.patch_to_surface_method == BoundMethod::measured) out.patch_to_surface_method = BoundMethod::measured;
    out.surface_to_patch_samples += p.surface_to_patch_samples;
    out.max_degree = std::max(out.max_degree, p.degree);
  }
  out.pieces = std::move(pieces);
  return out;
}

[[noreturn]] void not_met(const ApproximationParams& params, double best) {
  std::ostringstream text;
  text << "the tolerance " << params.tolerance << " (of the patch box's diagonal) cannot be met with at most "
       << params.max_pieces << " pieces of degree at most " << params.max_degree
       << ": the best two-sided bound reached is " << best << " of the diagonal";
  throw ToleranceNotMet(text.str(), best);
}

}  // namespace

PatchApproximation approximate_patch(const Parametrization& parametrization, const ParameterDomain& domain,
                                     const ApproximationParams& params, const Budget& budget) {
  validate(parametrization, domain, params);
  const double diagonal = diagonal_of(bound_patch(parametrization, domain, budget));
  if (!(diagonal > 0)) {
    throw InputError("method_not_applicable", "the patch is a single point: nothing to approximate").in_field("domain");
  }
  std::vector<Polynomial> forms = common_denominator_form(parametrization, budget);
  const PatchEvaluator patch(forms);
  const Context ctx{parametrization,
                    params,
                    budget,
                    std::move(forms),
                    patch,
                    Ring::make({"x", "y", "z"}),
                    params.tolerance * diagonal,
                    rect_of(domain)};

  // Depth first, lower half first: the pieces come out in domain order.
  std::vector<ApproximationPiece> accepted;
  std::vector<ParameterDomain> pending{domain};
  double worst_accepted = 0;
  while (!pending.empty()) {
    budget.check(kWhere);
    if (params.keep_going && !params.keep_going(accepted, pending.size())) {
      throw ApproximationStopped("the approximation was stopped after " + std::to_string(accepted.size()) + " pieces");
    }
    const ParameterDomain piece = pending.back();
    pending.pop_back();
    PieceResult r = approximate_piece(ctx, piece);
    if (r.piece) {
      worst_accepted = std::max(worst_accepted, r.best);
      accepted.push_back(std::move(*r.piece));
      continue;
    }
    if (accepted.size() + pending.size() + 2 > params.max_pieces) {
      double best = std::max(worst_accepted, r.best);
      for (const ParameterDomain& other : pending) best = std::max(best, approximate_piece(ctx, other).best);
      not_met(params, best / diagonal);
    }
    auto [lower, upper] = split(piece);
    pending.push_back(std::move(upper));
    pending.push_back(std::move(lower));
  }
  return summarise(std::move(accepted), diagonal, params.tolerance);
}

}  // namespace implicitizer
