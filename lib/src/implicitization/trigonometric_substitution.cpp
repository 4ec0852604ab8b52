#include "implicitizer/implicitization/trigonometric_substitution.hpp"

#include <cmath>
#include <map>
#include <numbers>
#include <optional>
#include <set>

#include "implicitizer/core/errors.hpp"
#include "implicitizer/implicitization/patch_bounds.hpp"
#include "implicitizer/polynomial/parser.hpp"

namespace implicitizer {

namespace {

// The largest |k| in cos(k·θ): (1 + i·t)^(2k) has 2k + 1 terms, as x^1000 is the
// parser's largest power.
constexpr long kMaxMultiple = 1000;

// The phase every limit of the conversion names.
constexpr const char* kWhere = "the trigonometric substitution";

bool is_trigonometric(const std::string& f) { return f == "cos" || f == "sin" || f == "tan"; }

// Where a parameter is used: the first call of each kind, the first use outside.
struct Use {
  std::size_t field = 0;
  std::size_t position = 0;
  std::string function;  // empty outside any function
};

struct ParameterUses {
  std::optional<Use> outside;
  std::optional<Use> trigonometric;
  std::optional<Use> hyperbolic;
};

// Σ k_j θ_j: one integer per parameter of the input's ring.
using Combination = std::vector<long>;

InputError error_at(const std::string& code, const std::string& message, const Use& use,
                    const std::vector<std::string>& fields) {
  return InputError(code, message, use.position).in_field(fields[use.field]);
}

std::string call_text(const Expression& call) { return "'" + call.name + "' (" + call.name + "(...))"; }

// The argument of `call` as an integer combination of the parameters, or the reason
// it is not one.
Combination combination_of(const Expression& call, const RingPtr& ring, const Budget& budget, std::size_t field,
                           const std::vector<std::string>& fields) {
  const Use at{field, call.position, call.name};
  const Expression& argument = *call.children[0];
  if (contains_call(argument)) {
    throw error_at("nonlinear_argument",
                   "the argument of " + call_text(call) +
                       " contains another function; it must be an integer "
                       "combination of parameters such as 2*u+v",
                   at, fields);
  }
  Polynomial p(ring);
  try {
    p = evaluate_polynomial(argument, ring, budget);
  } catch (const InputError& e) {
    if (e.code() != "non_constant_denominator") throw e.in_field(fields[field]);
    throw error_at("nonlinear_argument", "the argument of " + call_text(call) + " divides by a parameter", at, fields);
  }
  Combination k(ring->num_variables(), 0);
  for (std::size_t i = 0; i < p.num_terms(); ++i) {
    const std::vector<std::int32_t> e = p.exponents(i);
    std::int32_t degree = 0;
    std::size_t var = 0;
    for (std::size_t v = 0; v < e.size(); ++v) {
      degree += e[v];
      if (e[v]) var = v;
    }
    const mpq_class c = to_mpq(p.coefficient(i));
    if (degree > 1) {
      throw error_at("nonlinear_argument",
                     "the argument of " + call_text(call) + " is not linear in the parameters (like cos(s*t) or " +
                         "cos(u^2)); it must be an integer combination such as 2*u+v",
                     at, fields);
    }
    if (degree == 0 || c.get_den() != 1) {
      throw error_at("non_integer_argument",
                     "the argument of " + call_text(call) +
                         (degree == 0 ? " has a constant term" : " has a fractional multiple of a parameter") +
                         "; only integer combinations such as 2*u+v have an exact rational form (for cos(u/2), "
                         "take w = u/2 as the parameter: cos(w))",
                     at, fields);
    }
    if (abs(c) > kMaxMultiple) {
      throw error_at(
          "multiple_too_large",
          "a multiple in the argument of " + call_text(call) + " is larger than " + std::to_string(kMaxMultiple), at,
          fields);
    }
    k[var] = c.get_num().get_si();
  }
  return k;
}

// Records the uses of parameters in one coordinate's tree and the combination of each
// of its calls.
class UseScanner {
 public:
  UseScanner(const RingPtr& ring, const Budget& budget, const std::vector<std::string>& fields)
      : ring_(ring), budget_(budget), fields_(fields), uses_(ring->num_variables()) {}

