#include "implicitizer/implicitization/parametrization.hpp"

#include <set>

#include "implicitizer/core/errors.hpp"
#include "implicitizer/polynomial/expression.hpp"
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

}  // namespace

Parametrization parse_parametrization(const std::string& x, const std::string& y, const std::string& z,
                                      const std::optional<std::vector<std::string>>& parameters,
                                      const Budget& budget) {
  const std::array<const std::string*, 3> texts{&x, &y, &z};
  const std::array<const char*, 3> fields{"x", "y", "z"};
  std::array<std::unique_ptr<Expression>, 3> trees;
  std::vector<std::string> found;
  std::set<std::string> seen;
  for (std::size_t i = 0; i < 3; ++i) {
    try {
      trees[i] = parse_expression(*texts[i]);
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
  if (parameters) {
    names = *parameters;
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
  std::vector<RationalFunction> coordinates;
  for (std::size_t i = 0; i < 3; ++i) {
    try {
      coordinates.push_back(evaluate_rational_function(*trees[i], ring, budget));
    } catch (const InputError& e) {
      throw e.in_field(fields[i]);
    }
  }
  Parametrization result{ring, {coordinates[0], coordinates[1], coordinates[2]}, {x, y, z}};
  return result;
}

}  // namespace implicitizer
