#include "certificate.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "implicitizer/polynomial/ring.hpp"

namespace implicitizer::approximation {
namespace {

const char* const kWhere = "approximation: certificate";

// A sub-piece with its exact Bernstein coefficients: N, W (layout `values`) and ω, ξ
// (layout `forms`).
struct SubPiece {
  BernsteinBox box;
  BernsteinCoefficients n, w;
  std::vector<BernsteinCoefficients> forms;
  std::size_t depth = 0;
};

struct Problem {
  const Polynomial& q;
  std::vector<Polynomial> gradient;  // ∂q/∂x, ∂q/∂y, ∂q/∂z
  std::vector<Polynomial> forms;     // ω, ξ over the parameters
  BernsteinLayout values, form_layout;
  mpq_class delta;  // the target, exact
};

BernsteinLayout layout_of(const std::vector<const Polynomial*>& polynomials, std::size_t variables) {
  std::vector<std::size_t> extents(variables, 1);
  for (const Polynomial* p : polynomials) {
    for (std::size_t j = 0; j < variables; ++j) extents[j] = std::max(extents[j], std::size_t(p->degree_in(j)) + 1);
  }
  return BernsteinLayout(extents);
}

bool one_signed(const BernsteinCoefficients& c) {
  const int s = sgn(c[0]);
  return s != 0 && std::all_of(c.begin(), c.end(), [s](const mpq_class& x) { return sgn(x) == s; });
}

// A rational ν >= sqrt(x) (x >= 0): the double square root rounded up, raised until
// its square is at least x.
mpq_class sqrt_upper(const mpq_class& x) {
  double r = std::nextafter(std::sqrt(x.get_d()), HUGE_VAL);
  while (mpq_class(r) * mpq_class(r) < x) r = std::nextafter(r * (1 + 1e-15), HUGE_VAL);
  return mpq_class(r);
}

// n = ∇q at X(centre of the sub-piece), max |n_i| = 1, on the grid 2^-16, and ∇q·n
// there (in double, for choosing δ); none when ∇q vanishes there.
struct Direction {
  std::vector<mpq_class> n;
  double slope = 0;
};

std::optional<Direction> direction(const Problem& p, const SubPiece& piece) {
  std::vector<Rational> centre;
  for (const auto& [a, b] : piece.box) centre.push_back(to_rational((a + b) / 2));
  const mpq_class w = to_mpq(p.forms[0].evaluate(centre));
  if (sgn(w) == 0) return std::nullopt;
  std::vector<Rational> x;
  for (std::size_t i = 1; i < 4; ++i) x.push_back(to_rational(to_mpq(p.forms[i].evaluate(centre)) / w));
  std::vector<double> g;
  double largest = 0;
  for (const Polynomial& d : p.gradient) {
    g.push_back(to_mpq(d.evaluate(x)).get_d());
    largest = std::max(largest, std::abs(g.back()));
  }
  if (!(largest > 0) || !std::isfinite(largest)) return std::nullopt;
  Direction d;
  for (const double gi : g) {
    d.n.emplace_back(std::round(gi / largest * 65536.0) / 65536.0);
    d.slope += gi * d.n.back().get_d();
  }
  return d;
}

// The hull of X over the sub-piece (ω's coefficients one-signed), widened by δ and
// rounded outwards to doubles.
BernsteinBox widened_hull(const SubPiece& piece, const mpq_class& delta) {
  BernsteinBox box;
  for (std::size_t i = 1; i < 4; ++i) {
    mpq_class lo = piece.forms[i][0] / piece.forms[0][0], hi = lo;
    for (std::size_t k = 1; k < piece.forms[0].size(); ++k) {
      const mpq_class r = piece.forms[i][k] / piece.forms[0][k];
      lo = std::min(lo, r);
      hi = std::max(hi, r);
    }
    box.emplace_back(mpq_class(round_down<double>(to_rational(lo - delta))),
                     mpq_class(round_up<double>(to_rational(hi + delta))));
  }
  return box;
}

// e·ν/g for the sub-piece when the test of the file comment holds. The widening δ
// need only exceed e/g: δ = min(target, 2·e·ν/(∇q·n at the centre)), a double, so
// that the box (and the overestimate of its Bernstein bound) stays small when e is.
std::optional<mpq_class> local_bound(const Problem& p, const SubPiece& piece, const Budget& budget) {
  if (!one_signed(piece.w) || !one_signed(piece.forms[0])) return std::nullopt;
  mpq_class e = 0;
  for (std::size_t k = 0; k < piece.n.size(); ++k) e = std::max(e, mpq_class(abs(piece.n[k] / piece.w[k])));
  const std::optional<Direction> d = direction(p, piece);
  if (!d || !(d->slope > 0)) return std::nullopt;
  std::vector<Polynomial> parts;
  mpq_class norm2 = 0;
  for (std::size_t i = 0; i < 3; ++i) {
    norm2 += d->n[i] * d->n[i];
    if (sgn(d->n[i]) != 0) parts.push_back(p.gradient[i].scaled(to_rational(d->n[i])));
  }
  const mpq_class nu = sqrt_upper(norm2);
  const Polynomial slope = sum_of(p.q.ring(), std::move(parts));
  const BernsteinLayout layout = layout_of({&slope}, 3);
  budget.check_terms(layout.size, kWhere);
  double wanted = 4 * mpq_class(e * nu).get_d() / d->slope;
  // Twice at most: when g falls short of the slope at the centre, once more with δ
  // from g itself.
  for (int attempt = 0; attempt < 2; ++attempt) {
    const mpq_class delta = wanted < p.delta.get_d() ? mpq_class(std::max(wanted, 1e-300)) : p.delta;
    const BernsteinCoefficients c = bernstein_coefficients(slope, layout, widened_hull(piece, delta), budget, kWhere);
    const mpq_class g = *std::min_element(c.begin(), c.end());
    if (sgn(g) <= 0) return std::nullopt;
    if (e * nu <= g * delta) return mpq_class(e * nu / g);
    if (delta == p.delta) return std::nullopt;
    wanted = 2 * mpq_class(e * nu / g).get_d();
  }
  return std::nullopt;
}

std::pair<SubPiece, SubPiece> bisect(const Problem& p, const SubPiece& piece, const Budget& budget) {
  const std::size_t axis = piece.box[1].second - piece.box[1].first > piece.box[0].second - piece.box[0].first ? 1 : 0;
  SubPiece lower{piece.box, {}, {}, {}, piece.depth + 1}, upper = lower;
  const mpq_class middle = (piece.box[axis].first + piece.box[axis].second) / 2;
  lower.box[axis].second = middle;
  upper.box[axis].first = middle;
  std::tie(lower.n, upper.n) = split_along(piece.n, p.values, axis, budget, kWhere);
  std::tie(lower.w, upper.w) = split_along(piece.w, p.values, axis, budget, kWhere);
  for (const BernsteinCoefficients& f : piece.forms) {
    auto [l, u] = split_along(f, p.form_layout, axis, budget, kWhere);
    lower.forms.push_back(std::move(l));
    upper.forms.push_back(std::move(u));
  }
  return {std::move(lower), std::move(upper)};
}

}  // namespace

Certificate certify_patch_to_surface(const Polynomial& q, const std::vector<Polynomial>& forms,
                                     const BernsteinBox& piece, double target, std::size_t max_depth,
                                     const Budget& budget) {
  const RingPtr& parameters = forms[0].ring();
  const RingPtr homogeneous = Ring::make({"x", "y", "z", "w"});
  const std::size_t to_homogeneous[3] = {0, 1, 2};
  const unsigned m = unsigned(q.total_degree());
  // N = ω^m·q(ξ/ω): q homogenized with w, then w = ω, x = ξ_x, …
  const std::vector<Polynomial> values{forms[1], forms[2], forms[3], forms[0]};
  const Polynomial n = q.map_to(homogeneous, to_homogeneous).homogenize(3).compose(parameters, values, budget);
  const Polynomial w = forms[0].pow(m, budget);
  Problem p{q,
            {q.derivative(0), q.derivative(1), q.derivative(2)},
            forms,
            layout_of({&n, &w}, 2),
            layout_of({&forms[0], &forms[1], &forms[2], &forms[3]}, 2),
            mpq_class(target)};
  SubPiece root{piece,
                bernstein_coefficients(n, p.values, piece, budget, kWhere),
                bernstein_coefficients(w, p.values, piece, budget, kWhere),
                {},
                0};
  for (const Polynomial& f : forms)
    root.forms.push_back(bernstein_coefficients(f, p.form_layout, piece, budget, kWhere));

  Certificate result;
  mpq_class worst = 0;
  std::vector<SubPiece> stack;
  stack.push_back(std::move(root));
  while (!stack.empty()) {
    budget.check(kWhere);
    SubPiece sub = std::move(stack.back());
    stack.pop_back();
    if (const std::optional<mpq_class> bound = local_bound(p, sub, budget)) {
      worst = std::max(worst, *bound);
      ++result.pieces;
      continue;
    }
    if (sub.depth >= max_depth) return Certificate{};
    auto [lower, upper] = bisect(p, sub, budget);
    stack.push_back(std::move(lower));
    stack.push_back(std::move(upper));
  }
  result.proven = true;
  result.bound = round_up<double>(to_rational(worst));
  return result;
}

}  // namespace implicitizer::approximation
