#include "mod_polynomial.hpp"

#include <algorithm>

namespace implicitizer::detail {

ModularArithmetic::ModularArithmetic(const Ring& ring, std::uint64_t prime) : ring_(ring) {
  nmod_init(&modulus_, prime);
}

ModPolynomial ModularArithmetic::reduce_coefficients(const IntPolynomial& p) const {
  const std::size_t w = ring_.monomial_size();
  ModPolynomial out;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const std::uint64_t c = mpz_fdiv_ui(p.coefficients[i].get_mpz_t(), modulus_.n);
    if (c == 0) continue;
    out.coefficients.push_back(c);
    out.monomials.insert(out.monomials.end(), p.monomials.begin() + static_cast<std::ptrdiff_t>(i * w),
                         p.monomials.begin() + static_cast<std::ptrdiff_t>((i + 1) * w));
  }
  make_monic(out);
  return out;
}

void ModularArithmetic::make_monic(ModPolynomial& f) const {
  if (f.empty() || f.coefficients.front() == 1) return;
  const std::uint64_t inverse = nmod_inv(f.coefficients.front(), modulus_);
  for (auto& c : f.coefficients) c = nmod_mul(c, inverse, modulus_);
}

void ModularArithmetic::subtract_multiple(const ModPolynomial& f, std::size_t from_f, std::uint64_t c,
                                          const std::int32_t* shift, const ModPolynomial& g, std::size_t from_g,
                                          ModPolynomial& out) const {
  const std::size_t w = ring_.monomial_size();
  out.coefficients.clear();
  out.monomials.clear();
  out.coefficients.reserve(f.size() + g.size());
  out.monomials.reserve((f.size() + g.size()) * w);
  std::vector<std::int32_t> shifted(w);
  std::size_t i = from_f, j = from_g;
  bool have_shifted = false;
  while (i < f.size() || j < g.size()) {
    if (j < g.size() && !have_shifted) {
      ring_.multiply(g.monomials.data() + j * w, shift, shifted.data());
      have_shifted = true;
    }
    int cmp;
    if (i == f.size()) {
      cmp = -1;
    } else if (j == g.size()) {
      cmp = 1;
    } else {
      cmp = ring_.compare(f.monomials.data() + i * w, shifted.data());
    }
    if (cmp > 0) {
      out.coefficients.push_back(f.coefficients[i]);
      out.monomials.insert(out.monomials.end(), f.monomials.data() + i * w, f.monomials.data() + i * w + w);
      ++i;
    } else if (cmp < 0) {
      out.coefficients.push_back(nmod_neg(nmod_mul(c, g.coefficients[j], modulus_), modulus_));
      out.monomials.insert(out.monomials.end(), shifted.begin(), shifted.end());
      ++j;
      have_shifted = false;
    } else {
      const std::uint64_t v = nmod_sub(f.coefficients[i], nmod_mul(c, g.coefficients[j], modulus_), modulus_);
      if (v != 0) {
        out.coefficients.push_back(v);
        out.monomials.insert(out.monomials.end(), shifted.begin(), shifted.end());
      }
      ++i;
      ++j;
      have_shifted = false;
    }
  }
}

ModPolynomial ModularArithmetic::s_polynomial(const ModPolynomial& f, const ModPolynomial& g) const {
  const std::size_t w = ring_.monomial_size();
  std::vector<std::int32_t> l(w), sf(w), sg(w);
  ring_.lcm(f.monomials.data(), g.monomials.data(), l.data());
  ring_.divide(l.data(), f.monomials.data(), sf.data());
  ring_.divide(l.data(), g.monomials.data(), sg.data());
  // (L/lm f)·tail(f), then subtract (L/lm g)·tail(g): the leading terms cancel (both monic).
  ModPolynomial shifted_f;
  shifted_f.coefficients.assign(f.coefficients.begin() + 1, f.coefficients.end());
  shifted_f.monomials.resize((f.size() - 1) * w);
  for (std::size_t i = 1; i < f.size(); ++i) {
    ring_.multiply(f.monomials.data() + i * w, sf.data(), shifted_f.monomials.data() + (i - 1) * w);
  }
  ModPolynomial out;
  subtract_multiple(shifted_f, 0, 1, sg.data(), g, 1, out);
  make_monic(out);
  return out;
}

