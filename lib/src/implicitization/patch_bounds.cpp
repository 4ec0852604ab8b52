#include "implicitizer/implicitization/patch_bounds.hpp"

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <string>

#include "implicitizer/implicitization/bernstein.hpp"

namespace implicitizer {

namespace {

using Coefficients = BernsteinCoefficients;
using Layout = BernsteinLayout;

// A piece of the domain with the Bernstein coefficients of ω (forms[0]) and of the
// ξ_i (forms[1..n]) on it.
struct Piece {
  std::vector<std::pair<mpq_class, mpq_class>> box;
  std::vector<Coefficients> forms;
  std::size_t depth = 0;
};

const char* const kWhere = "patch bounds";

InputError domain_error(const std::string& message) { return InputError("invalid_domain", message).in_field("domain"); }

InputError unbounded_error(const std::string& message) {
  return InputError("unbounded_patch", message).in_field("domain");
}

std::string format_point(const RingPtr& ring, const std::vector<mpq_class>& point) {
  std::string names, values;
  for (std::size_t j = 0; j < point.size(); ++j) {
    names += (j ? ", " : "") + ring->variables()[j];
    values += (j ? ", " : "") + point[j].get_str();
  }
  return point.size() == 1 ? names + " = " + values : "(" + names + ") = (" + values + ")";
}

std::string format_box(const std::vector<std::pair<mpq_class, mpq_class>>& box) {
  std::string out;
  for (std::size_t j = 0; j < box.size(); ++j) {
    out += (j ? "×[" : "[") + box[j].first.get_str() + ", " + box[j].second.get_str() + "]";
  }
  return out.empty() ? "the point" : out;
}

std::vector<mpq_class> corner_point(const Piece& piece, std::size_t mask) {
  std::vector<mpq_class> point;
  for (std::size_t j = 0; j < piece.box.size(); ++j) {
    point.push_back(((mask >> j) & 1U) ? piece.box[j].second : piece.box[j].first);
  }
  return point;
}

// The parameter to bisect: the longest side among those the patch depends on
// (bisecting along another leaves every coefficient as it is). None when every such
// side has length 0.
std::optional<std::size_t> choose_axis(const Piece& piece, const Layout& layout) {
  std::optional<std::size_t> best;
  mpq_class longest = 0;
  for (std::size_t j = 0; j < piece.box.size(); ++j) {
    if (layout.extents[j] < 2) continue;
    const mpq_class side = piece.box[j].second - piece.box[j].first;
    if (side > longest) {
      longest = side;
      best = j;
    }
  }
  return best;
}

std::pair<Piece, Piece> bisect(const Piece& piece, const Layout& layout, std::size_t axis, const Budget& budget) {
  Piece lower{piece.box, {}, piece.depth + 1}, upper{piece.box, {}, piece.depth + 1};
  mpq_class middle = piece.box[axis].first + piece.box[axis].second;
  mpq_div_2exp(middle.get_mpq_t(), middle.get_mpq_t(), 1);
  lower.box[axis].second = middle;
  upper.box[axis].first = middle;
  for (const Coefficients& form : piece.forms) {
    auto [l, u] = split_along(form, layout, axis, budget, kWhere);
    lower.forms.push_back(std::move(l));
    upper.forms.push_back(std::move(u));
  }
  return {std::move(lower), std::move(upper)};
}

// Lowest and highest value seen, per coordinate.
struct Range {
  std::vector<std::optional<mpq_class>> lo, hi;

  explicit Range(std::size_t n) : lo(n), hi(n) {}

