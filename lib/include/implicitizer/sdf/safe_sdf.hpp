#pragma once
/// \file
/// Mode `safe`: a proven lower bound of the distance to the surface F = 0, computed
/// in fp32 by the same steps in GLSL and in C++ (float, or double with double
/// constants). Sphere tracing with it never steps across the surface.
///
/// Mathematics (docs/sdf.md §6). In the scene frame u = (p - c)·s, G(u) = F(p)/M =
/// Σ c_β u^β, let Ĝ(x) = Σ |c_β| x^β (the majorant) and a = |u| componentwise. For
/// every v with |v| <= r (so |v_i| <= r), expanding (u_i + v_i)^β_i and bounding each
/// term of order >= 2 in v by its absolute value gives
///     |G(u + v)| >= Φ(r) := |G(u)| - |∇G(u)|·r - R2(r),
///     R2(r) = Ĝ(a + r·1) - Ĝ(a) - r·(∂₁Ĝ + ∂₂Ĝ + ∂₃Ĝ)(a) >= 0.
/// R2 is a polynomial in r with nonnegative coefficients and no term below r², so
/// it is convex and R2(r)/r² does not decrease; Φ is concave and decreasing with
/// Φ(0) = |G(u)|. If Φ(r) >= 0 and G(u) != 0, concavity gives Φ > 0 on [0, r), so the
/// open ball of radius r around u holds no zero of G: r is a safe step. Two
/// one-sided models find such an r without solving Φ = 0:
///   - below any r_R, R2(r) <= R2(r_R)·(r/r_R)², so the root of the quadratic
///     |G| - |∇G|·r - R2(r_R)(r/r_R)² (clamped to r_R) is safe;
///   - between two points the chord of the concave Φ lies below Φ (regula falsi
///     from the left), so its root is safe and the iterates only grow.
/// The evaluation order: Ĝ at r1 = min(|G|/|∇G|, r_cap) (if Φ(r1) >= 0, r1 is the
/// answer), the quadratic root, then kChordSteps chords, each one value-only pass
/// of Ĝ at a + r.
///
/// Rounding: every quantity is replaced by a proven one-sided bound. With ε = 2^-23
/// for float (one ulp: GLSL ES leaves the rounding mode undefined, and a fused
/// multiply-add only removes roundings) and 2^-52 for double, Horner's error in the
/// nested three-level scheme is at most γ_{2n+4}·Ĝ(a) (2n + 3 roundings per term
/// plus the coefficient's own rounding); the constants below add slack for every
/// operation after the passes, the rounding of a + r, of u = (p - c)·s (subtracted
/// from the radius), of flushed subnormals and of dropped coefficients (an absolute
/// τ). Where |G| cannot be told from 0 (|G| - γ·Ĝ - τ < kMinimumValue) the result is
/// 0: the point is within fp32's resolution of the surface, and sphere tracing
/// counts a hit.
///
/// Shapes (sdf_shape.hpp, fixed at build time). Solid: the value has F's sign, and
/// where F < 0 inside the box it is minus the smaller of the radius and the distance
/// to the box's faces (the solid clipped to the box). Sheet: where F < 0 the value is
/// the same as where F > 0, max(box distance, radius) >= 0: both terms are lower
/// bounds of the distance from p to Z ∩ box (the radius of dist(p, Z), the box term of
/// dist(p, box)), so their maximum is one too, and it is 0 only where the radius
/// cannot be certified inside the box.
///
/// Fails (returns a small but correct value) near singular points of the surface,
/// where |∇G| vanishes on it, and where Horner's error exceeds |G| (degree 18 in
/// the power basis: docs/sdf.md §4; build() then splits the box into cells with
/// their own exact expansions, which resolves most such points: §6 "Cells"). Cost: three passes of the program (G and
/// ∇G, Ĝ and ∇Ĝ, Ĝ at r1) plus one value-only pass per chord step.

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "implicitizer/polynomial/polynomial.hpp"
#include "implicitizer/sdf/polynomial_program.hpp"
#include "implicitizer/sdf/scene_frame.hpp"
#include "implicitizer/sdf/sdf_shape.hpp"

