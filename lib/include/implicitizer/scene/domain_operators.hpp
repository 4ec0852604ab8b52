#pragma once
/// \file
/// Domain operators of a scene (Def. 1.20–1.21 of the seed thesis, with its slips
/// corrected): twist, bend, round, elongate, symmetry, infinite and finite
/// repetition, displacement. Each comes as a C++ template twin over Vec3<T>
/// (T = float or double) and, next to it, the GLSL text of the same operations in
/// the same order (domain_operators.cpp), so evaluate<float> predicts the GPU up to
/// the GPU's own freedoms (fused multiply-adds, its sin/cos; docs/sdf.md,
/// "Domain operators", gives the measured differences on llvmpipe).
///
/// Two modes. `fast` is the seeds' / Quílez's formula: the child evaluated at the
/// warped point q(p). `safe` returns v with the sign of the operated shape and
/// |v| ≤ the distance to the other side of its surface, PROVEN in exact arithmetic
/// (the claims hold up to a few ulps of fp32 rounding). The proofs rest on one lemma:
///
///   Lemma (warps). Let f be a bound (f(x) > 0 ⇒ f(x) ≤ dist(x, {f ≤ 0}), and
///   symmetrically inside), q a map, d = |f(q(p))|, and suppose q is L-Lipschitz on
///   the ball B(p, r) with r ≥ d/L. Then |f(q(p))|/L is a bound of g = f ∘ q at p.
///   Proof: if g(p') has the other sign with |p − p'| < d/L ≤ r, the segment [p, p']
///   lies in the ball, so |q(p) − q(p')| ≤ L·|p − p'| < d; but q(p') is on the other
///   side of f's surface, at distance ≥ d from q(p). Contradiction.
///   With L = 1 everywhere (q 1-Lipschitz on all of R³), f ∘ q is a bound, and it is
///   1-Lipschitz when f is (a composition of 1-Lipschitz maps).
///
/// Every operator's parameters are passed to the GLSL helpers as arguments (a
/// literal or a uniform), and every safety constant derived from them is computed
/// inside the helper from those arguments: a uniform's run-time value is what the
/// bound uses, nothing is baked at compile time.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

#include "implicitizer/scene/vec3.hpp"

namespace implicitizer {

/// A subset of the coordinate axes: the mirrored axes of a symmetry, the repeated
/// axes of a repetition. It shapes the code (which components are touched), so it is
/// never a uniform.
struct AxisSet {
  bool x = false, y = false, z = false;  ///< members of the set

