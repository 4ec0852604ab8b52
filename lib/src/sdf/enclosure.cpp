#include "implicitizer/sdf/enclosure.hpp"

#include <cmath>
#include <optional>
#include <stdexcept>
#include <vector>

namespace implicitizer {
namespace {

using Interval = std::pair<Rational, Rational>;

const char* const kWhere = "shape auto";

int sign_of(const Rational& q) { return q > Rational(0) ? 1 : (q < Rational(0) ? -1 : 0); }

// Power-basis coefficients q_0..q_n of a polynomial on [0, 1], replaced by its
// Bernstein coefficients b_k = Σ_{i ≤ k} C(k, i)/C(n, i)·q_i: divide by C(n, i), then
// the binomial transform as n rounds of adjacent sums: O(n²) exact additions, so the
// budget is checked every round (a degree of 1000 would otherwise run for hours).
void power_to_bernstein(std::vector<mpq_class>& q, const Budget& budget) {
  const std::size_t n = q.size() - 1;
  mpz_class binomial = 1;
  for (std::size_t i = 1; i <= n; ++i) {
    binomial = binomial * static_cast<unsigned long>(n - i + 1) / static_cast<unsigned long>(i);
    q[i] /= binomial;
  }
  for (std::size_t round = 1; round <= n; ++round) {
    budget.check(kWhere);
    for (std::size_t k = n; k >= round; --k) q[k] += q[k - 1];
  }
}

// The Bernstein coefficients of a facet polynomial on one piece, as a dense
// (degree_0 + 1) × (degree_1 + 1) array (degree_1 = 0 for a curve's edge).
struct BernsteinPatch {
  std::size_t extent0 = 1, extent1 = 1;
  std::vector<mpq_class> b;