namespace implicitizer {

/// A compiled safe-mode distance bound.
class SafeSdf {
 public:
  /// Beyond this max-norm of u only the box distance is returned, as in fast mode.
  static constexpr double kFarField = 2;
  /// The largest radius tried, in u units. With |u_i| <= kFarField the majorant is
  /// then evaluated at |u_i| + r <= 3; build() lowers it where Ĝ(3, 3, 3) would
  /// exceed kMajorantLimit.
  static constexpr double kRadiusCap = 1;
  /// Regula-falsi steps after the quadratic one (tests/sdf/safe_sdf_test.cpp
  /// measures what each step buys: docs/sdf.md §6).
  static constexpr int kChordSteps = 2;
  /// Below this lower bound of |G| (coefficients of G are at most 1) the result is
  /// 0. It keeps R2/|G| <= 2^120 and so every intermediate of the root formulas
  /// finite in fp32.
  static constexpr double kMinimumValue = 0x1p-70;
  /// The majorant may not exceed this where it is evaluated (|u_i| + r <= 2 + r_cap):
  /// squares of gradients and products such as |∇G|² stay below 2^120.
  static constexpr double kMajorantLimit = 0x1p50;
  /// The most cells per axis build() splits the box into by default (a power of 2).
  /// 4 resolves more (docs/sdf.md §6: 13 zeros in 10^4 points of tp_33 against 383
  /// with 2), but its GLSL holds 64 coefficients per term, and Mesa's compiler turns
  /// each dynamically indexed read into a chain of 64 selects: minutes on llvmpipe.
  static constexpr int kMaxCellsPerAxis = 2;
  /// build() splits the box while more than this fraction of its sample points
  /// cannot be resolved in fp32 (|G| <= Γ_A·Ĝ in the cell's frame).
  static constexpr double kUnresolvedTarget = 0.01;

  /// Frames `f` (three variables x, y, z in ring order) in `box` and compiles G, its
  /// majorant Ĝ (with gradient) and Ĝ (value only). Throws InputError
  /// `constant_polynomial` (no surface), `invalid_box`, `degree_too_high` (Ĝ
  /// exceeds kMajorantLimit already at |u_i| = kFarField: the terms of G cannot all
  /// be evaluated in fp32 at the box's margin), LimitExceeded from `budget`;
  /// std::invalid_argument for `shape` automatic (the caller decides it: enclosure.hpp).
  ///
  /// Cells (docs/sdf.md §6, "Cells"): where fp32 cannot resolve |G| at more than
  /// kUnresolvedTarget of a grid of sample points of the box (Horner's error bound
  /// Γ_A·Ĝ above |G|: the power basis cancels, as for degree 18), the box is split
  /// into k³ cells, k = 2, 4, … up to `max_cells_per_axis`, and G re-expanded exactly
  /// around each cell's centre, in the cell's own frame t = (p - c_cell)·k·s; the
  /// cell containing p is evaluated. Each expansion is the same polynomial F, so the
  /// theorem holds per cell with t for u. 1 turns cells off.
  static SafeSdf build(const Polynomial& f, const SceneBox& box, const Budget& budget = Budget(),
                       SdfShape shape = SdfShape::solid, int max_cells_per_axis = kMaxCellsPerAxis);

  /// The bound at p = (x, y, z), computed exactly as the GLSL does (float) or in
  /// double with double constants and ε = 2^-52. Guarantee (docs/sdf.md §6), under
  /// the rounding model of the file comment: |value| is at most the distance from p
  /// to the zero set of F inside the box. Solid: where the polynomial is evaluated
  /// (max_i |u_i| <= kFarField) a nonzero value has the sign of F(p); farther out the
  /// value is the (positive) distance to the box. Sheet: value >= 0 everywhere.
  template <typename T>
  T evaluate(T x, T y, T z) const {
    return evaluate_with_chord_steps(x, y, z, kChordSteps);
  }

  /// evaluate() with `chord_steps` regula-falsi steps instead of kChordSteps (the
  /// GLSL always uses kChordSteps); every count gives a valid bound. For measuring.
  template <typename T>
  T evaluate_with_chord_steps(T x, T y, T z, int chord_steps) const;

  /// `float FUNCTION(vec3 p) { ... }` with comment lines above it. Precondition:
  /// `function` is a valid GLSL identifier (check_glsl_name on its prefix).
  std::string to_glsl(const std::string& function) const;

  /// The frame (exact, float-representable centre and scale).
  const SceneFrame& frame() const { return frame_; }
  /// What the value describes: solid or sheet (never automatic).
  SdfShape shape() const { return shape_; }
  /// The compiled G (value and gradient).
  const PolynomialProgram& program() const { return program_; }
  /// The compiled majorant Ĝ (value and gradient).
  const PolynomialProgram& majorant() const { return majorant_; }
  /// The largest radius tried (kRadiusCap, or less for high degrees), in u units (a
  /// cell's frame has k times larger units; Constants::radius_cap is in those).
  double radius_cap() const { return constants_double_.radius_cap / cells_per_axis_; }
  /// k: the box is split into k³ cells, each with its own expansion of G (1: none).
  int cells_per_axis() const { return cells_per_axis_; }

