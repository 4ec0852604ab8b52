#pragma once
/// \file
/// What the renderer draws: a compiled scene (compiled_scene.hpp), evaluated in C++
/// exactly as its GLSL is (float by default: CompiledScene::evaluate<float> runs the
/// GLSL's operations in the GLSL's order with its float constants, so a preview
/// shows what a shader using the exported function shows; double is offered for
/// comparison and costs about the same on a CPU). An implicit equation is a scene
/// with one `implicit` leaf, a parametric surface one `parametric` leaf.
///
/// When the scene is a single polynomial leaf the target also keeps its algebraic
/// surface: the equation F, and G(u) = F(c + u/s)/M, F moved exactly to the frame
/// of the leaf's box (scene_frame.hpp), with its value-and-gradient program in
/// double. That serves two things: normals from the analytic gradient (∇_p F is
/// parallel to ∇_u G, the frame being a translation and one isotropic scale, and G's
/// coefficients are of size ≤ 1, so double evaluation near the box is well
/// conditioned), and the exact marcher (march_ray.hpp), which isolates the first
/// root of F on the ray. Other scenes get normals by the tetrahedron technique.
///
/// Shape and sides. The target knows what its value describes (shape()): a single
/// polynomial leaf is a solid or a sheet (PolynomialLeaf::shape()); any other scene
/// is drawn as a solid (its value may hold sheets through `shell`, which makes them
/// thin solids). A sheet has two sides, told apart by the sign of F: shading.hpp
/// colours the one a ray sees, from ∇G at the hit (docs/render.md §5). An approximated
/// sheet has no one F: its side is the leaf's SheetSide (sheet_side.hpp), the signed
/// estimate of its nearest piece, whose gradient (by the tetrahedron technique) and
/// sign serve in G's place.

#include <array>
#include <cstdint>
#include <memory>
#include <optional>

#include "implicitizer/core/budget.hpp"
#include "implicitizer/polynomial/polynomial.hpp"
#include "implicitizer/render/ray_polynomial.hpp"
#include "implicitizer/scene/compiled_scene.hpp"
#include "implicitizer/scene/scene_node.hpp"
#include "implicitizer/scene/sheet_side.hpp"
#include "implicitizer/sdf/polynomial_program.hpp"
#include "implicitizer/sdf/sdf_shape.hpp"

namespace implicitizer {

/// The arithmetic the scene is evaluated in.
enum class EvaluationPrecision : std::uint8_t {
  single,      ///< float: what the GLSL computes (the default)
  double_run,  ///< double, with the double-rounded constants
};

/// The algebraic surface of a scene that is one polynomial leaf.
struct AlgebraicSurface {
  Polynomial equation;  ///< F(x, y, z): the surface is F = 0 (a parametric leaf's implicitized equation)
  /// G(u, v, w) = ±F(centre + u/scale)/M, exact: −F where the leaf is a solid negated
  /// (PolynomialLeaf::negated()), so that G < 0 exactly where the value's surface has
  /// its inside; +F for sheets.
  Polynomial framed;
  std::array<double, 3> centre{};  ///< the frame's centre c (exactly a float)
  double scale = 1;                ///< the frame's scale s (exactly a float): u = (p − c)·s
  PolynomialProgram program;       ///< G and ∇G (run in double)
  /// G prepared for exact root isolation along rays (shared: one per target).
  std::shared_ptr<const RayPolynomialContext> ray_context;
  /// The scene's surface lies in [lo, hi] and its value is positive outside: the
  /// leaf's box |u_i| ≤ 1 (a solid F ≤ 0 clipped to it: F's zeros inside plus the caps
  /// where the faces cut the solid; a sheet: F's zeros inside, or a trimmed patch's,
  /// which lies inside too; docs/sdf.md §3).
  std::array<double, 3> lo{}, hi{};
  bool trimmed = false;  ///< a trimmed parametric patch: an unsigned sheet, no inside
  /// G alone (run in double): the sign tests with which a march notices that it
  /// stepped across a sheet (march_ray.hpp).
  PolynomialProgram value_program;
};

/// A scene ready to be ray-marched. Copyable; every method is const and thread-safe.
class RenderTarget {
 public:
  /// Compiles `root` with `options` (compile_scene) and keeps the algebraic surface
  /// when the root is a polynomial leaf. Throws what compile_scene() throws.
  static RenderTarget compile(const SceneNode& root, const SceneParams& options,
                              EvaluationPrecision precision = EvaluationPrecision::single,
                              const Budget& budget = Budget());

  /// The scene's value at p in the target's precision (p is rounded to float for a
  /// float run, as a shader receives it), returned as a double. Negative inside.
  double evaluate(const std::array<double, 3>& p) const;

