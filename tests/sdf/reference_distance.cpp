#include "sdf/reference_distance.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <random>

#include "implicitizer/core/errors.hpp"
#include "implicitizer/polynomial/gcd.hpp"

// The file comment of reference_distance.hpp says what each step computes and why.

namespace implicitizer::testing {
namespace {

// Real roots in [a, b] of the polynomial Σ c[k]·t^k (c in long double), found
// between consecutive critical points (the roots of the derivative in [a, b],
// recursively): P is monotone between them, so a sign change there brackets
// exactly one root, which bisection then pins to long double precision. A root of
// even multiplicity shows no sign change: callers pass square-free polynomials.
// Sorted, possibly with a root at a or b.
std::vector<long double> real_roots_in(std::vector<long double> c, long double a, long double b) {
  while (!c.empty() && c.back() == 0) c.pop_back();
  std::vector<long double> roots;
  if (c.size() <= 1) return roots;  // a constant: no root (or identically 0: the caller's case)
  auto p = [&c](long double t) {
    long double v = 0;
    for (std::size_t k = c.size(); k-- > 0;) v = v * t + c[k];
    return v;
  };
  std::vector<long double> derivative;
  for (std::size_t k = 1; k < c.size(); ++k) derivative.push_back(c[k] * static_cast<long double>(k));
  std::vector<long double> breaks = {a};
  for (long double t : real_roots_in(derivative, a, b)) {
    if (t > breaks.back() && t < b) breaks.push_back(t);
  }
  breaks.push_back(b);
  for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
    long double lo = breaks[i], hi = breaks[i + 1];
    long double plo = p(lo), phi = p(hi);
    if (plo == 0) {
      if (roots.empty() || roots.back() != lo) roots.push_back(lo);
      continue;
    }
    if (phi == 0) {
      roots.push_back(hi);
      continue;
    }
    if ((plo < 0) == (phi < 0)) continue;
    for (int step = 0; step < 200; ++step) {
      const long double mid = lo + (hi - lo) / 2;
      if (!(mid > lo && mid < hi)) break;  // the interval is two adjacent long doubles
      const long double pm = p(mid);
      if (pm == 0) {
        lo = hi = mid;
        break;
      }
      if ((pm < 0) == (plo < 0)) {
        lo = mid;
        plo = pm;
      } else {
        hi = mid;
      }
    }
    roots.push_back(std::fabs(p(lo)) <= std::fabs(p(hi)) ? lo : hi);
  }
  return roots;
}

// The coefficient of x^a y^b z^c in f (0 when absent).
Rational coefficient_of(const Polynomial& f, std::int32_t a, std::int32_t b, std::int32_t c) {
  for (std::size_t t = 0; t < f.num_terms(); ++t) {
    const std::vector<std::int32_t> e = f.exponents(t);
    if (e[0] == a && e[1] == b && e[2] == c) return f.coefficient(t);
  }
  return Rational(0);
}

// |a − b|².
double distance_squared(const Point3& a, const Point3& b) {
  const double dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
  return dx * dx + dy * dy + dz * dz;
}

// |x − p|² in long double, for the descents.
long double distance_squared_long(const Point3& p, const std::array<long double, 3>& x) {
  long double sum = 0;
  for (std::size_t i = 0; i < 3; ++i) sum += (x[i] - p[i]) * (x[i] - p[i]);
  return sum;
}

// The coefficients of `line`, a polynomial in the variable `along` alone, by
// increasing degree, divided by the largest in absolute value.
std::vector<long double> normalized_coefficients(const Polynomial& line, std::size_t along) {
  std::vector<long double> c(static_cast<std::size_t>(line.degree_in(along)) + 1, 0);
  long double largest = 0;
  for (std::size_t t = 0; t < line.num_terms(); ++t) {
    const long double v = to_mpq(line.coefficient(t)).get_d();
    c[static_cast<std::size_t>(line.exponents(t)[along])] = v;
    largest = std::max(largest, std::fabs(v));
  }
  for (long double& v : c) v /= largest;
  return c;
}

}  // namespace

// ---------------------------------------------------------------------------------
// DistanceBox

DistanceBox DistanceBox::from_scene_box(const SceneBox& box) {
  DistanceBox out;
  for (std::size_t i = 0; i < 3; ++i) {
    out.lo[i] = to_mpq(box.lo[i]).get_d();
    out.hi[i] = to_mpq(box.hi[i]).get_d();
    if (!(out.lo[i] < out.hi[i])) {
      throw InputError("invalid_box", "the box needs lo < hi on every axis").in_field("box");
    }
  }
  return out;
}

bool DistanceBox::contains(const Point3& p) const {
  for (std::size_t i = 0; i < 3; ++i) {
    if (p[i] < lo[i] || p[i] > hi[i]) return false;
  }
  return true;
}

// ---------------------------------------------------------------------------------
// FloatingPolynomial

FloatingPolynomial::FloatingPolynomial(const Polynomial& f, bool normalise) : variables_(f.ring()->num_variables()) {
  long double largest = 0;
  for (std::size_t t = 0; t < f.num_terms(); ++t) {
    const std::vector<std::int32_t> e = f.exponents(t);
    coefficients_.push_back(static_cast<long double>(to_mpq(f.coefficient(t)).get_d()));
    exponents_.insert(exponents_.end(), e.begin(), e.end());
    for (std::int32_t k : e) degree_ = std::max(degree_, k);
    largest = std::max(largest, std::fabs(coefficients_.back()));
  }
  if (normalise && largest > 0) {
    for (long double& c : coefficients_) c /= largest;
  }
}

long double FloatingPolynomial::value(const long double* x) const {
  std::vector<long double> powers = power_table(x);
  long double sum = 0;
  for (std::size_t t = 0; t < coefficients_.size(); ++t) {
    long double term = coefficients_[t];
    for (std::size_t i = 0; i < variables_; ++i) {
      term *= powers[i * (degree_ + 1) + exponent(t, i)];
    }
    sum += term;
  }
  return sum;
}