  const mpq_class& at(std::size_t i, std::size_t j) const { return b[i * extent1 + j]; }
};

// F on one facet: the variable `axis` fixed at `value`, the others (`free`, one or
// two) free within the facet's sides.
struct Facet {
  std::size_t axis;
  Rational value;
  std::vector<std::size_t> free;
  Polynomial g;
};

// A piece of a facet: its sides (one per free variable) and F's Bernstein
// coefficients on it.
struct Piece {
  std::vector<Interval> sides;
  BernsteinPatch patch;
  std::size_t depth = 0;
};

// The Bernstein coefficients of the two halves of `patch` along its axis `axis` (0 or
// 1), by de Casteljau's algorithm at 1/2 on every line of coefficients along it:
// exact, and far cheaper than composing F with each half's affine map again.
std::pair<BernsteinPatch, BernsteinPatch> halve(const BernsteinPatch& patch, std::size_t axis, const Budget& budget) {
  BernsteinPatch lower = patch, upper = patch;
  const std::size_t n = (axis == 0 ? patch.extent0 : patch.extent1) - 1;
  const std::size_t lines = axis == 0 ? patch.extent1 : patch.extent0;
  const std::size_t stride = axis == 0 ? patch.extent1 : 1;
  std::vector<mpq_class> work(n + 1);
  for (std::size_t line = 0; line < lines; ++line) {
    const std::size_t first = axis == 0 ? line : line * patch.extent1;
    budget.check(kWhere);  // O(n²) exact operations a line
    for (std::size_t k = 0; k <= n; ++k) work[k] = patch.b[first + k * stride];
    // After round r, work[0] is the lower half's coefficient r and work[n − r] the
    // upper half's coefficient n − r.
    for (std::size_t r = 1; r <= n; ++r) {
      for (std::size_t k = 0; k + r <= n; ++k) {
        work[k] += work[k + 1];
        mpq_div_2exp(work[k].get_mpq_t(), work[k].get_mpq_t(), 1);
      }
      lower.b[first + r * stride] = work[0];
      upper.b[first + (n - r) * stride] = work[n - r];
    }
  }
  return {std::move(lower), std::move(upper)};
}

// F's Bernstein coefficients on the facet's sub-box `sides`: compose with the affine
// map from [0, 1]^k, then convert the power basis along each free variable.
BernsteinPatch bernstein_on(const Facet& facet, const std::vector<Interval>& sides, const Budget& budget) {
  const RingPtr& ring = facet.g.ring();
  std::vector<Polynomial> values;
  for (std::size_t v = 0; v < ring->num_variables(); ++v) values.push_back(Polynomial::variable(ring, v));
  for (std::size_t j = 0; j < facet.free.size(); ++j) {
    const Interval& side = sides[j];
    values[facet.free[j]] = Polynomial::constant(ring, side.first) +
                            Polynomial::variable(ring, facet.free[j]).scaled(side.second - side.first);
  }
  const Polynomial h = facet.g.compose(ring, values, budget);
  BernsteinPatch patch;
  // Two free variables on a face of a 3-D box, one on an edge of a 2-D box (v1 = v0
  // then, with extent 1).
  const std::size_t v0 = facet.free[0];
  const bool two = facet.free.size() > 1;
  const std::size_t v1 = two ? facet.free[1] : v0;
  patch.extent0 = static_cast<std::size_t>(h.degree_in(v0)) + 1;
  patch.extent1 = two ? static_cast<std::size_t>(h.degree_in(v1)) + 1 : 1;
  patch.b.assign(patch.extent0 * patch.extent1, mpq_class(0));
  for (std::size_t t = 0; t < h.num_terms(); ++t) {
    const std::vector<std::int32_t> e = h.exponents(t);
    const auto i = static_cast<std::size_t>(e[v0]);
    const std::size_t j = two ? static_cast<std::size_t>(e[v1]) : 0;
    patch.b[i * patch.extent1 + j] = to_mpq(h.coefficient(t));
  }
  std::vector<mpq_class> line(patch.extent0);
  for (std::size_t j = 0; j < patch.extent1; ++j) {
    for (std::size_t i = 0; i < patch.extent0; ++i) line[i] = patch.b[i * patch.extent1 + j];
    power_to_bernstein(line, budget);
    for (std::size_t i = 0; i < patch.extent0; ++i) patch.b[i * patch.extent1 + j] = line[i];
  }
  line.resize(patch.extent1);
  for (std::size_t i = 0; i < patch.extent0; ++i) {
    for (std::size_t j = 0; j < patch.extent1; ++j) line[j] = patch.b[i * patch.extent1 + j];
    power_to_bernstein(line, budget);
    for (std::size_t j = 0; j < patch.extent1; ++j) patch.b[i * patch.extent1 + j] = line[j];
  }
  return patch;
}

std::string format_point(const RingPtr& ring, const std::vector<Rational>& point, std::size_t dimension) {
  std::string names, values;
  for (std::size_t j = 0; j < dimension; ++j) {
    names += (j ? ", " : "") + ring->variables()[j];
    values += (j ? ", " : "") + to_string(point[j]);
  }
  return "(" + names + ") = (" + values + ")";
}

// Step 1 of the file comment: the sign σ of F on the whole boundary, or why none was proven.
class BoundarySign {
 public:
  BoundarySign(const Polynomial& f, std::span<const Interval> box, const Budget& budget, const EnclosureParams& params)
      : f_(f), box_(box), budget_(budget), params_(params) {}

  // σ ∈ {−1, 1}, or nullopt with reason() set.
  std::optional<int> prove() {
    for (std::size_t axis = 0; axis < box_.size(); ++axis) {
      for (const Rational& value : {box_[axis].first, box_[axis].second}) {
        if (!prove_facet(axis, value)) return std::nullopt;
      }
    }
    return sign_;
  }
  const std::string& reason() const { return reason_; }

 private:
  // The point of the facet at corner `mask` of `piece`.
  std::vector<Rational> corner(const Facet& facet, const Piece& piece, std::size_t mask) const {
    std::vector<Rational> point(f_.ring()->num_variables(), Rational(0));
    point[facet.axis] = facet.value;
    for (std::size_t j = 0; j < facet.free.size(); ++j) {
      point[facet.free[j]] = ((mask >> j) & 1U) ? piece.sides[j].second : piece.sides[j].first;
    }
    return point;
  }

