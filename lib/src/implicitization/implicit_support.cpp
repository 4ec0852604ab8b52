#include "implicitizer/implicitization/implicit_support.hpp"

#include <algorithm>
#include <map>
#include <numeric>
#include <utility>

namespace implicitizer {

namespace {

using Point = std::array<std::int64_t, 2>;

std::int64_t cross(const Point& o, const Point& a, const Point& b) {
  return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

// The vertices of the convex hull, counter-clockwise (Andrew's monotone chain).
std::vector<Point> convex_hull(std::vector<Point> points) {
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());
  if (points.size() < 3) return points;
  std::vector<Point> hull(2 * points.size());
  std::size_t k = 0;
  for (const Point& p : points) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], p) <= 0) --k;
    hull[k++] = p;
  }
  for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && cross(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);
  return hull;
}

// Twice the area of the convex hull of `points` (an integer for lattice points).
std::int64_t doubled_area(const std::vector<Point>& points) {
  const std::vector<Point> hull = convex_hull(points);
  std::int64_t sum = 0;
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const Point& a = hull[i];
    const Point& b = hull[(i + 1) % hull.size()];
    sum += a[0] * b[1] - a[1] * b[0];
  }
  return sum < 0 ? -sum : sum;
}

// The exponents of a polynomial in two variables.
std::vector<Point> support_of(const Polynomial& f) {
  std::vector<Point> out;
  for (std::size_t t = 0; t < f.num_terms(); ++t) {
    const std::vector<std::int32_t> e = f.exponents(t);
    out.push_back({e[0], e[1]});
  }
  return out;
}

std::vector<Point> joined(std::vector<Point> a, const std::vector<Point>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

// ℤ²/L for the lattice L of fact 2, as a canonical representative of each class:
// L = ℤ·(a, b) + ℤ·(0, c) with a, c ≥ 0 (a Hermite basis; a = 0 or c = 0 where L has
// rank below 2).
class Grading {
 public:
  explicit Grading(const std::vector<Point>& generators) {
    // (a, b): the gcd of the first coordinates as a combination of the generators.
    for (Point g : generators) {
      if (g[0] < 0) g = {-g[0], -g[1]};
      if (g[0] == 0) continue;
      if (a_ == 0) {
        a_ = g[0];
        b_ = g[1];
        continue;
      }
      const auto [x, y, d] = extended_gcd(a_, g[0]);
      b_ = x * b_ + y * g[1];
      a_ = d;
    }
    // c: the gcd of the second coordinates of what is left once (a, b) removed the first.
    for (const Point& g : generators) {
      const std::int64_t rest = a_ == 0 ? g[1] : g[1] - (g[0] / a_) * b_;
      c_ = std::gcd(c_, rest < 0 ? -rest : rest);
    }
    if (c_ != 0) b_ = floor_mod(b_, c_);
  }

  std::size_t order() const { return static_cast<std::size_t>(a_ * c_); }

  Point canonical(Point v) const {
    if (a_ != 0) {
      const std::int64_t q = floor_div(v[0], a_);
      v = {v[0] - q * a_, v[1] - q * b_};
    }
    if (c_ != 0) v[1] = floor_mod(v[1], c_);
    return v;
  }

 private:
  static std::int64_t floor_div(std::int64_t x, std::int64_t m) {
    return x / m - ((x % m != 0) && ((x < 0) != (m < 0)));
  }
  static std::int64_t floor_mod(std::int64_t x, std::int64_t m) { return x - floor_div(x, m) * m; }
  // (x, y, d) with x·u + y·v = d = gcd(u, v), for u, v > 0.
  static std::array<std::int64_t, 3> extended_gcd(std::int64_t u, std::int64_t v) {
    std::int64_t x0 = 1, y0 = 0, x1 = 0, y1 = 1;
    while (v != 0) {
      const std::int64_t q = u / v;
      std::tie(u, v) = std::make_pair(v, u - q * v);
      std::tie(x0, x1) = std::make_pair(x1, x0 - q * x1);
      std::tie(y0, y1) = std::make_pair(y1, y0 - q * y1);
    }
    return {x0, y0, u};
  }

  std::int64_t a_ = 0, b_ = 0, c_ = 0;
};

// The degree bounds of fact 1 from the supports of ω, ξ_1, ξ_2, ξ_3.
void bound_degrees(const std::vector<std::vector<Point>>& supports, ImplicitSupport& out) {
  const std::vector<Point> x = joined(supports[1], supports[0]);
  const std::vector<Point> y = joined(supports[2], supports[0]);
  const std::vector<Point> z = joined(supports[3], supports[0]);
  out.degree_in = {static_cast<std::int32_t>(mixed_volume(y, z)), static_cast<std::int32_t>(mixed_volume(x, z)),
                   static_cast<std::int32_t>(mixed_volume(x, y))};
  const std::vector<Point> all = joined(joined(x, supports[2]), supports[3]);
  out.total_degree = static_cast<std::int32_t>(mixed_volume(all, all));
  for (std::int32_t& d : out.degree_in) d = std::min(d, out.total_degree);
}

// The monomials of the box, counted only until they pass `limit` (then the count
// returned is above it): exponents up to the parser's 1000 give degree bounds in the
// millions, whose full count would take about 10^12 steps.
double box_size(const ImplicitSupport& s, double limit) {
  double count = 0;
  for (std::int32_t i = 0; i <= s.degree_in[0]; ++i) {
    for (std::int32_t j = 0; j <= s.degree_in[1] && i + j <= s.total_degree; ++j) {
      count += std::min(s.degree_in[2], s.total_degree - i - j) + 1;
      if (count > limit) return count;
    }
  }
  return count;
}

}  // namespace