long double FloatingPolynomial::magnitude(const std::array<long double, 3>& q) const {
  const long double a[3] = {std::fabs(q[0]), std::fabs(q[1]), std::fabs(q[2])};
  std::vector<long double> powers = power_table(a);
  long double sum = 0;
  for (std::size_t t = 0; t < coefficients_.size(); ++t) {
    long double term = std::fabs(coefficients_[t]);
    for (std::size_t i = 0; i < 3; ++i) term *= powers[i * (degree_ + 1) + exponent(t, i)];
    sum += term;
  }
  return sum;
}

FloatingPolynomial::Derivatives FloatingPolynomial::derivatives(const std::array<long double, 3>& q) const {
  // powers[i][k] = q_i^k, with q_i^(-1) never needed: a factor k multiplies it.
  std::array<std::vector<long double>, 3> powers;
  for (std::size_t i = 0; i < 3; ++i) {
    powers[i].assign(static_cast<std::size_t>(degree_) + 1, 1);
    for (std::size_t k = 1; k < powers[i].size(); ++k) powers[i][k] = powers[i][k - 1] * q[i];
  }
  auto power = [&](std::size_t i, std::int32_t k) -> long double { return k < 0 ? 0 : powers[i][k]; };
  Derivatives d;
  for (std::size_t t = 0; t < coefficients_.size(); ++t) {
    const std::int32_t e[3] = {exponent(t, 0), exponent(t, 1), exponent(t, 2)};
    const long double c = coefficients_[t];
    // Factor i differentiated j times: e_i·(e_i − 1)·…·q_i^(e_i − j).
    auto factor = [&](std::size_t i, int j) -> long double {
      long double f = 1;
      for (int m = 0; m < j; ++m) f *= static_cast<long double>(e[i] - m);
      return f * power(i, e[i] - j);
    };
    const long double f0[3] = {factor(0, 0), factor(1, 0), factor(2, 0)};
    const long double f1[3] = {factor(0, 1), factor(1, 1), factor(2, 1)};
    const long double f2[3] = {factor(0, 2), factor(1, 2), factor(2, 2)};
    d.value += c * f0[0] * f0[1] * f0[2];
    d.gradient[0] += c * f1[0] * f0[1] * f0[2];
    d.gradient[1] += c * f0[0] * f1[1] * f0[2];
    d.gradient[2] += c * f0[0] * f0[1] * f1[2];
    d.hessian[0][0] += c * f2[0] * f0[1] * f0[2];
    d.hessian[1][1] += c * f0[0] * f2[1] * f0[2];
    d.hessian[2][2] += c * f0[0] * f0[1] * f2[2];
    d.hessian[0][1] += c * f1[0] * f1[1] * f0[2];
    d.hessian[0][2] += c * f1[0] * f0[1] * f1[2];
    d.hessian[1][2] += c * f0[0] * f1[1] * f1[2];
  }
  d.hessian[1][0] = d.hessian[0][1];
  d.hessian[2][0] = d.hessian[0][2];
  d.hessian[2][1] = d.hessian[1][2];
  return d;
}

std::vector<long double> FloatingPolynomial::power_table(const long double* x) const {
  std::vector<long double> powers(variables_ * (static_cast<std::size_t>(degree_) + 1), 1);
  for (std::size_t i = 0; i < variables_; ++i) {
    for (std::int32_t k = 1; k <= degree_; ++k) {
      powers[i * (degree_ + 1) + k] = powers[i * (degree_ + 1) + k - 1] * x[i];
    }
  }
  return powers;
}

// ---------------------------------------------------------------------------------
// ClosedForm

double ClosedForm::distance(const Point3& p) const {
  const double rho = std::hypot(p[0], p[1]);
  switch (kind) {
    case Kind::sphere:
      return std::fabs(std::sqrt(distance_squared(p, centre)) - radius);
    case Kind::torus:
      return std::fabs(std::hypot(rho - major, p[2]) - radius);
    case Kind::cylinder: {
      const double beyond = std::max({box.lo[2] - p[2], p[2] - box.hi[2], 0.0});
      return std::hypot(rho - radius, beyond);
    }
    case Kind::cone: {
      double best = std::numeric_limits<double>::infinity();
      for (double end : {box.lo[2], box.hi[2]}) {
        if (end == 0) continue;
        best = std::min(best, segment_distance_2d(rho, p[2], 0, 0, slope * std::fabs(end), end));
      }
      return best;
    }
    case Kind::plane: {
      const double signed_distance = normal[0] * p[0] + normal[1] * p[1] + normal[2] * p[2] + offset;
      const Point3 q = {p[0] - signed_distance * normal[0], p[1] - signed_distance * normal[1],
                        p[2] - signed_distance * normal[2]};
      if (box.contains(q)) return std::fabs(signed_distance);
      double best = std::numeric_limits<double>::infinity();
      for (std::size_t i = 0; i < polygon.size(); ++i) {
        best = std::min(best, segment_distance(p, polygon[i], polygon[(i + 1) % polygon.size()]));
      }
      return best;
    }
  }
  return std::numeric_limits<double>::infinity();
}

std::string ClosedForm::describe() const {
  auto number = [](double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%g", v);
    return std::string(buffer);
  };
  switch (kind) {
    case Kind::plane:
      return "plane";
    case Kind::sphere:
      return "sphere r=" + number(radius);
    case Kind::cylinder:
      return "cylinder r=" + number(radius);
    case Kind::cone:
      return "cone k=" + number(slope);
    case Kind::torus:
      return "torus R=" + number(major) + " r=" + number(radius);
  }
  return "";
}