  /// The constants of one precision, each rounded in the safe direction (names as
  /// in docs/sdf.md §6).
  template <typename T>
  struct Constants {
    std::array<T, 3> centre{};                   ///< c (exact)
    T scale = 1;                                 ///< s (exact)
    T half_extent = 1;                           ///< h = 1/s, rounded down
    T box_half = 1;                              ///< b: the box is inside |u_i| <= b; rounded up
    T box_clamp = 1;                             ///< L: box distances per axis are clamped to it (no overflow)
    T u_shrink = 1;                              ///< 1 - 4ε: |u_true,i| >= |u_i|·u_shrink after rounding
    T u_grow = 1;                                ///< 1 + 4ε: |u_true,i| <= |u_i|·u_grow after rounding
    T box_half_inner = 1;                        ///< b rounded down: the distance to the faces from inside
    T u_error = 0;                               ///< 3ε: |u - u_true| <= u_error·(|u|+|v|+|w|)
    T gamma_value = 0;                           ///< Γ_A: |G(u) - g| <= Γ_A·Ĝ(a), with slack
    T gamma_gradient = 0;                        ///< Γ_B: |∇G(u) - ∇g| <= Γ_B·ΣĜ_i(a), with slack
    T norm_up = 1;                               ///< 1 + 16ε: covers the rounding of |∇g|
    T tau = 0;                                   ///< absolute slack: dropped terms, flushed subnormals
    T minimum_value = 0;                         ///< kMinimumValue
    T radius_cap = 1;                            ///< r_cap
    T majorant_up = 1;                           ///< 1 + Γ_X: Ĝ(a + r) <= X·majorant_up
    T majorant_down = 1;                         ///< 1 - Γ_Y: Ĝ(a) + r·ΣĜ_i(a) >= Y·majorant_down
    T root_shrink = 1;                           ///< 1 - 32ε: covers the rounding of a root formula
    T out_shrink = 1;                            ///< 1 - 16ε: covers the last operations
    T cell_scale = 1;                            ///< k·s: the cells' frames t = (p - c_cell)·k·s (exact)
    T cell_step = 1;                             ///< 1/k: a radius in t units times this is in u units (exact)
    T cell_index_scale = 0.5f;                   ///< k/2: a cell's index is floor((u + 1)·k/2), clamped
    std::vector<std::array<T, 3>> cell_centres;  ///< c_cell (floats), cell = (i·k + j)·k + l
  };

 private:
  template <typename T>
  const Constants<T>& constants() const {
    if constexpr (sizeof(T) == sizeof(float)) {
      return constants_float_;
    } else {
      return constants_double_;
    }
  }

  // The cell holding p (u its frame coordinates; floor((u_i + 1)·k/2), clamped), and p
  // in that cell's frame, rounded as the GLSL rounds it.
  template <typename T>
  std::size_t find_cell(T x, T y, T z, std::array<T, 3> u, T& lu, T& lv, T& lw) const {
    const Constants<T>& k = constants<T>();
    std::size_t cell = 0;
    for (const T coordinate : u) {
      const int i = static_cast<int>(std::floor((coordinate + T(1)) * k.cell_index_scale));
      cell = cell * static_cast<std::size_t>(cells_per_axis_) +
             static_cast<std::size_t>(std::clamp(i, 0, cells_per_axis_ - 1));
    }
    lu = (x - k.cell_centres[cell][0]) * k.cell_scale;
    lv = (y - k.cell_centres[cell][1]) * k.cell_scale;
    lw = (z - k.cell_centres[cell][2]) * k.cell_scale;
    return cell;
  }

  // GLSL with cells: the array of the cells' centres, and the statements that find p's
  // cell and its coordinates there.
  std::string cell_centres_glsl(const std::string& name) const;
  std::string cell_frame_glsl(const std::string& centres) const;

