#pragma once
// Shared by the tests of lib/sdf: surfaces, exact reference values, glslangValidator.

#include <gmpxx.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "implicitization/surfaces.hpp"
#include "implicitizer/implicitization/implicitize.hpp"
#include "implicitizer/implicitization/parametrization.hpp"
#include "implicitizer/polynomial/parser.hpp"
#include "implicitizer/sdf/scene_frame.hpp"

namespace implicitizer::testing {

inline RingPtr xyz_ring() {
  static const RingPtr ring = Ring::make({"x", "y", "z"});
  return ring;
}

inline Polynomial parse_xyz(const std::string& text) { return parse_polynomial(text, xyz_ring()); }

inline Rational exact(const std::string& number) {
  const Polynomial c = parse_xyz(number);
  return c.is_zero() ? Rational(0) : c.coefficient(0);
}

inline SceneBox box_of(const std::string& x0, const std::string& y0, const std::string& z0, const std::string& x1,
                       const std::string& y1, const std::string& z1) {
  return SceneBox{{exact(x0), exact(y0), exact(z0)}, {exact(x1), exact(y1), exact(z1)}};
}

// The implicit equation of tp_33 (degree 18, ../shared/bench/surfaces_hard.json),
// computed once (about 0.4 s).
inline const Polynomial& tp33_implicit() {
  static const Polynomial f = [] {
    for (const Surface& s : read_surfaces(std::string(IMPLICITIZER_SHARED_DIR) + "/bench/surfaces_hard.json")) {
      if (s.name == "tp_33") return implicitize(parse_parametrization(s.x, s.y, s.z)).implicit;
    }
    std::abort();
  }();
  return f;
}

// The exact sign of F at float points, fast enough for 10^4 points of a degree-18 F:
// F's coefficients made integers (times the positive lcm of their denominators), the
// point's coordinates written as X/W, Y/W, Z/W with W = 2^E, and W^n·F(X/W, Y/W, Z/W)
// evaluated as an integer by nested Horner (each level homogeneous: a coefficient
// enters as k·W^(m - c), a shift). Rational arithmetic on Polynomial::evaluate takes
// several times longer at this degree.
class ExactSign {
 public:
  explicit ExactSign(const Polynomial& f) : degree_(f.total_degree()) {
    mpz_class lcm = 1;
    for (std::size_t t = 0; t < f.num_terms(); ++t) {
      const mpz_class d = to_mpq(f.coefficient(t)).get_den();
      mpz_lcm(lcm.get_mpz_t(), lcm.get_mpz_t(), d.get_mpz_t());
    }
    rows_.assign(static_cast<std::size_t>(degree_ + 1), std::vector<std::vector<mpz_class>>());
    for (std::size_t a = 0; a <= static_cast<std::size_t>(degree_); ++a) {
      rows_[a].assign(static_cast<std::size_t>(degree_) + 1 - a, std::vector<mpz_class>());
      for (std::size_t b = 0; b < rows_[a].size(); ++b) rows_[a][b].assign(rows_[a].size() - b, mpz_class(0));
    }
    for (std::size_t t = 0; t < f.num_terms(); ++t) {
      const std::vector<std::int32_t> e = f.exponents(t);
      rows_[e[0]][e[1]][e[2]] = mpq_class(to_mpq(f.coefficient(t)) * lcm).get_num();
    }
  }

  // -1, 0 or 1: the sign of F at exactly (x, y, z).
  int sign(float x, float y, float z) const {
    const float p[3] = {x, y, z};
    long shift = 0;  // E
    for (float c : p) {
      int e = 0;
      if (c != 0) std::frexp(c, &e);
      if (c != 0) shift = std::max(shift, 24L - e);
    }
    mpz_class q[3];  // p_i·2^E, integers
    for (std::size_t i = 0; i < 3; ++i) {
      int e = 0;
      const double mantissa = std::ldexp(std::frexp(static_cast<double>(p[i]), &e), 24);  // an integer
      q[i] = static_cast<long>(mantissa);
      if (p[i] != 0) q[i] <<= static_cast<mp_bitcnt_t>(shift - (24 - e));
    }
    mpz_class outer = 0, middle, inner, term;
    for (std::size_t a = rows_.size(); a-- > 0;) {
      middle = 0;
      for (std::size_t b = rows_[a].size(); b-- > 0;) {
        const std::vector<mpz_class>& ks = rows_[a][b];
        const std::size_t m = ks.size() - 1;  // n - a - b
        inner = 0;
        for (std::size_t c = ks.size(); c-- > 0;) {
          inner *= q[2];
          if (ks[c] != 0) {
            term = ks[c];
            term <<= static_cast<mp_bitcnt_t>(shift) * (m - c);
            inner += term;
          }
        }
        middle *= q[1];
        middle += inner;
      }
      outer *= q[0];
      outer += middle;
    }
    return sgn(outer);
  }

