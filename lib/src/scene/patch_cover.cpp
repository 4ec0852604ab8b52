#include "implicitizer/scene/patch_cover.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <queue>
#include <string>

#include "implicitizer/core/errors.hpp"
#include "implicitizer/sdf/polynomial_program.hpp"
#include "implicitizer/sdf/safe_sdf.hpp"

namespace implicitizer {
namespace {

const char* const kWhere = "patch cover";

using V = Vec3<double>;

// An axis-aligned box in double.
struct Box {
  V lo, hi;
};

bool overlaps(const Box& a, const Box& b) {
  return a.lo.x <= b.hi.x && b.lo.x <= a.hi.x && a.lo.y <= b.hi.y && b.lo.y <= a.hi.y && a.lo.z <= b.hi.z &&
         b.lo.z <= a.hi.z;
}

double component(const V& v, std::size_t i) { return i == 0 ? v.x : (i == 1 ? v.y : v.z); }
double& component(V& v, std::size_t i) { return i == 0 ? v.x : (i == 1 ? v.y : v.z); }

// The patch's coordinates in double, ξ_i/ω over the common denominator: for
// sampling only (the sample's rounding is covered by a slack, see build()).
class DoublePatch {
 public:
  DoublePatch(const Parametrization& parametrization, const Budget& budget) {
    for (const Polynomial& f : common_denominator_form(parametrization, budget)) {
      Form form;
      for (std::size_t t = 0; t < f.num_terms(); ++t) {
        form.coefficients.push_back(to_mpq(f.coefficient(t)).get_d());
        form.exponents.push_back(f.exponents(t));
      }
      forms_.push_back(std::move(form));
    }
  }

  V at(const std::vector<double>& parameters) const {
    const double w = value(forms_[0], parameters);
    V p{0, 0, 0};
    for (std::size_t i = 1; i < forms_.size(); ++i) component(p, i - 1) = value(forms_[i], parameters) / w;
    return p;
  }

 private:
  struct Form {
    std::vector<double> coefficients;
    std::vector<std::vector<std::int32_t>> exponents;
  };

  static double value(const Form& f, const std::vector<double>& parameters) {
    double sum = 0;
    for (std::size_t t = 0; t < f.coefficients.size(); ++t) {
      double term = f.coefficients[t];
      for (std::size_t j = 0; j < parameters.size(); ++j) {
        for (std::int32_t k = 0; k < f.exponents[t][j]; ++k) term *= parameters[j];
      }
      sum += term;
    }
    return sum;
  }

  std::vector<Form> forms_;
};

// Points in a uniform grid of buckets: answers "is a point within r of c?".
class PointGrid {
 public:
  PointGrid(const std::vector<V>& points, double cell) : cell_(cell) {
    if (points.empty()) {  // no point near anything: one empty bucket
      counts_ = {1, 1, 1};
      offsets_.assign(2, 0);
      return;
    }
    lo_ = hi_ = points.front();
    for (const V& p : points) {
      for (std::size_t i = 0; i < 3; ++i) {
        component(lo_, i) = std::min(component(lo_, i), component(p, i));
        component(hi_, i) = std::max(component(hi_, i), component(p, i));
      }
    }
    // At most 128 buckets per axis: a coarser grid costs time, never correctness.
    for (std::size_t i = 0; i < 3; ++i) cell_ = std::max(cell_, (component(hi_, i) - component(lo_, i)) / 127);
    for (std::size_t i = 0; i < 3; ++i) {
      counts_[i] = static_cast<std::size_t>((component(hi_, i) - component(lo_, i)) / cell_) + 1;
    }
    std::vector<std::size_t> keys;
    offsets_.assign(counts_[0] * counts_[1] * counts_[2] + 1, 0);
    for (const V& p : points) {
      keys.push_back(key(p));
      ++offsets_[keys.back() + 1];
    }
    for (std::size_t k = 1; k < offsets_.size(); ++k) offsets_[k] += offsets_[k - 1];
    points_.resize(points.size());
    std::vector<std::size_t> next(offsets_.begin(), offsets_.end() - 1);
    for (std::size_t i = 0; i < points.size(); ++i) points_[next[keys[i]]++] = points[i];
  }

  bool any_within(const V& c, double r) const {
    if (r < 0) return false;
    std::array<std::size_t, 3> first{}, last{};
    for (std::size_t i = 0; i < 3; ++i) {
      const double lo = (component(c, i) - r - component(lo_, i)) / cell_;
      const double hi = (component(c, i) + r - component(lo_, i)) / cell_;
      if (hi < 0 || lo >= static_cast<double>(counts_[i])) return false;
      first[i] = lo < 0 ? 0 : static_cast<std::size_t>(lo);
      last[i] = std::min(counts_[i] - 1, static_cast<std::size_t>(hi));
    }
    const double r2 = r * r;
    for (std::size_t a = first[0]; a <= last[0]; ++a) {
      for (std::size_t b = first[1]; b <= last[1]; ++b) {
        for (std::size_t k = first[2]; k <= last[2]; ++k) {
          const std::size_t bucket = (a * counts_[1] + b) * counts_[2] + k;
          for (std::size_t j = offsets_[bucket]; j < offsets_[bucket + 1]; ++j) {
            const V d = points_[j] - c;
            if (dot(d, d) <= r2) return true;
          }
        }
      }
    }
    return false;
  }

 private:
  std::size_t index(const V& p, std::size_t i) const {
    const double x = (component(p, i) - component(lo_, i)) / cell_;
    return std::min(counts_[i] - 1, static_cast<std::size_t>(std::max(0.0, x)));
  }
  std::size_t key(const V& p) const { return (index(p, 0) * counts_[1] + index(p, 1)) * counts_[2] + index(p, 2); }

