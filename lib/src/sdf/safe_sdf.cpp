#include "implicitizer/sdf/safe_sdf.hpp"

#include <algorithm>
#include <cfloat>
#include <limits>
#include <stdexcept>
#include <vector>

#include "implicitizer/core/errors.hpp"

namespace implicitizer {
namespace {

// The float or double nearest to d on the safe side.
template <typename T>
T round_up(double d) {
  T t = static_cast<T>(d);
  if (static_cast<double>(t) < d) t = std::nextafter(t, std::numeric_limits<T>::infinity());
  return t;
}
template <typename T>
T round_down(double d) {
  T t = static_cast<T>(d);
  if (static_cast<double>(t) > d) t = std::nextafter(t, -std::numeric_limits<T>::infinity());
  return t;
}

// (1 - e)^-k - 1 and 1 - (1 + e)^-k, accurate for tiny e (no cancellation).
double grow(double e, double k) { return std::expm1(-k * std::log1p(-e)); }
double shrink(double e, double k) { return -std::expm1(-k * std::log1p(e)); }
// Higham's γ_k = k·e / (1 - k·e): the relative error of k roundings.
double gamma_of(double e, double k) { return k * e / (1 - k * e); }

Rational abs_of(const Rational& q) { return q < Rational(0) ? -q : q; }

// Everything safe_sdf.hpp's Constants hold that depends on the precision: ε, the
// underflow threshold of the arithmetic. Derivations in docs/sdf.md §6.
template <typename T>
SafeSdf::Constants<T> make_constants(const SceneFrame& frame, double box_half, std::int32_t degree,
                                     std::int32_t full_degree, std::size_t dropped, std::size_t steps,
                                     double radius_cap, double far_in_cell) {
  // One ulp (not half): GLSL ES leaves the rounding mode undefined. The C++
  // evaluator rounds to nearest, so it is covered twice over.
  const double e = std::ldexp(1.0, -std::numeric_limits<T>::digits + 1);
  const double n = degree, m = 2.0 * degree + 4;  // roundings per term of a pass
  // 1 % on top of every relative constant covers the rounding of this double
  // arithmetic itself.
  const double margin = 1.01;
  SafeSdf::Constants<T> k;
  for (std::size_t i = 0; i < 3; ++i) k.centre[i] = static_cast<T>(to_mpq(frame.centre[i]).get_d());
  const mpq_class scale = to_mpq(frame.scale);
  k.scale = static_cast<T>(scale.get_d());
  // mpq's get_d truncates, so 1/s comes out rounded down already.
  k.half_extent = round_down<T>(mpq_class(1 / scale).get_d());
  k.box_half = round_up<T>(box_half);
  // L: sqrt(3)·L·h stays below 2^122 and L² below 2^120.
  k.box_clamp = round_down<T>(std::min(0x1p60, 0x1p120 / static_cast<double>(k.half_extent)));
  k.u_shrink = round_down<T>(1 - 4 * e);
  k.u_grow = round_up<T>(1 + 4 * e);
  k.box_half_inner = round_down<T>(box_half);
  k.u_error = round_up<T>(3 * e * margin);
  k.gamma_value = round_up<T>((gamma_of(e, m) * (1 + grow(e, m)) + 4 * e) * margin);
  k.gamma_gradient = round_up<T>((gamma_of(e, m) * (1 + grow(e, m + 2)) + 4 * e) * margin);
  k.norm_up = round_up<T>(1 + 16 * e);
  // τ: dropped coefficients (each below FLT_MIN, at |x_i| <= X = far_in_cell + r_cap,
  // 3 without cells) and every flushed subnormal (at most the smallest normal,
  // amplified by at most (n + 1)·X^n by the later steps) of the four passes, twice over.
  const double smallest = std::numeric_limits<T>::min();
  const double power = std::pow(far_in_cell + radius_cap, full_degree);
  k.tau = round_up<T>(2 * (static_cast<double>(dropped) * FLT_MIN * power +
                           8.0 * static_cast<double>(steps) * (full_degree + 1) * power * smallest));
  k.minimum_value = static_cast<T>(SafeSdf::kMinimumValue);
  k.radius_cap = static_cast<T>(radius_cap);
  // Γ_X: the Horner pass of Ĝ at x (2n + 3 roundings), the coefficients' rounding
  // (1) and x = a + r rounded down (n, through the degree), plus 10ε for the seven
  // operations that follow (remainder and φ; their operands are all at most about
  // X). Γ_Y: the pass of Ĝ and ∇Ĝ at a (2n + 4), the sum of the partials (2) and
  // Y = Ĝ(a) + r·ΣĜ_i(a) (2), plus 2ε for its product with K_Y.
  k.majorant_up = round_up<T>(1 + (grow(e, 3 * n + 4) + 10 * e) * margin);
  k.majorant_down = round_down<T>(1 - (shrink(e, 2 * n + 8) + 2 * e) * margin);
  k.root_shrink = round_down<T>(1 - 32 * e);
  k.out_shrink = round_down<T>(1 - 16 * e);
  return k;
}

// b: the smallest float >= max_i max(hi_i - c_i, c_i - lo_i)·s, so that the box is
// inside |u_i| <= b although c and s are rounded (b = 1 when they are exact).
double box_half_in_frame(const SceneBox& box, const SceneFrame& frame) {
  Rational largest(0);
  for (std::size_t i = 0; i < 3; ++i) {
    for (const Rational& side : {box.hi[i] - frame.centre[i], frame.centre[i] - box.lo[i]}) {
      const Rational r = abs_of(side) * frame.scale;
      if (r > largest) largest = r;
    }
  }
  const double d = to_mpq(largest).get_d();  // truncated: one ulp up covers it
  return Rational(d) == largest ? d : std::nextafter(d, std::numeric_limits<double>::infinity());
}

// G's expansions over k³ cells, compiled: with k = 1 the box's own frame.
struct CellPrograms {
  int k = 1;
  std::vector<SceneFrame> frames;  // cell = (i·k + j)·k + l
  std::int32_t degree = 0;         // of F
  PolynomialProgram program, majorant, majorant_value;