double ClosedForm::segment_distance(const Point3& p, const Point3& a, const Point3& b) {
  const Point3 ab = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const double length2 = ab[0] * ab[0] + ab[1] * ab[1] + ab[2] * ab[2];
  double t = length2 > 0 ? ((p[0] - a[0]) * ab[0] + (p[1] - a[1]) * ab[1] + (p[2] - a[2]) * ab[2]) / length2 : 0;
  t = std::clamp(t, 0.0, 1.0);
  return std::sqrt(distance_squared(p, {a[0] + t * ab[0], a[1] + t * ab[1], a[2] + t * ab[2]}));
}

double ClosedForm::segment_distance_2d(double px, double py, double ax, double ay, double bx, double by) {
  return segment_distance({px, py, 0}, {ax, ay, 0}, {bx, by, 0});
}

// ---------------------------------------------------------------------------------
// PointTree

PointTree::PointTree(std::vector<Point3> points) : points_(std::move(points)) {
  if (!points_.empty()) build(0, points_.size());
}

std::vector<std::pair<std::size_t, double>> PointTree::nearest(const Point3& p, std::size_t k) const {
  std::priority_queue<std::pair<double, std::size_t>> heap;  // farthest of the best on top
  if (!nodes_.empty() && k > 0) search(0, p, k, heap);
  std::vector<std::pair<std::size_t, double>> out(heap.size());
  for (std::size_t i = out.size(); i-- > 0;) {
    out[i] = {heap.top().second, heap.top().first};
    heap.pop();
  }
  return out;
}

std::size_t PointTree::build(std::size_t begin, std::size_t end) {
  const std::size_t id = nodes_.size();
  nodes_.push_back({begin, end, 0, 0, 0, 0});
  if (end - begin <= kLeaf) return id;
  Point3 lo = points_[begin], hi = points_[begin];
  for (std::size_t i = begin; i < end; ++i) {
    for (std::size_t a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], points_[i][a]);
      hi[a] = std::max(hi[a], points_[i][a]);
    }
  }
  std::size_t axis = 0;
  for (std::size_t a = 1; a < 3; ++a) {
    if (hi[a] - lo[a] > hi[axis] - lo[axis]) axis = a;
  }
  const std::size_t mid = begin + (end - begin) / 2;
  std::nth_element(points_.begin() + static_cast<std::ptrdiff_t>(begin),
                   points_.begin() + static_cast<std::ptrdiff_t>(mid),
                   points_.begin() + static_cast<std::ptrdiff_t>(end),
                   [axis](const Point3& a, const Point3& b) { return a[axis] < b[axis]; });
  const double split = points_[mid][axis];
  const std::size_t left = build(begin, mid);
  const std::size_t right = build(mid, end);
  nodes_[id].axis = axis;
  nodes_[id].split = split;
  nodes_[id].left = left;
  nodes_[id].right = right;
  return id;
}

void PointTree::search(std::size_t id, const Point3& p, std::size_t k,
                       std::priority_queue<std::pair<double, std::size_t>>& heap) const {
  const Node& node = nodes_[id];
  if (node.left == 0) {
    for (std::size_t i = node.begin; i < node.end; ++i) {
      const double d = distance_squared(p, points_[i]);
      if (heap.size() < k) {
        heap.push({d, i});
      } else if (d < heap.top().first) {
        heap.pop();
        heap.push({d, i});
      }
    }
    return;
  }
  const double delta = p[node.axis] - node.split;
  const std::size_t near = delta < 0 ? node.left : node.right;
  const std::size_t far = delta < 0 ? node.right : node.left;
  search(near, p, k, heap);
  if (heap.size() < k || delta * delta < heap.top().first) search(far, p, k, heap);
}

// ---------------------------------------------------------------------------------
// ReferenceDistance

ReferenceDistance ReferenceDistance::build(const Polynomial& f, const Parametrization* parametrization,
                                           const SceneBox& box, const ReferenceOptions& options, const Budget& budget) {
  if (f.ring()->num_variables() != 3 || f.is_constant()) {
    throw InputError("constant_polynomial", "the reference needs a non-constant F(x, y, z)").in_field("f");
  }
  if (options.lines_per_axis < 3 || options.lines_per_axis % 2 == 0 || options.parameter_samples < 0) {
    throw InputError("invalid_options", "lines_per_axis must be odd and >= 3, parameter_samples >= 0")
        .in_field("options");
  }
  ReferenceDistance out;
  out.box_ = DistanceBox::from_scene_box(box);
  out.h_ = out.box_.half_extent();
  out.f_ = FloatingPolynomial(f, true);
  out.closed_form_ = recognise_closed_form(f, out.box_);
  std::vector<Point3> cloud = out.line_roots(f, box, options, budget);
  out.line_points_ = cloud.size();
  if (parametrization != nullptr) out.add_parameter_samples(*parametrization, options, budget, cloud);
  out.parameter_points_ = cloud.size() - out.line_points_;
  out.starts_ = options.starts;
  out.spacing_ = 2 * out.h_ / (options.lines_per_axis - 1);
  out.tree_ = PointTree(std::move(cloud));
  out.singular_tree_ = PointTree(out.singular_);
  return out;
}

double ReferenceDistance::refined_distance(const Point3& p) const {
  double best = cloud_distance(p);
  if (const std::optional<double> d = project(p, {p[0], p[1], p[2]})) best = std::min(best, *d);
  // Starts closer than a quarter of the grid step to an earlier one join its basin
  // (the surface's features are resolved at the grid step): skipped.
  std::vector<Point3> used;
  auto is_new = [&](const Point3& q) {
    for (const Point3& u : used) {
      if (distance_squared(q, u) < spacing_ * spacing_ / 16) return false;
    }
    used.push_back(q);
    return true;
  };
  // Starts on a singular curve fail at once (no tangent plane there): the next
  // nearest points, on the sheets that meet at the curve, take their place.
  std::size_t descents = 0;
  for (const auto& [index, d2] : tree_.nearest(p, 4 * starts_)) {
    const Point3& q = tree_.points()[index];
    if (descents == starts_ || !is_new(q)) continue;
    const std::optional<Descent> descent = descend(p, {q[0], q[1], q[2]});
    if (!descent) continue;
    ++descents;
    best = std::min(best, descent->distance);
    if (const std::optional<double> d = project(p, descent->q)) best = std::min(best, *d);
  }
  // A singular curve can only be nearer than `best` if one of its sampled points
  // is within best plus the sampling gap (a few grid steps).
  used.clear();
  for (const auto& [index, d2] : singular_tree_.nearest(p, starts_)) {
    const Point3& q = singular_tree_.points()[index];
    if (std::sqrt(d2) > best + 4 * spacing_ || !is_new(q)) continue;
    best = std::min(best, descend_curve(p, {q[0], q[1], q[2]}));
  }
  return best;
}

