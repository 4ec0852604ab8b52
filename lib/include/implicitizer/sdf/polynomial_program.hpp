#pragma once
/// \file
/// A straight-line program that evaluates a trivariate polynomial G(u, v, w) and
/// its gradient together, in one pass, with two back ends that run the same steps
/// in the same order: GLSL source text (to_glsl) and a C++ evaluator in float or
/// double (evaluate). Tests compare the C++ float run with exact arithmetic, and so
/// learn what the GPU computes, up to the GPU's own freedoms (it may fuse a·b + c
/// into one fma, which only removes a rounding).
///
/// Shape: nested Horner, G = Σ_i u^i (Σ_j v^j (Σ_k c_ijk w^k)), each level
/// carrying forward-mode partial derivatives: for y = y·x + a, the derivative in
/// x is y' = y'·x + y (taken before y changes), and in the other variables
/// y'_v = y'_v·x + a'_v. No pow anywhere (GLSL's pow(x, y) is undefined for x < 0
/// and costs exp and log); about 2 multiply-adds per coefficient for the value and
/// w-derivative, 3 per inner polynomial and 4 per outer level for the rest.

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "implicitizer/polynomial/polynomial.hpp"

namespace implicitizer {

/// The program's registers. u, v, w are the inputs; a, aw hold the innermost
/// polynomial in w and its w-derivative; b, bv, bw the middle one in v; g, gu, gv,
/// gw the value and gradient of G.
enum class ProgramRegister : std::uint8_t { u, v, w, a, aw, b, bv, bw, g, gu, gv, gw };

/// Number of registers.
inline constexpr std::size_t kProgramRegisters = 12;

/// One step. Every step writes `target`:
///   load_constant:  target = constant
///   copy:           target = source
///   multiply:       target = target · by
///   multiply_add:   target = target · by + source
///   multiply_add_constant: target = target · by + constant
struct ProgramStep {
  enum class Kind : std::uint8_t { load_constant, copy, multiply, multiply_add, multiply_add_constant };
  Kind kind;
  ProgramRegister target;
  ProgramRegister by = ProgramRegister::u;      ///< the multiplier (multiply*)
  ProgramRegister source = ProgramRegister::u;  ///< copy and multiply_add
  double constant = 0;                          ///< the coefficient, rounded to double, then (float runs) to float
  float constant_float = 0;                     ///< float(constant): what the GLSL states
  /// Where the constant of a coefficient of G (load_constant, multiply_add_constant)
  /// sits in a cell's row of the coefficient table; -1 for the structural zeros of
  /// the derivative registers. constant and constant_float are cell 0's values.
  std::int32_t coefficient = -1;
};

/// What a program computes. Safe mode (safe_sdf.hpp) evaluates the majorant
/// several times per point but needs its gradient only once, so a value-only
/// program (about a third of the steps) serves the other evaluations.
enum class ProgramOutputs : std::uint8_t {
  value_and_gradient,  ///< g and gu, gv, gw
  value,               ///< g only; the gradient registers stay 0
};

/// The value of G and its partial derivatives.
template <typename T>
struct ValueAndGradient {
  T value;                    ///< G(u, v, w)
  std::array<T, 3> gradient;  ///< (∂G/∂u, ∂G/∂v, ∂G/∂w)
};

/// A compiled polynomial.
class PolynomialProgram {
 public:
  /// Compiles `g`, a polynomial of a ring with exactly three variables (u, v, w in
  /// ring order), whose coefficients should be at most 1 in magnitude (see
  /// frame_polynomial). Coefficients are rounded to float; those that become
  /// subnormal or 0 (below 1.2e-38 in magnitude) are dropped, as GPUs flush
  /// subnormals. With ProgramOutputs::value only the steps of G's value are
  /// emitted: the same steps, in the same order, as the value part of the full
  /// program, so both round identically. Precondition: g is not zero.
  static PolynomialProgram compile(const Polynomial& g, ProgramOutputs outputs = ProgramOutputs::value_and_gradient);

  /// One program for several polynomials ("cells": the local expansions of one G
  /// over sub-boxes, safe_sdf.hpp): the steps of the union of their supports, and a
  /// table with one row of coefficients per cell (0 where a cell lacks a term, or
  /// its float is flushed). The steps are the same for every cell, so one GLSL text
  /// serves all of them, reading its constants from an array indexed by the cell.
  /// With one polynomial this is compile(). Precondition: cells is not empty, every
  /// polynomial is in a ring of exactly three variables.
  static PolynomialProgram compile_cells(const std::vector<Polynomial>& cells,
                                         ProgramOutputs outputs = ProgramOutputs::value_and_gradient);

  /// The steps, in execution order.
  const std::vector<ProgramStep>& steps() const { return steps_; }
  /// Total degree of the compiled polynomial.
  std::int32_t degree() const { return degree_; }
  /// What the program computes.
  ProgramOutputs outputs() const { return outputs_; }
  /// How many nonzero coefficients of g were dropped because their float is not
  /// a normal number (an error bound must account for them: safe_sdf.hpp).
  /// With several cells, the largest such count of one cell.
  std::size_t dropped_terms() const { return dropped_terms_; }
  /// How many cells (rows of the coefficient table) the program has; 1 for compile().
  std::size_t cells() const { return cells_; }
  /// The length of one row of the coefficient table.
  std::size_t coefficients_per_cell() const { return per_cell_; }
  /// The coefficient table as floats, row by row (cells() × coefficients_per_cell()).
  const std::vector<float>& table_float() const { return table_float_; }