  // Checks the corner values (exact: the Bernstein corner coefficients) against σ.
  bool corners_agree(const Facet& facet, const Piece& piece, const BernsteinPatch& patch) {
    for (std::size_t mask = 0; mask < (std::size_t{1} << facet.free.size()); ++mask) {
      const std::size_t i = (mask & 1U) ? patch.extent0 - 1 : 0;
      const std::size_t j = (mask & 2U) ? patch.extent1 - 1 : 0;
      const int s = sgn(patch.at(i, j));
      if (s != 0 && sign_ == 0) sign_ = s;
      if (s == 0 || s != sign_) {
        reason_ = std::string(s == 0 ? "F vanishes on the boundary at " : "F changes sign on the boundary, at ") +
                  format_point(f_.ring(), corner(facet, piece, mask), box_.size());
        return false;
      }
    }
    return true;
  }

  bool prove_facet(std::size_t axis, const Rational& value) {
    Facet facet{axis, value, {}, f_.substitute(axis, Polynomial::constant(f_.ring(), value), budget_)};
    Piece root;
    for (std::size_t j = 0; j < box_.size(); ++j) {
      if (j == axis) continue;
      facet.free.push_back(j);
      root.sides.push_back(box_[j]);
    }
    root.patch = bernstein_on(facet, root.sides, budget_);
    std::vector<Piece> pending{root};
    std::size_t examined = 0;
    while (!pending.empty()) {
      budget_.check(kWhere);
      Piece piece = std::move(pending.back());
      pending.pop_back();
      if (++examined > params_.max_pieces) {
        return undecided(facet, "more than " + std::to_string(params_.max_pieces) + " pieces");
      }
      if (!corners_agree(facet, piece, piece.patch)) return false;
      bool strict = true;
      for (const mpq_class& c : piece.patch.b) strict = strict && sgn(c) == sign_;
      if (strict) continue;
      if (piece.depth >= params_.max_depth) {
        return undecided(facet, "still mixed signs after " + std::to_string(piece.depth) + " bisections");
      }
      // Bisect the longest side among the variables F depends on (halving another
      // changes no coefficient).
      std::optional<std::size_t> longest;
      for (std::size_t j = 0; j < piece.sides.size(); ++j) {
        if ((j == 0 ? piece.patch.extent0 : piece.patch.extent1) < 2) continue;
        if (!longest ||
            piece.sides[j].second - piece.sides[j].first > piece.sides[*longest].second - piece.sides[*longest].first) {
          longest = j;
        }
      }
      // Constant on the piece: its corners, which agreed, are all its coefficients.
      if (!longest) continue;
      auto [low, high] = halve(piece.patch, *longest, budget_);
      const Rational middle = (piece.sides[*longest].first + piece.sides[*longest].second) / Rational(2);
      Piece lower{piece.sides, std::move(low), piece.depth + 1}, upper{piece.sides, std::move(high), piece.depth + 1};
      lower.sides[*longest].second = middle;
      upper.sides[*longest].first = middle;
      pending.push_back(std::move(lower));
      pending.push_back(std::move(upper));
    }
    return true;
  }

  bool undecided(const Facet& facet, const std::string& what) {
    reason_ = "undecided: the sign of F on the facet " + f_.ring()->variables()[facet.axis] + " = " +
              to_string(facet.value) + " was not proven (" + what + ")";
    return false;
  }

