#include "patch_sample.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace implicitizer::bench {
namespace {

// A polynomial in the two parameters as (coefficient, exponent of s, exponent of t).
std::vector<std::array<double, 3>> terms_of(const Polynomial& p) {
  std::vector<std::array<double, 3>> out;
  for (std::size_t i = 0; i < p.num_terms(); ++i) {
    const std::vector<std::int32_t> e = p.exponents(i);
    out.push_back(
        {to_mpq(p.coefficient(i)).get_d(), e.empty() ? 0.0 : double(e[0]), e.size() < 2 ? 0.0 : double(e[1])});
  }
  return out;
}

}  // namespace

PatchSample::PatchSample(const Parametrization& parametrization, const std::array<double, 4>& domain, std::size_t side)
    : domain_(domain) {
  for (std::size_t i = 0; i < 3; ++i) {
    for (const auto& [c, s, t] : terms_of(parametrization.coordinates[i].numerator())) {
      numerators_[i].push_back({c, int(s), int(t)});
    }
    for (const auto& [c, s, t] : terms_of(parametrization.coordinates[i].denominator())) {
      denominators_[i].push_back({c, int(s), int(t)});
    }
  }
  const double inf = std::numeric_limits<double>::infinity();
  lo_ = {inf, inf, inf};
  hi_ = {-inf, -inf, -inf};
  std::vector<std::ptrdiff_t> index(side * side, -1);
  for (std::size_t j = 0; j < side; ++j) {
    for (std::size_t i = 0; i < side; ++i) {
      const double s = domain[0] + (domain[1] - domain[0]) * double(i) / double(side - 1);
      const double t = domain[2] + (domain[3] - domain[2]) * double(j) / double(side - 1);
      Point x;
      if (!evaluate(s, t, x)) continue;
      index[j * side + i] = std::ptrdiff_t(points_.size());
      points_.push_back(x);
      parameters_.push_back({s, t});
      for (std::size_t k = 0; k < 3; ++k) {
        lo_[k] = std::min(lo_[k], x[k]);
        hi_[k] = std::max(hi_[k], x[k]);
      }
    }
  }
  auto distance = [](const Point& a, const Point& b) {
    return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
  };
  for (std::size_t j = 0; j + 1 < side; ++j) {
    for (std::size_t i = 0; i + 1 < side; ++i) {
      const std::ptrdiff_t a = index[j * side + i], b = index[j * side + i + 1], c = index[(j + 1) * side + i],
                           d = index[(j + 1) * side + i + 1];
      if (a < 0 || b < 0 || c < 0 || d < 0) continue;
      // Any point of the cell's (nearly flat) image is within half its diagonal of a corner.
      spacing_ = std::max({spacing_, distance(points_[std::size_t(a)], points_[std::size_t(d)]) / 2,
                           distance(points_[std::size_t(b)], points_[std::size_t(c)]) / 2,
                           distance(points_[std::size_t(a)], points_[std::size_t(b)]),
                           distance(points_[std::size_t(a)], points_[std::size_t(c)])});
    }
  }
  const double extent = std::max({hi_[0] - lo_[0], hi_[1] - lo_[1], hi_[2] - lo_[2], 1e-300});
  cell_ = extent / 64;
  for (std::size_t k = 0; k < points_.size(); ++k) cells_[cell_key(cell_of(points_[k]))].push_back(k);
}

double PatchSample::evaluate_terms(const Terms& terms, double s, double t) {
  double sum = 0;
  for (const Term& term : terms) sum += term.coefficient * std::pow(s, term.s) * std::pow(t, term.t);
  return sum;
}

bool PatchSample::evaluate(double s, double t, Point& out) const {
  for (std::size_t i = 0; i < 3; ++i) {
    const double d = evaluate_terms(denominators_[i], s, t);
    if (d == 0 || !std::isfinite(d)) return false;
    out[i] = evaluate_terms(numerators_[i], s, t) / d;
    if (!std::isfinite(out[i])) return false;
  }
  return true;
}

std::array<long, 3> PatchSample::cell_of(const Point& p) const {
  return {long(std::floor((p[0] - lo_[0]) / cell_)), long(std::floor((p[1] - lo_[1]) / cell_)),
          long(std::floor((p[2] - lo_[2]) / cell_))};
}

std::size_t PatchSample::cell_key(const std::array<long, 3>& c) {
  return std::size_t(c[0]) * 73856093u ^ std::size_t(c[1]) * 19349663u ^ std::size_t(c[2]) * 83492791u;
}