double ReferenceDistance::cloud_distance(const Point3& p) const {
  double best = std::numeric_limits<double>::infinity();
  const auto nearest = tree_.nearest(p, 1);
  if (!nearest.empty()) best = std::sqrt(nearest[0].second);
  for (const auto& [a, b] : zero_lines_) best = std::min(best, ClosedForm::segment_distance(p, a, b));
  return best;
}

std::optional<Point3> ReferenceDistance::unit_normal(const Point3& q) const {
  const FloatingPolynomial::Derivatives d = f_.derivatives({q[0], q[1], q[2]});
  const long double n =
      std::sqrt(d.gradient[0] * d.gradient[0] + d.gradient[1] * d.gradient[1] + d.gradient[2] * d.gradient[2]);
  if (!(n * h_ > 1e-8L)) return std::nullopt;
  return Point3{static_cast<double>(d.gradient[0] / n), static_cast<double>(d.gradient[1] / n),
                static_cast<double>(d.gradient[2] / n)};
}

std::vector<Point3> ReferenceDistance::line_roots(const Polynomial& f, const SceneBox& box,
                                                  const ReferenceOptions& options, const Budget& budget) {
  const int n = options.lines_per_axis;
  const RingPtr& ring = f.ring();
  auto grid = [&box, n](std::size_t axis, int i) {
    return box.lo[axis] + (box.hi[axis] - box.lo[axis]) * Rational(i) / Rational(n - 1);
  };
  const double spacing = 2 * h_ / (n - 1);
  std::vector<Point3> cloud;
  std::vector<LongPoint> seeds;
  for (std::size_t along = 0; along < 3; ++along) {
    const std::size_t a = (along + 1) % 3, b = (along + 2) % 3;  // the two fixed coordinates
    for (int i = 0; i < n; ++i) {
      const Rational ca = grid(a, i);
      const Polynomial fa = f.substitute(a, Polynomial::constant(ring, ca));
      for (int j = 0; j < n; ++j) {
        budget.check("reference_distance");
        const Rational cb = grid(b, j);
        const Polynomial line = fa.substitute(b, Polynomial::constant(ring, cb));
        Point3 base{};
        base[a] = to_mpq(ca).get_d();
        base[b] = to_mpq(cb).get_d();
        if (line.is_zero()) {
          Point3 p0 = base, p1 = base;
          p0[along] = box_.lo[along];
          p1[along] = box_.hi[along];
          zero_lines_.push_back({p0, p1});
          continue;
        }
        if (line.is_constant()) continue;
        seed_singular_points(line, along, base, spacing, seeds);
        const Polynomial square_free = square_free_part(line, along);
        for (long double t :
             real_roots_in(normalized_coefficients(square_free, along), box_.lo[along], box_.hi[along])) {
          Point3 p = base;
          p[along] = static_cast<double>(t);
          cloud.push_back(p);
        }
      }
    }
  }
  for (const LongPoint& seed : seeds) {
    budget.check("reference_distance");
    LongPoint q = seed;
    if (!to_critical_set(q)) continue;
    const Point3 point = {static_cast<double>(q[0]), static_cast<double>(q[1]), static_cast<double>(q[2])};
    if (box_.contains(point)) singular_.push_back(point);
  }
  cloud.insert(cloud.end(), singular_.begin(), singular_.end());
  return cloud;
}

void ReferenceDistance::seed_singular_points(const Polynomial& line, std::size_t along, const Point3& base,
                                             double spacing, std::vector<LongPoint>& seeds) const {
  if (line.degree_in(along) < 2) return;
  const std::vector<long double> c = normalized_coefficients(line, along);
  std::vector<long double> d1, d2;
  for (std::size_t k = 1; k < c.size(); ++k) d1.push_back(c[k] * static_cast<long double>(k));
  for (std::size_t k = 1; k < d1.size(); ++k) d2.push_back(d1[k] * static_cast<long double>(k));
  auto horner = [](const std::vector<long double>& poly, long double t) {
    long double v = 0;
    for (std::size_t k = poly.size(); k-- > 0;) v = v * t + poly[k];
    return v;
  };
  for (long double t : real_roots_in(d1, box_.lo[along], box_.hi[along])) {
    if (std::fabs(horner(c, t)) <= std::fabs(horner(d2, t)) * spacing * spacing) {
      LongPoint seed = {base[0], base[1], base[2]};
      seed[along] = t;
      seeds.push_back(seed);
    }
  }
}

bool ReferenceDistance::regularised_solve(const std::array<std::array<long double, 3>, 3>& hessian,
                                          const std::array<long double, 3>& x, std::array<long double, 3>& y) {
  long double norm2 = 0;
  for (const auto& row : hessian) {
    for (long double v : row) norm2 += v * v;
  }
  if (!(norm2 > 0)) return false;
  long double a[4][5] = {};
  for (std::size_t r = 0; r < 3; ++r) {
    for (std::size_t c = 0; c < 3; ++c) {
      long double sum = 0;
      for (std::size_t k = 0; k < 3; ++k) sum += hessian[r][k] * hessian[k][c];
      a[r][c] = sum + (r == c ? 1e-24L * norm2 : 0);
    }
    long double hx = 0;
    for (std::size_t k = 0; k < 3; ++k) hx += hessian[r][k] * x[k];
    a[r][3] = hx;
  }
  std::array<long double, 4> solution{};
  if (!solve(a, 3, solution)) return false;
  y = {solution[0], solution[1], solution[2]};
  return true;
}

