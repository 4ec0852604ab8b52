#include "implicitizer/render/root_isolation.hpp"

#include <flint/fmpz.h>
#include <flint/fmpz_poly.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <string>

#include "dyadic.hpp"
#include "implicitizer/core/errors.hpp"

namespace implicitizer {

namespace {

constexpr double kUnitRoundoff = std::numeric_limits<double>::epsilon() / 2;

// γ_k = k·u / (1 − k·u): the relative error of k roundings (Higham, Lemma 3.1).
double gamma_of(double k) { return k * kUnitRoundoff / (1 - k * kUnitRoundoff); }

// ---------------------------------------------------------------------------------
// Double path.

// One subinterval [s_lo, s_lo + 2^-level] of an expansion segment [t0, t1] (the
// segment's parameter s ∈ [0, 1]), with Bernstein coefficients b_j, the majorant's
// m_j, and the bound |computed b_j − exact b_j| ≤ ε·m_j + band (stored in the pool).
struct Node {
  double t0 = 0, t1 = 0;
  double s_lo = 0;
  int level = 0;
  double epsilon = 0;
  double band = 0;
};

// A node whose signs stay uncertain is re-expanded on its own piece of the ray (a
// local majorant, see ray_polynomial.hpp) once it is a quarter of its expansion's
// segment; at most this many times per ray (each costs O(terms·n)).
constexpr int kMaxReexpansions = 16;

// Per-thread buffers: a render calls this per ray, so nothing is allocated once
// they have grown to the degree.
struct BernsteinWorkspace {
  std::size_t degree = 0;
  std::vector<double> ratios;  // r[j(n+1)+k] = C(j,k)/C(n,k), k ≤ j
  std::vector<double> pool;    // stacked nodes' b, m (2(n+1) each)
  std::vector<Node> stack;
  std::vector<double> b, m, left_b, left_m;
  std::vector<int> signs;