  double cell_;
  V lo_, hi_;
  std::array<std::size_t, 3> counts_{};
  std::vector<std::size_t> offsets_;
  std::vector<V> points_;
};

// Points of X(D) on a grid of D, refined (up to about 2^20 points) until
// neighbouring points are at most `spacing` apart: the far-cell search then finds
// a sample point near every point of the patch without descending far.
std::vector<V> sample_patch(const Parametrization& parametrization, const ParameterDomain& domain, double spacing,
                            const Budget& budget) {
  const DoublePatch patch(parametrization, budget);
  const std::size_t m = domain.intervals.size();
  std::vector<std::pair<double, double>> range;
  for (const auto& [lo, hi] : domain.intervals) range.emplace_back(to_mpq(lo).get_d(), to_mpq(hi).get_d());
  const std::size_t max_points = std::size_t{1} << 18;
  for (std::size_t n = 16;; n *= 2) {
    const std::size_t per_axis = n + 1;
    const std::size_t total = m == 1 ? per_axis : per_axis * per_axis;
    std::vector<V> points(total);
    std::vector<double> parameters(m);
    for (std::size_t index = 0; index < total; ++index) {
      if (index % 4096 == 0) budget.check(kWhere);
      std::size_t rest = index;
      for (std::size_t j = m; j-- > 0;) {
        const std::size_t k = rest % per_axis;
        rest /= per_axis;
        const double u = static_cast<double>(k) / static_cast<double>(n);
        parameters[j] = k == n ? range[j].second : range[j].first + u * (range[j].second - range[j].first);
      }
      points[index] = patch.at(parameters);
    }
    double gap = 0;
    for (std::size_t index = 0; index < total; ++index) {
      const std::size_t k = index % per_axis;
      if (k + 1 < per_axis) gap = std::max(gap, length(points[index + 1] - points[index]));
      if (m == 2 && index + per_axis < total) gap = std::max(gap, length(points[index + per_axis] - points[index]));
    }
    const std::size_t next = m == 1 ? 2 * n + 1 : (2 * n + 1) * (2 * n + 1);
    if (!(gap > spacing) || next > max_points) {
      // Coefficients beyond double's range (the common denominator's can be, for a
      // patch well inside it) give an infinite or NaN point, no point of the patch:
      // left out. A sample point only spares the far-cell search a descent, so the
      // cells it would have answered for are searched instead.
      std::erase_if(points, [](const V& p) { return !std::isfinite(p.x + p.y + p.z); });
      return points;
    }
  }
}

// The far cells: boxes that may hold a point of Z farther than `reach` from X(D)
// (the file comment of patch_cover.hpp). Searched lazily, one query box at a time,
// stopping at the first far cell found; the far cells found are kept (indexed by a
// coarse grid over the search region) and answer later queries first, since the
// children of a node that reached a far cell often reach it too.
class FarCellSearch {
 public:
  FarCellSearch(const Box& region, const std::optional<SafeSdf>& safe, const PointGrid& sample, double reach,
                double resolution, const Budget& budget, const PatchCoverParams& params, PatchCoverStats& stats)
      : region_(region),
        safe_(safe),
        sample_(sample),
        reach_(reach),
        resolution_(resolution),
        budget_(budget),
        params_(params),
        stats_(stats) {
    for (std::size_t i = 0; i < 3; ++i) {
      const double side = component(region.hi, i) - component(region.lo, i);
      counts_[i] = side > 0 ? kBuckets : 1;
      cell_[i] = side > 0 ? side / kBuckets : 1;
    }
    buckets_.resize(counts_[0] * counts_[1] * counts_[2]);
  }

  // Whether `box` may hold a far point (within the region).
  bool reaches_far(const Box& box) {
    Box query = box;
    for (std::size_t i = 0; i < 3; ++i) {
      component(query.lo, i) = std::max(component(query.lo, i), component(region_.lo, i));
      component(query.hi, i) = std::min(component(query.hi, i), component(region_.hi, i));
      if (component(query.lo, i) > component(query.hi, i)) return false;
    }
    bool known = false;
    for_each_bucket(query, [&](std::size_t bucket) {
      for (std::size_t c : buckets_[bucket]) known = known || overlaps(cells_[c], query);
    });
    return known || search(query);
  }

 private:
  static constexpr std::size_t kBuckets = 32;

  // Bisects cells of `query` along their longest side; true at the first cell it
  // can neither prove empty of Z nor within `reach` of the sample.
  bool search(const Box& query) {
    std::vector<Box> stack{query};
    while (!stack.empty()) {
      const Box cell = stack.back();
      stack.pop_back();
      if (++stats_.search_cells % 1024 == 0) budget_.check(kWhere);
      if (stats_.search_cells > params_.max_search_cells) {
        throw LimitExceeded(Limit::size, std::string("size limit exceeded during ") + kWhere + ": more than " +
                                             std::to_string(params_.max_search_cells) + " cells searched");
      }
      const V centre = (cell.lo + cell.hi) * 0.5;
      const double r = length(cell.hi - cell.lo) * 0.5;
      if (safe_ && std::abs(safe_->evaluate<double>(centre.x, centre.y, centre.z)) > r) continue;
      if (sample_.any_within(centre, reach_ - r)) continue;
      if (r <= resolution_) {
        cells_.push_back(cell);
        for_each_bucket(cell, [&](std::size_t bucket) { buckets_[bucket].push_back(cells_.size() - 1); });
        stats_.far_cells = cells_.size();
        return true;
      }
      std::size_t axis = 0;
      for (std::size_t i = 1; i < 3; ++i) {
        if (component(cell.hi, i) - component(cell.lo, i) > component(cell.hi, axis) - component(cell.lo, axis)) {
          axis = i;
        }
      }
      Box lower = cell, upper = cell;
      component(lower.hi, axis) = component(upper.lo, axis) = component(centre, axis);
      stack.push_back(upper);
      stack.push_back(lower);
    }
    return false;
  }

  template <class F>
  void for_each_bucket(const Box& box, F&& f) const {
    std::array<std::size_t, 3> first{}, last{};
    for (std::size_t i = 0; i < 3; ++i) {
      const double lo = (component(box.lo, i) - component(region_.lo, i)) / cell_[i];
      const double hi = (component(box.hi, i) - component(region_.lo, i)) / cell_[i];
      first[i] = std::min(counts_[i] - 1, static_cast<std::size_t>(std::max(0.0, lo)));
      last[i] = std::min(counts_[i] - 1, static_cast<std::size_t>(std::max(0.0, hi)));
    }
    for (std::size_t a = first[0]; a <= last[0]; ++a) {
      for (std::size_t b = first[1]; b <= last[1]; ++b) {
        for (std::size_t k = first[2]; k <= last[2]; ++k) f((a * counts_[1] + b) * counts_[2] + k);
      }
    }
  }

