#include "implicitizer/implicitization/parametrization.hpp"

#include <algorithm>
#include <set>
#include <stdexcept>

#include "implicitizer/core/errors.hpp"
#include "implicitizer/polynomial/expression.hpp"
#include "implicitizer/polynomial/gcd.hpp"
#include "implicitizer/polynomial/parser.hpp"

namespace implicitizer {

namespace {

bool is_space_variable(const std::string& name) { return name == "x" || name == "y" || name == "z"; }

const Expression* find_identifier(const Expression& e, const std::string& name) {
  if (e.kind == Expression::Kind::identifier && e.name == name) return &e;
  for (const auto& c : e.children) {
    if (const Expression* found = find_identifier(*c, name)) return found;
  }
  return nullptr;
}

constexpr const char* kCommonDenominator = "the common denominator of the parametrization";

// lcm(members), positive and primitive, with gcds taken only of members and their
// divisors, never of the growing lcm: FLINT's gcd and division cannot be interrupted,
// and the lcm of (1 + t²)^1000 and (1 + s²)^1000 has a million terms. Adding q to
// w = lcm(seen) multiplies w by q / gcd(w, q), and gcd(w, q) = lcm of the gcd(p, q),
// p in seen (gcd and lcm distribute over each other in a UFD): divisors of q. The
// recursion is on fewer members each time (2^members calls: a parametrization has
// at most three coordinates).
Polynomial lcm_of_members(const std::vector<Polynomial>& members, const RingPtr& ring, const Budget& budget) {
  Polynomial w = Polynomial::constant(ring, Rational(1));
  std::vector<Polynomial> seen;
  for (const Polynomial& q : members) {
    if (q.is_constant()) continue;
    std::vector<Polynomial> common;
    for (const Polynomial& p : seen) common.push_back(gcd(p, q, budget));
    const Polynomial g = lcm_of_members(common, ring, budget);
    if (!g.is_constant() && g.num_terms() == q.num_terms() && g == q.primitive_part()) continue;  // q | w
    w = w.multiply(g.is_constant() ? q : divide_exact(q, g, budget), budget).primitive_part();
    seen.push_back(q);
  }
  return w;
}

std::vector<Polynomial> denominators(const Parametrization& p) {
  std::vector<Polynomial> out;
  for (const auto& c : p.coordinates) out.push_back(c.denominator());
  return out;
}

}  // namespace

Polynomial common_denominator(const Parametrization& p, const Budget& budget) {
  return lcm_of_members(denominators(p), p.parameter_ring, budget.in_phase(kCommonDenominator));
}

std::vector<Polynomial> common_denominator_form(const Parametrization& p, const Budget& budget) {
  const Budget phased = budget.in_phase(kCommonDenominator);
  const std::vector<Polynomial> q = denominators(p);
  std::vector<Polynomial> forms = {lcm_of_members(q, p.parameter_ring, phased)};
  for (std::size_t i = 0; i < q.size(); ++i) {
    // ω / q_i = lcm over j of q_j / gcd(q_j, q_i) (compare the multiplicity of each
    // prime factor), again without dividing ω itself.
    std::vector<Polynomial> rest;
    for (std::size_t j = 0; j < q.size(); ++j) {
      if (j != i) rest.push_back(divide_exact(q[j], gcd(q[j], q[i], phased), phased));
    }
    const Polynomial cofactor = lcm_of_members(rest, p.parameter_ring, phased);
    const Polynomial& numerator = p.coordinates[i].numerator();
    // A polynomial parametrization (ω = 1) passes through unchanged, without a product.
    forms.push_back(cofactor.is_constant() ? numerator.scaled(cofactor.coefficient(0))
                                           : numerator.multiply(cofactor, phased));
  }
  return forms;
}

std::vector<std::string> coordinate_names(std::size_t count) {
  std::vector<std::string> names = {"x", "y", "z"};
  names.resize(count);
  return names;
}

Parametrization parse_parametrization(const std::string& x, const std::string& y, const std::string& z,
                                      const std::optional<std::vector<std::string>>& parameters, const Budget& budget) {
  return parse_parametrization(std::vector<std::string>{x, y, z}, parameters, budget);
}

Parametrization parse_parametrization(const std::vector<std::string>& texts,
                                      const std::optional<std::vector<std::string>>& parameters, const Budget& budget) {
  if (texts.size() != 2 && texts.size() != 3) {
    throw std::invalid_argument("parse_parametrization: two or three coordinates expected");
  }
  const std::size_t count = texts.size();
  const std::vector<std::string> fields = coordinate_names(count);
  std::vector<std::unique_ptr<Expression>> trees(count);
  std::vector<std::string> found;
  std::set<std::string> seen;
  for (std::size_t i = 0; i < count; ++i) {
    try {
      trees[i] = parse_expression(texts[i]);
    } catch (const InputError& e) {
      throw e.in_field(fields[i]);
    }
    for (const auto& name : collect_identifiers(*trees[i])) {
      if (is_space_variable(name)) {
        throw InputError("parameter_is_space_variable",
                         "'" + name + "' is a space variable and cannot be a parameter of the parametrization",
                         find_identifier(*trees[i], name)->position)
            .in_field(fields[i]);
      }
      if (seen.insert(name).second) found.push_back(name);
    }
  }
  std::vector<std::string> names = found;
  if (parameters) names = *parameters;
  budget.check_variables(names.size(), "the parametrization");
  if (parameters) {
    std::set<std::string> unique;
    for (const auto& p : names) {
      if (!is_identifier(p)) {
        throw InputError("invalid_parameter", "'" + p + "' is not a valid parameter name").in_field("parameters");
      }
      if (is_space_variable(p)) {
        throw InputError("parameter_is_space_variable", "'" + p + "' is a space variable and cannot be a parameter")
            .in_field("parameters");
      }
      if (!unique.insert(p).second) {
        throw InputError("invalid_parameter", "parameter '" + p + "' is listed twice").in_field("parameters");
      }
    }
  }
  RingPtr ring = Ring::make(names);
  if (std::any_of(trees.begin(), trees.end(), [](const auto& t) { return contains_call(*t); })) {
    std::vector<const Expression*> roots;
    for (const auto& t : trees) roots.push_back(t.get());
    RationalizedCoordinates rational = substitute_trigonometric(roots, fields, ring, budget);
    return {rational.parameter_ring, std::move(rational.coordinates), texts, std::move(rational.substitutions)};
  }
  Parametrization result{ring, {}, texts, {}};
  for (std::size_t i = 0; i < count; ++i) {
    try {
      result.coordinates.push_back(evaluate_rational_function(*trees[i], ring, budget));
    } catch (const InputError& e) {
      throw e.in_field(fields[i]);
    }
  }
  return result;
}

}  // namespace implicitizer