bool ReferenceDistance::on_critical_zero(const LongPoint& q, const FloatingPolynomial::Derivatives& d) const {
  long double g2 = 0, h2 = 0;
  for (std::size_t i = 0; i < 3; ++i) {
    g2 += d.gradient[i] * d.gradient[i];
    for (std::size_t j = 0; j < 3; ++j) h2 += d.hessian[i][j] * d.hessian[i][j];
  }
  return h2 > 0 && std::sqrt(g2) <= kSurfaceTolerance * h_ * std::sqrt(h2) &&
         std::fabs(d.value) <= 1e-13L * f_.magnitude(q);
}

bool ReferenceDistance::to_critical_set(LongPoint& q) const {
  for (int iteration = 0; iteration < 50; ++iteration) {
    const FloatingPolynomial::Derivatives d = f_.derivatives(q);
    if (on_critical_zero(q, d)) return true;
    std::array<long double, 3> step{};
    if (!regularised_solve(d.hessian, d.gradient, step)) return false;
    long double length2 = 0;
    for (std::size_t i = 0; i < 3; ++i) {
      q[i] -= step[i];
      length2 += step[i] * step[i];
    }
    if (!std::isfinite(static_cast<double>(length2)) || length2 > 4 * h_ * h_) return false;
    for (std::size_t i = 0; i < 3; ++i) {
      if (q[i] < box_.lo[i] || q[i] > box_.hi[i]) return false;
    }
  }
  return on_critical_zero(q, f_.derivatives(q));
}

double ReferenceDistance::descend_curve(const Point3& p, LongPoint q) const {
  long double best = distance_squared_long(p, q);
  for (int iteration = 0; iteration < 100; ++iteration) {
    const FloatingPolynomial::Derivatives d = f_.derivatives(q);
    const std::array<long double, 3> r = {p[0] - q[0], p[1] - q[1], p[2] - q[2]};
    std::array<long double, 3> seen{};
    if (!regularised_solve(d.hessian, r, seen)) break;
    std::array<long double, 3> t{};
    long double length2 = 0;
    for (std::size_t i = 0; i < 3; ++i) {
      long double hs = 0;
      for (std::size_t k = 0; k < 3; ++k) hs += d.hessian[i][k] * seen[k];
      t[i] = r[i] - hs;
      length2 += t[i] * t[i];
    }
    if (!(length2 > 1e-28L * h_ * h_)) break;
    bool improved = false;
    for (long double alpha = 1; alpha >= 1e-6L; alpha /= 2) {
      LongPoint trial = {q[0] + alpha * t[0], q[1] + alpha * t[1], q[2] + alpha * t[2]};
      if (!to_critical_set(trial)) continue;
      const long double trial_distance = distance_squared_long(p, trial);
      if (trial_distance < best) {
        improved = best - trial_distance > 1e-12L * best + 1e-30L * h_ * h_;
        q = trial;
        best = trial_distance;
        break;
      }
    }
    if (!improved) break;
  }
  return static_cast<double>(std::sqrt(best));
}

void ReferenceDistance::add_parameter_samples(const Parametrization& parametrization, const ReferenceOptions& options,
                                              const Budget& budget, std::vector<Point3>& cloud) const {
  if (parametrization.coordinates.size() != 3 || parametrization.parameter_ring->num_variables() != 2) return;
  std::array<FloatingPolynomial, 3> numerators, denominators;
  for (std::size_t i = 0; i < 3; ++i) {
    numerators[i] = FloatingPolynomial(parametrization.coordinates[i].numerator(), false);
    denominators[i] = FloatingPolynomial(parametrization.coordinates[i].denominator(), false);
  }
  const int m = options.parameter_samples;
  const long double pi = 3.141592653589793238462643383279502884L;
  for (int i = 0; i < m; ++i) {
    budget.check("reference_distance");
    for (int j = 0; j < m; ++j) {
      const long double st[2] = {std::tan(-pi / 2 + pi * (i + 0.5L) / m), std::tan(-pi / 2 + pi * (j + 0.5L) / m)};
      Point3 p{};
      bool finite = true;
      for (std::size_t k = 0; k < 3; ++k) {
        const long double value = numerators[k].value(st) / denominators[k].value(st);
        finite = finite && std::isfinite(value);
        p[k] = static_cast<double>(value);
      }
      if (finite && box_.contains(p)) cloud.push_back(p);
    }
  }
}

bool ReferenceDistance::on_surface(const FloatingPolynomial::Derivatives& d, const std::array<bool, 3>& held) const {
  long double gradient2 = 0;
  for (std::size_t i = 0; i < 3; ++i) {
    if (!held[i]) gradient2 += d.gradient[i] * d.gradient[i];
  }
  return gradient2 > 0 && std::fabs(d.value) <= kSurfaceTolerance * h_ * std::sqrt(gradient2);
}

bool ReferenceDistance::reproject(LongPoint& q, std::array<bool, 3>& held) const {
  for (int iteration = 0; iteration < 12; ++iteration) {
    const FloatingPolynomial::Derivatives d = f_.derivatives(q);
    long double gradient2 = 0;
    for (std::size_t i = 0; i < 3; ++i) {
      if (!held[i]) gradient2 += d.gradient[i] * d.gradient[i];
    }
    if (!(gradient2 > 0) || !std::isfinite(static_cast<double>(d.value))) return false;
    if (std::fabs(d.value) <= 1e-3L * kSurfaceTolerance * h_ * std::sqrt(gradient2)) return true;
    const long double factor = d.value / gradient2;
    for (std::size_t i = 0; i < 3; ++i) {
      if (held[i]) continue;
      q[i] -= factor * d.gradient[i];
      if (q[i] < box_.lo[i] || q[i] > box_.hi[i]) {
        q[i] = std::clamp<long double>(q[i], box_.lo[i], box_.hi[i]);
        held[i] = true;
      }
    }
  }
  return on_surface(f_.derivatives(q), held);
}

