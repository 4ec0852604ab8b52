#include "implicitizer/render/ray_polynomial.hpp"

#include <flint/fmpz.h>
#include <flint/fmpz_poly.h>
#include <flint/fmpz_vec.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "dyadic.hpp"
#include "implicitizer/core/errors.hpp"

namespace implicitizer {

namespace {

using render_detail::add;
using render_detail::Dyadic;
using render_detail::Fmpz;
using render_detail::FmpzPoly;
using render_detail::multiply;
using render_detail::negate;

// p ← p·(a0 + a1·s)^times on the first `length` entries (p has room for length + times).
// Returns the new length. Running from the top keeps it in place.
std::size_t multiply_linear(double* p, std::size_t length, double a0, double a1, std::int32_t times) {
  for (std::int32_t r = 0; r < times; ++r) {
    p[length] = p[length - 1] * a1;
    for (std::size_t k = length - 1; k > 0; --k) p[k] = p[k] * a0 + p[k - 1] * a1;
    p[0] = p[0] * a0;
    ++length;
  }
  return length;
}

// into[0 … length) += from[0 … from_length); returns the longer length.
std::size_t add_into(double* into, std::size_t length, const double* from, std::size_t from_length) {
  for (std::size_t k = length; k < from_length; ++k) into[k] = 0;
  for (std::size_t k = 0; k < from_length; ++k) into[k] += from[k];
  return std::max(length, from_length);
}

void multiply_linear_exact(fmpz_poly_struct* p, const fmpz_poly_struct* linear, std::int32_t times) {
  for (std::int32_t r = 0; r < times; ++r) fmpz_poly_mul(p, p, linear);
}

}  // namespace

// Terms in nested Horner order: by x exponent, then y, then z, all decreasing.
struct RayPolynomialContext::Terms {
  std::vector<std::array<std::int32_t, 3>> exponents;
  std::vector<std::int32_t> total_degrees;
  std::vector<double> coefficients;      // sign(F)·P_m / 2^⌈log2 max|P|⌉, truncated
  std::vector<double> abs_coefficients;  // |coefficient|, at least 2^-1022
  fmpz* integers = nullptr;              // sign(content)·P_m (exact)
  std::size_t count = 0;

  Terms() = default;
  Terms(const Terms&) = delete;
  Terms& operator=(const Terms&) = delete;
  ~Terms() {
    if (integers != nullptr) _fmpz_vec_clear(integers, static_cast<slong>(count));
  }
};

RayPolynomialContext::RayPolynomialContext(const Polynomial& f) : terms_(std::make_unique<Terms>()) {
  const Ring& ring = *f.ring();
  if (ring.num_variables() != 3) {
    throw InputError("invalid_variables", "a surface needs a polynomial in exactly three variables (x, y, z)")
        .in_field("equation");
  }
  if (f.is_constant())
    throw InputError("constant_polynomial", "a constant polynomial has no surface").in_field("equation");
  degree_ = f.total_degree();
  const bool negative = f.content() < Rational(0);
  const std::vector<Integer>& p = f.integer_coefficients();

  std::vector<std::size_t> order(f.num_terms());
  for (std::size_t t = 0; t < order.size(); ++t) order[t] = t;
  auto exponents_of = [&](std::size_t t) {
    const std::int32_t* e = ring.exponents(f.monomial(t));
    return std::array<std::int32_t, 3>{e[0], e[1], e[2]};
  };
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return exponents_of(a) > exponents_of(b); });

  // Scale by a power of two near the largest |P_m|: the doubles are then at most 1 in
  // magnitude whatever F's size (1e30·sphere), and scaling by 2^-e is exact.
  long max_exponent = std::numeric_limits<long>::min();
  for (const Integer& c : p) {
    long e = 0;
    mpz_get_d_2exp(&e, c.get_mpz_t());
    max_exponent = std::max(max_exponent, e);
  }
  Terms& terms = *terms_;
  terms.count = order.size();
  terms.integers = _fmpz_vec_init(static_cast<slong>(terms.count));
  for (std::size_t r = 0; r < order.size(); ++r) {
    const std::size_t t = order[r];
    const std::array<std::int32_t, 3> e = exponents_of(t);
    terms.exponents.push_back(e);
    terms.total_degrees.push_back(e[0] + e[1] + e[2]);
    long exponent = 0;
    const double mantissa = mpz_get_d_2exp(&exponent, p[t].get_mpz_t());  // truncated: < 2 ulps
    const double c = std::ldexp(negative ? -mantissa : mantissa, static_cast<int>(exponent - max_exponent));
    terms.coefficients.push_back(c);
    terms.abs_coefficients.push_back(std::max(std::fabs(c), std::numeric_limits<double>::min()));
    fmpz_set_mpz(terms.integers + r, p[t].get_mpz_t());
    if (negative) fmpz_neg(terms.integers + r, terms.integers + r);
  }
}