  Box region_;
  const std::optional<SafeSdf>& safe_;
  const PointGrid& sample_;
  double reach_, resolution_;
  const Budget& budget_;
  const PatchCoverParams& params_;
  PatchCoverStats& stats_;
  std::vector<Box> cells_;
  std::array<std::size_t, 3> counts_{};
  std::array<double, 3> cell_{};
  std::vector<std::vector<std::size_t>> buckets_;
};

// A leaf's slabs (patch_cover.hpp, "Slabs"): normals w (float, |w| <= 1) and float
// bounds of w·(x − o) over its sub-patch, o the box's lower corner, rounded outwards;
// all zero (0 <= 0·x <= 0 holds everywhere, an excess never above 0): none. `lo_at`
// and `hi_at` are the bounds of w·x themselves, in double, for the edge criterion.
struct Slabs {
  std::array<Vec3<float>, 3> w{};
  Vec3<float> lo{0, 0, 0}, hi{0, 0, 0};
  std::array<double, 3> lo_at{}, hi_at{};
  bool used = false;
};

// One node of the quadtree: a sub-domain, the box of its sub-patch (corners rounded
// outwards to float: the evaluated box) and its slabs.
struct Node {
  ParameterDomain domain;
  Vec3<float> lo, hi;
  std::vector<std::size_t> children;
  float largest_side = 0;
  Slabs slabs;
};

// A point of Z a step of sharp_reach·h past an edge of D, and its parameter along
// that edge.
struct BeyondPoint {
  V point;
  double along;
};

// What every node's construction reads.
struct CoverContext {
  const Parametrization& parametrization;
  DoublePatch patch;
  const Budget& budget;
  PatchBoundsParams bounds_params;
  const ParameterDomain& domain;  // D, the whole domain
  // Per edge of a surface's D (s = s0, s = s1, t = t0, t = t1): Z a step past it,
  // inside the frame (beside_edges()).
  std::array<std::vector<BeyondPoint>, 4> beyond{};
};

std::vector<double> centre_of(const ParameterDomain& domain) {
  std::vector<double> c;
  for (const auto& [lo, hi] : domain.intervals) c.push_back(to_mpq((lo + hi) / Rational(2)).get_d());
  return c;
}

// ∂X/∂u_j at u by a central difference (the slabs' normals need only be some
// vectors; their bounds are exact for whatever vectors are chosen).
V partial(const DoublePatch& patch, std::vector<double> u, std::size_t j, double step) {
  u[j] += step;
  const V plus = patch.at(u);
  u[j] -= 2 * step;
  return (plus - patch.at(u)) / (2 * step);
}

V cross(const V& a, const V& b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }

std::optional<V> unit(const V& v) {
  const double l = length(v);
  if (!std::isfinite(l) || l <= 0) return std::nullopt;
  return v / l;
}

// X_s and X_t at `u` (steps relative to `domain`'s widths), and the unit normal there;
// no normal where |X_s × X_t| is far below |X_s|·|X_t| (no tangent plane worth the name).
struct SurfaceFrame {
  V xs, xt;
  std::optional<V> n;
};
SurfaceFrame surface_frame(const CoverContext& ctx, const ParameterDomain& domain, const std::vector<double>& u) {
  SurfaceFrame f;
  f.xs = partial(ctx.patch, u, 0, to_mpq(domain.intervals[0].second - domain.intervals[0].first).get_d() * 1e-4);
  f.xt = partial(ctx.patch, u, 1, to_mpq(domain.intervals[1].second - domain.intervals[1].first).get_d() * 1e-4);
  const V cross_st = cross(f.xs, f.xt);
  if (length(cross_st) > 1e-9 * length(f.xs) * length(f.xt)) f.n = unit(cross_st);
  return f;
}

// The slab normals of the leaf over `domain`: for a surface w_n ∥ X_s × X_t at its
// centre, and the in-plane normals w_s ⊥ X_t, w_t ⊥ X_s taken at the middle of the
// leaf's side nearer D's edge in that parameter (at the centre when the leaf spans D
// in it): a leaf on an edge is halved along the edge only and stays deep across it,
// so at its centre X_t would differ from the edge's by X_st times that depth, a face
// tilted against the edge to first order, while at the side's middle the face follows
// the edge up to its curvature. For a curve its tangent and two normals (in the plane
// z = 0 and e_z for a plane curve). None where the frame degenerates at the centre.
std::optional<std::array<V, 3>> tangent_frame(const CoverContext& ctx, const ParameterDomain& domain,
                                              bool plane_curve) {
  const std::vector<double> c = centre_of(domain);
  std::optional<V> a, b, n;
  if (c.size() == 2) {
    const SurfaceFrame centre = surface_frame(ctx, domain, c);
    n = centre.n;
    if (!n) return std::nullopt;
    const auto side_frame = [&](std::size_t j) {
      const auto& [lo, hi] = domain.intervals[j];
      const auto& [edge_lo, edge_hi] = ctx.domain.intervals[j];
      // Spanning D, both sides lie on edges: the centre serves both alike.
      if (lo == edge_lo && hi == edge_hi) return centre;
      std::vector<double> u = c;
      u[j] = to_mpq(lo - edge_lo <= edge_hi - hi ? lo : hi).get_d();
      const SurfaceFrame side = surface_frame(ctx, domain, u);
      return side.n ? side : centre;
    };
    const SurfaceFrame s_side = side_frame(0), t_side = side_frame(1);
    a = unit(cross(s_side.xt, *s_side.n));
    b = unit(cross(*t_side.n, t_side.xs));
  } else {
    const double width = to_mpq(domain.intervals[0].second - domain.intervals[0].first).get_d();
    const std::vector<V> d{partial(ctx.patch, c, 0, width * 1e-4)};
    n = unit(d[0]);
    if (!n) return std::nullopt;
    if (plane_curve) {
      a = V{-n->y, n->x, 0};
      b = V{0, 0, 1};
    } else {
      // Any unit vector off the tangent, then the two normals.
      const V e = std::abs(n->x) < 0.6 ? V{1, 0, 0} : V{0, 1, 0};
      a = unit(cross(*n, e));
      if (a) b = cross(*n, *a);
    }
  }
  if (!a || !b) return std::nullopt;
  return std::array<V, 3>{*n, *a, *b};
}

Rational exact(double x) { return to_rational(mpq_class(x)); }

// The patch in the slab coordinates w_i·X (three coordinates).
Parametrization rotated(const Parametrization& parametrization, const std::array<Vec3<float>, 3>& w) {
  Parametrization out;
  out.parameter_ring = parametrization.parameter_ring;
  for (const Vec3<float>& wi : w) {
    const double c[3] = {wi.x, wi.y, wi.z};
    RationalFunction sum(Polynomial(parametrization.parameter_ring));
    for (std::size_t j = 0; j < parametrization.coordinates.size(); ++j) {
      if (c[j] == 0) continue;
      sum = sum + RationalFunction(Polynomial::constant(parametrization.parameter_ring, exact(c[j]))) *
                      parametrization.coordinates[j];
    }
    out.coordinates.push_back(std::move(sum));
  }
  return out;
}

constexpr float kLargestFloat = std::numeric_limits<float>::max();

Slabs make_slabs(const CoverContext& ctx, const ParameterDomain& domain, const Vec3<float>& origin) {
  Slabs slabs;
  const bool plane_curve = ctx.parametrization.coordinates.size() == 2;
  const std::optional<std::array<V, 3>> frame = tangent_frame(ctx, domain, plane_curve);
  if (!frame) return slabs;
  // (1 − 2^-20) and one rounding to float per component keep |w| below 1.
  for (std::size_t i = 0; i < 3; ++i) {
    const V v = (*frame)[i] * (1 - 0x1p-20);
    slabs.w[i] = {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z)};
  }
  const PatchBounds bounds = bound_patch(rotated(ctx.parametrization, slabs.w), domain, ctx.budget, ctx.bounds_params);
  float* lo[3] = {&slabs.lo.x, &slabs.lo.y, &slabs.lo.z};
  float* hi[3] = {&slabs.hi.x, &slabs.hi.y, &slabs.hi.z};
  for (std::size_t i = 0; i < 3; ++i) {
    const Vec3<float>& w = slabs.w[i];
    const Rational offset = exact(w.x) * exact(origin.x) + exact(w.y) * exact(origin.y) + exact(w.z) * exact(origin.z);
    *lo[i] = round_down<float>(bounds.lo[i] - offset);
    *hi[i] = round_up<float>(bounds.hi[i] - offset);
    slabs.lo_at[i] = to_mpq(bounds.lo[i]).get_d();
    slabs.hi_at[i] = to_mpq(bounds.hi[i]).get_d();
    // A bound beyond float's range cannot be stated: the leaf keeps its box alone.
    if (!(std::abs(*lo[i]) <= kLargestFloat && std::abs(*hi[i]) <= kLargestFloat)) return Slabs{};
  }
  slabs.used = true;
  return slabs;
}

Node make_node(const CoverContext& ctx, ParameterDomain domain, bool with_slabs = true) {
  const PatchBounds bounds = bound_patch(ctx.parametrization, domain, ctx.budget, ctx.bounds_params);
  Node node{std::move(domain), {0, 0, 0}, {0, 0, 0}, {}, 0, {}};
  float* lo[3] = {&node.lo.x, &node.lo.y, &node.lo.z};
  float* hi[3] = {&node.hi.x, &node.hi.y, &node.hi.z};
  // Beyond float's range a corner is clamped to ±FLT_MAX: for every float point p
  // the distance to the clamped box is at most the distance to the true one (equal
  // when the box reaches beyond on one side only), and the GLSL can state it.
  bool clamped = false;
  for (std::size_t i = 0; i < bounds.lo.size(); ++i) {
    const float l = round_down<float>(bounds.lo[i]);
    const float u = round_up<float>(bounds.hi[i]);
    *lo[i] = std::clamp(l, -kLargestFloat, kLargestFloat);
    *hi[i] = std::clamp(u, -kLargestFloat, kLargestFloat);
    clamped = clamped || *lo[i] != l || *hi[i] != u;
    node.largest_side = std::max(node.largest_side, *hi[i] - *lo[i]);
  }
  // Slabs relative to a clamped corner could overflow their own arithmetic.
  if (with_slabs && !clamped) node.slabs = make_slabs(ctx, node.domain, node.lo);
  return node;
}

// The halves of a sub-domain along the parameters whose bit is set in `halve` (all
// of them: 2^m pieces, m = 1 or 2), lower halves first, the last parameter fastest:
// consecutive leaves are neighbours in D (a Z-order).
std::vector<ParameterDomain> split_domain(const ParameterDomain& domain, unsigned halve = ~0U) {
  std::vector<ParameterDomain> out(1);
  for (std::size_t j = 0; j < domain.intervals.size(); ++j) {
    const auto& [lo, hi] = domain.intervals[j];
    const Rational middle = (lo + hi) / Rational(2);
    std::vector<std::pair<Rational, Rational>> parts{{lo, hi}};
    if ((halve >> j) & 1U) parts = {{lo, middle}, {middle, hi}};
    std::vector<ParameterDomain> next;
    for (const ParameterDomain& d : out) {
      for (const auto& part : parts) {
        ParameterDomain e = d;
        e.intervals.push_back(part);
        next.push_back(std::move(e));
      }
    }
    out = std::move(next);
  }
  return out;
}

// The safe bound of Z on the frame box widened by h/2: inside the frame its box term
// (the distance to the widened box's faces, >= h/2) never clips the bound for cells of
// half diagonal below h/2. None when F's terms exceed fp32 (degree_too_high).
std::optional<SafeSdf> safe_bound_around(const Polynomial& equation, const SceneBox& frame_box, double h,
                                         const Budget& budget) {
  SceneBox wide = frame_box;
  const Rational pad = to_rational(mpq_class(h / 2));
  for (std::size_t i = 0; i < 3; ++i) {
    wide.lo[i] = wide.lo[i] - pad;
    wide.hi[i] = wide.hi[i] + pad;
  }
  try {
    return SafeSdf::build(equation, wide, budget);
  } catch (const InputError& e) {
    if (e.code() != "degree_too_high") throw;
  }
  return std::nullopt;
}

// The leaves of the quadtree `nodes` (root 0) in depth-first order.
std::vector<std::size_t> leaves_in_order(const std::vector<Node>& nodes) {
  std::vector<std::size_t> order;
  std::vector<std::size_t> stack{0};
  while (!stack.empty()) {
    const std::size_t i = stack.back();
    stack.pop_back();
    if (nodes[i].children.empty()) order.push_back(i);
    for (auto c = nodes[i].children.rbegin(); c != nodes[i].children.rend(); ++c) stack.push_back(*c);
  }
  return order;
}

Box widened(const Vec3<float>& lo, const Vec3<float>& hi, double by) {
  const V w{by, by, by};
  return {V{lo.x, lo.y, lo.z} - w, V{hi.x, hi.y, hi.z} + w};
}

double box_distance(const Box& box, const V& p) {
  const V q{std::max({box.lo.x - p.x, p.x - box.hi.x, 0.0}), std::max({box.lo.y - p.y, p.y - box.hi.y, 0.0}),
            std::max({box.lo.z - p.z, p.z - box.hi.z, 0.0})};
  return length(q);
}

// Whether the frame box leaves Z past D's edge u_j = `edge` (an upper edge when
// `upper`), along `node`'s range of the other parameter, to the slabs: the patch's
// continuation a step of sharp_reach·h past the edge, at points along it about 0.01·h apart, lies
// within 1.05·sharp_value·h of the frame box (sampled; a stationary or non-finite point
// counts). Elsewhere the frame's own box distance already gives the points
// sharp_reach·h past the edge their value (a graph over D in its fitted box: Z leaves
// the box at the edge).
bool continues_in_frame(const CoverContext& ctx, const Node& node, std::size_t j, double edge, bool upper,
                        const Box& frame, double h, const PatchCoverParams& params) {
  const std::size_t m = node.domain.intervals.size();
  std::vector<double> u = centre_of(node.domain);
  u[j] = edge;
  const std::size_t other = 1 - j;  // used when m == 2
  // About one sample per 0.01·h of the node's box (5 to 129): the frame can be nearly
  // tangent to the continuation, and a sparse sample missed a point where it was not
  // (tp_22's t = 0 edge).
  const int samples =
      m == 2 ? static_cast<int>(std::clamp(std::ceil(node.largest_side / (0.01 * h)) + 1, 5.0, 129.0)) : 1;
  const double width = to_mpq(node.domain.intervals[j].second - node.domain.intervals[j].first).get_d();
  for (int k = 0; k < samples; ++k) {
    if (m == 2) {
      const double lo = to_mpq(node.domain.intervals[other].first).get_d();
      const double hi = to_mpq(node.domain.intervals[other].second).get_d();
      u[other] = lo + (hi - lo) * k / (samples - 1);
    }
    const double speed = length(partial(ctx.patch, u, j, width * 1e-4));
    if (!std::isfinite(speed) || speed <= 0) return true;
    std::vector<double> beyond = u;
    beyond[j] += (upper ? 1 : -1) * params.sharp_reach * h / speed;
    const V q = ctx.patch.at(beyond);
    if (!std::isfinite(q.x + q.y + q.z) || box_distance(frame, q) <= 1.05 * params.sharp_value * h) return true;
  }
  return false;
}

// Z a step of sharp_reach·h past each edge of a surface's D, at 1025 points along
// the edge (about 0.001 of its length apart), those the frame keeps (within
// 1.05·sharp_value·h of it, as continues_in_frame() asks).
std::array<std::vector<BeyondPoint>, 4> beside_edges(const CoverContext& ctx, const Box& frame, double h,
                                                     const PatchCoverParams& params) {
  constexpr int kSamples = 1024;
  std::array<std::vector<BeyondPoint>, 4> out;
  for (std::size_t j = 0; j < 2; ++j) {
    const std::size_t other = 1 - j;
    const double width = to_mpq(ctx.domain.intervals[j].second - ctx.domain.intervals[j].first).get_d();
    const double lo = to_mpq(ctx.domain.intervals[other].first).get_d();
    const double hi = to_mpq(ctx.domain.intervals[other].second).get_d();
    for (const bool upper : {false, true}) {
      ctx.budget.check(kWhere);
      std::vector<double> u(2);
      u[j] = to_mpq(upper ? ctx.domain.intervals[j].second : ctx.domain.intervals[j].first).get_d();
      for (int k = 0; k <= kSamples; ++k) {
        u[other] = lo + (hi - lo) * k / kSamples;
        const double speed = length(partial(ctx.patch, u, j, width * 1e-4));
        if (!std::isfinite(speed) || speed <= 0) continue;
        std::vector<double> beyond = u;
        beyond[j] += (upper ? 1 : -1) * params.sharp_reach * h / speed;
        const V q = ctx.patch.at(beyond);
        if (!std::isfinite(q.x + q.y + q.z) || box_distance(frame, q) > 1.05 * params.sharp_value * h) continue;
        out[2 * j + (upper ? 1 : 0)].push_back({q, u[other]});
      }
    }
  }
  return out;
}

// The leaf's value at q in double: the larger of its box distance and its largest slab
// excess (the evaluation's, without the rounding).
double leaf_value(const Node& node, const V& q) {
  const Box box{V{node.lo.x, node.lo.y, node.lo.z}, V{node.hi.x, node.hi.y, node.hi.z}};
  double value = box_distance(box, q);
  for (std::size_t i = 0; i < 3; ++i) {
    const V w{node.slabs.w[i].x, node.slabs.w[i].y, node.slabs.w[i].z};
    value = std::max({value, node.slabs.lo_at[i] - dot(w, q), dot(w, q) - node.slabs.hi_at[i]});
  }
  return value;
}

// Whether a point of `beyond` (Z a step past one of D's edges, beside_edges()) that is
// not in front of the node's own side u_j = const comes within 1.2·sharp_value·h of the
// node's box and slabs. Those points belong to other sub-patches, whose faces trim
// them, but where X_s and X_t are nearly parallel the node's own in-plane slab along
// the edge is wide and can take them in (tp_22's t = 0 edge, 1.5 leaf lengths away).
bool takes_in_beside(const Node& node, std::size_t j, const std::vector<BeyondPoint>& beyond, double h,
                     const PatchCoverParams& params) {
  const std::size_t other = 1 - j;
  const double lo = to_mpq(node.domain.intervals[other].first).get_d();
  const double hi = to_mpq(node.domain.intervals[other].second).get_d();
  for (const BeyondPoint& b : beyond) {
    if (b.along >= lo && b.along <= hi) continue;
    if (leaf_value(node, b.point) <= 1.2 * params.sharp_value * h) return true;
  }
  return false;
}

// Whether a side of `node` lets Z past an edge of `domain` come too close to its slab
// face (patch_cover.hpp, "Edges"). Side (j, upper) of the node lies a parameter gap g
// inside D's edge on that side, about g·|w·X_j| in the facing slab's coordinate; the
// node's sub-patch reaches past its own side by the overshoot σ (the bound of w·X over
// that side against the face), so the face lies σ − g·|w·X_j| past D's edge, which
// the criterion bounds by (sharp_reach − 1.2·sharp_value)·h.
// An edge node has g = 0; an inner node's side is checked only when the slab's width
// (which bounds σ) exceeds 0.9·g·|w·X_j|. Returns the parameters to halve, as bits:
// the one along each blunt side (σ grows with the square of the side's length, and
// halving across it would only add inner leaves); 0: none.
unsigned blunt_edge(const CoverContext& ctx, const Node& node, const ParameterDomain& domain, const Box& frame,
                    double h, const PatchCoverParams& params) {
  // Without a tangent frame (a singular point) smaller boxes would be all there is,
  // and a singular edge would split to the cap: the leaf keeps its box (box_leaves).
  if (!node.slabs.used) return 0;
  const std::size_t m = node.domain.intervals.size();
  const std::vector<double> c = centre_of(node.domain);
  unsigned halve = 0;
  for (std::size_t j = 0; j < m; ++j) {
    // The slab facing the sides u_j = const: w_s (1) for s, w_t (2) for t; a curve's tangent (0).
    const std::size_t i = m == 2 ? 1 + j : 0;
    const Vec3<float>& wf = node.slabs.w[i];
    const V w{wf.x, wf.y, wf.z};
    const double width = to_mpq(node.domain.intervals[j].second - node.domain.intervals[j].first).get_d();
    const V xj = partial(ctx.patch, c, j, width * 1e-4);
    const double along = dot(w, xj);
    const double allowed = (params.sharp_reach - 1.2 * params.sharp_value) * h;
    for (const bool upper : {false, true}) {
      const Rational& at = upper ? node.domain.intervals[j].second : node.domain.intervals[j].first;
      const Rational& edge = upper ? domain.intervals[j].second : domain.intervals[j].first;
      const double inside = 0.9 * std::abs(to_mpq(edge - at).get_d()) * std::abs(along);
      if (inside >= node.slabs.hi_at[i] - node.slabs.lo_at[i]) continue;
      if (!continues_in_frame(ctx, node, j, to_mpq(edge).get_d(), upper, frame, h, params)) continue;
      // Only down to 1/32 of D along the edge: where the edge bends sharply or X is
      // singular Z beside a node is within reach of X(D) itself, and no split helps.
      if (m == 2 && at == edge && 32 * (node.domain.intervals[1 - j].second - node.domain.intervals[1 - j].first) >
                                      domain.intervals[1 - j].second - domain.intervals[1 - j].first &&
          takes_in_beside(node, j, ctx.beyond[2 * j + (upper ? 1 : 0)], h, params)) {
        halve |= 1U << (1 - j);
      }
      // The face the side lies along: the lower one when w·X grows inward from it.
      const bool lower_face = (along > 0) != upper;
      ParameterDomain side = node.domain;
      side.intervals[j] = {at, at};
      const PatchBounds e =
          bound_patch(rotated(ctx.parametrization, node.slabs.w), side, ctx.budget, ctx.bounds_params);
      const double overshoot = lower_face ? to_mpq(e.hi[i]).get_d() - node.slabs.lo_at[i]
                                          : node.slabs.hi_at[i] - to_mpq(e.lo[i]).get_d();
      // A curve's side is a point: its tangent slab's overshoot shrinks with the node.
      if (!(overshoot <= allowed + inside)) halve |= m == 2 ? 1U << (1 - j) : 1U;
    }
  }
  return halve;
}

// The quadtree over `domain`, largest boxes split first so that the leaf cap leaves a
// uniform refinement behind: a node is split while its box is larger than
// params.tolerance·h and, widened by params.margin·h, may reach a far cell of `far`
// (none: nothing to trim against), or while it is a blunt edge (blunt_edge()).
std::vector<Node> refine_quadtree(const CoverContext& ctx, const ParameterDomain& domain, FarCellSearch* far,
                                  const Box& frame, double h, const PatchCoverParams& params, PatchCoverStats& stats) {
  std::vector<Node> nodes{make_node(ctx, domain)};
  const auto smaller = [&](std::size_t a, std::size_t b) { return nodes[a].largest_side < nodes[b].largest_side; };
  std::priority_queue<std::size_t, std::vector<std::size_t>, decltype(smaller)> open(smaller);
  open.push(0);
  std::size_t leaves = 1;
  while (!open.empty()) {
    ctx.budget.check(kWhere);
    const std::size_t i = open.top();
    open.pop();
    const bool near_far = nodes[i].largest_side > params.tolerance * h && far != nullptr &&
                          far->reaches_far(widened(nodes[i].lo, nodes[i].hi, params.margin * h));
    const unsigned halve =
        near_far ? ~0U : (far != nullptr ? blunt_edge(ctx, nodes[i], domain, frame, h, params) : 0U);
    if (halve == 0) continue;
    const std::vector<ParameterDomain> halves = split_domain(nodes[i].domain, halve);
    if (leaves + halves.size() - 1 > params.max_leaves) {
      if (near_far) {
        ++stats.unresolved;
        stats.tolerance_reached = std::max(stats.tolerance_reached, nodes[i].largest_side / h);
      } else {
        ++stats.edge_unresolved;
      }
      continue;
    }
    for (const ParameterDomain& half : halves) {
      nodes[i].children.push_back(nodes.size());
      nodes.push_back(make_node(ctx, half));
      open.push(nodes.size() - 1);
    }
    leaves += halves.size() - 1;
  }
  return nodes;
}

}  // namespace

