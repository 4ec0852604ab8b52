#include "implicitizer/sdf/polynomial_program.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <map>

namespace implicitizer {
namespace {

using Kind = ProgramStep::Kind;
using R = ProgramRegister;

// The support by exponent: u-degree → v-degree → w-degree → column of the coefficient table.
using Coefficients = std::map<std::int32_t, std::map<std::int32_t, std::map<std::int32_t, std::int32_t>>>;

class Emitter {
 public:
  // `row` is cell 0's row of the coefficient table: the constants the steps state.
  Emitter(std::vector<ProgramStep>& steps, bool gradient, const double* row)
      : gradient_(gradient), row_(row), steps_(steps) {}

  // Whether the derivative registers are computed (their steps emitted).
  bool gradient() const { return gradient_; }

  // The coefficient in column `column` of the table.
  void load_coefficient(R target, std::int32_t column) {
    ProgramStep s = step(Kind::load_constant, target, R::u, R::u, row_[column]);
    s.coefficient = column;
    steps_.push_back(s);
  }
  void multiply_add_coefficient(R target, R by, std::int32_t column) {
    ProgramStep s = step(Kind::multiply_add_constant, target, by, R::u, row_[column]);
    s.coefficient = column;
    steps_.push_back(s);
  }
  void load(R target, double c) { steps_.push_back(step(Kind::load_constant, target, R::u, R::u, c)); }
  void copy(R target, R source) { steps_.push_back(step(Kind::copy, target, R::u, source, 0)); }
  void multiply(R target, R by) { steps_.push_back(step(Kind::multiply, target, by, R::u, 0)); }
  void multiply_add(R target, R by, R source) { steps_.push_back(step(Kind::multiply_add, target, by, source, 0)); }
  void multiply_add_constant(R target, R by, double c) {
    steps_.push_back(step(Kind::multiply_add_constant, target, by, R::u, c));
  }