std::vector<std::size_t> PatchSample::nearest(const Point& p, std::size_t count) const {
  // Rings of cells around p's cell (clamped to the sample's grid), until the ring's
  // inner distance exceeds the count-th best distance found.
  std::array<long, 3> centre = cell_of(p);
  const std::array<long, 3> top = cell_of(hi_);
  for (std::size_t k = 0; k < 3; ++k) centre[k] = std::clamp(centre[k], 0L, top[k]);
  std::vector<std::pair<double, std::size_t>> best;
  const long reach = std::max({top[0], top[1], top[2]}) + 1;
  for (long r = 0; r <= reach; ++r) {
    for (long a = -r; a <= r; ++a) {
      for (long b = -r; b <= r; ++b) {
        for (long c = -r; c <= r; ++c) {
          if (std::max({std::labs(a), std::labs(b), std::labs(c)}) != r) continue;
          const std::array<long, 3> cell = {centre[0] + a, centre[1] + b, centre[2] + c};
          const auto it = cells_.find(cell_key(cell));
          if (it == cells_.end()) continue;
          for (std::size_t k : it->second) {
            const Point& q = points_[k];
            const double d2 =
                (q[0] - p[0]) * (q[0] - p[0]) + (q[1] - p[1]) * (q[1] - p[1]) + (q[2] - p[2]) * (q[2] - p[2]);
            best.emplace_back(d2, k);
          }
        }
      }
    }
    std::sort(best.begin(), best.end());
    best.erase(std::unique(best.begin(), best.end()), best.end());
    if (best.size() > count) best.resize(count);
    // Every sample outside the rings searched is at least r·cell from the projection
    // of p onto the sample's grid (which lies in the clamped centre cell), and p is
    // no nearer to the grid's points than its projection.
    const double outside = double(r) * cell_;
    if (best.size() == count && best.back().first <= outside * outside) break;
  }
  std::vector<std::size_t> out;
  for (const auto& [d2, k] : best) out.push_back(k);
  return out;
}

double PatchSample::lower_bound(const Point& p) const {
  const std::vector<std::size_t> n = nearest(p, 1);
  if (n.empty()) return 0;
  const Point& q = points_[n[0]];
  const double d =
      std::sqrt((q[0] - p[0]) * (q[0] - p[0]) + (q[1] - p[1]) * (q[1] - p[1]) + (q[2] - p[2]) * (q[2] - p[2]));
  return std::max(d - spacing_, 0.0);
}

double PatchSample::upper_bound(const Point& p) const {
  double best = std::numeric_limits<double>::infinity();
  auto distance_at = [&](double s, double t) {
    Point x;
    if (!evaluate(s, t, x)) return std::numeric_limits<double>::infinity();
    return std::sqrt((x[0] - p[0]) * (x[0] - p[0]) + (x[1] - p[1]) * (x[1] - p[1]) + (x[2] - p[2]) * (x[2] - p[2]));
  };
  const double ds = (domain_[1] - domain_[0]) * 1e-7, dt = (domain_[3] - domain_[2]) * 1e-7;
  for (std::size_t k : nearest(p, 4)) {
    double s = parameters_[k][0], t = parameters_[k][1];
    double current = distance_at(s, t);
    // Gauss–Newton on |X(s, t) − p|², clamped to D, with a halving line search so the
    // distance never grows.
    for (int iteration = 0; iteration < 30 && current > 0; ++iteration) {
      Point x, xs, xt;
      if (!evaluate(s, t, x) || !evaluate(s + ds, t, xs) || !evaluate(s, t + dt, xt)) break;
      double a = 0, b = 0, c = 0, gs = 0, gt = 0;
      for (std::size_t i = 0; i < 3; ++i) {
        const double js = (xs[i] - x[i]) / ds, jt = (xt[i] - x[i]) / dt, r = x[i] - p[i];
        a += js * js;
        b += js * jt;
        c += jt * jt;
        gs += js * r;
        gt += jt * r;
      }
      const double det = a * c - b * b;
      if (!(std::fabs(det) > 0)) break;
      double step_s = -(c * gs - b * gt) / det, step_t = -(a * gt - b * gs) / det;
      bool improved = false;
      for (int halving = 0; halving < 20; ++halving) {
        const double ns = std::clamp(s + step_s, domain_[0], domain_[1]);
        const double nt = std::clamp(t + step_t, domain_[2], domain_[3]);
        const double candidate = distance_at(ns, nt);
        if (candidate < current) {
          s = ns;
          t = nt;
          current = candidate;
          improved = true;
          break;
        }
        step_s /= 2;
        step_t /= 2;
      }
      if (!improved) break;
    }
    best = std::min(best, current);
  }
  return best;
}

}  // namespace implicitizer::bench