PatchCover PatchCover::build(const Parametrization& parametrization, const ParameterDomain& domain,
                             const Polynomial& equation, const SceneBox& frame_box, const Budget& budget,
                             const PatchCoverParams& params) {
  PatchCover cover;
  PatchCoverStats& stats = cover.stats_;
  const bool plane_curve = parametrization.coordinates.size() == 2;
  Box frame;
  double h = 0;
  for (std::size_t i = 0; i < 3; ++i) {
    component(frame.lo, i) = round_down<double>(frame_box.lo[i]);
    component(frame.hi, i) = round_up<double>(frame_box.hi[i]);
    h = std::max(h, (component(frame.hi, i) - component(frame.lo, i)) / 2);
  }
  if (plane_curve) frame.lo.z = frame.hi.z = 0;

  const std::optional<SafeSdf> safe = safe_bound_around(equation, frame_box, h, budget);
  stats.proven_empty_cells = safe.has_value();

  // Far cells. The sample points carry the rounding of a double evaluation of the
  // parametrization (relative 1e-12 is far above it for the bench's degrees); the
  // reach is shrunk by that much, relative to the patch's size.
  const double reach = params.reach * h;
  const std::vector<V> points = sample_patch(parametrization, domain, reach / 4, budget);
  stats.sample_points = points.size();
  double extent = 0;
  for (const V& p : points) extent = std::max({extent, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  const PointGrid sample(points, reach / 2);
  const CoverContext coarse_ctx{parametrization, DoublePatch(parametrization, budget), budget,
                                {0, PatchBoundsParams().max_denominator_depth}, domain};
  const Node hull = make_node(coarse_ctx, domain, false);
  // Every node box lies in the Bernstein hull of D (de Casteljau's control points
  // are convex combinations of the parent's), so far cells beyond it cannot matter.
  Box region = widened(hull.lo, hull.hi, 2 * params.margin * h);
  for (std::size_t i = 0; i < 3; ++i) {
    component(region.lo, i) = std::max(component(region.lo, i), component(frame.lo, i));
    component(region.hi, i) = std::min(component(region.hi, i), component(frame.hi, i));
  }
  // A patch entirely outside the frame box has no far cells: nothing of Z is drawn.
  const bool searched = region.lo.x <= region.hi.x && region.lo.y <= region.hi.y && region.lo.z <= region.hi.z;
  FarCellSearch far(region, safe, sample, reach - 1e-12 * std::max(extent, h), params.resolution * h, budget, params,
                    stats);

  CoverContext ctx{parametrization, DoublePatch(parametrization, budget), budget,
                   {params.tightening_depth, PatchBoundsParams().max_denominator_depth}, domain};
  if (domain.intervals.size() == 2 && searched) ctx.beyond = beside_edges(ctx, frame, h, params);
  const std::vector<Node> nodes = refine_quadtree(ctx, domain, searched ? &far : nullptr, frame, h, params, stats);
  stats.nodes = nodes.size();

  // The leaves in depth-first order, clusters of cluster_size, the last one padded.
  std::vector<std::size_t> order = leaves_in_order(nodes);
  stats.leaves = order.size();
  for (std::size_t i : order) stats.box_leaves += nodes[i].slabs.used ? 0 : 1;
  cover.cluster_size_ = params.cluster_size;
  if (cover.cluster_size_ == 0) {
    cover.cluster_size_ = static_cast<std::size_t>(std::ceil(std::sqrt(static_cast<double>(order.size()))));
  }
  const std::size_t k = cover.cluster_size_;
  while (order.size() % k != 0) order.push_back(order.back());
  stats.clusters = order.size() / k;
  double point_extent = 0;
  for (std::size_t c = 0; c < stats.clusters; ++c) {
    Vec3<float> clo = nodes[order[c * k]].lo, chi = nodes[order[c * k]].hi;
    for (std::size_t j = c * k; j < (c + 1) * k; ++j) {
      const Node& n = nodes[order[j]];
      cover.float_.lo.push_back(n.lo);
      cover.float_.hi.push_back(n.hi);
      cover.float_.w0.push_back(n.slabs.w[0]);
      cover.float_.w1.push_back(n.slabs.w[1]);
      cover.float_.w2.push_back(n.slabs.w[2]);
      cover.float_.slab_lo.push_back(n.slabs.lo);
      cover.float_.slab_hi.push_back(n.slabs.hi);
      clo = {std::min(clo.x, n.lo.x), std::min(clo.y, n.lo.y), std::min(clo.z, n.lo.z)};
      chi = {std::max(chi.x, n.hi.x), std::max(chi.y, n.hi.y), std::max(chi.z, n.hi.z)};
    }
    cover.float_.cluster_lo.push_back(clo);
    cover.float_.cluster_hi.push_back(chi);
    // The cluster's middle leaf's centre: central in the cluster, so the seed is near
    // wherever the cluster is.
    const V x = ctx.patch.at(centre_of(nodes[order[c * k + k / 2]].domain));
    if (std::isfinite(x.x) && std::isfinite(x.y) && std::isfinite(x.z) &&
        std::max({std::abs(x.x), std::abs(x.y), std::abs(x.z)}) < kClamp) {
      cover.float_.cluster_point.push_back({static_cast<float>(x.x), static_cast<float>(x.y), static_cast<float>(x.z)});
      point_extent = std::max({point_extent, std::abs(x.x), std::abs(x.y), std::abs(x.z)});
    }
  }
  // The points' rounding, e <= √3·2^-24 of the points' extent M (the double
  // evaluation's 1e-12 is far below): with a the distance to the exact point,
  // (a − e)²·kSeedScale + E² >= a² for every a once (E/e)² exceeds about 3·2^10,
  // so E = 2^-16·M, the seed staying above the squared distance to the leaves' hull.
  cover.float_.seed_margin =
      static_cast<float>(std::min(std::pow(std::ldexp(point_extent, -16), 2), kFarSquared));
  cover.copy_boxes_to_double();
  return cover;
}

void PatchCover::copy_boxes_to_double() {
  // The same float corners (exact in double), so both evaluations bound the distance
  // to the same union.
  const auto to_double = [](const std::vector<Vec3<float>>& v) {
    std::vector<Vec3<double>> out;
    for (const auto& p : v) out.push_back({p.x, p.y, p.z});
    return out;
  };
  double_.lo = to_double(float_.lo);
  double_.hi = to_double(float_.hi);
  double_.w0 = to_double(float_.w0);
  double_.w1 = to_double(float_.w1);
  double_.w2 = to_double(float_.w2);
  double_.slab_lo = to_double(float_.slab_lo);
  double_.slab_hi = to_double(float_.slab_hi);
  float_.slack = static_cast<float>(kSlabSlack);
  double_.slack = kSlabSlackDouble;
  double_.cluster_lo = to_double(float_.cluster_lo);
  double_.cluster_hi = to_double(float_.cluster_hi);
  double_.cluster_point = to_double(float_.cluster_point);
  double_.seed_margin = float_.seed_margin;
  float_.hull_lo = lo();
  float_.hull_hi = hi();
  double_.hull_lo = {float_.hull_lo.x, float_.hull_lo.y, float_.hull_lo.z};
  double_.hull_hi = {float_.hull_hi.x, float_.hull_hi.y, float_.hull_hi.z};
  float_.shrink = 1.0f - 0x1p-17f;
  double_.shrink = 1.0 - 0x1p-46;
}

Vec3<float> PatchCover::lo() const {
  Vec3<float> out = float_.cluster_lo.front();
  for (const auto& p : float_.cluster_lo) out = {std::min(out.x, p.x), std::min(out.y, p.y), std::min(out.z, p.z)};
  return out;
}

Vec3<float> PatchCover::hi() const {
  Vec3<float> out = float_.cluster_hi.front();
  for (const auto& p : float_.cluster_hi) out = {std::max(out.x, p.x), std::max(out.y, p.y), std::max(out.z, p.z)};
  return out;
}

namespace {

std::string vec3_literal(const Vec3<float>& v);

}  // namespace

std::string PatchCover::hull_glsl(const std::string& p) const {
  // squared_distance's steps: the larger overshoot per axis, clamped to [0, kClamp].
  const std::string q = "min(max(max(" + vec3_literal(float_.hull_lo) + " - " + p + ", " + p + " - " +
                        vec3_literal(float_.hull_hi) + "), 0.0), " + format_glsl_float(float(kClamp)) + ")";
  return "sqrt(dot(" + q + ", " + q + ")) * " +
         format_glsl_float(static_cast<float>(float_.shrink * static_cast<float>(kHullShrink)));
}

namespace {

std::string vec3_literal(const Vec3<float>& v) {
  return "vec3(" + format_glsl_float(v.x) + ", " + format_glsl_float(v.y) + ", " + format_glsl_float(v.z) + ")";
}

}  // namespace

std::string PatchCover::to_glsl(const std::string& function) const {
  // The walk of distance_lower_bound() unrolled, the boxes and slabs as literals: a
  // GPU indexing a constant array by a loop counter may copy the whole array for every
  // call (SwiftShader does: docs/sdf.md, "A browser frame"), which costs more than
  // the boxes' arithmetic. The padding of the last cluster repeats a leaf, and a
  // repeated min changes nothing, so it is left out; a leaf without slabs is its box.
  const std::string f = function;
  const std::size_t clusters = float_.cluster_lo.size();
  std::string out =
      "// The distance to " + std::to_string(stats_.leaves) + " leaves covering the patch (" +
      std::to_string(clusters) + " clusters of up to " + std::to_string(cluster_size_) +
      "): each a box and three slabs around its piece, rounded down; at least |d|.\n"
      "float " + f + "_d2(vec3 p, vec3 lo, vec3 hi) {\n"
      "  vec3 m = min(max(max(lo - p, p - hi), 0.0), vec3(" + format_glsl_float(static_cast<float>(kClamp)) + "));\n"
      "  return m.x * m.x + m.y * m.y + m.z * m.z;\n"
      "}\n"
      "float " + f + "_s2(vec3 p, vec3 s) {\n"
      "  vec3 q = p - s;\n"
      "  return q.x * q.x + q.y * q.y + q.z * q.z;\n"
      "}\n"
      "float " + f + "_leaf(vec3 p, float best, vec3 lo, vec3 hi, vec3 w0, vec3 w1, vec3 w2, vec3 slo, vec3 shi) {\n"
      "  float a = " + f + "_d2(p, lo, hi);\n"
      "  vec3 d = p - lo;\n"
      "  vec3 q = vec3(dot(d, w0), dot(d, w1), dot(d, w2));\n"
      "  vec3 s = max(slo - q, q - shi);\n"
      "  float t = max(max(max(s.x, s.y), s.z) - " + format_glsl_float(float_.slack) +
      " * max(max(abs(d.x), abs(d.y)), abs(d.z)), 0.0);\n"
      "  return min(best, max(a, t * t));\n"
      "}\n"
      "float " + f + "(vec3 p, float d) {\n"
      "  float ad = abs(d);\n"
      "  float d2 = ad * ad;\n"
      "  float best = " + format_glsl_float(static_cast<float>(kFarSquared)) + ";\n";
  for (const Vec3<float>& s : float_.cluster_point) {
    out += "  best = min(best, " + f + "_s2(p, " + vec3_literal(s) + "));\n";
  }
  out += "  best = best * " + format_glsl_float(static_cast<float>(kSeedScale)) + " + " +
         format_glsl_float(float_.seed_margin) + ";\n"
         "  if (best <= d2) return ad;\n";
  const auto zero = [](const Vec3<float>& v) { return v.x == 0 && v.y == 0 && v.z == 0; };
  for (std::size_t c = 0; c < clusters; ++c) {
    out += "  if (" + f + "_d2(p, " + vec3_literal(float_.cluster_lo[c]) + ", " + vec3_literal(float_.cluster_hi[c]) +
           ") < best) {\n";
    for (std::size_t j = c * cluster_size_; j < std::min((c + 1) * cluster_size_, stats_.leaves); ++j) {
      if (!(zero(float_.w0[j]) && zero(float_.w1[j]) && zero(float_.w2[j]))) {
        out += "    best = " + f + "_leaf(p, best, " + vec3_literal(float_.lo[j]) + ", " + vec3_literal(float_.hi[j]) +
               ", " + vec3_literal(float_.w0[j]) + ", " + vec3_literal(float_.w1[j]) + ", " +
               vec3_literal(float_.w2[j]) + ", " + vec3_literal(float_.slab_lo[j]) + ", " +
               vec3_literal(float_.slab_hi[j]) + ");\n";
      } else {
        out += "    best = min(best, " + f + "_d2(p, " + vec3_literal(float_.lo[j]) + ", " +
               vec3_literal(float_.hi[j]) + "));\n";
      }
    }
    out += "    if (best <= d2) return ad;\n  }\n";
  }
  return out + "  return max(ad, sqrt(best) * " + format_glsl_float(float_.shrink) + ");\n}\n";
}

}  // namespace implicitizer
