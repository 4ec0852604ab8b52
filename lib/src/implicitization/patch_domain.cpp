#include "implicitizer/implicitization/patch_domain.hpp"

#include <algorithm>
#include <cstdint>
#include <stdexcept>

#include "implicitizer/core/errors.hpp"

namespace implicitizer {
namespace {

// p̃ = σ^d·p(…) with parameter `var` at infinity: the coefficients reversed in `var`
// (d = deg_var p, the chart s_var = 1/σ) or, `projective`, homogenized into `var`
// (d = total degree, the chart s_var = 1/σ, s_other = τ/σ of the projective plane).
Polynomial reverse_in(const Polynomial& p, std::size_t var, std::int32_t d, bool projective) {
  std::vector<Polynomial> terms;
  for (std::size_t i = 0; i < p.num_terms(); ++i) {
    std::vector<std::int32_t> e = p.exponents(i);
    std::int32_t degree = e[var];
    if (projective) {
      degree = 0;
      for (std::int32_t x : e) degree += x;
    }
    e[var] = d - degree;
    terms.push_back(Polynomial::term(p.ring(), p.coefficient(i), e));
  }
  return sum_of(p.ring(), std::move(terms));
}

// n/q in the chart of reverse_in(): n(…)/q(…) = σ^(d_q − d_n)·ñ(σ, …)/q̃(σ, …).
RationalFunction to_chart(const RationalFunction& f, std::size_t var, bool projective, const Budget& budget) {
  const Polynomial& n = f.numerator();
  if (n.is_zero()) return f;
  const auto degree = [&](const Polynomial& p) { return projective ? p.total_degree() : p.degree_in(var); };
  const std::int32_t dn = degree(n), dq = degree(f.denominator());
  Polynomial numerator = reverse_in(n, var, dn, projective);
  Polynomial denominator = reverse_in(f.denominator(), var, dq, projective);
  const Polynomial sigma = Polynomial::variable(n.ring(), var);
  if (dq > dn) numerator = numerator.multiply(sigma.pow(static_cast<unsigned>(dq - dn), budget), budget);
  if (dn > dq) denominator = denominator.multiply(sigma.pow(static_cast<unsigned>(dn - dq), budget), budget);
  return RationalFunction(numerator, denominator);
}

bool is_unbounded_polynomial_map(const Parametrization& parametrization) {
  bool moves = false;
  for (const RationalFunction& c : parametrization.coordinates) {
    if (!c.is_polynomial()) return false;
    moves = moves || !c.numerator().is_constant();
  }
  return moves;
}

void include(PatchBounds& into, const PatchBounds& bounds) {
  if (into.lo.empty()) {
    into = bounds;
    return;
  }
  for (std::size_t i = 0; i < into.lo.size(); ++i) {
    into.lo[i] = std::min(into.lo[i], bounds.lo[i]);
    into.hi[i] = std::max(into.hi[i], bounds.hi[i]);
  }
}

}  // namespace

namespace {

Parametrization chart_of(const Parametrization& parametrization, const std::vector<std::size_t>& at_infinity,
                         bool projective, const Budget& budget) {
  Parametrization chart = parametrization;
  for (RationalFunction& c : chart.coordinates) {
    for (std::size_t var : at_infinity) c = to_chart(c, var, projective, budget);
    budget.check("parameter charts");
  }
  return chart;
}

}  // namespace

std::vector<Parametrization> parameter_charts(const Parametrization& parametrization, const Budget& budget) {
  const std::size_t m = parametrization.parameter_ring->num_variables();
  std::vector<Parametrization> charts;
  for (std::size_t mask = 0; mask < (std::size_t{1} << m); ++mask) {
    std::vector<std::size_t> at_infinity;
    for (std::size_t j = 0; j < m; ++j) {
      if ((mask >> j) & 1U) at_infinity.push_back(j);
    }
    charts.push_back(chart_of(parametrization, at_infinity, false, budget));
  }
  return charts;
}

std::vector<Parametrization> projective_charts(const Parametrization& parametrization, const Budget& budget) {
  if (parametrization.parameter_ring->num_variables() != 2) {
    throw std::invalid_argument("projective_charts: two parameters expected");
  }
  return {parametrization, chart_of(parametrization, {0}, true, budget), chart_of(parametrization, {1}, true, budget)};
}

ParameterDomain unit_domain(const Parametrization& parametrization) {
  ParameterDomain domain;
  domain.intervals.assign(parametrization.parameter_ring->num_variables(), {Rational(0), Rational(1)});
  return domain;
}

namespace {

PatchBounds bound_charts(const std::vector<Parametrization>& charts, const Budget& budget,
                         const PatchBoundsParams& params) {
  ParameterDomain square;
  square.intervals.assign(charts.front().parameter_ring->num_variables(), {Rational(-1), Rational(1)});
  PatchBounds bounds;
  for (const Parametrization& chart : charts) include(bounds, bound_patch(chart, square, budget, params));
  return bounds;
}

}  // namespace

PatchBounds bound_patch_on_plane(const Parametrization& parametrization, const Budget& budget,
                                 const PatchBoundsParams& params) {
  if (parametrization.parameter_ring->num_variables() != 2) {
    return bound_charts(parameter_charts(parametrization, budget), budget, params);
  }
  // Product charts first (natural for maps on P¹×P¹, e.g. the torus); when one fails,
  // the projective ones (natural on P², e.g. the sphere and Steiner's surface, whose
  // product chart at (∞, ∞) has a denominator vanishing at a removable 0/0).
  try {
    return bound_charts(parameter_charts(parametrization, budget), budget, params);
  } catch (const InputError& e) {
    if (e.code() != "unbounded_patch") throw;
  }
  return bound_charts(projective_charts(parametrization, budget), budget, params);
}

DefaultPatchDomain default_patch_domain(const Parametrization& parametrization, const Budget& budget,
                                        const PatchBoundsParams& params) {
  DefaultPatchDomain out;
  // A non-constant polynomial map is unbounded on ℝ^m: skip the charts, whose
  // denominators σ^k would only say so at greater cost.
  if (!is_unbounded_polynomial_map(parametrization)) {
    try {
      out.bounds = bound_patch_on_plane(parametrization, budget, params);
      out.whole_plane = true;
      return out;
    } catch (const InputError& e) {
      if (e.code() != "unbounded_patch") throw;
    }
  }
  out.domain = unit_domain(parametrization);
  out.bounds = bound_patch(parametrization, out.domain, budget, params);
  return out;
}

}  // namespace implicitizer