RayPolynomialContext::~RayPolynomialContext() = default;
RayPolynomialContext::RayPolynomialContext(RayPolynomialContext&&) noexcept = default;
RayPolynomialContext& RayPolynomialContext::operator=(RayPolynomialContext&&) noexcept = default;

std::size_t RayPolynomialContext::num_terms() const { return terms_->count; }

namespace {

// Value and gradient of Σ c_m x^i y^j z^k by nested sparse Horner with forward-mode
// derivatives (as sdf/polynomial_program.hpp): each step y ← y·v + a carries
// y'_v ← y'_v·v + y (before y changes). Terms sorted by (i, j, k) decreasing.
// `rounding` is a running error bound of the value (Higham, Accuracy and Stability,
// §5.1): with fl(a ∘ b) = (a ∘ b)/(1 + δ), |δ| ≤ u, each operation adds u·|result|
// and multiplies the error so far by |v|; a coefficient brings its own 2u·|c|
// (truncation to double). It bounds |value − Σ c_m p^m| for the exact coefficients
// at the double point p, and is usually far below the a-priori γ_L·F̂(|p|).
struct ValueAndGradient {
  double value = 0, dx = 0, dy = 0, dz = 0;
  double rounding = 0;
};

ValueAndGradient evaluate_nested(const std::vector<std::array<std::int32_t, 3>>& exponents, const double* c, double x,
                                 double y, double z) {
  const double u = std::numeric_limits<double>::epsilon() / 2;
  const double ax = std::fabs(x), ay = std::fabs(y), az_ = std::fabs(z);
  ValueAndGradient g;
  std::int32_t previous_i = -1;
  std::size_t t = 0;
  const std::size_t count = exponents.size();
  auto times_x = [&](ValueAndGradient& v, std::int32_t power) {
    for (std::int32_t r = 0; r < power; ++r) {
      v.dx = v.dx * x + v.value;
      v.dy *= x;
      v.dz *= x;
      v.value *= x;
      v.rounding = v.rounding * ax + u * std::fabs(v.value);
    }
  };
  while (t < count) {
    const std::int32_t i = exponents[t][0];
    double b = 0, by = 0, bz = 0, be = 0;
    std::int32_t previous_j = -1;
    auto times_y = [&](std::int32_t power) {
      for (std::int32_t r = 0; r < power; ++r) {
        by = by * y + b;
        bz *= y;
        b *= y;
        be = be * ay + u * std::fabs(b);
      }
    };
    while (t < count && exponents[t][0] == i) {
      const std::int32_t j = exponents[t][1];
      double a = 0, az = 0, ae = 0;
      std::int32_t previous_k = -1;
      auto times_z = [&](std::int32_t power) {
        for (std::int32_t r = 0; r < power; ++r) {
          az = az * z + a;
          a *= z;
          ae = ae * az_ + u * std::fabs(a);
        }
      };
      while (t < count && exponents[t][0] == i && exponents[t][1] == j) {
        const std::int32_t k = exponents[t][2];
        if (previous_k >= 0) times_z(previous_k - k);
        a += c[t];
        ae += 2 * u * std::fabs(c[t]) + u * std::fabs(a);
        previous_k = k;
        ++t;
      }
      times_z(previous_k);
      if (previous_j >= 0) times_y(previous_j - j);
      b += a;
      bz += az;
      be += ae + u * std::fabs(b);
      previous_j = j;
    }
    times_y(previous_j);
    if (previous_i >= 0) times_x(g, previous_i - i);
    g.value += b;
    g.dy += by;
    g.dz += bz;
    g.rounding += be + u * std::fabs(g.value);
    previous_i = i;
  }
  times_x(g, previous_i);
  return g;
}

// The linear polynomials X(s) = x0 + x1·s of the three coordinates on a segment,
// their majorants, and how far x0 may be from the true start. x0 = fl(o + t_begin·d)
// is taken as exact (the rounding goes into the band, start_band()); x1 =
// fl(fl(t_end − t_begin)·d) is within γ₂ of the true slope, relative to itself, which
// the coefficient bound covers.
struct SegmentLines {
  std::array<double, 3> a0{}, a1{}, m0{}, m1{}, delta{};
};

SegmentLines segment_lines(const RaySegment& segment) {
  const double u = std::numeric_limits<double>::epsilon() / 2;
  const double width = segment.t_end - segment.t_begin;
  SegmentLines l;
  for (std::size_t v = 0; v < 3; ++v) {
    const double o = segment.origin[v], d = segment.direction[v];
    l.a0[v] = o + segment.t_begin * d;
    l.a1[v] = width * d;
    l.m0[v] = std::fabs(l.a0[v]);
    l.m1[v] = std::fabs(l.a1[v]);
    // |x0 − (o + t_begin·d)| ≤ 2.02u(|o| + |t_begin·d|); exact when t_begin = 0.
    l.delta[v] = segment.t_begin == 0 ? 0.0 : 2.02 * u * (std::fabs(o) + std::fabs(segment.t_begin * d));
  }
  return l;
}

// The band: F(P + e) − F(P) for the true start P + e, |e| ≤ δ, has power (and so
// Bernstein) coefficients bounded coefficient-wise by those of F̂(P̂ + δ) − F̂(P̂),
// whose sum, its value at s = 1, is at most Σ_i δ_i·∂_iF̂(P̂(1) + δ).
double start_band(const std::vector<std::array<std::int32_t, 3>>& exponents,
                  const std::vector<double>& abs_coefficients, const SegmentLines& l) {
  const double u = std::numeric_limits<double>::epsilon() / 2;
  const ValueAndGradient m =
      evaluate_nested(exponents, abs_coefficients.data(), l.m0[0] + l.m1[0] * (1 + 4 * u) + l.delta[0],
                      l.m0[1] + l.m1[1] * (1 + 4 * u) + l.delta[1], l.m0[2] + l.m1[2] * (1 + 4 * u) + l.delta[2]);
  return 1.01 * (m.dx * l.delta[0] + m.dy * l.delta[1] + m.dz * l.delta[2]);
}

}  // namespace