  // The largest Ĝ of a cell at (x, x, x) in its frame (double, 0.1 % margin).
  double majorant_at(double x) const {
    double largest = 0;
    for (std::size_t cell = 0; cell < frames.size(); ++cell) {
      largest = std::max(largest, majorant_value.evaluate_in_cell(cell, x, x, x).value * 1.001);
    }
    return largest;
  }
  // The farthest a point with |u_i| <= kFarField is from its cell's centre, in t units:
  // the outer cells' centres are at 1 - 1/k, so (kFarField - 1 + 1/k)·k.
  double far_in_cell() const { return (SafeSdf::kFarField - 1) * k + 1; }
};

// Cell centres c + h·(-1 + (2i + 1)/k) rounded to float, scale k·s (exact: k a power of
// 2), and G = F(c_cell + t/(k·s))/M_cell exactly in each.
CellPrograms compile_cell_programs(const Polynomial& f, const SceneFrame& frame, int k, const Budget& budget) {
  CellPrograms cells;
  cells.k = k;
  cells.degree = f.total_degree();
  std::vector<Polynomial> expansions, majorants;
  for (int cell = 0; cell < k * k * k; ++cell) {
    const int index[3] = {cell / (k * k), cell / k % k, cell % k};
    SceneFrame local{{}, frame.scale * Rational(k)};
    for (std::size_t i = 0; i < 3; ++i) {
      const Rational offset = Rational(2 * index[i] + 1 - k) / Rational(k) / frame.scale;
      local.centre[i] = Rational(static_cast<double>(static_cast<float>(to_mpq(frame.centre[i] + offset).get_d())));
    }
    cells.frames.push_back(local);
    expansions.push_back(frame_polynomial(f, local, budget));
    const Polynomial& g = expansions.back();
    std::vector<Polynomial> absolute_terms;
    absolute_terms.reserve(g.num_terms());
    for (std::size_t t = 0; t < g.num_terms(); ++t) {
      absolute_terms.push_back(Polynomial::term(g.ring(), abs_of(g.coefficient(t)), g.exponents(t)));
    }
    budget.check("safe sdf majorant");
    majorants.push_back(sum_of(g.ring(), std::move(absolute_terms)));
  }
  cells.program = PolynomialProgram::compile_cells(expansions);
  cells.majorant = PolynomialProgram::compile_cells(majorants);
  cells.majorant_value = PolynomialProgram::compile_cells(majorants, ProgramOutputs::value);
  return cells;
}

// The fraction of kSamples points of the box where fp32 cannot resolve G in the
// cell's frame: |G| <= Γ_A·Ĝ(|t|), evaluated in double. Only a heuristic for choosing
// k; the bound's correctness does not depend on it. The points are the first of
// Roberts' R3 sequence (frac(1/2 + i·α), α_j = φ^-j with φ^4 = φ + 1): well spread,
// and the same on every platform, unlike std::uniform_real_distribution, whose
// output the standard leaves to the library (the GLSL must not depend on it).
double unresolved_fraction(const CellPrograms& cells) {
  constexpr int kSamples = 2000;
  constexpr double kPhi = 1.2207440846057594;  // the real root of x^4 = x + 1
  constexpr std::array<double, 3> kAlpha = {1 / kPhi, 1 / (kPhi * kPhi), 1 / (kPhi * kPhi * kPhi)};
  const double gamma = gamma_of(0x1p-23, 2.0 * cells.program.degree() + 4);
  int unresolved = 0;
  for (int i = 0; i < kSamples; ++i) {
    std::size_t cell = 0;
    std::array<double, 3> t{};
    for (std::size_t axis = 0; axis < 3; ++axis) {
      const double r = 0.5 + (i + 1) * kAlpha[axis];
      const double u = 2 * (r - std::floor(r)) - 1;
      const int index = std::clamp(static_cast<int>(std::floor((u + 1) * cells.k / 2)), 0, cells.k - 1);
      cell = cell * static_cast<std::size_t>(cells.k) + static_cast<std::size_t>(index);
      t[axis] = (u + 1) * cells.k - (2 * index + 1);
    }
    const double g = cells.program.evaluate_in_cell(cell, t[0], t[1], t[2]).value;
    const double m =
        cells.majorant_value.evaluate_in_cell(cell, std::fabs(t[0]), std::fabs(t[1]), std::fabs(t[2])).value;
    if (std::fabs(g) <= gamma * m) ++unresolved;
  }
  return static_cast<double>(unresolved) / kSamples;
}

// The cells' float constants: each cell's centre, k·s, 1/k, k/2.
template <typename T>
void set_cell_constants(SafeSdf::Constants<T>& k, const CellPrograms& cells) {
  k.cell_scale = static_cast<T>(to_mpq(cells.frames.front().scale).get_d());
  k.cell_step = static_cast<T>(1.0 / cells.k);
  k.cell_index_scale = static_cast<T>(cells.k / 2.0);
  k.cell_centres.clear();
  for (const SceneFrame& frame : cells.frames) {
    k.cell_centres.push_back({static_cast<T>(to_mpq(frame.centre[0]).get_d()),
                              static_cast<T>(to_mpq(frame.centre[1]).get_d()),
                              static_cast<T>(to_mpq(frame.centre[2]).get_d())});
  }
}

}  // namespace

SafeSdf SafeSdf::build(const Polynomial& f, const SceneBox& box, const Budget& budget, SdfShape shape,
                       int max_cells_per_axis) {
  if (shape == SdfShape::automatic) throw std::invalid_argument("SafeSdf::build: decide the shape first");
  SafeSdf sdf;
  sdf.shape_ = shape;
  sdf.frame_ = make_scene_frame(box);
  CellPrograms cells = compile_cell_programs(f, sdf.frame_, 1, budget);
  if (!(cells.majorant_at(kFarField) <= kMajorantLimit)) {
    throw InputError("degree_too_high", "the safe bound evaluates the polynomial's terms at up to " +
                                            std::to_string(static_cast<int>(kFarField)) +
                                            " box half-sides from the centre, where they exceed fp32's safe "
                                            "range (degree " +
                                            std::to_string(f.total_degree()) + "); use mode fast");
  }
  // Split while fp32 cannot resolve G at too many points, and the finer cells' terms
  // stay within the majorant's range at the far field.
  for (int k = 2; k <= max_cells_per_axis && unresolved_fraction(cells) > kUnresolvedTarget; k *= 2) {
    CellPrograms finer = compile_cell_programs(f, sdf.frame_, k, budget);
    if (!(finer.majorant_at(finer.far_in_cell()) <= kMajorantLimit)) break;
    cells = std::move(finer);
  }
  // r_cap (in t units: k·kRadiusCap is kRadiusCap in u units): halve until Ĝ(far + r_cap) fits.
  double radius_cap = kRadiusCap * cells.k;
  while (!(cells.majorant_at(cells.far_in_cell() + radius_cap) <= kMajorantLimit)) radius_cap /= 2;
  sdf.cells_per_axis_ = cells.k;
  sdf.program_ = std::move(cells.program);
  sdf.majorant_ = std::move(cells.majorant);
  sdf.majorant_value_ = std::move(cells.majorant_value);

  const double box_half = box_half_in_frame(box, sdf.frame_);
  const std::size_t steps = sdf.program_.steps().size();
  const double far = cells.far_in_cell();
  sdf.constants_float_ = make_constants<float>(sdf.frame_, box_half, sdf.program_.degree(), cells.degree,
                                               sdf.program_.dropped_terms(), steps, radius_cap, far);
  sdf.constants_double_ = make_constants<double>(sdf.frame_, box_half, sdf.program_.degree(), cells.degree,
                                                 sdf.program_.dropped_terms(), steps, radius_cap, far);
  set_cell_constants(sdf.constants_float_, cells);
  set_cell_constants(sdf.constants_double_, cells);
  if (!(sdf.constants_float_.tau < 0x1p-24f)) {
    throw InputError("degree_too_high", "degree " + std::to_string(cells.degree) +
                                            " is too high for an fp32 bound: underflow alone could hide "
                                            "|F| of 2^-24 of its largest term; use mode fast");
  }
  return sdf;
}

std::string SafeSdf::cell_centres_glsl(const std::string& name) const {
  const std::vector<std::array<float, 3>>& centres = constants_float_.cell_centres;
  const std::string size = std::to_string(3 * centres.size());
  std::string out = "const float " + name + "[" + size + "] = float[" + size + "](";
  for (std::size_t cell = 0; cell < centres.size(); ++cell) {
    out += "\n  " + format_glsl_float(centres[cell][0]) + ", " + format_glsl_float(centres[cell][1]) + ", " +
           format_glsl_float(centres[cell][2]) + (cell + 1 < centres.size() ? "," : "");
  }
  return out + ");\n";
}

// The cell of p (floor((u + 1)·k/2) per axis, clamped), p in the cell's frame and the absolute values: what
// evaluate_with_chord_steps does.
std::string SafeSdf::cell_frame_glsl(const std::string& centres) const {
  const Constants<float>& k = constants_float_;
  const std::string last = std::to_string(cells_per_axis_ - 1), count = std::to_string(cells_per_axis_);
  std::string out;
  for (const char* axis : {"u", "v", "w"}) {
    out += std::string("  int i") + axis + " = clamp(int(floor((" + axis + " + 1.0) * " +
           format_glsl_float(k.cell_index_scale) + ")), 0, " + last + ");\n";
  }
  out += "  int cell = (iu * " + count + " + iv) * " + count + " + iw;\n";
  const char* axes[3] = {"x", "y", "z"};
  const char* names[3] = {"lu", "lv", "lw"};
  for (std::size_t i = 0; i < 3; ++i) {
    out += std::string("  float ") + names[i] + " = (p." + axes[i] + " - " + centres + "[3 * cell + " +
           std::to_string(i) + "]) * " + format_glsl_float(k.cell_scale) + ";\n";
  }
  out += "  float abs_lu = abs(lu), abs_lv = abs(lv), abs_lw = abs(lw);\n";
  return out;
}

// One function longer than a screen on purpose: it is the GLSL function, written top
// to bottom as it reads in the shader; split, one shader function would be spread over
// several C++ ones.
std::string SafeSdf::to_glsl(const std::string& function) const {
  const Constants<float>& k = constants_float_;
  const auto f = [](float x) { return format_glsl_float(x); };
  std::string out;
  out += "// " + function + ": safe distance bound of the degree-" + std::to_string(program_.degree()) +
         " surface F = 0 (never more than the\n";
  const bool sheet = shape_ == SdfShape::sheet;
  out += "// distance to the surface inside the box; 0 within fp32's resolution of it), " +
         std::string(sheet ? "as a sheet\n// (>= 0, 0 on the surface)" : "negative\n// where F < 0") +
         "; evaluated in the frame u = (p - c) * s of the scene box, with\n";
  out += "// |u| <= " + f(static_cast<float>(kFarField)) + " (farther: the distance to the box). See docs/sdf.md.\n";
  const bool cells = cells_per_axis_ > 1;
  // With cells: the coefficient table (all cells' rows) and the cells' centres.
  const std::string table = cells ? function + "_c" : "";
  if (cells) out += program_.glsl_table(table) + cell_centres_glsl(function + "_cc");
  out += "float " + function + "(vec3 p) {\n";
  const char* axes[3] = {"x", "y", "z"};
  const char* names[3] = {"u", "v", "w"};
  for (std::size_t i = 0; i < 3; ++i) {
    out +=
        std::string("  float ") + names[i] + " = (p." + axes[i] + " - " + f(k.centre[i]) + ") * " + f(k.scale) + ";\n";
  }
  out += "  float abs_u = abs(u), abs_v = abs(v), abs_w = abs(w);\n";
  for (std::size_t i = 0; i < 3; ++i) {
    out += std::string("  float d") + names[i] + " = min(max(abs_" + names[i] + " * " + f(k.u_shrink) + " - " +
           f(k.box_half) + ", 0.0), " + f(k.box_clamp) + ");\n";
  }
  out += "  float box = sqrt(du * du + dv * dv + dw * dw);\n";
  out += "  if (max(abs_u, max(abs_v, abs_w)) > " + f(static_cast<float>(kFarField)) + ") {\n";
  out += "    return box * " + f(k.half_extent) + " * " + f(k.out_shrink) + ";\n";
  out += "  }\n";
  // The polynomial's inputs: u, v, w, or p in its cell's frame (lu, lv, lw).
  const std::string l = cells ? "l" : "";
  if (cells) out += cell_frame_glsl(function + "_cc");
  out += "  float g_value, g_u, g_v, g_w;\n";
  out += "  {\n";
  if (cells) out += "    float u = lu, v = lv, w = lw;\n";
  out += program_.to_glsl("    ", table);
  out += "    g_value = g;\n    g_u = gu;\n    g_v = gv;\n    g_w = gw;\n";
  out += "  }\n";
  out += "  float m_value, m_sum;\n";
  out += "  {\n";
  out += "    float u = abs_" + l + "u, v = abs_" + l + "v, w = abs_" + l + "w;\n";
  out += majorant_.to_glsl("    ", table, true);
  out += "    m_value = g;\n    m_sum = gu + gv + gw;\n";
  out += "  }\n";
  out += "  float lower = (abs(g_value) - " + f(k.gamma_value) + " * m_value) - " + f(k.tau) + ";\n";
  out += "  if (!(lower >= " + f(k.minimum_value) + ")) {\n    return box * " + f(k.half_extent) + " * " +
         f(k.out_shrink) + ";\n  }\n";
  out += "  float slope = sqrt(g_u * g_u + g_v * g_v + g_w * g_w) * " + f(k.norm_up) + " + " + f(k.gamma_gradient) +
         " * m_sum;\n";
  out += "  float r = " + f(k.radius_cap) + " * lower / max(slope * " + f(k.radius_cap) + ", lower);\n";
  out += "  float safe = 0.0, right = 0.0, phi_right = 0.0;\n";
  out += "  for (int iteration = 0; iteration <= " + std::to_string(kChordSteps) + "; ++iteration) {\n";
  out += "    float big;\n";
  out += "    {\n";
  out += "      float u = abs_" + l + "u + r, v = abs_" + l + "v + r, w = abs_" + l + "w + r;\n";
  out += majorant_value_.to_glsl("      ", table, true);
  out += "      big = g;\n";
  out += "    }\n";
  out += "    float remainder = big * " + f(k.majorant_up) + " - (m_value + r * m_sum) * " + f(k.majorant_down) + ";\n";
  out += "    float phi = (lower - slope * r) - remainder;\n";
  out += "    if (iteration == 0) {\n";
  out += "      if (phi >= 0.0) {\n        safe = r;\n        break;\n      }\n";
  out += "      right = r;\n      phi_right = phi;\n";
  out += "      float b = slope * r / lower;\n";
  out += "      float c = remainder / lower;\n";
  out += "      float t = min(2.0 / (b + sqrt(b * b + 4.0 * c)), 1.0);\n";
  out += "      safe = t * r * " + f(k.root_shrink) + ";\n";
  out += "    } else {\n";
  out += "      if (phi < 0.0) {\n        break;\n      }\n";
  out += "      safe = max(safe, (safe + phi * (right - safe) / (phi - phi_right)) * " + f(k.root_shrink) + ");\n";
  out += "    }\n";
  out += "    r = safe;\n";
  out += "  }\n";
  out += cells
             ? "  float radius = (safe - (abs_lu + abs_lv + abs_lw) * " + f(k.u_error) + ") * " + f(k.cell_step) + ";\n"
             : "  float radius = safe - (abs_u + abs_v + abs_w) * " + f(k.u_error) + ";\n";
  out += "  if (!(radius > 0.0)) {\n    return box * " + f(k.half_extent) + " * " + f(k.out_shrink) + ";\n  }\n";
  if (sheet) {
    // Both terms bound the distance to Z ∩ box from below, whatever F's sign.
    out += "  return max(box, radius) * " + f(k.half_extent) + " * " + f(k.out_shrink) + ";\n}\n";
    return out;
  }
  out += "  if (g_value >= 0.0) {\n    return max(box, radius) * " + f(k.half_extent) + " * " + f(k.out_shrink) +
         ";\n  }\n";
  out += "  if (box > 0.0) {\n    return box * " + f(k.half_extent) + " * " + f(k.out_shrink) + ";\n  }\n";
  out +=
      "  float inner = max(" + f(k.box_half_inner) + " - max(abs_u, max(abs_v, abs_w)) * " + f(k.u_grow) + ", 0.0);\n";
  out += "  return -(min(radius, inner) * " + f(k.half_extent) + " * " + f(k.out_shrink) + ");\n";
  out += "}\n";
  return out;
}

}  // namespace implicitizer
