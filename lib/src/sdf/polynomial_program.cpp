#include "implicitizer/sdf/polynomial_program.hpp"

#include <cfloat>
#include <cmath>
#include <cstdio>
#include <map>

namespace implicitizer {
namespace {

using Kind = ProgramStep::Kind;
using R = ProgramRegister;

// The coefficients by exponent: u-degree → v-degree → w-degree → coefficient.
using Coefficients = std::map<std::int32_t, std::map<std::int32_t, std::map<std::int32_t, double>>>;

class Emitter {
 public:
  Emitter(std::vector<ProgramStep>& steps, bool gradient) : gradient_(gradient), steps_(steps) {}

  // Whether the derivative registers are computed (their steps emitted).
  bool gradient() const { return gradient_; }

  void load(R target, double c) { steps_.push_back(step(Kind::load_constant, target, R::u, R::u, c)); }
  void copy(R target, R source) { steps_.push_back(step(Kind::copy, target, R::u, source, 0)); }
  void multiply(R target, R by) { steps_.push_back(step(Kind::multiply, target, by, R::u, 0)); }
  void multiply_add(R target, R by, R source) {
    steps_.push_back(step(Kind::multiply_add, target, by, source, 0));
  }
  void multiply_add_constant(R target, R by, double c) {
    steps_.push_back(step(Kind::multiply_add_constant, target, by, R::u, c));
  }

 private:
  static ProgramStep step(Kind kind, R target, R by, R source, double c) {
    return ProgramStep{kind, target, by, source, c, static_cast<float>(c)};
  }
  bool gradient_;
  std::vector<ProgramStep>& steps_;
};

// a(w) = Σ_k c_k w^k and aw = a'(w), by Horner from the highest k.
void emit_inner(Emitter& e, const std::map<std::int32_t, double>& ks) {
  auto it = ks.rbegin();
  std::int32_t k = it->first;
  e.load(R::a, it->second);
  if (e.gradient()) e.load(R::aw, 0.0);
  ++it;
  for (; k > 0; --k) {
    if (e.gradient()) e.multiply_add(R::aw, R::w, R::a);  // before a changes: (a·w + c)' = a'·w + a
    if (it != ks.rend() && it->first == k - 1) {
      e.multiply_add_constant(R::a, R::w, it->second);
      ++it;
    } else {
      e.multiply(R::a, R::w);
    }
  }
}

// b(v, w) = Σ_j v^j a_j(w) with bv, bw.
void emit_middle(Emitter& e, const std::map<std::int32_t, std::map<std::int32_t, double>>& js) {
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
  Coefficients coefficients;
  PolynomialProgram program;
  program.outputs_ = outputs;
  const bool gradient = outputs == ProgramOutputs::value_and_gradient;
  for (std::size_t t = 0; t < g.num_terms(); ++t) {
    const double c = to_mpq(g.coefficient(t)).get_d();
    // Flushed as a GPU would flush it; both back ends then drop the same terms.
    if (!(std::fabs(static_cast<float>(c)) >= FLT_MIN)) {
      ++program.dropped_terms_;
      continue;
    }
    const std::vector<std::int32_t> e = g.exponents(t);
    coefficients[e[0]][e[1]][e[2]] = c;
    program.degree_ = std::max(program.degree_, e[0] + e[1] + e[2]);
  }
  Emitter e(program.steps_, gradient);
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
  static const char* const kNames[kProgramRegisters] = {"u", "v", "w", "a", "aw", "b", "bv", "bw", "g", "gu", "gv", "gw"};
  return kNames[static_cast<std::size_t>(r)];
}

// "+ 1.5e+00" or "- 1.5e+00": a - c and a + (-c) are the same IEEE operation.
std::string signed_term(float c) {
  return c < 0 ? " - " + format_glsl_float(-c) : " + " + format_glsl_float(c);
}

}  // namespace

std::string format_glsl_float(float x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.8e", static_cast<double>(x));
  return buffer;
}

std::string PolynomialProgram::to_glsl(const std::string& indent) const {
  std::string out = outputs_ == ProgramOutputs::value
                        ? indent + "float a = 0.0, b = 0.0, g = 0.0;\n"
                        : indent + "float a = 0.0, aw = 0.0, b = 0.0, bv = 0.0, bw = 0.0;\n" + indent +
                              "float g = 0.0, gu = 0.0, gv = 0.0, gw = 0.0;\n";
  for (const ProgramStep& s : steps_) {
    const std::string t = register_name(s.target);
    out += indent + t + " = ";
    switch (s.kind) {
      case Kind::load_constant:
        out += format_glsl_float(s.constant_float);
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
        out += t + " * " + register_name(s.by) + signed_term(s.constant_float);
        break;
    }
    out += ";\n";
  }
  return out;
}

}  // namespace implicitizer