// Longer than a screen: the three nested sparse Horner loops (in x, y, z) share their
// buffers and lengths, and read as one algorithm only together.
void RayPolynomialContext::expand_double(const RaySegment& segment, DoubleRayPolynomial& out) const {
  const Terms& terms = *terms_;
  const std::size_t size = static_cast<std::size_t>(degree_) + 1;
  const double u = std::numeric_limits<double>::epsilon() / 2;
  const SegmentLines lines = segment_lines(segment);
  const auto& [a0, a1, m0, m1, delta] = lines;
  out.band = segment.t_begin == 0 ? 0.0 : start_band(terms.exponents, terms.abs_coefficients, lines);

  out.coefficients.assign(size, 0.0);
  out.majorant.assign(size, 0.0);
  thread_local std::vector<double> scratch;
  scratch.assign(4 * size, 0.0);
  double* g = out.coefficients.data();
  double* gm = out.majorant.data();
  double* b = scratch.data();
  double* bm = b + size;
  double* a = bm + size;
  double* am = a + size;

  // G = Σ_i X^i B_i, B_i = Σ_j Y^j A_ij, A_ij = Σ_k c_ijk Z^k, each by sparse Horner.
  std::size_t g_length = 0;
  std::int32_t previous_i = -1;
  std::size_t t = 0;
  while (t < terms.count) {
    const std::int32_t i = terms.exponents[t][0];
    std::size_t b_length = 0;
    std::int32_t previous_j = -1;
    while (t < terms.count && terms.exponents[t][0] == i) {
      const std::int32_t j = terms.exponents[t][1];
      std::size_t a_length = 0;
      std::int32_t previous_k = -1;
      while (t < terms.count && terms.exponents[t][0] == i && terms.exponents[t][1] == j) {
        const std::int32_t k = terms.exponents[t][2];
        if (a_length == 0) {
          a[0] = terms.coefficients[t];
          am[0] = terms.abs_coefficients[t];
          a_length = 1;
        } else {
          multiply_linear(a, a_length, a0[2], a1[2], previous_k - k);
          a_length = multiply_linear(am, a_length, m0[2], m1[2], previous_k - k);
          a[0] += terms.coefficients[t];
          am[0] += terms.abs_coefficients[t];
        }
        previous_k = k;
        ++t;
      }
      multiply_linear(a, a_length, a0[2], a1[2], previous_k);
      a_length = multiply_linear(am, a_length, m0[2], m1[2], previous_k);
      if (b_length > 0) {
        multiply_linear(b, b_length, a0[1], a1[1], previous_j - j);
        b_length = multiply_linear(bm, b_length, m0[1], m1[1], previous_j - j);
      }
      add_into(b, b_length, a, a_length);
      b_length = add_into(bm, b_length, am, a_length);
      previous_j = j;
    }
    multiply_linear(b, b_length, a0[1], a1[1], previous_j);
    b_length = multiply_linear(bm, b_length, m0[1], m1[1], previous_j);
    if (g_length > 0) {
      multiply_linear(g, g_length, a0[0], a1[0], previous_i - i);
      g_length = multiply_linear(gm, g_length, m0[0], m1[0], previous_i - i);
    }
    add_into(g, g_length, b, b_length);
    g_length = add_into(gm, g_length, bm, b_length);
    previous_i = i;
  }
  multiply_linear(g, g_length, a0[0], a1[0], previous_i);
  multiply_linear(gm, g_length, m0[0], m1[0], previous_i);

  const double l = 6.0 * degree_ + 6.0;
  out.relative_error = 2 * l * u / (1 - l * u);
  out.finite = std::isfinite(out.band);
  for (std::size_t k = 0; k < size; ++k) {
    if (!std::isfinite(g[k]) || !std::isfinite(gm[k])) out.finite = false;
  }
}