  /// The unit outward normal at p (the direction in which the value grows): from
  /// the analytic gradient of G when the target has an algebraic surface and the
  /// gradient there is finite and nonzero, else by the tetrahedron technique
  /// (tetrahedron_normal). Adds the scene evaluations spent to *evaluations.
  /// Returns (0, 0, 0) when neither gives a direction (a flat or NaN value).
  std::array<double, 3> normal(const std::array<double, 3>& p, std::uint64_t* evaluations = nullptr) const;

  /// The unit gradient of G at p (∇F's direction: it points to where F > 0), when the
  /// target has an algebraic surface and the gradient there is finite and nonzero.
  std::optional<std::array<double, 3>> equation_gradient(const std::array<double, 3>& p) const;

  /// The tetrahedron technique: N = Σ_i k_i f(p + h·k_i), k_i the vertices
  /// (1,−1,−1), (−1,−1,1), (−1,1,−1), (1,1,1), normalised; four evaluations.
  /// Why it works: Taylor gives f(p + h k_i) = f(p) + h k_i·∇f + O(h²); Σ k_i = 0
  /// removes f(p), and Σ k_i k_iᵀ = 4I (each diagonal entry sums four 1s, each
  /// off-diagonal one two 1s and two −1s), so N = 4h∇f + O(h²). The first thesis'
  /// proof writes Σ k_i·k_i = (1, 1, 1) instead, which is not the identity its own
  /// last step uses. h = 1e-3·length_unit().
  std::array<double, 3> tetrahedron_normal(const std::array<double, 3>& p, std::uint64_t* evaluations = nullptr) const;

  /// The signed side of a sheet at p: G (the algebraic surface's) or the approximated
  /// leaf's SheetSide value, in double; none for a solid or a scene of more than one
  /// node. Its sign changes across the drawn sheet (and elsewhere where the sheet's
  /// value is not small: sheet_side.hpp).
  std::optional<double> side_value(const std::array<double, 3>& p) const;
  /// The unit gradient of the side at p (it points to where the side is positive):
  /// equation_gradient(), or for an approximated sheet the tetrahedron technique on its
  /// SheetSide; none when neither applies or the direction vanishes.
  std::optional<std::array<double, 3>> side_gradient(const std::array<double, 3>& p) const;
  /// Whether side_value() answers.
  bool has_side() const { return shape_ == SdfShape::sheet && (algebraic_ || side_); }

  /// The algebraic surface, when the scene is a single polynomial leaf of one exact
  /// equation (not an approximation, polynomial_leaf.hpp).
  const std::optional<AlgebraicSurface>& algebraic() const { return algebraic_; }

  /// The object's box: the leaf's frame box when the scene is one polynomial leaf
  /// (for a parametric leaf without a box, fitted to its patch), else the scene box
  /// of SceneParams. The camera frames it (render_image.hpp default_camera).
  const std::array<double, 3>& box_lo() const { return box_lo_; }
  /// See box_lo().
  const std::array<double, 3>& box_hi() const { return box_hi_; }
  /// The scene's length unit: half the largest half side of the object's box (1 for
  /// the default box [−2, 2]³). Defaults of the renderer given in the first
  /// thesis' units (its hit threshold 1e-4, its miss distance 100, its shadow and
  /// occlusion distances) are multiplied by it.
  double length_unit() const { return length_unit_; }
  /// The object box's centre (the default look-at point).
  const std::array<double, 3>& box_centre() const { return box_centre_; }
  /// What the value describes: the single polynomial leaf's shape, else solid.
  SdfShape shape() const { return shape_; }
  /// 3: a scene in space; 2: a plane curve, evaluated at z = 0 (SceneParams::dimension),
  /// drawn in the plane by render_curve.hpp.
  int dimension() const { return dimension_; }
  /// The compiled scene.
  const CompiledScene& scene() const { return scene_; }
  /// The mode it was compiled in.
  SdfMode mode() const { return scene_.mode(); }
  /// The arithmetic of evaluate().
  EvaluationPrecision precision() const { return precision_; }

 private:
  RenderTarget(CompiledScene scene, EvaluationPrecision precision) : scene_(std::move(scene)), precision_(precision) {}

  CompiledScene scene_;
  EvaluationPrecision precision_;
  double length_unit_ = 1;
  std::array<double, 3> box_lo_{}, box_hi_{}, box_centre_{};
  SdfShape shape_ = SdfShape::solid;
  int dimension_ = 3;
  std::optional<AlgebraicSurface> algebraic_;
  std::optional<SheetSide> side_;  // an approximated sheet's (algebraic_ is then none)
};

}  // namespace implicitizer
