#include "implicitizer/implicitization/patch_bounds.hpp"

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <string>

namespace implicitizer {

namespace {

using Coefficients = std::vector<mpq_class>;

// The layout of a dense coefficient tensor: one axis per parameter with
// degree + 1 entries, the last parameter fastest.
struct Layout {
  std::vector<std::size_t> extents;
  std::vector<std::size_t> strides;
  std::size_t size = 1;

  explicit Layout(std::vector<std::size_t> e) : extents(std::move(e)), strides(extents.size()) {
    for (std::size_t j = extents.size(); j-- > 0;) {
      strides[j] = size;
      size *= extents[j];
    }
  }

  // Calls f(first, stride) for every line of coefficients along `axis`.
  template <class F>
  void for_each_fiber(std::size_t axis, F&& f) const {
    const std::size_t stride = strides[axis];
    const std::size_t block = stride * extents[axis];
    for (std::size_t outer = 0; outer < size; outer += block) {
      for (std::size_t inner = 0; inner < stride; ++inner) f(outer + inner, stride);
    }
  }

  // The index of corner `mask` (bit j set: the upper end of parameter j).
  std::size_t corner(std::size_t mask) const {
    std::size_t index = 0;
    for (std::size_t j = 0; j < extents.size(); ++j) {
      if ((mask >> j) & 1U) index += (extents[j] - 1) * strides[j];
    }
    return index;
  }
};

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

// The power-basis coefficients of `p` as a dense tensor of `layout`.
Coefficients dense_coefficients(const Polynomial& p, const Layout& layout) {
  Coefficients c(layout.size);
  for (std::size_t t = 0; t < p.num_terms(); ++t) {
    const std::vector<std::int32_t> e = p.exponents(t);
    std::size_t index = 0;
    for (std::size_t j = 0; j < e.size(); ++j) index += static_cast<std::size_t>(e[j]) * layout.strides[j];
    c[index] = to_mpq(p.coefficient(t));
  }
  return c;
}

// Rewrites power-basis coefficients in parameter `axis` as Bernstein coefficients
// on [a, b]: p(t) = q(u) with t = a + (b − a)·u (Taylor shift, then scaling), then
// b_k = Σ_{i ≤ k} C(k,i)/C(n,i)·q_i, the Bernstein form of q on [0, 1].
void to_bernstein_along(Coefficients& c, const Layout& layout, std::size_t axis, const mpq_class& a,
                        const mpq_class& b) {
  const std::size_t n = layout.extents[axis] - 1;
  if (n == 0) return;
  const mpq_class h = b - a;
  // ratio[k][i] = C(k,i)/C(n,i).
  std::vector<std::vector<mpq_class>> ratio(n + 1, std::vector<mpq_class>(n + 1));
  {
    std::vector<std::vector<mpz_class>> binomial(n + 1, std::vector<mpz_class>(n + 1));
    for (std::size_t k = 0; k <= n; ++k) {
      binomial[k][0] = 1;
      for (std::size_t i = 1; i <= k; ++i) binomial[k][i] = binomial[k - 1][i - 1] + (i < k ? binomial[k - 1][i] : 0);
    }
    for (std::size_t k = 0; k <= n; ++k) {
      for (std::size_t i = 0; i <= k; ++i) {
        ratio[k][i] = mpq_class(binomial[k][i], binomial[n][i]);
        ratio[k][i].canonicalize();
      }
    }
  }
  std::vector<mpq_class> q(n + 1);
  layout.for_each_fiber(axis, [&](std::size_t first, std::size_t stride) {
    for (std::size_t i = 0; i <= n; ++i) q[i] = c[first + i * stride];
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t k = n; k-- > i;) q[k] += a * q[k + 1];
    }
    mpq_class power = h;
    for (std::size_t i = 1; i <= n; ++i, power *= h) q[i] *= power;
    for (std::size_t k = 0; k <= n; ++k) {
      mpq_class sum = 0;
      for (std::size_t i = 0; i <= k; ++i) sum += ratio[k][i] * q[i];
      c[first + k * stride] = sum;
    }
  });
}

// Splits Bernstein coefficients at the midpoint of parameter `axis` (de Casteljau
// with weight 1/2): the coefficients of the lower and of the upper half.
std::pair<Coefficients, Coefficients> split_along(const Coefficients& c, const Layout& layout, std::size_t axis) {
  const std::size_t n = layout.extents[axis] - 1;
  Coefficients lower(c.size()), upper(c.size());
  std::vector<mpq_class> work(n + 1);
  layout.for_each_fiber(axis, [&](std::size_t first, std::size_t stride) {
    for (std::size_t i = 0; i <= n; ++i) work[i] = c[first + i * stride];
    lower[first] = work[0];
    upper[first + n * stride] = work[n];
    for (std::size_t r = 1; r <= n; ++r) {
      for (std::size_t k = 0; k + r <= n; ++k) {
        work[k] += work[k + 1];
        mpq_div_2exp(work[k].get_mpq_t(), work[k].get_mpq_t(), 1);
      }
      lower[first + r * stride] = work[0];
      upper[first + (n - r) * stride] = work[n - r];
    }
  });
  return {std::move(lower), std::move(upper)};
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

std::pair<Piece, Piece> bisect(const Piece& piece, const Layout& layout, std::size_t axis) {
  Piece lower{piece.box, {}, piece.depth + 1}, upper{piece.box, {}, piece.depth + 1};
  mpq_class middle = piece.box[axis].first + piece.box[axis].second;
  mpq_div_2exp(middle.get_mpq_t(), middle.get_mpq_t(), 1);
  lower.box[axis].second = middle;
  upper.box[axis].first = middle;
  for (const Coefficients& form : piece.forms) {
    auto [l, u] = split_along(form, layout, axis);
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
  for (const Polynomial& f : forms) {
    Coefficients c = dense_coefficients(f, layout);
    for (std::size_t j = 0; j < layout.extents.size(); ++j) {
      to_bernstein_along(c, layout, j, root.box[j].first, root.box[j].second);
      budget.check(kWhere);
    }
    root.forms.push_back(std::move(c));
  }
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
void push_halves(const Piece& piece, const Layout& layout, std::size_t axis, std::vector<Piece>& next) {
  auto [lower, upper] = bisect(piece, layout, axis);
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
    push_halves(piece, s.layout, *axis, next);
  }
  for (auto& [piece, hull] : positive) {
    bool widens = false;
    for (std::size_t i = 0; i < n; ++i)
      widens = widens || *hull.lo[i] < *s.attained.lo[i] || *hull.hi[i] > *s.attained.hi[i];
    if (!widens) continue;
    const std::optional<std::size_t> axis =
        piece.depth < s.params.tightening_depth ? choose_axis(piece, s.layout) : std::nullopt;
    if (axis) {
      push_halves(piece, s.layout, *axis, next);
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
  const std::vector<Polynomial> forms = common_denominator_form(parametrization);
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
