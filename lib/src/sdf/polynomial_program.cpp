#include "implicitizer/sdf/polynomial_program.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <functional>
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

namespace {

// The gradient program's registers as components of three vectors, A = (a, aw),
// B = (b, bv, bw), G = (g, gu, gv, gw): Horner's steps on one level write one vector
// with one operation, so the GLSL states them in one statement each.
struct Slot {
  int vector = -1;  // 0: A, 1: B, 2: G; -1: an input (u, v, w)
  int component = 0;
};

// By register, in ProgramRegister's order (u, v, w, a, aw, b, bv, bw, g, gu, gv, gw).
constexpr Slot kSlots[kProgramRegisters] = {{-1, 0}, {-1, 0}, {-1, 0}, {0, 0}, {0, 1}, {1, 0},
                                            {1, 1},  {1, 2},  {2, 0},  {2, 1}, {2, 2}, {2, 3}};

Slot slot_of(R r) { return kSlots[static_cast<std::size_t>(r)]; }

constexpr const char* kVectorNames[3] = {"A", "B", "G"};
constexpr int kVectorSizes[3] = {2, 3, 4};
constexpr const char* kComponents = "xyzw";

std::string vector_register(R r) {
  const Slot slot = slot_of(r);
  if (slot.vector < 0) return register_name(r);
  return std::string(kVectorNames[slot.vector]) + "." + kComponents[slot.component];
}

// Consecutive steps that write distinct components of one vector with the same
// operation (loads and copies; or multiply-adds by one register; or multiplies by
// one register), none reading a component an earlier one wrote: one GLSL vector
// statement computes each component exactly as the scalar step does (a vector
// assignment reads every operand before it writes), so the C++ evaluator's steps
// stay what the GPU runs.
class VectorStatement {
 public:
  explicit VectorStatement(const ProgramStep& first) { steps_.push_back(&first); }

  bool joins(const ProgramStep& s) const {
    const ProgramStep& first = *steps_.front();
    if (slot_of(s.target).vector != slot_of(first.target).vector || kind_class(s) != kind_class(first)) return false;
    if (kind_class(s) != 0 && s.by != first.by) return false;
    for (const ProgramStep* earlier : steps_) {
      if (earlier->target == s.target) return false;
      if (reads(s, earlier->target)) return false;
    }
    return true;
  }
  void add(const ProgramStep& s) { steps_.push_back(&s); }

  // The statement; `operand` states a step's added term (constant or register).
  template <typename Operand>
  std::string glsl(const Operand& operand) const {
    std::vector<const ProgramStep*> sorted = steps_;
    std::sort(sorted.begin(), sorted.end(), [](const ProgramStep* x, const ProgramStep* y) {
      return slot_of(x->target).component < slot_of(y->target).component;
    });
    const int vector = slot_of(sorted.front()->target).vector;
    std::string lhs = kVectorNames[vector];
    if (static_cast<int>(sorted.size()) < kVectorSizes[vector]) {
      lhs += ".";
      for (const ProgramStep* s : sorted) lhs += kComponents[slot_of(s->target).component];
    }
    std::string terms;
    for (const ProgramStep* s : sorted) terms += (terms.empty() ? "" : ", ") + operand(*s);
    if (sorted.size() > 1) terms = "vec" + std::to_string(sorted.size()) + "(" + terms + ")";
    const ProgramStep& first = *sorted.front();
    switch (kind_class(first)) {
      case 0:
        return lhs + " = " + terms;
      case 1:
        return lhs + " = " + lhs + " * " + register_name(first.by) + " + " + terms;
      default:
        return lhs + " = " + lhs + " * " + register_name(first.by);
    }
  }

 private:
  // 0: the target is replaced (load, copy); 1: multiply-add; 2: multiply.
  static int kind_class(const ProgramStep& s) {
    switch (s.kind) {
      case Kind::load_constant:
      case Kind::copy:
        return 0;
      case Kind::multiply_add:
      case Kind::multiply_add_constant:
        return 1;
      default:
        return 2;
    }
  }
  static bool reads(const ProgramStep& s, R r) {
    switch (s.kind) {
      case Kind::load_constant:
        return false;
      case Kind::copy:
        return s.source == r;
      case Kind::multiply:
        return s.by == r;
      default:
        return s.by == r || (s.kind == Kind::multiply_add && s.source == r);
    }
  }

  std::vector<const ProgramStep*> steps_;
};

}  // namespace

std::string PolynomialProgram::to_glsl(const std::string& indent, const std::string& table, bool absolute) const {
  // A coefficient as the GLSL reads it: a literal, or an entry of the table.
  const auto coefficient = [&](const ProgramStep& s) {
    if (table.empty() || s.coefficient < 0) return format_glsl_float(s.constant_float);
    const std::string entry = table + std::to_string(s.coefficient) + "[cell]";
    return absolute ? "abs(" + entry + ")" : entry;
  };
  if (outputs_ == ProgramOutputs::value) return scalar_glsl(indent, coefficient);
  const auto operand = [&](const ProgramStep& s) {
    return s.kind == Kind::copy || s.kind == Kind::multiply_add ? vector_register(s.source) : coefficient(s);
  };
  std::string out =
      indent + "vec2 A = vec2(0.0);\n" + indent + "vec3 B = vec3(0.0);\n" + indent + "vec4 G = vec4(0.0);\n";
  for (std::size_t i = 0; i < steps_.size();) {
    VectorStatement statement(steps_[i]);
    for (++i; i < steps_.size() && statement.joins(steps_[i]); ++i) statement.add(steps_[i]);
    out += indent + statement.glsl(operand) + ";\n";
  }
  return out + indent + "float g = G.x, gu = G.y, gv = G.z, gw = G.w;\n";
}

std::string PolynomialProgram::scalar_glsl(const std::string& indent,
                                           const std::function<std::string(const ProgramStep&)>& coefficient) const {
  std::string out = indent + "float a = 0.0, b = 0.0, g = 0.0;\n";
  for (const ProgramStep& s : steps_) {
    const std::string t = register_name(s.target);
    out += indent + t + " = ";
    switch (s.kind) {
      case Kind::load_constant:
        out += coefficient(s);
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
      case Kind::multiply_add_constant: {
        // "- 1.5e+00" for a negative literal: a - c and a + (-c) are the same IEEE operation.
        const std::string c = coefficient(s);
        out += t + " * " + register_name(s.by) + (c[0] == '-' ? " - " + c.substr(1) : " + " + c);
        break;
      }
    }
    out += ";\n";
  }
  return out;
}

}  // namespace implicitizer
