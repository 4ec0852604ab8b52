#include "implicitizer/implicitization/reproduce.hpp"

#include <algorithm>
#include <set>

#include "implicitizer/polynomial/gcd.hpp"
#include "implicitizer/polynomial/printer.hpp"

namespace implicitizer {

namespace {

// Names a script can use for the parameters. Both systems reserve words (`ring`,
// `gb`, `ideal`, ...) and Macaulay2 reads `_` as an operator, so unless every name is
// plain letters and digits and not reserved, the parameters become t1, t2, ...
std::vector<std::string> script_parameter_names(const Ring& params) {
  static const std::set<std::string> reserved = {
      "ring",  "ideal", "poly",  "int",   "number", "matrix", "vector", "module", "map",   "list",  "string",
      "proc",  "std",   "gb",    "dp",    "lp",     "Dp",     "ds",     "ls",     "size",  "print", "return",
      "if",    "else",  "for",   "while", "do",     "then",   "QQ",     "ZZ",     "R",     "I",     "J",
      "ii",    "ideal", "basering", "eliminate", "quit", "exit", "gens", "true", "false", "and", "or", "not",
      "e",     "pi",    "ii",    "w",     "x",      "y",      "z",      "minpoly", "char",  "var",  "deg"};
  bool plain = true;
  for (const auto& v : params.variables()) {
    // Singular and Macaulay2 names: ASCII letters and digits (no '_', which
    // Macaulay2 refuses in symbols).
    const bool alnum = std::all_of(v.begin(), v.end(), [](char c) {
      return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
    });
    if (!alnum || reserved.count(v)) plain = false;
  }
  if (plain) return params.variables();
  std::vector<std::string> names;
  for (std::size_t i = 0; i < params.num_variables(); ++i) names.push_back("t" + std::to_string(i + 1));
  return names;
}

struct ScriptIdeal {
  std::vector<std::string> eliminated;  // w (if any) and the parameters
  std::vector<std::string> generators;  // printed polynomials
};

// The ideal of Theorem 1.9 with the lcm of the denominators, printed in a ring whose
// variable names both systems accept.
ScriptIdeal script_ideal(const Parametrization& p) {
  const Ring& params = *p.parameter_ring;
  const std::vector<std::string> names = script_parameter_names(params);
  RingPtr ring = Ring::make(names);
  std::vector<std::size_t> same(names.size());
  for (std::size_t i = 0; i < same.size(); ++i) same[i] = i;
  const Polynomial l = common_denominator(p);
  ScriptIdeal out;
  const std::vector<std::string> space = coordinate_names(p.coordinates.size());
  for (std::size_t v = 0; v < space.size(); ++v) {
    const std::string num = to_string(p.coordinates[v].numerator().map_to(ring, same));
    const std::string den = to_string(p.coordinates[v].denominator().map_to(ring, same));
    out.generators.push_back((den == "1" ? std::string() : "(" + den + ")*") + space[v] + "-(" + num + ")");
  }
  if (!l.is_constant()) {
    out.eliminated.push_back("w");
    out.generators.push_back("1-(" + to_string(l.map_to(ring, same)) + ")*w");
  }
  out.eliminated.insert(out.eliminated.end(), names.begin(), names.end());
  return out;
}

std::string join(const std::vector<std::string>& parts, const std::string& separator) {
  std::string out;
  for (std::size_t i = 0; i < parts.size(); ++i) out += (i ? separator : "") + parts[i];
  return out;
}

std::string comment_of(const Parametrization& p) {
  const std::vector<std::string> space = coordinate_names(p.coordinates.size());
  std::vector<std::string> parts;
  for (std::size_t v = 0; v < space.size(); ++v) parts.push_back(space[v] + " = " + p.sources[v]);
  if (p.substitutions.empty()) return join(parts, ", ");
  // The ideal below is of the rational form: say which substitution made it.
  std::vector<std::string> substitutions;
  for (const auto& s : p.substitutions) substitutions.push_back(to_string(s));
  return join(parts, ", ") + ", made rational by " + join(substitutions, ", ");
}

std::string singular_script_of(const Parametrization& p, const ScriptIdeal& ideal) {
  std::vector<std::string> vars = ideal.eliminated;
  for (const auto& v : coordinate_names(p.coordinates.size())) vars.push_back(v);
  std::string product = join(ideal.eliminated, "*");
  if (product.empty()) product = "1";
  return "// implicitizer: the implicit equation of " + comment_of(p) +
         "\n"
         "ring r = 0, (" +
         join(vars, ",") +
         "), dp;\n"
         "short = 0;\n"
         "ideal I = " +
         join(ideal.generators, ",\n  ") +
         ";\n"
         "ideal J = eliminate(I, " +
         product +
         ");\n"
         "int i;\n"
         "for (i = 1; i <= size(J); i++) { print(J[i]); }\n"
         "quit;\n";
}

std::string macaulay2_script_of(const Parametrization& p, const ScriptIdeal& ideal) {
  std::vector<std::string> vars = ideal.eliminated;
  for (const auto& v : coordinate_names(p.coordinates.size())) vars.push_back(v);
  return "-- implicitizer: the implicit equation of " + comment_of(p) +
         "\n"
         "R = QQ[" +
         join(vars, ",") +
         "];\n"
         "I = ideal(" +
         join(ideal.generators, ",\n  ") +
         ");\n"
         "J = eliminate({" +
         join(ideal.eliminated, ",") +
         "}, I);\n"
         "scan(flatten entries gens J, g -> print toString g);\n"
         "exit 0\n";
}

}  // namespace

std::string singular_script(const Parametrization& p) { return singular_script_of(p, script_ideal(p)); }

std::string macaulay2_script(const Parametrization& p) { return macaulay2_script_of(p, script_ideal(p)); }

ReproduceScripts reproduce_scripts(const Parametrization& p) {
  const ScriptIdeal ideal = script_ideal(p);
  return {singular_script_of(p, ideal), macaulay2_script_of(p, ideal)};
}

}  // namespace implicitizer