  void scan(const Expression& e, std::size_t field) {
    if (e.kind == Expression::Kind::identifier) {
      if (const auto v = ring_->index_of(e.name); v && !uses_[*v].outside)
        uses_[*v].outside = Use{field, e.position, ""};
      return;
    }
    if (e.kind == Expression::Kind::call) {
      const Combination k = combination_of(e, ring_, budget_, field, fields_);
      for (std::size_t v = 0; v < k.size(); ++v) {
        if (k[v] == 0) continue;
        auto& slot = is_trigonometric(e.name) ? uses_[v].trigonometric : uses_[v].hyperbolic;
        if (!slot) slot = Use{field, e.position, e.name};
      }
      combinations_.emplace(&e, k);
      return;
    }
    for (const auto& c : e.children) scan(*c, field);
  }

  // Throws for a parameter used in two ways no single substitution makes rational.
  void check_uses() const {
    for (std::size_t v = 0; v < uses_.size(); ++v) {
      const ParameterUses& u = uses_[v];
      const std::string& name = ring_->variables()[v];
      const std::optional<Use>& inside = u.trigonometric ? u.trigonometric : u.hyperbolic;
      if (u.outside && inside) {
        throw error_at("parameter_inside_and_outside",
                       "parameter '" + name + "' is inside the function '" + inside->function +
                           "' and also outside any function (" + fields_[u.outside->field] + ", position " +
                           std::to_string(u.outside->position) + "); a mix like u*cos(u) has no rational form",
                       *inside, fields_);
      }
      if (u.trigonometric && u.hyperbolic) {
        throw error_at("mixed_function_kinds",
                       "parameter '" + name + "' is inside the trigonometric '" + u.trigonometric->function +
                           "' and the hyperbolic '" + u.hyperbolic->function +
                           "'; one substitution cannot make both "
                           "rational",
                       *u.hyperbolic, fields_);
      }
    }
  }

  const std::vector<ParameterUses>& uses() const { return uses_; }
  const Combination& combination(const Expression& call) const { return combinations_.at(&call); }