ModPolynomial ModularArithmetic::reduce(ModPolynomial f, const std::vector<BasicReducer<ModPolynomial>>& reducers,
                                        bool full, const Budget& budget, ReductionCounters& counters,
                                        std::int32_t* sugar) const {
  const std::size_t w = ring_.monomial_size();
  ModPolynomial done;  // terms already in normal form (full reduction only)
  ModPolynomial scratch;
  std::vector<std::int32_t> shift(w);
  std::size_t start = 0;  // f's terms before `start` were moved to `done`
  while (start < f.size()) {
    const std::int32_t* lead = f.monomials.data() + start * w;
    const BasicReducer<ModPolynomial>* r = find_reducer(ring_, lead, reducers);
    if (r == nullptr) {
      if (!full) break;
      done.coefficients.push_back(f.coefficients[start]);
      done.monomials.insert(done.monomials.end(), lead, lead + w);
      ++start;
      continue;
    }
    const ModPolynomial& g = *r->polynomial;
    ring_.divide(lead, g.monomials.data(), shift.data());
    if (sugar != nullptr) *sugar = std::max(*sugar, r->sugar + ring_.sugar_degree(shift.data()));
    subtract_multiple(f, start + 1, f.coefficients[start], shift.data(), g, 1, scratch);
    std::swap(f, scratch);
    start = 0;
    ++counters.steps;
    const std::uint64_t work = kWorkPerStep + kWorkPerModularTerm * f.size();
    counters.work += work;
    budget.charge_work(work, "Groebner basis reduction modulo a prime");
    budget.check_terms(f.size() + done.size(), "Groebner basis reduction modulo a prime");
  }
  if (full) {
    done.coefficients.insert(done.coefficients.end(), f.coefficients.begin() + static_cast<std::ptrdiff_t>(start),
                             f.coefficients.end());
    done.monomials.insert(done.monomials.end(), f.monomials.begin() + static_cast<std::ptrdiff_t>(start * w),
                          f.monomials.end());
    f = std::move(done);
  }
  make_monic(f);
  return f;
}

std::vector<ModPolynomial> ModularArithmetic::minimal_basis(std::vector<ModPolynomial> basis) const {
  std::sort(basis.begin(), basis.end(), [&](const ModPolynomial& a, const ModPolynomial& b) {
    return ring_.compare(a.monomials.data(), b.monomials.data()) < 0;
  });
  // Minimal: in increasing order, keep an element only if no kept leading monomial
  // divides its own.
  std::vector<ModPolynomial> minimal;
  for (auto& g : basis) {
    if (g.empty()) continue;
    const bool divisible = std::any_of(minimal.begin(), minimal.end(), [&](const ModPolynomial& m) {
      return ring_.divides(m.monomials.data(), g.monomials.data());
    });
    if (!divisible) minimal.push_back(std::move(g));
  }
  return minimal;
}

std::vector<ModPolynomial> ModularArithmetic::reduce_basis(std::vector<ModPolynomial> basis,
                                                           const Budget& budget) const {
  std::vector<ModPolynomial> minimal = minimal_basis(std::move(basis));
  // Interreduce: each tail by the others (the leading terms are irreducible).
  std::vector<ModPolynomial> reduced(minimal.size());
  ReductionCounters counters;
  std::vector<std::uint64_t> masks(minimal.size());
  for (std::size_t j = 0; j < minimal.size(); ++j) masks[j] = ring_.divisor_mask(minimal[j].monomials.data());
  std::vector<BasicReducer<ModPolynomial>> others;
  for (std::size_t i = 0; i < minimal.size(); ++i) {
    others.clear();
    for (std::size_t j = 0; j < minimal.size(); ++j) {
      if (j != i) others.push_back({&minimal[j], masks[j], 0});
    }
    reduced[i] = reduce(minimal[i], others, true, budget, counters);
  }
  return reduced;
}

}  // namespace implicitizer::detail