  void prepare(std::size_t n) {
    if (degree == n && !ratios.empty()) return;
    degree = n;
    ratios.assign((n + 1) * (n + 1), 0.0);
    for (std::size_t j = 0; j <= n; ++j) {
      double r = 1;
      for (std::size_t k = 0; k <= j; ++k) {
        ratios[j * (n + 1) + k] = r;  // Π_{i<k} (j−i)/(n−i)
        if (k < j) r *= static_cast<double>(j - k) / static_cast<double>(n - k);
      }
    }
    for (auto* v : {&b, &m, &left_b, &left_m}) v->assign(n + 1, 0.0);
    signs.assign(n + 1, 0);
  }
};

// Signs the bounds certify: +1, −1, or 0 (|b_j| ≤ ε·m_j: either sign possible).
int certified_sign(double value, double bound) { return value > bound ? 1 : (value < -bound ? -1 : 0); }

// The largest number of sign variations of b over every choice of signs for the
// uncertain entries (signs[j] = 0). Descartes' rule bounds the roots in the open
// interval by the variations of the true coefficients, which lie in the bands.
int max_variations(const int* signs, std::size_t count) {
  int variations = 0;
  int last = 0;         // the last certified sign (0: none yet)
  std::size_t gap = 0;  // uncertain entries since it
  for (std::size_t j = 0; j < count; ++j) {
    if (signs[j] == 0) {
      ++gap;
      continue;
    }
    if (last == 0) {
      variations += static_cast<int>(gap);  // a free prefix alternates freely
    } else if (gap == 0) {
      variations += last != signs[j] ? 1 : 0;
    } else {
      // gap free signs between two fixed ones: gap + 1 changes when the parity fits.
      const bool differ = last != signs[j];
      const int most = static_cast<int>(gap) + 1;
      variations += (most % 2 == 1) == differ ? most : most - 1;
    }
    last = signs[j];
    gap = 0;
  }
  variations += static_cast<int>(gap) - (last == 0 && gap > 0 ? 1 : 0);
  return variations;
}

// Splits b, m at 1/2 (de Casteljau): the left half's coefficients into left_*,
// the right half's in place. After level r of the triangle, b[0] is the left half's
// coefficient r, and b[j] is never touched again once j > n − r, leaving it at level
// n − j: the right half's coefficient j.
void halve(std::vector<double>& b, std::vector<double>& m, std::vector<double>& left_b, std::vector<double>& left_m) {
  const std::size_t n = b.size() - 1;
  for (std::size_t r = 0; r <= n; ++r) {
    left_b[r] = b[0];
    left_m[r] = m[0];
    for (std::size_t j = 0; j + r < n; ++j) {
      b[j] = (b[j] + b[j + 1]) * 0.5;
      m[j] = (m[j] + m[j + 1]) * 0.5;
    }
  }
}

// q's Bernstein coefficients on [0, 1] into w.b and the majorant's into w.m:
// b_j = Σ_{k≤j} C(j,k)/C(n,k)·a_k, weights in [0, 1], so errors stay relative to the
// majorant's Bernstein coefficients. Returns ε with |b_j − exact| ≤ ε·m_j + band, or
// nothing when q is out of double's range or its majorant so small that halving
// would reach subnormals (where rounding is no longer relative).
std::optional<double> load_bernstein(const DoubleRayPolynomial& q, BernsteinWorkspace& w) {
  if (!q.finite) return std::nullopt;
  const std::size_t n = q.coefficients.size() - 1;
  double largest = 0;
  for (std::size_t j = 0; j <= n; ++j) {
    double value = 0, majorant = 0;
    const double* r = w.ratios.data() + j * (n + 1);
    for (std::size_t k = 0; k <= j; ++k) {
      value += r[k] * q.coefficients[k];
      majorant += r[k] * q.majorant[k];
    }
    w.b[j] = value;
    w.m[j] = majorant;
    largest = std::max(largest, majorant);
  }
  if (!(largest > 1e-250) || !std::isfinite(largest)) return std::nullopt;
  // Conversion: the ratios carry ≤ 2n roundings, products and the sum n + 1 more.
  const double dn = static_cast<double>(n);
  return (q.relative_error + 2 * gamma_of(3 * dn + 2)) * (1 + gamma_of(3 * dn + 2));
}

SegmentRootSearch undecided(FallbackReason reason, int subdivisions) {
  SegmentRootSearch out;
  out.outcome = SegmentRootSearch::Outcome::undecided;
  out.reason = reason;
  out.subdivisions = subdivisions;
  return out;
}

// Refines the single root in (lo, hi) (t values; sign(F) = sign_lo at lo, −sign_lo at
// hi, certified). Newton's method in a bracket: a step that leaves the bracket is
// replaced by bisection; every evaluation whose sign the point bound certifies
// shrinks the bracket; near convergence the two points x ± 0.45·tolerance are probed,
// so the bracket ends at most 0.9·tolerance wide. An evaluation that the bound cannot
// sign while the bracket is still wider than that means double cannot pin the root:
// ill-conditioned (std::nullopt).
std::optional<double> refine_on_ray(const RayPolynomialContext& context, const RaySegment& segment, double lo,
                                    double hi, int sign_lo, const RootIsolationParams& options) {
  // The answer (lo + hi)/2 is within (hi − lo)/2 of the root, which is ≥ lo: the
  // bracket is narrow enough at 2·tolerance_at(lo). Probes are placed by the
  // tolerance at the candidate, shrunk by (1 − rel) so that the bracket they leave
  // passes that test.
  auto tolerance_at = [&](double t) { return options.relative_tolerance * std::max(options.scale, t); };
  auto narrow_enough = [&] { return hi - lo <= 2 * tolerance_at(lo); };
  auto signed_value = [&](double t, double& newton) {
    const RayPointValue p = context.evaluate_double(segment.origin, segment.direction, t);
    newton = p.derivative != 0 ? -p.value / p.derivative : std::numeric_limits<double>::quiet_NaN();
    return certified_sign(p.value, p.error);
  };
  auto narrow = [&](double t, int sign) {
    if (sign == sign_lo) {
      lo = std::max(lo, t);
    } else if (sign != 0) {
      hi = std::min(hi, t);
    }
  };
  double t = 0.5 * (lo + hi);
  for (int iteration = 0; iteration < 200; ++iteration) {
    if (narrow_enough()) return 0.5 * (lo + hi);
    double step = 0;
    const int sign = signed_value(t, step);
    narrow(t, sign);
    if (narrow_enough()) return 0.5 * (lo + hi);
    double next = t + step;
    if (sign == 0 || (std::isfinite(next) && std::fabs(step) <= 0.5 * tolerance_at(next))) {
      const double centre = sign == 0 ? t : next;
      const double delta = 0.45 * tolerance_at(centre) * (1 - options.relative_tolerance);
      const double below_t = std::max(lo, centre - delta), above_t = std::min(hi, centre + delta);
      double ignored = 0;
      const int below = signed_value(below_t, ignored);
      const int above = signed_value(above_t, ignored);
      narrow(below_t, below);
      narrow(above_t, above);
      if (narrow_enough()) return 0.5 * (lo + hi);
      if (below == 0 || above == 0) return std::nullopt;  // the root hides in the noise
      next = 0.5 * (lo + hi);
    } else if (!(next > lo && next < hi)) {
      next = 0.5 * (lo + hi);
    }
    t = next;
  }
  return std::nullopt;
}

// ---------------------------------------------------------------------------------
// Exact path.

using render_detail::add;
using render_detail::Dyadic;
using render_detail::Fmpz;
using render_detail::FmpzPoly;
using render_detail::multiply;
using render_detail::negate;

// Sign variations of p's coefficients, zeros skipped.
int sign_variations(const fmpz_poly_struct* p) {
  int variations = 0, last = 0;
  for (slong i = 0; i < fmpz_poly_length(p); ++i) {
    const int s = fmpz_sgn(p->coeffs + i);
    if (s == 0) continue;
    if (last != 0 && s != last) ++variations;
    last = s;
  }
  return variations;
}

// Descartes' bound for the roots of Q in (0, 1): the variations of
// (x + 1)^n Q(1/(x + 1)), which maps (0, 1) onto (0, ∞) (Vincent's transform).
int descartes_bound(const fmpz_poly_struct* q, FmpzPoly& scratch) {
  fmpz_poly_reverse(scratch.get(), q, fmpz_poly_length(q));
  Fmpz one;
  fmpz_one(one.get());
  fmpz_poly_taylor_shift(scratch.get(), scratch.get(), one.get());
  return sign_variations(scratch.get());
}

// Divides p by the gcd of its coefficients (keeps the integers small; signs unchanged).
void remove_content(fmpz_poly_struct* p) {
  Fmpz content;
  fmpz_poly_content(content.get(), p);
  if (!fmpz_is_zero(content.get()) && !fmpz_is_one(content.get())) {
    fmpz_poly_scalar_divexact_fmpz(p, p, content.get());
  }
}

// sign(p(a / 2^m)), from 2^(m·n)·p(a/2^m) = Σ p_i a^i 2^(m(n−i)) by Horner.
int sign_at(const fmpz_poly_struct* p, const fmpz* a, ulong m, Fmpz& value, Fmpz& term) {
  const slong n = fmpz_poly_degree(p);
  fmpz_set(value.get(), p->coeffs + n);
  for (slong i = n - 1; i >= 0; --i) {
    fmpz_mul(value.get(), value.get(), a);
    fmpz_mul_2exp(term.get(), p->coeffs + i, m * static_cast<ulong>(n - i));
    fmpz_add(value.get(), value.get(), term.get());
  }
  return fmpz_sgn(value.get());
}

// One item of the depth-first search: a node Q on (c/2^k, (c+1)/2^k), Q(x) a positive
// multiple of p((c + x)/2^k), or the marker of a node's midpoint, visited after its
// left half and before its right half.
struct ExactItem {
  FmpzPoly polynomial;
  Fmpz c;
  ulong k = 0;
  bool is_midpoint = false;
  bool midpoint_is_root = false;
};

// t_begin + width·(a / 2^m), exactly, rounded to double.
double parameter_at(const Dyadic& begin, const Dyadic& width, const fmpz* a, ulong m) {
  Dyadic x;
  fmpz_set(x.mantissa.get(), a);
  x.exponent = -static_cast<slong>(m);
  return add(begin, multiply(width, x)).to_double();
}

SegmentRootSearch root_at(double t, int subdivisions) {
  SegmentRootSearch out;
  out.outcome = SegmentRootSearch::Outcome::root;
  out.t = t;
  out.subdivisions = subdivisions;
  return out;
}

// ---------------------------------------------------------------------------------
// Input checks.

InputError invalid_ray(const std::string& field, const std::string& message) {
  return InputError("invalid_ray", message).in_field(field);
}

void validate(const std::array<double, 3>& origin, const std::array<double, 3>& direction, double t_min, double t_max,
              const RootIsolationParams& options) {
  for (double x : origin) {
    if (!std::isfinite(x)) throw invalid_ray("origin", "the ray's origin must be finite");
  }
  bool nonzero = false;
  for (double x : direction) {
    if (!std::isfinite(x)) throw invalid_ray("direction", "the ray's direction must be finite");
    nonzero = nonzero || x != 0;
  }
  if (!nonzero) throw invalid_ray("direction", "the ray's direction must not be zero");
  if (!std::isfinite(t_min) || t_min < 0) throw invalid_ray("t_min", "t_min must be finite and at least 0");
  if (!std::isfinite(t_max) || t_max < t_min) throw invalid_ray("t_max", "t_max must be finite and at least t_min");
  if (!(options.relative_tolerance >= 1e-15 && options.relative_tolerance <= 1e-1)) {
    throw InputError("invalid_value", "the relative tolerance must be in [1e-15, 1e-1]").in_field("relative_tolerance");
  }
  if (!(std::isfinite(options.scale) && options.scale > 0)) {
    throw InputError("invalid_value", "the tolerance's scale must be positive and finite").in_field("scale");
  }
  if (options.max_subdivisions < 1) {
    throw InputError("invalid_value", "max_subdivisions must be at least 1").in_field("max_subdivisions");
  }
}

}  // namespace

const char* to_string(RootPath path) { return path == RootPath::exact ? "exact" : "double"; }

const char* to_string(FallbackReason reason) {
  switch (reason) {
    case FallbackReason::none:
      return "none";
    case FallbackReason::out_of_range:
      return "out_of_range";
    case FallbackReason::uncertain_sign:
      return "uncertain_sign";
    case FallbackReason::root_cluster:
      return "root_cluster";
    case FallbackReason::ill_conditioned_root:
      return "ill_conditioned_root";
    case FallbackReason::subdivision_limit:
      return "subdivision_limit";
  }
  return "none";
}

void RootIsolationStats::add(const RootIsolationStats& other) {
  rays += other.rays;
  hits += other.hits;
  exact_rays += other.exact_rays;
  double_subdivisions += other.double_subdivisions;
  exact_subdivisions += other.exact_subdivisions;
  for (std::size_t i = 0; i < kFallbackReasons; ++i) fallbacks[i] += other.fallbacks[i];
}

namespace {

// What the certified signs of a node's Bernstein coefficients say.
struct NodeSigns {
  bool all_same = true;  ///< every sign certain and equal: no root on the node
  bool certain = true;   ///< no sign is uncertain
};

// Fills signs[j] with the certified sign of b_j (0 where the error bound covers 0).
NodeSigns certified_signs(const std::vector<double>& b, const std::vector<double>& m, const Node& node,
                          std::vector<int>& signs) {
  NodeSigns out;
  for (std::size_t j = 0; j < b.size(); ++j) {
    signs[j] = certified_sign(b[j], node.epsilon * m[j] * (1 + 4 * kUnitRoundoff) + node.band);
    if (signs[j] == 0 || signs[j] != signs[0]) out.all_same = false;
    out.certain = out.certain && signs[j] != 0;
  }
  return out;
}

}  // namespace

// Longer than a screen: each node's decisions (no root, one root to refine, a cluster,
// re-expansion, halving) share the node's state and the workspace's stack, and read
// best in the one loop that makes them, in the order they are tried.
SegmentRootSearch isolate_first_root_bernstein(const RayPolynomialContext& context, const RaySegment& segment,
                                               const DoubleRayPolynomial& q, const RootIsolationParams& options) {
  const std::size_t n = q.coefficients.size() - 1;
  const std::size_t size = n + 1;
  thread_local BernsteinWorkspace w;
  w.prepare(n);
  thread_local DoubleRayPolynomial local;
  const std::optional<double> epsilon0 = load_bernstein(q, w);
  if (!epsilon0) return undecided(FallbackReason::out_of_range, 0);
  // Each halving: n levels of one rounded sum, in b and in m alike.
  const double epsilon_step = 2 * gamma_of(static_cast<double>(n) + 1);

  std::vector<int>& signs = w.signs;
  w.stack.clear();
  w.pool.clear();
  auto push = [&](const Node& node, const std::vector<double>& b, const std::vector<double>& m) {
    w.stack.push_back(node);
    w.pool.insert(w.pool.end(), b.begin(), b.end());
    w.pool.insert(w.pool.end(), m.begin(), m.end());
  };
  push(Node{segment.t_begin, segment.t_end, 0, 0, *epsilon0, q.band}, w.b, w.m);
  int subdivisions = 0, reexpansions = 0;
  while (!w.stack.empty()) {
    const Node node = w.stack.back();
    w.stack.pop_back();
    const std::size_t offset = w.pool.size() - 2 * size;
    std::copy(w.pool.begin() + static_cast<std::ptrdiff_t>(offset),
              w.pool.begin() + static_cast<std::ptrdiff_t>(offset + size), w.b.begin());
    std::copy(w.pool.begin() + static_cast<std::ptrdiff_t>(offset + size), w.pool.end(), w.m.begin());
    w.pool.resize(offset);

    const NodeSigns node_signs = certified_signs(w.b, w.m, node, signs);
    if (node_signs.all_same) continue;  // q has the sign of every b_j on the node: no root
    const bool certain = node_signs.certain;
    const double width = node.t1 - node.t0;
    const double node_width = std::ldexp(1.0, -node.level);
    const double t_lo = node.t0 + width * node.s_lo;
    const double t_hi = node.s_lo + node_width >= 1 ? node.t1 : node.t0 + width * (node.s_lo + node_width);
    const double tolerance_t = options.relative_tolerance * std::max(options.scale, t_lo);
    const int variations = max_variations(signs.data(), size);
    if (variations == 1 && signs[0] != 0 && signs[n] == -signs[0]) {
      // Exactly one root in the node: Descartes' bound is 1 and the ends differ.
      const std::optional<double> t = refine_on_ray(context, segment, t_lo, t_hi, signs[0], options);
      if (!t) return undecided(FallbackReason::ill_conditioned_root, subdivisions);
      SegmentRootSearch out;
      out.outcome = SegmentRootSearch::Outcome::root;
      out.t = *t;
      out.subdivisions = subdivisions;
      return out;
    }
    if (width * node_width <= tolerance_t) {
      return undecided(certain ? FallbackReason::root_cluster : FallbackReason::uncertain_sign, subdivisions);
    }
    if (subdivisions >= options.max_subdivisions) return undecided(FallbackReason::subdivision_limit, subdivisions);
    ++subdivisions;
    if (!certain && node.level >= 2 && reexpansions < kMaxReexpansions) {
      // Re-expand on a piece of the ray that contains the node: its ends rounded
      // outwards (t ≥ 0, each end within 3 ulps), clamped to the segment.
      ++reexpansions;
      const double t_a = std::max(segment.t_begin, t_lo * (1 - 4 * kUnitRoundoff));
      const double t_b = std::min(segment.t_end, t_hi * (1 + 4 * kUnitRoundoff));
      context.expand_double(RaySegment{segment.origin, segment.direction, t_a, t_b}, local);
      const std::optional<double> epsilon = load_bernstein(local, w);
      if (!epsilon) return undecided(FallbackReason::out_of_range, subdivisions);
      push(Node{t_a, t_b, 0, 0, *epsilon, local.band}, w.b, w.m);
      continue;
    }
    halve(w.b, w.m, w.left_b, w.left_m);
    const double epsilon = node.epsilon + epsilon_step;
    const int level = node.level + 1;
    push(Node{node.t0, node.t1, node.s_lo + 0.5 * node_width, level, epsilon, node.band}, w.b, w.m);
    push(Node{node.t0, node.t1, node.s_lo, level, epsilon, node.band}, w.left_b, w.left_m);
  }
  SegmentRootSearch out;
  out.outcome = SegmentRootSearch::Outcome::no_root;
  out.subdivisions = subdivisions;
  return out;
}

namespace {

// The square-free part of q(s) = Σ q_k s^k, primitive: p / gcd(p, p') has the same
// roots, all simple, so every root is a sign change (a tangent ray's double root
// included). Sets `p` to it.
void set_square_free_part(FmpzPoly& p, const std::vector<Integer>& q) {
  Fmpz c;
  for (std::size_t k = 0; k < q.size(); ++k) {
    fmpz_set_mpz(c.get(), q[k].get_mpz_t());
    fmpz_poly_set_coeff_fmpz(p.get(), static_cast<slong>(k), c.get());
  }
  if (fmpz_poly_degree(p.get()) < 1) return;
  FmpzPoly derivative, divisor;
  fmpz_poly_derivative(derivative.get(), p.get());
  fmpz_poly_gcd(divisor.get(), p.get(), derivative.get());
  if (fmpz_poly_degree(divisor.get()) > 0) fmpz_poly_div(p.get(), p.get(), divisor.get());
  remove_content(p.get());
}

// The parameter interval of the search: t = begin + width·s for s in [0, 1].
struct ExactInterval {
  Dyadic begin;
  Dyadic width;
  double width_t = 0;
};

// One simple root of p in (c/2^k, (c+1)/2^k) and p(c/2^k) ≠ 0 (checked on the way
// there): bisects on the sign of p until the interval is below 2·tolerance.
SegmentRootSearch bisect_simple_root(const fmpz_poly_struct* p, const ExactItem& item, const ExactInterval& interval,
                                     const RootIsolationParams& options, const Budget& budget, int subdivisions) {
  Fmpz a, next, value, term;
  fmpz_set(a.get(), item.c.get());
  ulong m = item.k;
  const int sign_lo = sign_at(p, a.get(), m, value, term);
  for (;;) {
    const double t_lo = parameter_at(interval.begin, interval.width, a.get(), m);
    const double tolerance_t = options.relative_tolerance * std::max(options.scale, t_lo);
    if (interval.width_t * std::ldexp(1.0, -static_cast<int>(m)) <= 1.9 * tolerance_t) break;
    budget.check("isolate_first_root_descartes");
    ++subdivisions;
    fmpz_mul_2exp(next.get(), a.get(), 1);
    fmpz_add_ui(next.get(), next.get(), 1);  // the midpoint (2a + 1)/2^(m+1)
    ++m;
    const int sign = sign_at(p, next.get(), m, value, term);
    if (sign == 0) return root_at(parameter_at(interval.begin, interval.width, next.get(), m), subdivisions);
    fmpz_mul_2exp(a.get(), a.get(), 1);
    if (sign == sign_lo) fmpz_set(a.get(), next.get());
  }
  fmpz_mul_2exp(next.get(), a.get(), 1);
  fmpz_add_ui(next.get(), next.get(), 1);
  return root_at(parameter_at(interval.begin, interval.width, next.get(), m + 1), subdivisions);
}

// Halves `item` onto the stack, to be taken left half first, then its midpoint, then
// the right half: Q_L(x) = 2^n Q(x/2), Q_R(x) = Q_L(x + 1).
void push_halves(const ExactItem& item, std::vector<std::unique_ptr<ExactItem>>& stack) {
  const fmpz_poly_struct* node = item.polynomial.get();
  const slong n = fmpz_poly_degree(node);
  auto left = std::make_unique<ExactItem>();
  auto right = std::make_unique<ExactItem>();
  auto midpoint = std::make_unique<ExactItem>();
  fmpz_poly_set(left->polynomial.get(), node);
  for (slong i = 0; i < n; ++i) {
    fmpz_mul_2exp(left->polynomial.get()->coeffs + i, left->polynomial.get()->coeffs + i, static_cast<ulong>(n - i));
  }
  remove_content(left->polynomial.get());
  Fmpz one;
  fmpz_one(one.get());
  fmpz_poly_taylor_shift(right->polynomial.get(), left->polynomial.get(), one.get());
  midpoint->is_midpoint = true;
  midpoint->midpoint_is_root = fmpz_is_zero(right->polynomial.get()->coeffs);
  if (midpoint->midpoint_is_root) fmpz_poly_shift_right(right->polynomial.get(), right->polynomial.get(), 1);
  fmpz_mul_2exp(left->c.get(), item.c.get(), 1);
  fmpz_add_ui(right->c.get(), left->c.get(), 1);
  fmpz_set(midpoint->c.get(), item.c.get());
  left->k = right->k = item.k + 1;
  midpoint->k = item.k;
  stack.push_back(std::move(right));
  stack.push_back(std::move(midpoint));
  stack.push_back(std::move(left));
}

}  // namespace

SegmentRootSearch isolate_first_root_descartes(const std::vector<Integer>& q, double t_begin, double t_end,
                                               const RootIsolationParams& options, const Budget& budget) {
  if (q.empty() || sgn(q.front()) == 0) return root_at(t_begin, 0);  // q ≡ 0 or q(0) = 0
  FmpzPoly p;
  set_square_free_part(p, q);
  SegmentRootSearch none;
  none.outcome = SegmentRootSearch::Outcome::no_root;
  if (fmpz_poly_degree(p.get()) < 1) return none;  // a nonzero constant
  ExactInterval interval{Dyadic::of(t_begin), {}, t_end - t_begin};
  interval.width = add(Dyadic::of(t_end), negate(interval.begin));
  int subdivisions = 0;
  FmpzPoly scratch;

  std::vector<std::unique_ptr<ExactItem>> stack;
  stack.push_back(std::make_unique<ExactItem>());
  fmpz_poly_set(stack.back()->polynomial.get(), p.get());
  while (!stack.empty()) {
    budget.check("isolate_first_root_descartes");
    const std::unique_ptr<ExactItem> item = std::move(stack.back());
    stack.pop_back();
    if (item->is_midpoint) {
      if (!item->midpoint_is_root) continue;
      Fmpz numerator;
      fmpz_mul_2exp(numerator.get(), item->c.get(), 1);
      fmpz_add_ui(numerator.get(), numerator.get(), 1);
      return root_at(parameter_at(interval.begin, interval.width, numerator.get(), item->k + 1), subdivisions);
    }
    const int bound = descartes_bound(item->polynomial.get(), scratch);
    if (bound == 0) continue;
    if (bound == 1) return bisect_simple_root(p.get(), *item, interval, options, budget, subdivisions);
    ++subdivisions;  // two or more roots: halve
    push_halves(*item, stack);
  }
  // No root in [0, 1): the last candidate is s = 1.
  Fmpz sum;
  for (slong i = 0; i < fmpz_poly_length(p.get()); ++i) fmpz_add(sum.get(), sum.get(), p.get()->coeffs + i);
  if (fmpz_is_zero(sum.get())) return root_at(t_end, subdivisions);
  none.subdivisions = subdivisions;
  return none;
}

std::optional<RayRoot> first_ray_root(const RayPolynomialContext& context, const std::array<double, 3>& origin,
                                      const std::array<double, 3>& direction, double t_min, double t_max,
                                      const RootIsolationParams& options, RootIsolationStats* stats,
                                      const Budget& budget) {
  validate(origin, direction, t_min, t_max, options);
  const RaySegment segment{origin, direction, t_min, t_max};
  RayRoot root;
  SegmentRootSearch search;
  if (options.method == RootMethod::automatic) {
    thread_local DoubleRayPolynomial q;
    context.expand_double(segment, q);
    search = isolate_first_root_bernstein(context, segment, q, options);
    root.subdivisions = search.subdivisions;
    if (stats != nullptr) stats->double_subdivisions += static_cast<std::size_t>(search.subdivisions);
  }
  if (options.method == RootMethod::exact || search.outcome == SegmentRootSearch::Outcome::undecided) {
    root.path = RootPath::exact;
    root.fallback = search.reason;
    search = isolate_first_root_descartes(context.expand_exact(segment, budget), t_min, t_max, options, budget);
    root.subdivisions += search.subdivisions;
    if (stats != nullptr) {
      ++stats->exact_rays;
      ++stats->fallbacks[static_cast<std::size_t>(root.fallback)];
      stats->exact_subdivisions += static_cast<std::size_t>(search.subdivisions);
    }
  }
  if (stats != nullptr) ++stats->rays;
  if (search.outcome != SegmentRootSearch::Outcome::root) return std::nullopt;
  if (stats != nullptr) ++stats->hits;
  // Rounding may step a root at an end of the segment just outside it.
  root.t = std::clamp(search.t, t_min, t_max);
  return root;
}

std::optional<RayRoot> first_ray_root(const Polynomial& f, const std::array<double, 3>& origin,
                                      const std::array<double, 3>& direction, double t_min, double t_max,
                                      const RootIsolationParams& options, RootIsolationStats* stats,
                                      const Budget& budget) {
  validate(origin, direction, t_min, t_max, options);
  return first_ray_root(RayPolynomialContext(f), origin, direction, t_min, t_max, options, stats, budget);
}

}  // namespace implicitizer