  void include(std::size_t i, const mpq_class& low, const mpq_class& high) {
    if (!lo[i] || low < *lo[i]) lo[i] = low;
    if (!hi[i] || high > *hi[i]) hi[i] = high;
  }
};

// The sign shared by every coefficient of ω on the piece (0: they differ or one is 0).
int common_sign(const Coefficients& w) {
  const int s = sgn(w[0]);
  for (const mpq_class& c : w) {
    if (sgn(c) != s) return 0;
  }
  return s;
}

// Records the values at the piece's corners as attained values, after proving that
// ω does not vanish at them and does not change sign between them.
void record_corners(const Piece& piece, const Layout& layout, const RingPtr& ring, Range& attained) {
  const std::size_t corners = std::size_t{1} << piece.box.size();
  int first_sign = 0;
  std::size_t first_mask = 0;
  for (std::size_t mask = 0; mask < corners; ++mask) {
    const std::size_t index = layout.corner(mask);
    const mpq_class& w = piece.forms[0][index];
    if (sgn(w) == 0) {
      throw unbounded_error("the denominator vanishes at " + format_point(ring, corner_point(piece, mask)) +
                            ", in the domain");
    }
    if (first_sign == 0) {
      first_sign = sgn(w);
      first_mask = mask;
    } else if (sgn(w) != first_sign) {
      throw unbounded_error("the denominator changes sign between " +
                            format_point(ring, corner_point(piece, first_mask)) + " and " +
                            format_point(ring, corner_point(piece, mask)) + ", so it vanishes in the domain");
    }
    for (std::size_t i = 1; i < piece.forms.size(); ++i) {
      const mpq_class value = piece.forms[i][index] / w;
      attained.include(i - 1, value, value);
    }
  }
}

// The rational Bézier hull of the piece: [min_J, max_J] of ξ_{i,J}/w_J per coordinate.
Range hull_of(const Piece& piece) {
  Range hull(piece.forms.size() - 1);
  const Coefficients& w = piece.forms[0];
  for (std::size_t i = 1; i < piece.forms.size(); ++i) {
    for (std::size_t index = 0; index < w.size(); ++index) {
      const mpq_class ratio = piece.forms[i][index] / w[index];
      hull.include(i - 1, ratio, ratio);
    }
  }
  return hull;
}

void check_domain(const Parametrization& parametrization, const ParameterDomain& domain) {
  const std::size_t m = parametrization.parameter_ring->num_variables();
  if (domain.intervals.size() != m) {
    throw domain_error("the domain has " + std::to_string(domain.intervals.size()) +
                       " intervals, the parametrization " + std::to_string(m) + " parameters");
  }
  for (std::size_t j = 0; j < m; ++j) {
    if (domain.intervals[j].first > domain.intervals[j].second) {
      throw domain_error("the interval of " + parametrization.parameter_ring->variables()[j] + " is [" +
                         to_string(domain.intervals[j].first) + ", " + to_string(domain.intervals[j].second) +
                         "]: its lower end exceeds its upper end");
    }
  }
  if (parametrization.coordinates.empty()) throw std::invalid_argument("bound_patch: a coordinate expected");
}

// One layout for all forms: degree per parameter = the largest among ω and the ξ_i.
Layout common_layout(const std::vector<Polynomial>& forms, std::size_t m) {
  std::vector<std::size_t> extents(m, 1);
  for (const Polynomial& f : forms) {
    for (std::size_t j = 0; j < m; ++j) extents[j] = std::max(extents[j], static_cast<std::size_t>(f.degree_in(j) + 1));
  }
  return Layout(extents);
}

// The whole domain as one piece: every form in the Bernstein basis of the box.
Piece root_piece(const std::vector<Polynomial>& forms, const Layout& layout, const ParameterDomain& domain,
                 const Budget& budget) {
  Piece root;
  for (const auto& [a, b] : domain.intervals) root.box.emplace_back(to_mpq(a), to_mpq(b));
  for (const Polynomial& f : forms) root.forms.push_back(bernstein_coefficients(f, layout, root.box, budget, kWhere));
  return root;
}

// What one level of the branch and bound learns, and the pieces it passes on.
struct BoundState {
  const Layout& layout;
  const RingPtr& ring;
  const PatchBoundsParams& params;
  Range attained;  ///< the corner values seen so far: the patch reaches them
  Range result;    ///< the hulls of the pieces kept
};

// Bisects `piece` along `axis` into `next`.
void push_halves(const Piece& piece, const Layout& layout, std::size_t axis, std::vector<Piece>& next,
                 const Budget& budget) {
  auto [lower, upper] = bisect(piece, layout, axis, budget);
  next.push_back(std::move(lower));
  next.push_back(std::move(upper));
}

// The next level: pieces whose denominator's coefficients change sign are bisected
// until they agree (or a corner shows a zero); then, every corner value of this level
// known, a piece whose hull lies inside the attained range cannot widen the box and is
// dropped, and the others are bisected while depth remains, else their hull joins the
// result.
std::vector<Piece> bound_level(std::vector<Piece>& level, BoundState& s, const Budget& budget) {
  const std::size_t n = s.attained.lo.size();
  std::vector<Piece> next;
  std::vector<std::pair<Piece, Range>> positive;
  for (Piece& piece : level) {
    budget.check(kWhere);
    record_corners(piece, s.layout, s.ring, s.attained);
    if (common_sign(piece.forms[0]) != 0) {
      // All w_J < 0 needs no flip: the ratios and the convex weights are unchanged.
      Range hull = hull_of(piece);
      positive.emplace_back(std::move(piece), std::move(hull));
      continue;
    }
    const std::optional<std::size_t> axis = choose_axis(piece, s.layout);
    if (!axis || piece.depth >= s.params.max_denominator_depth) {
      throw unbounded_error("could not prove the denominator zero-free on " + format_box(piece.box) + " within " +
                            std::to_string(s.params.max_denominator_depth) + " bisections");
    }
    push_halves(piece, s.layout, *axis, next, budget);
  }
  for (auto& [piece, hull] : positive) {
    bool widens = false;
    for (std::size_t i = 0; i < n; ++i)
      widens = widens || *hull.lo[i] < *s.attained.lo[i] || *hull.hi[i] > *s.attained.hi[i];
    if (!widens) continue;
    const std::optional<std::size_t> axis =
        piece.depth < s.params.tightening_depth ? choose_axis(piece, s.layout) : std::nullopt;
    if (axis) {
      push_halves(piece, s.layout, *axis, next, budget);
    } else {
      for (std::size_t i = 0; i < n; ++i) s.result.include(i, *hull.lo[i], *hull.hi[i]);
    }
  }
  return next;
}

}  // namespace

PatchBounds bound_patch(const Parametrization& parametrization, const ParameterDomain& domain, const Budget& budget,
                        const PatchBoundsParams& params) {
  check_domain(parametrization, domain);
  const RingPtr& ring = parametrization.parameter_ring;
  const std::size_t n = parametrization.coordinates.size();
  const std::vector<Polynomial> forms = common_denominator_form(parametrization, budget);
  const Layout layout = common_layout(forms, ring->num_variables());
  // The size limit bounds the Bernstein coefficients held at once: layout.size per
  // form and piece.
  budget.check_terms(layout.size * forms.size(), kWhere);

  BoundState state{layout, ring, params, Range(n), Range(n)};
  std::vector<Piece> level;
  level.push_back(root_piece(forms, layout, domain, budget));
  while (!level.empty()) {
    budget.check_terms(level.size() * layout.size * forms.size(), kWhere);
    level = bound_level(level, state, budget);
  }

  PatchBounds bounds;
  for (std::size_t i = 0; i < n; ++i) {
    // Dropped pieces lie inside the attained range, kept ones inside their hulls.
    state.result.include(i, *state.attained.lo[i], *state.attained.hi[i]);
    bounds.lo.push_back(to_rational(*state.result.lo[i]));
    bounds.hi.push_back(to_rational(*state.result.hi[i]));
  }
  return bounds;
}

}  // namespace implicitizer