  /// Runs the steps in T (float or double). Float runs use constant_float, double
  /// runs constant.
  template <typename T>
  ValueAndGradient<T> evaluate(T u, T v, T w) const {
    return run(u, v, w, [](const ProgramStep& s) { return constant_as<T>(s); });
  }

  /// evaluate() with the coefficients of row `cell` (< cells()).
  template <typename T>
  ValueAndGradient<T> evaluate_in_cell(std::size_t cell, T u, T v, T w) const {
    if (cell == 0) return evaluate(u, v, w);
    const std::size_t row = cell * per_cell_;
    return run(u, v, w, [&](const ProgramStep& s) {
      return s.coefficient < 0 ? T(0) : table_as<T>(row + static_cast<std::size_t>(s.coefficient));
    });
  }

  /// GLSL statements that run the steps, each line starting with `indent`. The
  /// inputs must be float variables named u, v, w in scope; the result is left in
  /// float variables g, gu, gv, gw (g for a value-only program). A value-only program
  /// states one step per statement in registers a, b, g; a full one keeps its
  /// registers in vec2 A = (a, aw), vec3 B = (b, bv, bw) and vec4 G = (g, gu, gv, gw)
  /// and states each run of steps that one vector operation computes (a Horner step
  /// of one level and its derivatives) as one statement, the same floating-point
  /// operations per component. Two programs in one function need a block `{ ... }` each.
  ///
  /// With a non-empty `table` coefficient i is read as `TABLEi[cell]` (or
  /// `abs(TABLEi[cell])` when `absolute`: the majorant reads G's table), `cell` an int
  /// in scope; see glsl_table.
  std::string to_glsl(const std::string& indent, const std::string& table = "", bool absolute = false) const;

  /// `const float NAMEi[C] = float[C](...);` for each column i: coefficient i of every
  /// cell (the float table by column).
  std::string glsl_table(const std::string& name) const;

 private:
  static std::size_t index(ProgramRegister r) { return static_cast<std::size_t>(r); }
  // to_glsl() of a value-only program: one statement per step.
  std::string scalar_glsl(const std::string& indent,
                          const std::function<std::string(const ProgramStep&)>& coefficient) const;
  // The steps in T, each constant given by `constant(step)`.
  template <typename T, typename Constant>
  ValueAndGradient<T> run(T u, T v, T w, Constant constant) const {
    std::array<T, kProgramRegisters> r{};
    r[index(ProgramRegister::u)] = u;
    r[index(ProgramRegister::v)] = v;
    r[index(ProgramRegister::w)] = w;
    for (const ProgramStep& s : steps_) {
      T& t = r[index(s.target)];
      switch (s.kind) {
        case ProgramStep::Kind::load_constant:
          t = constant(s);
          break;
        case ProgramStep::Kind::copy:
          t = r[index(s.source)];
          break;
        case ProgramStep::Kind::multiply:
          t = t * r[index(s.by)];
          break;
        case ProgramStep::Kind::multiply_add:
          t = t * r[index(s.by)] + r[index(s.source)];
          break;
        case ProgramStep::Kind::multiply_add_constant:
          t = t * r[index(s.by)] + constant(s);
          break;
      }
    }
    return {r[index(ProgramRegister::g)],
            {r[index(ProgramRegister::gu)], r[index(ProgramRegister::gv)], r[index(ProgramRegister::gw)]}};
  }
  template <typename T>
  static T constant_as(const ProgramStep& s) {
    if constexpr (sizeof(T) == sizeof(float)) {
      return s.constant_float;
    } else {
      return static_cast<T>(s.constant);
    }
  }

  template <typename T>
  T table_as(std::size_t i) const {
    if constexpr (sizeof(T) == sizeof(float)) {
      return table_float_[i];
    } else {
      return static_cast<T>(table_[i]);
    }
  }

  std::vector<ProgramStep> steps_;
  std::vector<double> table_;       // cells_ rows of per_cell_ coefficients (flushed ones 0)
  std::vector<float> table_float_;  // the same, rounded to float
  std::size_t cells_ = 1, per_cell_ = 0;
  std::int32_t degree_ = 0;
  ProgramOutputs outputs_ = ProgramOutputs::value_and_gradient;
  std::size_t dropped_terms_ = 0;
};

/// `x` as a GLSL float literal that reads back as exactly x: 9 significant digits
/// in exponent form ("1.50000000e+00", "-2.00000005e-30"), valid in GLSL ES 3.00
/// and 330 alike (a `.` and an exponent, never an int literal, no `f` suffix, which
/// ES 3.00 accepts but some older desktop compilers do not). Precondition: x finite.
std::string format_glsl_float(float x);

}  // namespace implicitizer