  SceneFrame frame_;
  SdfShape shape_ = SdfShape::solid;
  PolynomialProgram program_;         // G with gradient
  PolynomialProgram majorant_;        // Ĝ with gradient
  PolynomialProgram majorant_value_;  // Ĝ, value only
  int cells_per_axis_ = 1;
  Constants<float> constants_float_;
  Constants<double> constants_double_;
};

template <typename T>
T SafeSdf::evaluate_with_chord_steps(T x, T y, T z, int chord_steps) const {
  const Constants<T>& k = constants<T>();
  const T zero(0);
  const T u = (x - k.centre[0]) * k.scale;
  const T v = (y - k.centre[1]) * k.scale;
  const T w = (z - k.centre[2]) * k.scale;
  const T abs_u = std::abs(u), abs_v = std::abs(v), abs_w = std::abs(w);
  // A lower bound of the distance from the exact u to the box, per axis.
  const T du = std::min(std::max(abs_u * k.u_shrink - k.box_half, zero), k.box_clamp);
  const T dv = std::min(std::max(abs_v * k.u_shrink - k.box_half, zero), k.box_clamp);
  const T dw = std::min(std::max(abs_w * k.u_shrink - k.box_half, zero), k.box_clamp);
  const T box = std::sqrt(du * du + dv * dv + dw * dw);
  if (std::max(abs_u, std::max(abs_v, abs_w)) > T(kFarField)) return box * k.half_extent * k.out_shrink;

  // The cell holding p and p in its frame (the box's own frame when there is one cell).
  std::size_t cell = 0;
  T lu = u, lv = v, lw = w;
  if (cells_per_axis_ > 1) cell = find_cell(x, y, z, {u, v, w}, lu, lv, lw);
  const T abs_lu = std::abs(lu), abs_lv = std::abs(lv), abs_lw = std::abs(lw);
  const ValueAndGradient<T> g = program_.evaluate_in_cell(cell, lu, lv, lw);
  const ValueAndGradient<T> m = majorant_.evaluate_in_cell(cell, abs_lu, abs_lv, abs_lw);
  const T m_sum = m.gradient[0] + m.gradient[1] + m.gradient[2];
  // A <= |G(u)|, B >= |∇G(u)|.
  const T lower = (std::abs(g.value) - k.gamma_value * m.value) - k.tau;
  // Within fp32's resolution of F = 0: 0 inside the box, the distance to the box
  // outside it (the zero set outside the box is not drawn).
  if (!(lower >= k.minimum_value)) return box * k.half_extent * k.out_shrink;
  const T slope =
      std::sqrt(g.gradient[0] * g.gradient[0] + g.gradient[1] * g.gradient[1] + g.gradient[2] * g.gradient[2]) *
          k.norm_up +
      k.gamma_gradient * m_sum;
  // r1 = min(A/B, r_cap), without dividing by B (which may be 0).
  T r = k.radius_cap * lower / std::max(slope * k.radius_cap, lower);
  T safe = zero, right = zero, phi_right = zero;
  for (int step = 0; step <= chord_steps; ++step) {
    const T big = majorant_value_.evaluate_in_cell(cell, abs_lu + r, abs_lv + r, abs_lw + r).value;
    const T remainder = big * k.majorant_up - (m.value + r * m_sum) * k.majorant_down;
    const T phi = (lower - slope * r) - remainder;
    if (step == 0) {
      if (phi >= zero) {
        safe = r;
        break;
      }
      right = r;
      phi_right = phi;
      // The quadratic model, scaled by A: t = 2 / (b + sqrt(b² + 4c)), root = t·r1.
      const T b = slope * r / lower;
      const T c = remainder / lower;
      const T t = std::min(T(2) / (b + std::sqrt(b * b + T(4) * c)), T(1));
      safe = t * r * k.root_shrink;
    } else {
      if (phi < zero) break;
      safe = std::max(safe, (safe + phi * (right - safe) / (phi - phi_right)) * k.root_shrink);
    }
    r = safe;
  }
  // In t units, then u units (× 1/k, exact).
  const T radius = (safe - (abs_lu + abs_lv + abs_lw) * k.u_error) * k.cell_step;
  if (!(radius > zero)) return box * k.half_extent * k.out_shrink;
  // F > 0, or a sheet: both terms bound the distance to Z ∩ box from below.
  if (g.value >= zero || shape_ == SdfShape::sheet) return std::max(box, radius) * k.half_extent * k.out_shrink;
  // F < 0: the solid clipped to the box. Outside the box the value is the distance to
  // it (positive); inside, minus the smaller of the radius and the distance to the faces.
  if (box > zero) return box * k.half_extent * k.out_shrink;
  const T inner = std::max(k.box_half_inner - std::max(abs_u, std::max(abs_v, abs_w)) * k.u_grow, zero);
  return -(std::min(radius, inner) * k.half_extent * k.out_shrink);
}

}  // namespace implicitizer