 private:
  static ProgramStep step(Kind kind, R target, R by, R source, double c) {
    return ProgramStep{kind, target, by, source, c, static_cast<float>(c)};
  }
  bool gradient_;
  const double* row_;
  std::vector<ProgramStep>& steps_;
};

// a(w) = Σ_k c_k w^k and aw = a'(w), by Horner from the highest k.
void emit_inner(Emitter& e, const std::map<std::int32_t, std::int32_t>& ks) {
  auto it = ks.rbegin();
  std::int32_t k = it->first;
  e.load_coefficient(R::a, it->second);
  if (e.gradient()) e.load(R::aw, 0.0);
  ++it;
  for (; k > 0; --k) {
    if (e.gradient()) e.multiply_add(R::aw, R::w, R::a);  // before a changes: (a·w + c)' = a'·w + a
    if (it != ks.rend() && it->first == k - 1) {
      e.multiply_add_coefficient(R::a, R::w, it->second);
      ++it;
    } else {
      e.multiply(R::a, R::w);
    }
  }
}

// b(v, w) = Σ_j v^j a_j(w) with bv, bw.
void emit_middle(Emitter& e, const std::map<std::int32_t, std::map<std::int32_t, std::int32_t>>& js) {
  auto it = js.rbegin();
  std::int32_t j = it->first;
  emit_inner(e, it->second);
  e.copy(R::b, R::a);
  if (e.gradient()) {
    e.copy(R::bw, R::aw);
    e.load(R::bv, 0.0);
  }
  ++it;
  for (; j > 0; --j) {
    const bool present = it != js.rend() && it->first == j - 1;
    if (present) emit_inner(e, it->second);
    if (e.gradient()) e.multiply_add(R::bv, R::v, R::b);
    if (present) {
      e.multiply_add(R::b, R::v, R::a);
      if (e.gradient()) e.multiply_add(R::bw, R::v, R::aw);
      ++it;
    } else {
      e.multiply(R::b, R::v);
      if (e.gradient()) e.multiply(R::bw, R::v);
    }
  }
}

}  // namespace

PolynomialProgram PolynomialProgram::compile(const Polynomial& g, ProgramOutputs outputs) {
  return compile_cells({g}, outputs);
}

namespace {

// The cells' coefficients by exponent, flushed as a GPU would flush them (both back
// ends then drop the same terms); counts the dropped ones per cell.
using Exponent = std::array<std::int32_t, 3>;
std::vector<std::map<Exponent, double>> kept_coefficients(const std::vector<Polynomial>& cells,
                                                          std::vector<std::size_t>& dropped) {
  std::vector<std::map<Exponent, double>> kept(cells.size());
  dropped.assign(cells.size(), 0);
  for (std::size_t cell = 0; cell < cells.size(); ++cell) {
    const Polynomial& g = cells[cell];
    for (std::size_t t = 0; t < g.num_terms(); ++t) {
      const double c = to_mpq(g.coefficient(t)).get_d();
      if (!(std::fabs(static_cast<float>(c)) >= FLT_MIN)) {
        ++dropped[cell];
        continue;
      }
      const std::vector<std::int32_t> e = g.exponents(t);
      kept[cell][{e[0], e[1], e[2]}] = c;
    }
  }
  return kept;
}

}  // namespace

PolynomialProgram PolynomialProgram::compile_cells(const std::vector<Polynomial>& cells, ProgramOutputs outputs) {
  PolynomialProgram program;
  program.outputs_ = outputs;
  const bool gradient = outputs == ProgramOutputs::value_and_gradient;
  std::vector<std::size_t> dropped;
  const std::vector<std::map<Exponent, double>> kept = kept_coefficients(cells, dropped);
  program.dropped_terms_ = *std::max_element(dropped.begin(), dropped.end());
  // The union of the supports, one column each (in exponent order, whatever `outputs`,
  // so that a value-only program reads the same columns as the full one).
  std::map<Exponent, std::int32_t> columns;
  for (const auto& cell : kept) {
    for (const auto& [e, c] : cell) columns.emplace(e, 0);
  }
  Coefficients coefficients;
  for (auto& [e, column] : columns) {
    column = static_cast<std::int32_t>(program.per_cell_++);
    coefficients[e[0]][e[1]][e[2]] = column;
    program.degree_ = std::max(program.degree_, e[0] + e[1] + e[2]);
  }
  program.cells_ = cells.size();
  program.table_.assign(program.cells_ * program.per_cell_, 0.0);
  for (std::size_t cell = 0; cell < kept.size(); ++cell) {
    for (const auto& [e, c] : kept[cell]) program.table_[cell * program.per_cell_ + columns.at(e)] = c;
  }
  for (double c : program.table_) program.table_float_.push_back(static_cast<float>(c));
  Emitter e(program.steps_, gradient, program.table_.data());
  if (coefficients.empty()) {
    e.load(R::g, 0.0);
    if (gradient) {
      for (R r : {R::gu, R::gv, R::gw}) e.load(r, 0.0);
    }
    return program;
  }
  auto it = coefficients.rbegin();
  std::int32_t i = it->first;
  emit_middle(e, it->second);
  e.copy(R::g, R::b);
  if (gradient) {
    e.copy(R::gv, R::bv);
    e.copy(R::gw, R::bw);
    e.load(R::gu, 0.0);
  }
  ++it;
  for (; i > 0; --i) {
    const bool present = it != coefficients.rend() && it->first == i - 1;
    if (present) emit_middle(e, it->second);
    if (gradient) e.multiply_add(R::gu, R::u, R::g);
    if (present) {
      e.multiply_add(R::g, R::u, R::b);
      if (gradient) {
        e.multiply_add(R::gv, R::u, R::bv);
        e.multiply_add(R::gw, R::u, R::bw);
      }
      ++it;
    } else {
      e.multiply(R::g, R::u);
      if (gradient) {
        e.multiply(R::gv, R::u);
        e.multiply(R::gw, R::u);
      }
    }
  }
  return program;
}

namespace {

const char* register_name(R r) {
  static const char* const kNames[kProgramRegisters] = {"u",  "v",  "w", "a",  "aw", "b",
                                                        "bv", "bw", "g", "gu", "gv", "gw"};
  return kNames[static_cast<std::size_t>(r)];
}

// "+ 1.5e+00" or "- 1.5e+00": a - c and a + (-c) are the same IEEE operation.
std::string signed_term(float c) { return c < 0 ? " - " + format_glsl_float(-c) : " + " + format_glsl_float(c); }

}  // namespace

std::string format_glsl_float(float x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.8e", static_cast<double>(x));
  return buffer;
}

std::string PolynomialProgram::glsl_table(const std::string& name) const {
  // One small array per column, indexed by the cell: a compiler that lowers a dynamic
  // index into a chain of selects (Mesa does) then pays cells() selects per
  // coefficient, not the whole table's length.
  const std::string size = std::to_string(cells_);
  std::string out;
  for (std::size_t column = 0; column < per_cell_; ++column) {
    out += "const float " + name + std::to_string(column) + "[" + size + "] = float[" + size + "](";
    for (std::size_t cell = 0; cell < cells_; ++cell) {
      out += format_glsl_float(table_float_[cell * per_cell_ + column]) + (cell + 1 < cells_ ? ", " : ");\n");
    }
  }
  return out;
}

std::string PolynomialProgram::to_glsl(const std::string& indent, const std::string& table, bool absolute) const {
  // A coefficient as the GLSL reads it: a literal, or an entry of the table.
  const auto coefficient = [&](const ProgramStep& s) {
    const std::string entry = table + std::to_string(s.coefficient) + "[cell]";
    return absolute ? "abs(" + entry + ")" : entry;
  };
  const bool tabled = !table.empty();
  std::string out = outputs_ == ProgramOutputs::value
                        ? indent + "float a = 0.0, b = 0.0, g = 0.0;\n"
                        : indent + "float a = 0.0, aw = 0.0, b = 0.0, bv = 0.0, bw = 0.0;\n" + indent +
                              "float g = 0.0, gu = 0.0, gv = 0.0, gw = 0.0;\n";
  for (const ProgramStep& s : steps_) {
    const std::string t = register_name(s.target);
    out += indent + t + " = ";
    switch (s.kind) {
      case Kind::load_constant:
        out += tabled && s.coefficient >= 0 ? coefficient(s) : format_glsl_float(s.constant_float);
        break;
      case Kind::copy:
        out += register_name(s.source);
        break;
      case Kind::multiply:
        out += t + " * " + register_name(s.by);
        break;
      case Kind::multiply_add:
        out += t + " * " + register_name(s.by) + " + " + register_name(s.source);
        break;
      case Kind::multiply_add_constant:
        out += t + " * " + register_name(s.by) +
               (tabled && s.coefficient >= 0 ? " + " + coefficient(s) : signed_term(s.constant_float));
        break;
    }
    out += ";\n";
  }
  return out;
}

}  // namespace implicitizer