  const Polynomial& f_;
  std::span<const Interval> box_;
  const Budget& budget_;
  const EnclosureParams& params_;
  int sign_ = 0;
  std::string reason_;
};

// Step 2: a point strictly inside the box where F has sign `wanted`, found on grids
// in double and confirmed exactly; nullopt if none of the grids shows one.
std::optional<std::vector<Rational>> find_interior_sign(const Polynomial& f, std::span<const Interval> box, int wanted,
                                                        const Budget& budget, const EnclosureParams& params) {
  const std::size_t n = box.size();
  const std::size_t variables = f.ring()->num_variables();
  std::vector<double> coefficients;
  std::vector<std::vector<std::int32_t>> exponents;
  for (std::size_t t = 0; t < f.num_terms(); ++t) {
    coefficients.push_back(to_mpq(f.coefficient(t)).get_d());
    exponents.push_back(f.exponents(t));
  }
  std::vector<std::int32_t> degree(n);
  for (std::size_t j = 0; j < n; ++j) degree[j] = f.degree_in(j);
  for (std::size_t level = 1; level <= params.max_grid_level; ++level) {
    const std::size_t steps = std::size_t{1} << level;
    // powers[j][i][e] = (grid coordinate i of axis j)^e, i = 1 .. steps − 1.
    std::vector<std::vector<std::vector<double>>> powers(n);
    for (std::size_t j = 0; j < n; ++j) {
      const double lo = to_mpq(box[j].first).get_d(), hi = to_mpq(box[j].second).get_d();
      powers[j].resize(steps);
      for (std::size_t i = 1; i < steps; ++i) {
        const double x = lo + (hi - lo) * static_cast<double>(i) / static_cast<double>(steps);
        powers[j][i].assign(static_cast<std::size_t>(degree[j]) + 1, 1.0);
        for (std::size_t e = 1; e < powers[j][i].size(); ++e) powers[j][i][e] = powers[j][i][e - 1] * x;
      }
    }
    // The grid point where wanted·F is largest, in double.
    double best = 0;
    std::vector<std::size_t> best_index, index(n, 1);
    for (bool more = true; more;) {
      double value = 0;
      for (std::size_t t = 0; t < coefficients.size(); ++t) {
        double term = coefficients[t];
        for (std::size_t j = 0; j < n; ++j) term *= powers[j][index[j]][static_cast<std::size_t>(exponents[t][j])];
        value += term;
      }
      if (wanted * value > best) {
        best = wanted * value;
        best_index = index;
      }
      more = false;
      for (std::size_t j = 0; j < n && !more; ++j) {
        if (++index[j] < steps) {
          more = true;
        } else {
          index[j] = 1;
        }
      }
      if (index[0] == 1) budget.check(kWhere);
    }
    if (best_index.empty()) continue;
    std::vector<Rational> point(variables, Rational(0));
    for (std::size_t j = 0; j < n; ++j) {
      point[j] = box[j].first + (box[j].second - box[j].first) * Rational(static_cast<int>(best_index[j])) /
                                    Rational(static_cast<int>(steps));
    }
    if (sign_of(f.evaluate(point)) == wanted) return point;
  }
  return std::nullopt;
}

}  // namespace

Enclosure decide_enclosure(const Polynomial& f, std::span<const std::pair<Rational, Rational>> box,
                           const Budget& budget, const EnclosureParams& params) {
  const std::size_t n = box.size();
  if (n < 2 || n > 3 || n > f.ring()->num_variables()) {
    throw std::invalid_argument("decide_enclosure: a box of 2 or 3 intervals within the ring's variables");
  }
  for (std::size_t j = 0; j < f.ring()->num_variables(); ++j) {
    if (j < n && !(box[j].first < box[j].second)) throw std::invalid_argument("decide_enclosure: empty box side");
    if (j >= n && f.involves(j)) throw std::invalid_argument("decide_enclosure: F involves a variable beyond the box");
  }
  Enclosure out;
  if (f.is_constant()) {
    out.reason = "F is constant";
    return out;
  }
  BoundarySign boundary(f, box, budget, params);
  const std::optional<int> sign = boundary.prove();
  if (!sign) {
    out.reason = boundary.reason();
    return out;
  }
  const std::string side = *sign > 0 ? "F > 0" : "F < 0";
  const std::optional<std::vector<Rational>> inside = find_interior_sign(f, box, -*sign, budget, params);
  if (!inside) {
    out.reason = side + " on the boundary, and no point of the other sign was found inside (undecided)";
    return out;
  }
  out.shape = SdfShape::solid;
  out.negate = *sign < 0;
  out.reason = side + " on the boundary and " + (*sign > 0 ? "F < 0" : "F > 0") + " at " +
               format_point(f.ring(), *inside, n) + ": the surface encloses a region inside the box";
  return out;
}

}  // namespace implicitizer