namespace {

// Error-free transformations (Dekker 1971, Knuth TAOCP 4.2.2): a·b = product + error
// and a + b = sum + error exactly, in round-to-nearest without overflow. They need
// every operation rounded as written: no fused multiply-add contraction (off in
// GCC's ISO modes, -std=c++20, and absent from the x86-64 baseline) and no -ffast-math.
void two_product(double a, double b, double& product, double& error) {
  constexpr double kSplitter = 134217729.0;  // 2^27 + 1
  product = a * b;
  const double ca = kSplitter * a, cb = kSplitter * b;
  const double a_hi = ca - (ca - a), a_lo = a - a_hi;
  const double b_hi = cb - (cb - b), b_lo = b - b_hi;
  error = ((a_hi * b_hi - product) + a_hi * b_lo + a_lo * b_hi) + a_lo * b_lo;
}

void two_sum(double a, double b, double& sum, double& error) {
  sum = a + b;
  const double bb = sum - a;
  error = (a - (sum - bb)) + (b - bb);
}

}  // namespace

RayPointValue RayPolynomialContext::evaluate_double(const std::array<double, 3>& origin,
                                                    const std::array<double, 3>& direction, double t) const {
  const Terms& terms = *terms_;
  const double u = std::numeric_limits<double>::epsilon() / 2;
  // p = o + t·d = s + e + b exactly (two_product, two_sum); r = fl(e + b).
  std::array<double, 3> s{}, r{}, r_error{}, far{};
  double h = 0, r_sum = 0;
  for (std::size_t v = 0; v < 3; ++v) {
    double a = 0, b = 0, e = 0;
    two_product(t, direction[v], a, b);
    two_sum(origin[v], a, s[v], e);
    r[v] = e + b;
    r_error[v] = u * (std::fabs(e) + std::fabs(b));
    h = std::max(h, std::fabs(s[v]) + std::fabs(r[v]) + r_error[v]);
    r_sum += std::fabs(r[v]) + r_error[v];
  }
  if (!(h > 0)) h = 1;
  for (std::size_t v = 0; v < 3; ++v) far[v] = std::fabs(s[v]) + std::fabs(r[v]) + r_error[v] + h;
  const ValueAndGradient f = evaluate_nested(terms.exponents, terms.coefficients.data(), s[0], s[1], s[2]);
  // G = ∇F̂ at |s| + |r| + h: it bounds ∇F̂(|s|) and, divided by h, the second
  // derivatives ∂_ij F̂ up to |s| + |r| (a polynomial G with non-negative coefficients
  // has ∂_j G(y) ≤ G(y + h·e_j)/h).
  const ValueAndGradient m = evaluate_nested(terms.exponents, terms.abs_coefficients.data(), far[0], far[1], far[2]);
  const std::array<double, 3> gradient{f.dx, f.dy, f.dz}, bound{m.dx, m.dy, m.dz};
  double correction = 0, correction_size = 0, first_order = 0;
  for (std::size_t v = 0; v < 3; ++v) {
    correction += gradient[v] * r[v];
    correction_size += std::fabs(gradient[v] * r[v]);
    // ∇F̃(s) is within γ_{8n+8}·∇F̂(|s|) of ∇F(s) (forward mode doubles the operations
    // of the value's path), and r̃ within r_error of r.
    const double l = 8.0 * degree_ + 8.0;
    first_order += bound[v] * (l * u / (1 - l * u) * (std::fabs(r[v]) + r_error[v]) + r_error[v]);
  }
  RayPointValue out;
  out.value = f.value + correction;
  out.derivative = f.dx * direction[0] + f.dy * direction[1] + f.dz * direction[2];
  // Taylor: |F(s + r) − F(s) − ∇F(s)·r| ≤ ½ Σ_ij |r_i||r_j| ∂_ij F̂ ≤ ½ (Σ|r|/h)·Σ_i |r_i|·G_i.
  double second_order = 0;
  for (std::size_t v = 0; v < 3; ++v) second_order += (std::fabs(r[v]) + r_error[v]) * bound[v];
  second_order *= 0.5 * r_sum / h;
  // The dot product and the final sum: γ_4 of their sizes.
  const double sums = 4 * u * (correction_size + std::fabs(f.value) + std::fabs(out.value));
  // 1.01: the bounds are computed in double too (relative error ≪ 1%); 1e-300
  // absorbs subnormal results, where rounding is absolute rather than relative.
  out.error = 1.01 * (f.rounding + first_order + second_order + sums) + 1e-300;
  return out;
}

