#include "implicitizer/render/render_target.hpp"

#include <algorithm>
#include <cmath>

#include "implicitizer/core/rational.hpp"
#include "implicitizer/sdf/fast_sdf.hpp"
#include "implicitizer/sdf/safe_sdf.hpp"
#include "implicitizer/sdf/scene_frame.hpp"

namespace implicitizer {
namespace {

double to_double(const Rational& q) { return to_mpq(q).get_d(); }

// The tetrahedron's vertices (000, Prop. 1.3).
constexpr std::array<std::array<double, 3>, 4> kTetrahedron{{{1, -1, -1}, {-1, -1, 1}, {-1, 1, -1}, {1, 1, 1}}};

std::array<double, 3> normalised(const std::array<double, 3>& v) {
  const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  if (!(n > 0) || !std::isfinite(n)) return {0, 0, 0};
  return {v[0] / n, v[1] / n, v[2] / n};
}

}  // namespace

RenderTarget RenderTarget::compile(const SceneNode& root, const SceneParams& options, EvaluationPrecision precision,
                                   const Budget& budget) {
  RenderTarget target(compile_scene(root, options, budget), precision);
  target.dimension_ = options.dimension;
  // A scene of one node whose only leaf is polynomial: the root is that leaf, and the
  // object's box is its frame box (fitted to a patch when the leaf gives none).
  const CompiledScene& scene = target.scene_;
  const bool one_leaf = scene.node_count() == 1 && scene.leaves().size() == 1;
  const SceneBox& box = one_leaf ? scene.leaves().front().frame_box() : options.box;
  double half = 0;
  for (std::size_t i = 0; i < 3; ++i) {
    target.box_lo_[i] = to_double(box.lo[i]);
    target.box_hi_[i] = to_double(box.hi[i]);
    target.box_centre_[i] = (target.box_lo_[i] + target.box_hi_[i]) / 2;
    half = std::max(half, (target.box_hi_[i] - target.box_lo_[i]) / 2);
  }
  // The default box has half side 2 and the first thesis' scene is of that size.
  target.length_unit_ = half / 2;
  if (!one_leaf) return target;

  const PolynomialLeaf& leaf = scene.leaves().front();
  target.shape_ = leaf.shape();
  // An approximation is a union of pieces, each its own surface in its own frame: no
  // one algebraic surface stands for it (the exact method does not apply); its side
  // function tells its sides apart.
  if (leaf.approximation()) {
    if (leaf.sheet_side()) target.side_ = *leaf.sheet_side();
    return target;
  }
  const SceneFrame frame = make_scene_frame(leaf.frame_box());
  // G has the sign of the leaf's value near the surface: −F for a solid whose enclosed
  // region is where F > 0 (PolynomialLeaf::negated()), so that the exact method's
  // "G < 0 where the segment starts" still means inside. Sheets are never negated:
  // their sides keep F's own sign (F > 0 is the warm side).
  Polynomial framed = frame_polynomial(leaf.negated() ? -leaf.equation() : leaf.equation(), frame, budget);
  PolynomialProgram program = PolynomialProgram::compile(framed);
  PolynomialProgram value_program = PolynomialProgram::compile(framed, ProgramOutputs::value);
  auto context = std::make_shared<const RayPolynomialContext>(framed);
  AlgebraicSurface surface{leaf.equation(),    std::move(framed),       {}, to_double(frame.scale),
                           std::move(program), std::move(context),      {}, {},
                           leaf.trimmed(),     std::move(value_program)};
  for (std::size_t i = 0; i < 3; ++i) surface.centre[i] = to_double(frame.centre[i]);
  // The value is clipped to the frame's cube |u_i| <= 1 (docs/sdf.md §3), a solid's
  // caps and a sheet's ends alike; a trimmed patch lies inside it too, and the exact
  // method passes the roots off the patch by the value there (march_ray.cpp).
  for (std::size_t i = 0; i < 3; ++i) {
    surface.lo[i] = surface.centre[i] - 1 / surface.scale;
    surface.hi[i] = surface.centre[i] + 1 / surface.scale;
  }
  target.algebraic_ = std::move(surface);
  return target;
}

double RenderTarget::evaluate(const std::array<double, 3>& p) const {
  if (precision_ == EvaluationPrecision::single) {
    return scene_.evaluate<float>(
        Vec3<float>{static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2])});
  }
  return scene_.evaluate<double>(Vec3<double>{p[0], p[1], p[2]});
}

std::array<double, 3> RenderTarget::normal(const std::array<double, 3>& p, std::uint64_t* evaluations) const {
  if (const auto g = side_gradient(p)) return *g;
  return tetrahedron_normal(p, evaluations);
}

std::optional<double> RenderTarget::side_value(const std::array<double, 3>& p) const {
  if (shape_ != SdfShape::sheet) return std::nullopt;
  if (algebraic_) {
    const AlgebraicSurface& a = *algebraic_;
    return a.value_program
        .evaluate((p[0] - a.centre[0]) * a.scale, (p[1] - a.centre[1]) * a.scale, (p[2] - a.centre[2]) * a.scale)
        .value;
  }
  if (side_) return side_->evaluate(Vec3<double>{p[0], p[1], p[2]});
  return std::nullopt;
}

std::optional<std::array<double, 3>> RenderTarget::side_gradient(const std::array<double, 3>& p) const {
  if (algebraic_) return equation_gradient(p);
  if (!side_ || shape_ != SdfShape::sheet) return std::nullopt;
  // The tetrahedron technique (tetrahedron_normal) on the side, which is smooth across
  // the sheet where the sheet's own value has a kink.
  const double h = 1e-3 * length_unit_;
  std::array<double, 3> sum{0, 0, 0};
  for (const auto& k : kTetrahedron) {
    const double f = side_->evaluate(Vec3<double>{p[0] + h * k[0], p[1] + h * k[1], p[2] + h * k[2]});
    for (std::size_t i = 0; i < 3; ++i) sum[i] += k[i] * f;
  }
  const std::array<double, 3> n = normalised(sum);
  if (n[0] == 0 && n[1] == 0 && n[2] == 0) return std::nullopt;
  return n;
}

std::optional<std::array<double, 3>> RenderTarget::equation_gradient(const std::array<double, 3>& p) const {
  if (!algebraic_) return std::nullopt;
  const AlgebraicSurface& a = *algebraic_;
  const ValueAndGradient<double> g = a.program.evaluate((p[0] - a.centre[0]) * a.scale, (p[1] - a.centre[1]) * a.scale,
                                                        (p[2] - a.centre[2]) * a.scale);
  const std::array<double, 3> n = normalised(g.gradient);
  if (n[0] == 0 && n[1] == 0 && n[2] == 0) return std::nullopt;
  return n;
}

std::array<double, 3> RenderTarget::tetrahedron_normal(const std::array<double, 3>& p,
                                                       std::uint64_t* evaluations) const {
  const double h = 1e-3 * length_unit_;
  std::array<double, 3> sum{0, 0, 0};
  for (const auto& k : kTetrahedron) {
    const double f = evaluate({p[0] + h * k[0], p[1] + h * k[1], p[2] + h * k[2]});
    for (std::size_t i = 0; i < 3; ++i) sum[i] += k[i] * f;
  }
  if (evaluations) *evaluations += kTetrahedron.size();
  return normalised(sum);
}

}  // namespace implicitizer