std::int64_t mixed_volume(const std::vector<Point>& p, const std::vector<Point>& q) {
  if (p.empty() || q.empty()) return 0;
  std::vector<Point> sum;
  for (const Point& a : convex_hull(p)) {
    for (const Point& b : convex_hull(q)) sum.push_back({a[0] + b[0], a[1] + b[1]});
  }
  // MV(P, Q) = area(P + Q) − area(P) − area(Q); the doubled areas halve exactly.
  return (doubled_area(sum) - doubled_area(p) - doubled_area(q)) / 2;
}

double space_monomial_count(std::int32_t d) {
  const double e = d;
  return (e + 1) * (e + 2) * (e + 3) / 6;
}

std::optional<ImplicitSupport> predict_implicit_support(const Parametrization& parametrization, const Budget& budget) {
  if (parametrization.coordinates.size() != 3 || parametrization.parameter_ring->num_variables() != 2) {
    return std::nullopt;
  }
  const std::vector<Polynomial> forms = common_denominator_form(parametrization, budget);
  std::vector<std::vector<Point>> supports;
  std::vector<Point> differences;
  for (const Polynomial& f : forms) {
    if (f.is_zero()) return std::nullopt;  // a coordinate is 0: the image lies in a plane
    supports.push_back(support_of(f));
    for (const Point& e : supports.back()) {
      differences.push_back({e[0] - supports.back()[0][0], e[1] - supports.back()[0][1]});
    }
  }
  ImplicitSupport out;
  bound_degrees(supports, out);
  const double size = box_size(out, kMaxPredictedBox);
  if (size > kMaxPredictedBox) return std::nullopt;

  // x^α has the class Σ α_i·(g_i − g_0), g_i the class of any exponent of form i.
  const Grading grading(differences);
  out.group_order = grading.order();
  std::array<Point, 3> step;
  for (std::size_t i = 0; i < 3; ++i) {
    step[i] = {supports[i + 1][0][0] - supports[0][0][0], supports[i + 1][0][1] - supports[0][0][1]};
  }
  std::map<Point, std::size_t> index;
  std::size_t visited = 0;
  for (std::int32_t i = 0; i <= out.degree_in[0]; ++i) {
    for (std::int32_t j = 0; j <= out.degree_in[1] && i + j <= out.total_degree; ++j) {
      for (std::int32_t k = 0; k <= out.degree_in[2] && i + j + k <= out.total_degree; ++k) {
        // A box near kMaxPredictedBox outlasts a short deadline (the request fuzzer
        // found one); a check reads the clock, hence one every 4096 monomials.
        if (++visited % 4096 == 0) budget.check("the predicted support");
        const Point cls = grading.canonical(
            {i * step[0][0] + j * step[1][0] + k * step[2][0], i * step[0][1] + j * step[1][1] + k * step[2][1]});
        const auto [it, fresh] = index.emplace(cls, out.classes.size());
        if (fresh) out.classes.emplace_back();
        out.classes[it->second].insert(out.classes[it->second].end(), {i, j, k});
      }
    }
  }
  out.columns = static_cast<std::size_t>(size);
  for (const auto& c : out.classes) {
    const double m = static_cast<double>(c.size() / 3);
    out.largest_class = std::max(out.largest_class, c.size() / 3);
    out.cubed_columns += m * m * m;
  }
  return out;
}

}  // namespace implicitizer