 private:
  RingPtr ring_;
  const Budget& budget_;
  const std::vector<std::string>& fields_;
  std::vector<ParameterUses> uses_;
  std::map<const Expression*, Combination> combinations_;
};

// The ring after the substitution: replaced parameters renamed tθ or eθ.
std::vector<ParameterSubstitution> name_substitutions(const Ring& ring, const std::vector<ParameterUses>& uses,
                                                      std::vector<std::string>& names) {
  names = ring.variables();
  std::set<std::string> taken(names.begin(), names.end());
  std::vector<ParameterSubstitution> substitutions;
  for (std::size_t v = 0; v < uses.size(); ++v) {
    if (!uses[v].trigonometric && !uses[v].hyperbolic) continue;
    ParameterSubstitution s;
    s.kind = uses[v].trigonometric ? ParameterSubstitution::Kind::half_angle : ParameterSubstitution::Kind::exponential;
    s.parameter = names[v];
    // No '_': the reproduce scripts keep names of letters and digits (Macaulay2 reads
    // '_' as an operator), so the scripts and the answer name the same parameters.
    const std::string base = (uses[v].trigonometric ? "t" : "e") + names[v];
    s.variable = base;
    for (int n = 1; taken.count(s.variable); ++n) s.variable = base + std::to_string(n);
    taken.insert(s.variable);
    names[v] = s.variable;
    substitutions.push_back(s);
  }
  return substitutions;
}

// a + i·b with polynomial parts.
struct Gaussian {
  Polynomial re;
  Polynomial im;
};

Gaussian multiply(const Gaussian& a, const Gaussian& b, const Budget& budget) {
  return {a.re.multiply(b.re, budget) - a.im.multiply(b.im, budget),
          a.re.multiply(b.im, budget) + a.im.multiply(b.re, budget)};
}

// (1 + sign·i·t)^n by the binomial theorem: the term C(n, m)·(sign·i)^m·t^m is real
// for even m (sign (−1)^(m/2)), imaginary for odd m. The terms are collected and
// sorted once: adding them one by one to a polynomial copied every coefficient at
// every step, quadratic in n.
Gaussian binomial_power(const RingPtr& ring, std::size_t var, long n, int sign, const Budget& budget) {
  constexpr const char* kExpansion = "the binomial expansion";
  budget.check_predicted_terms(static_cast<std::size_t>(n) + 1, kExpansion,
                               [&] { return "(1 + i*t)^" + std::to_string(n); });
  const std::size_t w = ring->monomial_size();
  std::vector<Integer> coefficients[2];
  std::vector<std::int32_t> monomials[2];
  Integer binomial = 1;
  std::vector<std::int32_t> exponents(ring->num_variables(), 0);
  for (long m = 0; m <= n; ++m) {
    exponents[var] = static_cast<std::int32_t>(m);
    const int i_power = static_cast<int>(m % 4);  // i^m = 1, i, −1, −i
    const int i_sign = (i_power >= 2 ? -1 : 1) * ((m % 2 == 1 && sign < 0) ? -1 : 1);
    const std::size_t part = static_cast<std::size_t>(m % 2);
    coefficients[part].push_back(binomial * i_sign);
    monomials[part].resize(monomials[part].size() + w);
    ring->encode(exponents.data(), monomials[part].data() + monomials[part].size() - w);
    binomial = binomial * (n - m) / (m + 1);
    if (m % 64 == 0) budget.check(kExpansion);
  }
  return {Polynomial::from_terms(ring, Rational(1), std::move(coefficients[0]), std::move(monomials[0])),
          Polynomial::from_terms(ring, Rational(1), std::move(coefficients[1]), std::move(monomials[1]))};
}

// cos, sin or tan of Σ k_j θ_j, the θ_j half angles t_j.
RationalFunction trigonometric_value(const std::string& f, const Combination& k, const RingPtr& ring,
                                     const Budget& budget) {
  Gaussian z{Polynomial::constant(ring, Rational(1)), Polynomial(ring)};
  Polynomial denominator = Polynomial::constant(ring, Rational(1));
  for (std::size_t v = 0; v < k.size(); ++v) {
    if (k[v] == 0) continue;
    const long n = k[v] < 0 ? -k[v] : k[v];
    z = multiply(z, binomial_power(ring, v, 2 * n, k[v] < 0 ? -1 : 1, budget), budget);
    const Polynomial t = Polynomial::variable(ring, v);
    const Polynomial one_plus_t2 = Polynomial::constant(ring, Rational(1)) + t * t;
    denominator = denominator.multiply(one_plus_t2.pow(static_cast<unsigned>(n), budget), budget);
  }
  // In lowest terms already, so no gcd (of two polynomials of 2|k| + 1 terms per
  // parameter) is taken: with P = Π (1 + i·t_j)^(2|k_j|) and P̄ its conjugate, the
  // denominator's only prime factors are the 1 + t_j² = (1 + i·t_j)(1 − i·t_j), and at
  // t_j = ±i one of P, P̄ vanishes and the other does not, so neither re = (P + P̄)/2
  // nor im = (P − P̄)/(2i) vanishes there; and a common factor of re and im would
  // divide P and P̄, which share none.
  if (f == "cos") return RationalFunction::from_coprime(z.re, denominator);
  if (f == "sin") return RationalFunction::from_coprime(z.im, denominator);
  return RationalFunction::from_coprime(z.im, z.re);
}

// cosh, sinh or tanh of Σ k_j θ_j, the θ_j exponentials e_j: E = N/D with monomials.
RationalFunction hyperbolic_value(const std::string& f, const Combination& k, const RingPtr& ring,
                                  const Budget& budget) {
  std::vector<std::int32_t> up(ring->num_variables(), 0);
  std::vector<std::int32_t> down(ring->num_variables(), 0);
  for (std::size_t v = 0; v < k.size(); ++v)
    (k[v] > 0 ? up : down)[v] = static_cast<std::int32_t>(k[v] < 0 ? -k[v] : k[v]);
  const Polynomial n = Polynomial::term(ring, Rational(1), up);
  const Polynomial d = Polynomial::term(ring, Rational(1), down);
  const Polynomial n2 = n.multiply(n, budget);
  const Polynomial d2 = d.multiply(d, budget);
  const Polynomial two_nd = n.multiply(d, budget).scaled(Rational(2));
  // In lowest terms already: N and D are monomials in disjoint variables, so no
  // variable divides N² ± D², and a common factor of N² − D² and N² + D² would divide
  // 2N² and 2D².
  if (f == "cosh") return RationalFunction::from_coprime(n2 + d2, two_nd);
  if (f == "sinh") return RationalFunction::from_coprime(n2 - d2, two_nd);
  return RationalFunction::from_coprime(n2 - d2, n2 + d2);
}

}  // namespace

const char* to_string(ParameterSubstitution::Kind kind) {
  return kind == ParameterSubstitution::Kind::half_angle ? "half_angle" : "exponential";
}

std::string to_string(const ParameterSubstitution& s) {
  return s.variable + " = " +
         (s.kind == ParameterSubstitution::Kind::half_angle ? "tan(" + s.parameter + "/2)"
                                                            : "exp(" + s.parameter + ")");
}

bool contains_call(const Expression& e) {
  if (e.kind == Expression::Kind::call) return true;
  for (const auto& c : e.children) {
    if (contains_call(*c)) return true;
  }
  return false;
}

RationalizedCoordinates substitute_trigonometric(const std::vector<const Expression*>& coordinates,
                                                 const std::vector<std::string>& fields, const RingPtr& parameters,
                                                 const Budget& budget) {
  UseScanner scanner(parameters, budget, fields);
  for (std::size_t i = 0; i < coordinates.size(); ++i) scanner.scan(*coordinates[i], i);
  scanner.check_uses();
  RationalizedCoordinates out;
  std::vector<std::string> names;
  out.substitutions = name_substitutions(*parameters, scanner.uses(), names);
  out.parameter_ring = Ring::make(names);
  const RingPtr& ring = out.parameter_ring;
  // The products and powers of the converted values are where the terms multiply: a
  // limit they reach names this phase.
  const Budget phased = budget.in_phase(kWhere);
  const CallEvaluator calls = [&](const Expression& call) {
    const Combination& k = scanner.combination(call);
    return is_trigonometric(call.name) ? trigonometric_value(call.name, k, ring, phased)
                                       : hyperbolic_value(call.name, k, ring, phased);
  };
  for (std::size_t i = 0; i < coordinates.size(); ++i) {
    try {
      out.coordinates.push_back(evaluate_rational_function(*coordinates[i], ring, phased, calls));
    } catch (const InputError& e) {
      throw e.in_field(fields[i]);
    }
  }
  return out;
}

ParameterDomain map_parameter_domain(const std::vector<ParameterSubstitution>& substitutions,
                                     const Ring& rational_parameters, const ParameterDomain& domain) {
  ParameterDomain out = domain;
  for (const auto& s : substitutions) {
    const auto index = rational_parameters.index_of(s.variable);
    if (!index || *index >= out.intervals.size()) continue;
    auto& [lo, hi] = out.intervals[*index];
    const double a = CGAL::to_double(lo);
    const double b = CGAL::to_double(hi);
    const bool half_angle = s.kind == ParameterSubstitution::Kind::half_angle;
    const double mapped_lo = half_angle ? std::tan(a / 2) : std::exp(a);
    const double mapped_hi = half_angle ? std::tan(b / 2) : std::exp(b);
    const bool inside = half_angle ? (a > -std::numbers::pi && b < std::numbers::pi) : std::isfinite(mapped_hi);
    if (!inside) {
      throw InputError("domain_out_of_range",
                       "the interval of " + s.parameter + " maps through " + to_string(s) +
                           (half_angle ? " only inside (-pi, pi): theta = pi is tan(theta/2) = infinity"
                                       : " to a number beyond double range"))
          .in_field("domain");
    }
    lo = Rational(mapped_lo);
    hi = Rational(mapped_hi);
  }
  return out;
}

}  // namespace implicitizer