std::optional<ReferenceDistance::Descent> ReferenceDistance::descend(const Point3& p, LongPoint q) const {
  std::array<bool, 3> held = {false, false, false};
  if (!reproject(q, held)) return std::nullopt;
  long double best = distance_squared_long(p, q);
  for (int iteration = 0; iteration < 100; ++iteration) {
    const FloatingPolynomial::Derivatives d = f_.derivatives(q);
    LongPoint t{};
    held = {false, false, false};
    for (int pass = 0; pass < 3; ++pass) {
      long double gradient2 = 0, along = 0;
      for (std::size_t i = 0; i < 3; ++i) {
        if (held[i]) continue;
        gradient2 += d.gradient[i] * d.gradient[i];
        along += d.gradient[i] * (p[i] - q[i]);
      }
      if (!(gradient2 > 0)) return Descent{q, static_cast<double>(std::sqrt(best))};
      bool changed = false;
      for (std::size_t i = 0; i < 3; ++i) {
        t[i] = held[i] ? 0 : (p[i] - q[i]) - along / gradient2 * d.gradient[i];
        if (!held[i] && ((q[i] <= box_.lo[i] && t[i] < 0) || (q[i] >= box_.hi[i] && t[i] > 0))) {
          held[i] = true;
          changed = true;
        }
      }
      if (!changed) break;
    }
    const long double length2 = t[0] * t[0] + t[1] * t[1] + t[2] * t[2];
    if (!(length2 > 1e-28L * h_ * h_)) break;
    bool improved = false;
    for (long double alpha = 1; alpha >= 1e-6L; alpha /= 2) {
      LongPoint trial = q;
      std::array<bool, 3> trial_held = held;
      for (std::size_t i = 0; i < 3; ++i) {
        if (trial_held[i]) continue;
        trial[i] += alpha * t[i];
        if (trial[i] < box_.lo[i] || trial[i] > box_.hi[i]) {
          trial[i] = std::clamp<long double>(trial[i], box_.lo[i], box_.hi[i]);
          trial_held[i] = true;
        }
      }
      if (!reproject(trial, trial_held)) continue;
      const long double trial_distance = distance_squared_long(p, trial);
      if (trial_distance < best) {
        // Slow progress (linear convergence near the minimum): project() polishes.
        const bool stalled = best - trial_distance <= 1e-10L * best + 1e-30L * h_ * h_;
        q = trial;
        best = trial_distance;
        improved = !stalled;
        break;
      }
    }
    if (!improved) break;
  }
  return Descent{q, static_cast<double>(std::sqrt(best))};
}

std::optional<double> ReferenceDistance::project(const Point3& p, std::array<long double, 3> q) const {
  std::array<bool, 3> held = {false, false, false};
  auto least_squares_lambda = [&](const FloatingPolynomial::Derivatives& d) {
    long double num = 0, den = 0;
    for (std::size_t i = 0; i < 3; ++i) {
      if (held[i]) continue;
      num += d.gradient[i] * (q[i] - p[i]);
      den += d.gradient[i] * d.gradient[i];
    }
    return den > 0 ? -num / den : 0.0L;
  };
  FloatingPolynomial::Derivatives d = f_.derivatives(q);
  long double lambda = least_squares_lambda(d);
  bool converged = false;
  for (int iteration = 0; iteration < 60 && !converged; ++iteration) {
    std::array<std::size_t, 3> free{};
    std::size_t m = 0;
    for (std::size_t i = 0; i < 3; ++i) {
      if (!held[i]) free[m++] = i;
    }
    if (m == 0) break;
    // The (m + 1)×(m + 2) augmented system J·Δ = −r.
    long double a[4][5] = {};
    for (std::size_t r = 0; r < m; ++r) {
      const std::size_t i = free[r];
      for (std::size_t c = 0; c < m; ++c) a[r][c] = (r == c ? 1 : 0) + lambda * d.hessian[i][free[c]];
      a[r][m] = d.gradient[i];
      a[m][r] = d.gradient[i];
      a[r][m + 1] = -((q[i] - p[i]) + lambda * d.gradient[i]);
    }
    a[m][m] = 0;
    a[m][m + 1] = -d.value;
    std::array<long double, 4> delta{};
    if (!solve(a, m + 1, delta)) return std::nullopt;
    // Damp steps longer than h/2: Newton far from the solution can jump wildly.
    long double step2 = 0;
    for (std::size_t r = 0; r < m; ++r) step2 += delta[r] * delta[r];
    const long double limit = 0.5L * h_;
    const long double damping = step2 > limit * limit ? limit / std::sqrt(step2) : 1.0L;
    bool clamped = false;
    for (std::size_t r = 0; r < m; ++r) {
      const std::size_t i = free[r];
      q[i] += damping * delta[r];
      if (q[i] < box_.lo[i] || q[i] > box_.hi[i]) {
        q[i] = std::clamp<long double>(q[i], box_.lo[i], box_.hi[i]);
        held[i] = true;
        clamped = true;
      }
    }
    d = f_.derivatives(q);
    if (clamped) {
      lambda = least_squares_lambda(d);
      continue;
    }
    lambda += damping * delta[m];
    converged = damping == 1.0L && step2 <= 1e-36L * h_ * h_;
  }
  // On a face the zero set's curve is what q must be close to: F's first-order
  // distance within the face uses the free part of the gradient.
  if (!std::isfinite(static_cast<double>(d.value)) || !on_surface(d, held)) return std::nullopt;
  const Point3 qd = {static_cast<double>(q[0]), static_cast<double>(q[1]), static_cast<double>(q[2])};
  if (!box_.contains(qd)) return std::nullopt;
  return std::sqrt(distance_squared(p, qd));
}