 private:
  std::int32_t degree_;
  std::vector<std::vector<std::vector<mpz_class>>> rows_;  // [a][b][c]: the integer coefficient of x^a y^b z^c
};

// tp_33's box (docs/sdf.md §4) and 10^4 uniform random float points in it (seed 19),
// with F's exact signs there; computed once (about a second).
struct SignSample {
  SceneBox box;
  std::vector<std::array<float, 3>> points;
  std::vector<int> signs;
};
inline const SignSample& tp33_sign_sample() {
  static const SignSample sample = [] {
    SignSample s{box_of("-8", "-10", "-18", "8", "6", "4"), {}, {}};
    const ExactSign exact(tp33_implicit());
    std::mt19937 random(19);
    std::uniform_real_distribution<double> unit(0, 1);
    for (int i = 0; i < 10000; ++i) {
      s.points.push_back({static_cast<float>(-8 + 16 * unit(random)), static_cast<float>(-10 + 16 * unit(random)),
                          static_cast<float>(-18 + 22 * unit(random))});
      s.signs.push_back(exact.sign(s.points.back()[0], s.points.back()[1], s.points.back()[2]));
    }
    return s;
  }();
  return sample;
}

// F/|∇F| at the point (exactly the doubles given), in exact arithmetic, then rounded:
// sign(F)·sqrt(F²/|∇F|²). NaN where ∇F = 0.
inline double exact_estimate(const Polynomial& f, double x, double y, double z) {
  const Rational point[3] = {Rational(x), Rational(y), Rational(z)};
  const Rational value = f.evaluate(point);
  Rational norm2(0);
  for (std::size_t i = 0; i < 3; ++i) {
    const Rational d = f.derivative(i).evaluate(point);
    norm2 += d * d;
  }
  if (norm2 == Rational(0)) return std::nan("");
  const double magnitude = std::sqrt(to_mpq(value * value / norm2).get_d());
  return value < Rational(0) ? -magnitude : magnitude;
}

// The signed distance from (x, y, z) to the frame's box |u_i| <= 1 (iq's box: positive
// outside, minus the distance to the nearest face inside), in double. Fast and safe
// mode draw the solid F <= 0 clipped to it: fast returns max(F/|∇F|, this).
inline double signed_box_distance(const SceneFrame& frame, double x, double y, double z) {
  const double s = to_mpq(frame.scale).get_d();
  const double p[3] = {x, y, z};
  double outside = 0, largest = -1;
  for (std::size_t i = 0; i < 3; ++i) {
    const double q = std::fabs((p[i] - to_mpq(frame.centre[i]).get_d()) * s) - 1;
    outside += std::max(q, 0.0) * std::max(q, 0.0);
    largest = std::max(largest, q);
  }
  return (std::sqrt(outside) + std::min(largest, 0.0)) / s;
}

// Subnormals flushed to zero, as GPUs may (GLSL ES 3.00 §4.5.1 allows it).
inline float flush(float x) { return std::fabs(x) < 1.17549435e-38f ? 0.0f : x; }

// F at the point in plain float arithmetic, term by term from the expanded
// coefficients, subnormals flushed: what a shader without the frame computes.
inline float naive_float_value(const Polynomial& f, float x, float y, float z) {
  float sum = 0;
  for (std::size_t t = 0; t < f.num_terms(); ++t) {
    float term = static_cast<float>(to_mpq(f.coefficient(t)).get_d());
    const std::vector<std::int32_t> e = f.exponents(t);
    const float xyz[3] = {x, y, z};
    for (std::size_t i = 0; i < 3; ++i) {
      for (std::int32_t k = 0; k < e[i]; ++k) term = flush(term * xyz[i]);
    }
    sum = flush(sum + flush(term));
  }
  return sum;
}

// Compiles `function` (defining float NAME(vec3)) in a fragment shader with
// glslangValidator; `header` is "#version 300 es\nprecision highp float;" or
// "#version 330". Returns the validator's output when it fails, "" on success.
inline std::string glslang_errors(const std::string& header, const std::string& function, const std::string& name) {
  char dir[] = "/tmp/sdf_glslXXXXXX";
  if (mkdtemp(dir) == nullptr) return "mkdtemp failed";
  const std::string path = std::string(dir) + "/shader.frag";
  {
    std::ofstream out(path);
    out << header << "\n"
        << function << "\nout vec4 colour;\nvoid main() {\n"
        << "  colour = vec4(" << name << "(vec3(0.5, -0.25, 0.125)));\n}\n";
  }
  const std::string log = std::string(dir) + "/log.txt";
  const int rc = std::system(("/usr/bin/glslangValidator " + path + " > " + log + " 2>&1").c_str());
  std::ifstream in(log);
  const std::string output((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::remove(log.c_str());
  std::remove(path.c_str());
  rmdir(dir);
  return rc == 0 ? "" : "status " + std::to_string(rc) + ": " + output;
}

}  // namespace implicitizer::testing