  /// Whether axis 0 (x), 1 (y) or 2 (z) is in the set.
  bool has(int axis) const { return axis == 0 ? x : axis == 1 ? y : z; }
  /// How many axes are in the set (0 to 3).
  int size() const { return int(x) + int(y) + int(z); }
  /// "x", "xz", "xyz", …: the suffix of the GLSL helper names ("" for the empty set).
  std::string letters() const;
};

/// The axes whose component of `v` is nonzero (a repetition's period: 0 = not repeated).
AxisSet axes_of(const Vec3<double>& v);

namespace domain_detail {
/// Component `axis` (0, 1, 2) of v, assignable.
template <typename T>
T& component(Vec3<T>& v, int axis) {
  return axis == 0 ? v.x : axis == 1 ? v.y : v.z;
}
/// Component `axis` (0, 1, 2) of v.
template <typename T>
T component(const Vec3<T>& v, int axis) {
  return axis == 0 ? v.x : axis == 1 ? v.y : v.z;
}
/// The largest finite float, in T: the squared distance to "no copy" in the
/// repetition bounds (any value bounds the distance to nothing).
template <typename T>
constexpr T kNoCopy = T(3.40282347e+38);
/// The distance from u to the interval [a, b]: 0 inside it.
template <typename T>
T gap(T u, T a, T b) {
  return std::max(std::max(a - u, u - b), T(0));
}
/// GLSL's floor(x + 0.5): rounding to the nearest integer with ties upwards, the same
/// in both back ends (GLSL's round() may round .5 either way).
template <typename T>
T round_half_up(T x) {
  return std::floor(x + T(0.5));
}
}  // namespace domain_detail

// ---------------------------------------------------------------------------
// Twist about the y axis by k radians per unit of y.
//
//   q(p) = (c·x − s·z, y, s·x + c·z),   c, s = cos, sin(k·y).
//
// (The seeds' R_z(ky)·(x, z, y) also swaps y and z, a slip copied from a shader.)
// Safe: the Jacobian of q is J = [R e_x | e_y + k·(−q_z, 0, q_x) | R e_z] with R the
// rotation about y and ρ = |(x, z)| = |(q_x, q_z)| the distance to the axis. For a
// unit v, |Jv|² = 1 + 2a·v_y·w + a²·v_y² with a = |k|ρ and w the component of v
// along the tangent: the largest singular value is exactly
//   ‖J‖ = g(a) = (a + sqrt(a² + 4))/2   (the root of L² − aL − 1 = 0),
// larger than sqrt(1 + a²) (the norm of the y column alone, e.g. 1.62 vs 1.41 at
// a = 1, so sqrt(1 + a²) would not prove anything). On the ball B(p, r) the distance
// to the axis is ≤ ρ + r and g is increasing, so L(r) = g(|k|(ρ + r)). The lemma
// needs r ≥ d/L(r); taking r = v = d/L, L − 1/L = |k|(ρ + d/L) gives
// L² − |k|ρ·L − (1 + |k|d) = 0, hence
//   v = d/L = 2d / (|k|ρ + sqrt(k²ρ² + 4 + 4|k||d|))       (d the child's value).
// v ≤ d, v = d when k = 0, v ≈ sqrt(|d|/|k|) far away (no scene box needed).
// Fast overshoots: with D the true distance, the same argument on B(p, D) gives
// |d| ≤ g(|k|(ρ + D))·D.
// ---------------------------------------------------------------------------

/// The child's point of a twist: (c·x − s·z, y, s·x + c·z), c, s = cos, sin(k·y).
template <typename T>
Vec3<T> twist_point(const Vec3<T>& p, T k) {
  const T a = k * p.y;
  const T c = std::cos(a);
  const T s = std::sin(a);
  return {c * p.x - s * p.z, p.y, s * p.x + c * p.z};
}
/// `vec3 PREFIX_twist(vec3 p, float k)`: twist_point.
std::string twist_glsl(const std::string& prefix);

/// Safe twist: the child's value d at twist_point(p, k) divided by the local
/// Lipschitz constant, 2d / (|k|ρ + sqrt(k²ρ² + 4 + 4|k||d|)), ρ = |(p.x, p.z)|.
/// A bound when d is (see above); not 1-Lipschitz in general.
template <typename T>
T twist_bound(const Vec3<T>& p, T k, T d) {
  const T m = std::abs(k) * std::sqrt(p.x * p.x + p.z * p.z);
  return T(2) * d / (m + std::sqrt(m * m + T(4) + T(4) * std::abs(k) * std::abs(d)));
}
/// `float PREFIX_twist_bound(vec3 p, float k, float d)`: twist_bound.
std::string twist_bound_glsl(const std::string& prefix);

// ---------------------------------------------------------------------------
// Bend: the xy plane rotated by the angle k·x.
//
//   q(p) = (c·x − s·y, s·x + c·y, z),   c, s = cos, sin(k·x).
//
// Safe: in the xy block J = R·(I + k·(−y, x) e_xᵀ) (R the rotation by kx), so
// Jv = R·(v_x(1 − ky), v_y + kx·v_x) and ‖J‖ ≤ 1 + |k|ρ, ρ = |(x, y)| the distance
// to the z axis (the rank-one term has norm |k|ρ), with equality where x = 0 and
// ky < 0. On B(p, r): L(r) = 1 + |k|(ρ + r). With r = v = d/L:
// |k|v² + (1 + |k|ρ)v − |d| = 0, hence
//   v = 2d / (m + sqrt(m² + 4|k||d|)),   m = 1 + |k|ρ.
// Fast overshoots: |d| ≤ (1 + |k|(ρ + D))·D, D the true distance.
// ---------------------------------------------------------------------------

/// The child's point of a bend: (c·x − s·y, s·x + c·y, z), c, s = cos, sin(k·x).
template <typename T>
Vec3<T> bend_point(const Vec3<T>& p, T k) {
  const T a = k * p.x;
  const T c = std::cos(a);
  const T s = std::sin(a);
  return {c * p.x - s * p.y, s * p.x + c * p.y, p.z};
}
/// `vec3 PREFIX_bend(vec3 p, float k)`: bend_point.
std::string bend_glsl(const std::string& prefix);

/// Safe bend: 2d / (m + sqrt(m² + 4|k||d|)), m = 1 + |k|·|(p.x, p.y)|. A bound when
/// d is; not 1-Lipschitz in general.
template <typename T>
T bend_bound(const Vec3<T>& p, T k, T d) {
  const T m = T(1) + std::abs(k) * std::sqrt(p.x * p.x + p.y * p.y);
  return T(2) * d / (m + std::sqrt(m * m + T(4) * std::abs(k) * std::abs(d)));
}
/// `float PREFIX_bend_bound(vec3 p, float k, float d)`: bend_bound.
std::string bend_bound_glsl(const std::string& prefix);

// ---------------------------------------------------------------------------
// Round: f − r, the same in both modes.
//
// Safe only over a 1-Lipschitz child: then f − r is 1-Lipschitz, hence a bound of its
// own surface {f = r} (|g(p)| = |g(p) − g(p')| ≤ |p − p'| for p' on the other side's
// boundary). Over a bound-only child {f = r} is an arbitrary level set, not the
// r-offset of f's surface, and f − r bounds nothing: f = |p| − 1 for |p| ≤ 2 and
// (|p| − 1)/2 beyond is a bound of the unit sphere, yet with r = 0.75, f − r is 0.25
// just inside |p| = 2 and negative just outside. Refused (`unsafe_operator`).
// ---------------------------------------------------------------------------

/// d − r.
template <typename T>
T round_value(T d, T r) {
  return d - r;
}
/// `float PREFIX_round(float d, float r)`: round_value.
std::string round_glsl(const std::string& prefix);

// ---------------------------------------------------------------------------
// Elongate by h ≥ 0 (half extents of the inserted slab):
//
//   fast:  f(e(p)),   e(p) = p − clamp(p, −h, h)      (the seeds' formula)
//   safe:  v = f(e(p)); v < 0 ? v + min(max_i(|p_i| − h_i), 0) : v
//
// e is 1-Lipschitz (each component is a 1-Lipschitz function of one coordinate), so
// f ∘ e is a bound when f is and 1-Lipschitz when f is: fast is already safe.
// Quílez's "exact" variant f(max(|p| − h, 0)) + min(max_i q_i, 0) adds the
// correction −(distance from p to the box's boundary) inside the box [−h, h], where
// e(p) = 0 and the fast value is the constant f(0). It assumes the child symmetric
// (it folds p by |p|) and that the origin is inside the child: with f(0) > 0 it
// turns the value negative outside the shape (a sphere of radius 1 at (1.5, 0, 0),
// h = (10, 10, 10): f(0) = 0.5, the value at p = 0 is −9.5, yet p is outside).
// Safe mode keeps the unfolded e(p) and applies the correction only when f(0) < 0.
// Proof: B(0, |f(0)|) lies inside the child (f is a bound), so the shape contains
// box ⊕ B(0, |f(0)|); from p in the box every path out of that set first leaves the
// box (length ≥ m = min_i(h_i − |p_i|)) and then crosses |f(0)| more, so
// −v = |f(0)| + m is a bound. The result is 1-Lipschitz when f is (both pieces are,
// and they agree on the box's boundary). It is exact when f is the exact distance of
// a ball centred at the origin (it is then iq's round box) or of a cube [−b, b]³,
// and a strict underestimate inside for boxes with unequal sides.
// ---------------------------------------------------------------------------

/// The child's point of an elongation: p − clamp(p, −h, h). Precondition: h ≥ 0.
template <typename T>
Vec3<T> elongate_point(const Vec3<T>& p, const Vec3<T>& h) {
  return p - clamp(p, -h, h);
}
/// `vec3 PREFIX_elongate(vec3 p, vec3 h)`: elongate_point.
std::string elongate_glsl(const std::string& prefix);

/// Safe elongation: the child's value d at elongate_point(p, h), lowered inside the
/// box by its distance to the box's boundary when d < 0 (see above).
template <typename T>
T elongate_bound(const Vec3<T>& p, const Vec3<T>& h, T d) {
  const Vec3<T> q = abs(p) - h;
  return d < T(0) ? d + std::min(max_component(q), T(0)) : d;
}
/// `float PREFIX_elongate_bound(vec3 p, vec3 h, float d)`: elongate_bound.
std::string elongate_bound_glsl(const std::string& prefix);

// ---------------------------------------------------------------------------
// Symmetry over a set of axes: the child at (|x|, y, z), (|x|, |y|, z), … The same in
// both modes: |·| is 1-Lipschitz (||a| − |b|| ≤ |a − b|), so the map is, and by the
// lemma the value is a bound when f is (1-Lipschitz when f is). Where the child
// crosses a mirror plane its part on the negative side is discarded, and inside, near
// the plane, the value still sees that part's boundary: a bound, not the distance.
// ---------------------------------------------------------------------------

/// The child's point of a symmetry: |p_i| on the axes in `axes`, p_i elsewhere.
template <typename T>
Vec3<T> mirror_point(const Vec3<T>& p, AxisSet axes) {
  return {axes.x ? std::abs(p.x) : p.x, axes.y ? std::abs(p.y) : p.y, axes.z ? std::abs(p.z) : p.z};
}
/// `vec3 PREFIX_symmetry_AXES(vec3 p)` (AXES = axes.letters()): mirror_point.
/// Precondition: axes not empty.
std::string symmetry_glsl(const std::string& prefix, AxisSet axes);

// ---------------------------------------------------------------------------
// Repetition with period s_i > 0 along the axes of `axes` (copies of the child at
// (k_x·s_x, k_y·s_y, k_z·s_z), k integer; finite: |k_i| ≤ l_i).
//
//   cell   c_i = floor(p_i/s_i + 0.5)      (finite: clamp(c_i, −l_i, l_i))
//   fast:  f(q), q_i = p_i − s_i·c_i       (Quílez; equal to mod(p + s/2, s) − s/2
//                                           in exact arithmetic, but one formula is
//                                           used in both back ends)
//
// GLSL's round() may round .5 either way, hence floor(x + 0.5) in both back ends.
// Fast is wrong when a copy in a neighbour cell is nearer than the own one (a small
// sphere at x = 1.4 with s = 3 is 0.15 from p = (−1.4, 0, 0) through the copy at
// −1.6, while fast says 2.75): no relative bound (docs/sdf.md gives measurements).
//
// Safe: let [lo, hi] be the child's bounding box, u_i = p_i − s_i·c_i the local
// coordinate along a repeated axis and σ_i = +1 if u_i ≥ 0 else −1 (the side of the
// nearest neighbour cell). The child is evaluated in the 2^m cells
// c + Σ ε_i σ_i e_i, ε ∈ {0, 1}^m (m = |axes|; finite: a neighbour beyond ±l_i is
// replaced by the own cell). Every other copy differs from all of them along some
// repeated axis i, where its index is c_i + 2σ_i or beyond or c_i − σ_i or beyond,
// so its box lies in the slab [lo_i + t s_i, hi_i + t s_i] with t = 2σ_i or t = −σ_i
// or farther (copies that do not exist in a finite repetition are left out), and
// within [lo_k, hi_k] along every axis k that is not repeated. So every point of it
// is at least
//   D = sqrt(min_i G_i² + Σ_k gap(p_k, lo_k, hi_k)²),
//   G_i = min(gap(u_i, lo_i + 2σ_i s_i, hi_i + 2σ_i s_i), gap(u_i, lo_i − σ_i s_i, hi_i − σ_i s_i))
// from p, and
//   v = min(D, f at the 2^m cells)
// is a bound of the union of the copies: outside it, each term bounds the distance
// to some copies and all copies are covered; inside, p lies in an evaluated copy
// (below) and each negative term bounds the depth in a copy, a subset of the union.
// The sign is right when p is in the box of no other copy, i.e. when D > 0. For
// |u_i| ≤ s_i/2 the gaps are positive if and only if −s_i < lo_i and hi_i < s_i: the
// child's box may be almost two periods wide (copies may overlap). If the box fits
// one cell (−s_i/2 ≤ lo_i, hi_i ≤ s_i/2), G_i ≥ s_i/2: all other copies lie beyond
// half a period. A box unbounded along a repeated axis cannot satisfy this (refused,
// `unbounded_child`), nor one outside (−s, s) (refused, `repetition_overlap`);
// unbounded along an axis that is not repeated is fine (pass ±3.40282347e38, the
// largest float, which GLSL can state). For a period given as a uniform the
// condition is checked against its default; at run time a gap is 0 where it fails,
// so |v| stays a bound but the value reads 0 there (a ray stops) instead of having
// the right sign. Not 1-Lipschitz: the choice of cells jumps at cell boundaries.
// Cost: 2^m child evaluations instead of one, plus D.
// ---------------------------------------------------------------------------

/// The child's point of an infinite repetition with periods s (components of the
/// axes in `axes`; the others are not read).
template <typename T>
Vec3<T> repeat_point(const Vec3<T>& p, const Vec3<T>& s, AxisSet axes) {
  using namespace domain_detail;
  Vec3<T> q = p;
  for (int i = 0; i < 3; ++i) {
    if (!axes.has(i)) continue;
    const T c = round_half_up(component(p, i) / component(s, i));
    component(q, i) = component(p, i) - component(s, i) * c;
  }
  return q;
}
/// `vec3 PREFIX_repeat_AXES(vec3 p, vec3 s)`: repeat_point. Precondition: axes not empty.
std::string repeat_glsl(const std::string& prefix, AxisSet axes);

/// The child's point in candidate cell `cell` (0 ≤ cell < 2^m) of a safe infinite
/// repetition: bit j of `cell` moves the j-th axis of `axes` (in x, y, z order) to
/// the neighbour cell. Cell 0 is repeat_point.
template <typename T>
Vec3<T> repeat_cell_point(const Vec3<T>& p, const Vec3<T>& s, AxisSet axes, int cell) {
  using namespace domain_detail;
  Vec3<T> q = p;
  int bit = 1;
  for (int i = 0; i < 3; ++i) {
    if (!axes.has(i)) continue;
    const T pi = component(p, i), si = component(s, i);
    T c = round_half_up(pi / si);
    const T u = pi - si * c;
    if ((cell & bit) != 0) c = c + (u >= T(0) ? T(1) : T(-1));
    component(q, i) = pi - si * c;
    bit *= 2;
  }
  return q;
}

/// D above for an infinite repetition: a lower bound of the distance from p to every
/// copy outside the 2^m evaluated cells, given the child's bounding box [lo, hi]
/// (±3.40282347e38 for unbounded sides). 0 where the safety condition fails.
template <typename T>
T repeat_rest_bound(const Vec3<T>& p, const Vec3<T>& s, AxisSet axes, const Vec3<T>& lo, const Vec3<T>& hi) {
  using namespace domain_detail;
  T n = T(0);
  for (int i = 0; i < 3; ++i) {
    if (axes.has(i)) continue;
    const T e = gap(component(p, i), component(lo, i), component(hi, i));
    n = n + e * e;
  }
  T r = kNoCopy<T>;
  for (int i = 0; i < 3; ++i) {
    if (!axes.has(i)) continue;
    const T pi = component(p, i), si = component(s, i), a = component(lo, i), b = component(hi, i);
    const T c = round_half_up(pi / si);
    const T u = pi - si * c;
    const T g = u >= T(0) ? T(1) : T(-1);
    T e = gap(u, a + T(2) * g * si, b + T(2) * g * si);
    r = std::min(r, e * e);
    e = gap(u, a - g * si, b - g * si);
    r = std::min(r, e * e);
  }
  return std::sqrt(r + n);
}
/// `vec3 PREFIX_repeat_AXES_cell(vec3 p, vec3 s, int cell)` and
/// `float PREFIX_repeat_AXES_rest(vec3 p, vec3 s, vec3 lo, vec3 hi)`:
/// repeat_cell_point and repeat_rest_bound. Precondition: axes not empty.
std::string repeat_safe_glsl(const std::string& prefix, AxisSet axes);

/// The child's point of a finite repetition (copies |k_i| ≤ l_i, l_i ≥ 0 integers).
template <typename T>
Vec3<T> repeat_finite_point(const Vec3<T>& p, const Vec3<T>& s, const Vec3<T>& l, AxisSet axes) {
  using namespace domain_detail;
  Vec3<T> q = p;
  for (int i = 0; i < 3; ++i) {
    if (!axes.has(i)) continue;
    const T li = component(l, i);
    const T c = std::min(std::max(round_half_up(component(p, i) / component(s, i)), -li), li);
    component(q, i) = component(p, i) - component(s, i) * c;
  }
  return q;
}
/// `vec3 PREFIX_repeat_finite_AXES(vec3 p, vec3 s, vec3 l)`: repeat_finite_point.
std::string repeat_finite_glsl(const std::string& prefix, AxisSet axes);

/// repeat_cell_point for a finite repetition: a neighbour beyond ±l_i is replaced by
/// the own cell (evaluated twice, harmless).
template <typename T>
Vec3<T> repeat_finite_cell_point(const Vec3<T>& p, const Vec3<T>& s, const Vec3<T>& l, AxisSet axes, int cell) {
  using namespace domain_detail;
  Vec3<T> q = p;
  int bit = 1;
  for (int i = 0; i < 3; ++i) {
    if (!axes.has(i)) continue;
    const T pi = component(p, i), si = component(s, i), li = component(l, i);
    T c = std::min(std::max(round_half_up(pi / si), -li), li);
    const T u = pi - si * c;
    if ((cell & bit) != 0) c = std::min(std::max(c + (u >= T(0) ? T(1) : T(-1)), -li), li);
    component(q, i) = pi - si * c;
    bit *= 2;
  }
  return q;
}

/// repeat_rest_bound for a finite repetition: copies beyond ±l_i do not count.
template <typename T>
T repeat_finite_rest_bound(const Vec3<T>& p, const Vec3<T>& s, const Vec3<T>& l, AxisSet axes, const Vec3<T>& lo,
                           const Vec3<T>& hi) {
  using namespace domain_detail;
  T n = T(0);
  for (int i = 0; i < 3; ++i) {
    if (axes.has(i)) continue;
    const T e = gap(component(p, i), component(lo, i), component(hi, i));
    n = n + e * e;
  }
  T r = kNoCopy<T>;
  for (int i = 0; i < 3; ++i) {
    if (!axes.has(i)) continue;
    const T pi = component(p, i), si = component(s, i), li = component(l, i);
    const T a = component(lo, i), b = component(hi, i);
    const T c = std::min(std::max(round_half_up(pi / si), -li), li);
    const T u = pi - si * c;
    const T g = u >= T(0) ? T(1) : T(-1);
    T e = gap(u, a + T(2) * g * si, b + T(2) * g * si);
    if (std::abs(c + T(2) * g) <= li) r = std::min(r, e * e);
    e = gap(u, a - g * si, b - g * si);
    if (std::abs(c - g) <= li) r = std::min(r, e * e);
  }
  return std::sqrt(r + n);
}
/// `vec3 PREFIX_repeat_finite_AXES_cell(vec3 p, vec3 s, vec3 l, int cell)` and
/// `float PREFIX_repeat_finite_AXES_rest(vec3 p, vec3 s, vec3 l, vec3 lo, vec3 hi)`.
std::string repeat_finite_safe_glsl(const std::string& prefix, AxisSet axes);

/// Safe infinite repetition in one call (the C++ twin of the GLSL the scene writes:
/// the rest bound, then min over the cells in order): `child(q)` is the child's value.
template <typename T, typename Child>
T repeat_bound(const Vec3<T>& p, const Vec3<T>& s, AxisSet axes, const Vec3<T>& lo, const Vec3<T>& hi, Child&& child) {
  T v = repeat_rest_bound(p, s, axes, lo, hi);
  for (int cell = 0; cell < (1 << axes.size()); ++cell) v = std::min(v, child(repeat_cell_point(p, s, axes, cell)));
  return v;
}
/// Safe finite repetition in one call (see repeat_bound).
template <typename T, typename Child>
T repeat_finite_bound(const Vec3<T>& p, const Vec3<T>& s, const Vec3<T>& l, AxisSet axes, const Vec3<T>& lo,
                      const Vec3<T>& hi, Child&& child) {
  T v = repeat_finite_rest_bound(p, s, l, axes, lo, hi);
  for (int cell = 0; cell < (1 << axes.size()); ++cell) {
    v = std::min(v, child(repeat_finite_cell_point(p, s, l, axes, cell)));
  }
  return v;
}

/// The largest limit of a finite repetition on an axis: cell indices and c ± 2 stay
/// exact in fp32 (below 2^23), and 2·10^6 + 1 copies per axis are more than a scene
/// can show.
inline constexpr double kMaxRepeatLimit = 1e6;

/// Throws InputError `unbounded_child` when the child's box [lo, hi] is unbounded
/// (±inf, NaN) along a repeated axis, and `repetition_overlap` when it does not lie in
/// (−s_i, s_i) there (the safety condition above), both with field `field`.
void check_repetition_box(const Vec3<double>& lo, const Vec3<double>& hi, const Vec3<double>& period, AxisSet axes,
                          const std::string& field);

// ---------------------------------------------------------------------------
// Displacement by a·sin(ω x)·sin(ω y)·sin(ω z):
//
//   fast:  f(p) + δ(p)
//   safe:  (f(p) + δ(p)) / (1 + |a·ω|)
//
// δ's gradient is aω·(C_x S_y S_z, S_x C_y S_z, S_x S_y C_z) (S, C = sin, cos of ω·
// coordinate); its squared norm over (aω)² is (1−X)YZ + X(1−Y)Z + XY(1−Z) with
// X, Y, Z = S_x², S_y², S_z² ∈ [0, 1], multilinear, so its maximum over the cube
// is at a vertex: 1 (at (1, 1, 0)). So δ is exactly |aω|-Lipschitz (the component
// bound aω√3 holds but is loose by √3). Over a 1-Lipschitz child f + δ is
// (1 + |aω|)-Lipschitz and the quotient is 1-Lipschitz with the sign of f + δ:
// a bound, and 1-Lipschitz. Over a bound-only child f + δ bounds nothing (refused).
// Fast overshoots by at most the factor 1 + |aω| over a 1-Lipschitz child.
// ---------------------------------------------------------------------------

/// d + a·sin(ω p.x)·sin(ω p.y)·sin(ω p.z) (d the child's value at p).
template <typename T>
T displace_value(const Vec3<T>& p, T a, T w, T d) {
  return d + a * std::sin(w * p.x) * std::sin(w * p.y) * std::sin(w * p.z);
}
/// `float PREFIX_displace(vec3 p, float a, float w, float d)`: displace_value.
std::string displace_glsl(const std::string& prefix);

/// Safe displacement: displace_value / (1 + |a·ω|). Precondition: the child is 1-Lipschitz.
template <typename T>
T displace_bound(const Vec3<T>& p, T a, T w, T d) {
  return (d + a * std::sin(w * p.x) * std::sin(w * p.y) * std::sin(w * p.z)) / (T(1) + std::abs(a * w));
}
/// `float PREFIX_displace_bound(vec3 p, float a, float w, float d)`: displace_bound.
std::string displace_bound_glsl(const std::string& prefix);

}  // namespace implicitizer