bool ReferenceDistance::solve(long double (&a)[4][5], std::size_t n, std::array<long double, 4>& x) {
  for (std::size_t col = 0; col < n; ++col) {
    std::size_t pivot = col;
    for (std::size_t r = col + 1; r < n; ++r) {
      if (std::fabs(a[r][col]) > std::fabs(a[pivot][col])) pivot = r;
    }
    if (!(std::fabs(a[pivot][col]) > 1e-300L)) return false;
    for (std::size_t c = 0; c <= n; ++c) std::swap(a[col][c], a[pivot][c]);
    for (std::size_t r = col + 1; r < n; ++r) {
      const long double factor = a[r][col] / a[col][col];
      for (std::size_t c = col; c <= n; ++c) a[r][c] -= factor * a[col][c];
    }
  }
  for (std::size_t r = n; r-- > 0;) {
    long double sum = a[r][n];
    for (std::size_t c = r + 1; c < n; ++c) sum -= a[r][c] * x[c];
    x[r] = sum / a[r][r];
  }
  return true;
}

std::optional<ClosedForm> recognise_closed_form(const Polynomial& f, const DistanceBox& box) {
  const RingPtr& ring = f.ring();
  auto var = [&ring](std::size_t i) { return Polynomial::variable(ring, i); };
  auto num = [&ring](const Rational& c) { return Polynomial::constant(ring, c); };
  auto to_double = [](const Rational& q) { return to_mpq(q).get_d(); };
  ClosedForm form;
  form.box = box;
  const std::int32_t degree = f.total_degree();
  const Polynomial x = var(0), y = var(1), z = var(2);
  const Polynomial x2y2 = x * x + y * y;
  // The xy-square half side around the axis, for the surfaces of revolution.
  const double axis_room = std::min({-box.lo[0], box.hi[0], -box.lo[1], box.hi[1]});
  if (degree == 1) {
    const double a = to_double(coefficient_of(f, 1, 0, 0)), b = to_double(coefficient_of(f, 0, 1, 0));
    const double c = to_double(coefficient_of(f, 0, 0, 1)), d = to_double(coefficient_of(f, 0, 0, 0));
    const double n = std::sqrt(a * a + b * b + c * c);
    form.kind = ClosedForm::Kind::plane;
    form.normal = {a / n, b / n, c / n};
    form.offset = d / n;
    // The polygon: the plane's crossings of the box's 12 edges, in angular order.
    std::vector<Point3> corners;
    for (int k = 0; k < 8; ++k) {
      corners.push_back(
          {(k & 1) ? box.hi[0] : box.lo[0], (k & 2) ? box.hi[1] : box.lo[1], (k & 4) ? box.hi[2] : box.lo[2]});
    }
    auto level = [&form](const Point3& p) {
      return form.normal[0] * p[0] + form.normal[1] * p[1] + form.normal[2] * p[2] + form.offset;
    };
    for (int i = 0; i < 8; ++i) {
      for (int bit : {1, 2, 4}) {
        if (i & bit) continue;
        const Point3& p0 = corners[i];
        const Point3& p1 = corners[i | bit];
        const double l0 = level(p0), l1 = level(p1);
        if ((l0 < 0) == (l1 < 0) && l0 != 0 && l1 != 0) continue;
        const double t = l0 == l1 ? 0 : l0 / (l0 - l1);
        form.polygon.push_back({p0[0] + t * (p1[0] - p0[0]), p0[1] + t * (p1[1] - p0[1]), p0[2] + t * (p1[2] - p0[2])});
      }
    }
    if (form.polygon.size() < 3) return std::nullopt;
    Point3 mid{};
    for (const Point3& p : form.polygon) {
      for (std::size_t i = 0; i < 3; ++i) mid[i] += p[i] / static_cast<double>(form.polygon.size());
    }
    // An orthonormal pair (e1, e2) in the plane orders the vertices by angle.
    const Point3 helper = std::fabs(form.normal[0]) < 0.9 ? Point3{1, 0, 0} : Point3{0, 1, 0};
    Point3 e1 = {helper[1] * form.normal[2] - helper[2] * form.normal[1],
                 helper[2] * form.normal[0] - helper[0] * form.normal[2],
                 helper[0] * form.normal[1] - helper[1] * form.normal[0]};
    const double l = std::sqrt(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
    for (double& v : e1) v /= l;
    const Point3 e2 = {form.normal[1] * e1[2] - form.normal[2] * e1[1], form.normal[2] * e1[0] - form.normal[0] * e1[2],
                       form.normal[0] * e1[1] - form.normal[1] * e1[0]};
    auto angle = [&](const Point3& p) {
      const Point3 r = {p[0] - mid[0], p[1] - mid[1], p[2] - mid[2]};
      return std::atan2(r[0] * e2[0] + r[1] * e2[1] + r[2] * e2[2], r[0] * e1[0] + r[1] * e1[1] + r[2] * e1[2]);
    };
    std::sort(form.polygon.begin(), form.polygon.end(),
              [&](const Point3& u, const Point3& v) { return angle(u) < angle(v); });
    return form;
  }
  if (degree != 2 && degree != 4) return std::nullopt;
  const Rational lead = coefficient_of(f, degree, 0, 0);  // x² or x⁴, 1 in every shape
  if (lead == Rational(0)) return std::nullopt;
  const Polynomial g = f.divided_by(lead);  // x² (or x⁴) now has coefficient 1
  if (degree == 2) {
    const Rational bx = coefficient_of(g, 1, 0, 0), by = coefficient_of(g, 0, 1, 0), bz = coefficient_of(g, 0, 0, 1);
    const Rational e = coefficient_of(g, 0, 0, 0);
    const Polynomial sphere = x2y2 + z * z + x.scaled(bx) + y.scaled(by) + z.scaled(bz) + num(e);
    if (g == sphere) {
      form.kind = ClosedForm::Kind::sphere;
      form.centre = {-to_double(bx) / 2, -to_double(by) / 2, -to_double(bz) / 2};
      const double r2 = form.centre[0] * form.centre[0] + form.centre[1] * form.centre[1] +
                        form.centre[2] * form.centre[2] - to_double(e);
      if (!(r2 > 0)) return std::nullopt;
      form.radius = std::sqrt(r2);
      for (std::size_t i = 0; i < 3; ++i) {
        if (form.centre[i] - form.radius < box.lo[i] || form.centre[i] + form.radius > box.hi[i]) return std::nullopt;
      }
      return form;
    }
    if (g == x2y2 + num(e) && e < Rational(0)) {
      form.kind = ClosedForm::Kind::cylinder;
      form.radius = std::sqrt(-to_double(e));
      if (form.radius > axis_room) return std::nullopt;
      return form;
    }
    const Rational k2 = -coefficient_of(g, 0, 0, 2);
    if (g == x2y2 - (z * z).scaled(k2) && k2 > Rational(0)) {
      form.kind = ClosedForm::Kind::cone;
      form.slope = std::sqrt(to_double(k2));
      const double reach = form.slope * std::max(std::fabs(box.lo[2]), std::fabs(box.hi[2]));
      if (box.lo[2] > 0 || box.hi[2] < 0 || reach > axis_room) return std::nullopt;
      return form;
    }
    return std::nullopt;
  }
  if (degree == 4) {
    // (S + A)² − 4B(x² + y²), S = x² + y² + z²: the z² coefficient is 2A, the x²
    // coefficient 2A − 4B.
    const Rational a = coefficient_of(g, 0, 0, 2) / Rational(2);
    const Rational b = (Rational(2) * a - coefficient_of(g, 2, 0, 0)) / Rational(4);
    const Polynomial s_plus_a = x2y2 + z * z + num(a);
    if (!(g == s_plus_a * s_plus_a - x2y2.scaled(Rational(4) * b)) || !(b > Rational(0)) || !(b > a) ||
        !(a > Rational(0))) {
      return std::nullopt;  // a > 0 is R > r: a ring torus
    }
    form.kind = ClosedForm::Kind::torus;
    form.major = std::sqrt(to_double(b));
    form.radius = std::sqrt(to_double(b - a));
    if (form.major + form.radius > axis_room || form.radius > std::min(-box.lo[2], box.hi[2])) return std::nullopt;
    return form;
  }
  return std::nullopt;
}

SceneBox public_surface_box(const std::string& name) {
  auto cube = [](int cx, int half) {
    return SceneBox{{Rational(cx - half), Rational(-half), Rational(-half)},
                    {Rational(cx + half), Rational(half), Rational(half)}};
  };
  if (name == "torus_R2_r1" || name == "enneper") return cube(0, 4);
  if (name == "steiner_roman") return cube(0, 1);
  if (name == "biquadratic_patch") return cube(2, 4);
  return cube(0, 2);
}

std::vector<Point3> accuracy_samples(const ReferenceDistance& reference, std::size_t count, unsigned seed) {
  auto to_float = [](Point3 p) {
    for (double& c : p) c = static_cast<float>(c);
    return p;
  };
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> unit(0, 1);
  const DistanceBox& box = reference.box();
  const double size = 2 * box.half_extent();
  std::vector<Point3> points;
  for (std::size_t i = 0; i < count - count / 2; ++i) {
    points.push_back(to_float({box.lo[0] + (box.hi[0] - box.lo[0]) * unit(random),
                               box.lo[1] + (box.hi[1] - box.lo[1]) * unit(random),
                               box.lo[2] + (box.hi[2] - box.lo[2]) * unit(random)}));
  }
  const std::vector<Point3>& cloud = reference.cloud();
  std::uniform_int_distribution<std::size_t> pick(0, cloud.size() - 1);
  for (std::size_t tries = 0; points.size() < count && tries < 100 * count; ++tries) {
    const Point3& q = cloud[pick(random)];
    const std::optional<Point3> n = reference.unit_normal(q);
    const double sign = unit(random) < 0.5 ? -1 : 1;
    const double offset = sign * size * std::pow(10.0, -3 + 2 * unit(random));
    if (!n) continue;
    const Point3 p = to_float({q[0] + offset * (*n)[0], q[1] + offset * (*n)[1], q[2] + offset * (*n)[2]});
    if (box.contains(p)) points.push_back(p);
  }
  return points;
}

EstimateStatistics summarise_estimates(const std::vector<double>& values, const std::vector<double>& distances,
                                       double h) {
  EstimateStatistics s;
  std::vector<double> ratios;
  for (std::size_t i = 0; i < values.size() && i < distances.size(); ++i) {
    const double v = std::fabs(values[i]), d = distances[i];
    ++s.points;
    if (v > d * (1 + EstimateStatistics::kOverRelative) + EstimateStatistics::kOverAbsolute * h) ++s.over;
    if (d >= EstimateStatistics::kRatioFloor * h) ratios.push_back(v / d);
  }
  s.ratios = ratios.size();
  if (ratios.empty()) return s;
  std::sort(ratios.begin(), ratios.end());
  s.median_ratio = ratios.size() % 2 == 1 ? ratios[ratios.size() / 2]
                                          : (ratios[ratios.size() / 2 - 1] + ratios[ratios.size() / 2]) / 2;
  s.p5_ratio = ratios[static_cast<std::size_t>(std::ceil(0.05 * static_cast<double>(ratios.size()))) - 1];
  s.max_ratio = ratios.back();
  return s;
}

}  // namespace implicitizer::testing