// Longer than a screen for the reason expand_double() is: one nested Horner scheme.
std::vector<Integer> RayPolynomialContext::expand_exact(const RaySegment& segment, const Budget& budget) const {
  const Terms& terms = *terms_;
  // The segment's point at s is P + s·W exactly (dyadics), then (O + s·D)·2^E.
  const Dyadic begin = Dyadic::of(segment.t_begin);
  const Dyadic width = add(Dyadic::of(segment.t_end), negate(begin));
  std::array<Dyadic, 6> values;
  for (std::size_t v = 0; v < 3; ++v) {
    const Dyadic d = Dyadic::of(segment.direction[v]);
    values[v] = add(Dyadic::of(segment.origin[v]), multiply(begin, d));
    values[3 + v] = multiply(width, d);
  }
  slong common = 0;  // E = min(0, every exponent): then O, D are integers
  for (const Dyadic& d : values) {
    if (!d.is_zero()) common = std::min(common, d.exponent);
  }
  const ulong shift = static_cast<ulong>(-common);  // σ = −E ≥ 0
  std::array<FmpzPoly, 3> linear;
  for (std::size_t v = 0; v < 3; ++v) {
    Fmpz c;
    fmpz_mul_2exp(c.get(), values[v].mantissa.get(), static_cast<ulong>(values[v].exponent - common));
    fmpz_poly_set_coeff_fmpz(linear[v].get(), 0, c.get());
    fmpz_mul_2exp(c.get(), values[3 + v].mantissa.get(), static_cast<ulong>(values[3 + v].exponent - common));
    fmpz_poly_set_coeff_fmpz(linear[v].get(), 1, c.get());
  }

  FmpzPoly g, b, a;
  Fmpz c;
  std::int32_t previous_i = -1;
  std::size_t t = 0;
  while (t < terms.count) {
    const std::int32_t i = terms.exponents[t][0];
    fmpz_poly_zero(b.get());
    std::int32_t previous_j = -1;
    while (t < terms.count && terms.exponents[t][0] == i) {
      const std::int32_t j = terms.exponents[t][1];
      fmpz_poly_zero(a.get());
      std::int32_t previous_k = -1;
      while (t < terms.count && terms.exponents[t][0] == i && terms.exponents[t][1] == j) {
        budget.check("expand_exact");
        const std::int32_t k = terms.exponents[t][2];
        if (previous_k >= 0) multiply_linear_exact(a.get(), linear[2].get(), previous_k - k);
        // c_m·2^(σ(n − |m|)): the homogenising power that clears the denominators 2^(σ|m|).
        fmpz_mul_2exp(c.get(), terms.integers + t, shift * static_cast<ulong>(degree_ - terms.total_degrees[t]));
        Fmpz constant;
        fmpz_poly_get_coeff_fmpz(constant.get(), a.get(), 0);
        fmpz_add(constant.get(), constant.get(), c.get());
        fmpz_poly_set_coeff_fmpz(a.get(), 0, constant.get());
        previous_k = k;
        ++t;
      }
      multiply_linear_exact(a.get(), linear[2].get(), previous_k);
      if (previous_j >= 0) multiply_linear_exact(b.get(), linear[1].get(), previous_j - j);
      fmpz_poly_add(b.get(), b.get(), a.get());
      previous_j = j;
    }
    multiply_linear_exact(b.get(), linear[1].get(), previous_j);
    if (previous_i >= 0) multiply_linear_exact(g.get(), linear[0].get(), previous_i - i);
    fmpz_poly_add(g.get(), g.get(), b.get());
    previous_i = i;
  }
  multiply_linear_exact(g.get(), linear[0].get(), previous_i);

  std::vector<Integer> out(static_cast<std::size_t>(fmpz_poly_length(g.get())));
  if (out.empty()) return out;
  fmpz_poly_content(c.get(), g.get());  // > 0: dividing keeps the signs
  fmpz_poly_scalar_divexact_fmpz(g.get(), g.get(), c.get());
  for (std::size_t k = 0; k < out.size(); ++k) {
    fmpz_poly_get_coeff_fmpz(c.get(), g.get(), static_cast<slong>(k));
    fmpz_get_mpz(out[k].get_mpz_t(), c.get());
  }
  return out;
}

}  // namespace implicitizer
