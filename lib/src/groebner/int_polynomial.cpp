#include "int_polynomial.hpp"

#include <algorithm>

namespace implicitizer::detail {

IntPolynomial to_int_polynomial(const Polynomial& p) {
  return IntPolynomial{p.integer_coefficients(), p.monomial_data()};
}

Polynomial to_monic_polynomial(const RingPtr& ring, const IntPolynomial& p) {
  if (p.empty()) return Polynomial(ring);
  mpq_class inverse(1, p.coefficients.front());
  inverse.canonicalize();
  return Polynomial::from_terms(ring, to_rational(inverse), p.coefficients, p.monomials);
}

void make_primitive(IntPolynomial& p) {
  if (p.empty()) return;
  Integer g = 0;
  for (const auto& c : p.coefficients) {
    mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), c.get_mpz_t());
    if (g == 1) break;
  }
  if (p.coefficients.front() < 0) g = -g;
  if (g == 1) return;
  for (auto& c : p.coefficients) mpz_divexact(c.get_mpz_t(), c.get_mpz_t(), g.get_mpz_t());
}

namespace {

// Divides f and done by the gcd of all their coefficients (the sign is left alone).
void remove_common_content(IntPolynomial& f, IntPolynomial& done) {
  Integer g = 0;
  for (const auto* part : {&done, &f}) {
    for (const auto& c : part->coefficients) {
      mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), c.get_mpz_t());
      if (g == 1) return;
    }
  }
  if (g == 0) return;
  for (auto* part : {&done, &f}) {
    for (auto& c : part->coefficients) mpz_divexact(c.get_mpz_t(), c.get_mpz_t(), g.get_mpz_t());
  }
}

// out ← fa·f[from_f..] − ga·(shift·g)[from_g..], merged in decreasing order. f's
// coefficients are moved out (f is consumed): copying them cost one malloc per term
// per reduction step, a third of the time of a small elimination.
void combine(const Ring& ring, const Integer& fa, IntPolynomial& f, std::size_t from_f, const Integer& ga,
             const std::int32_t* shift, const IntPolynomial& g, std::size_t from_g, IntPolynomial& out) {
  const std::size_t w = ring.monomial_size();
  out.coefficients.clear();
  out.monomials.clear();
  out.coefficients.reserve(f.size() + g.size());
  out.monomials.reserve((f.size() + g.size()) * w);
  std::vector<std::int32_t> shifted(w);
  const bool scale_f = fa != 1;
  std::size_t i = from_f, j = from_g;
  bool have_shifted = false;
  while (i < f.size() || j < g.size()) {
    if (j < g.size() && !have_shifted) {
      ring.multiply(g.monomials.data() + j * w, shift, shifted.data());
      have_shifted = true;
    }
    int cmp;
    if (i == f.size()) {
      cmp = -1;
    } else if (j == g.size()) {
      cmp = 1;
    } else {
      cmp = ring.compare(f.monomials.data() + i * w, shifted.data());
    }
    if (cmp > 0) {
      out.coefficients.push_back(std::move(f.coefficients[i]));
      if (scale_f) mpz_mul(out.coefficients.back().get_mpz_t(), out.coefficients.back().get_mpz_t(), fa.get_mpz_t());
      out.monomials.insert(out.monomials.end(), f.monomials.data() + i * w, f.monomials.data() + i * w + w);
      ++i;
    } else if (cmp < 0) {
      out.coefficients.emplace_back(-ga * g.coefficients[j]);
      out.monomials.insert(out.monomials.end(), shifted.begin(), shifted.end());
      ++j;
      have_shifted = false;
    } else {
      Integer c = std::move(f.coefficients[i]);
      if (scale_f) mpz_mul(c.get_mpz_t(), c.get_mpz_t(), fa.get_mpz_t());
      mpz_submul(c.get_mpz_t(), ga.get_mpz_t(), g.coefficients[j].get_mpz_t());
      if (c != 0) {
        out.coefficients.push_back(std::move(c));
        out.monomials.insert(out.monomials.end(), shifted.begin(), shifted.end());
      }
      ++i;
      ++j;
      have_shifted = false;
    }
  }
}

// The work of writing `p` (reducer.hpp's units): its terms and their limbs. Counting
// limbs keeps a unit near one cost on huge coefficients (10^100000 is 5 200 limbs).
std::uint64_t written_work(const IntPolynomial& p) {
  std::uint64_t limbs = 0;
  for (const Integer& c : p.coefficients) limbs += mpz_size(c.get_mpz_t());
  return kWorkPerTerm * p.size() + kWorkPerLimb * limbs;
}

}  // namespace

IntPolynomial reduce(const Ring& ring, IntPolynomial f, const std::vector<Reducer>& reducers, bool full,
                     const Budget& budget, ReductionCounters& counters, std::int32_t* sugar) {
  const std::size_t w = ring.monomial_size();
  IntPolynomial done;  // terms already in normal form (full reduction only)
  IntPolynomial scratch;
  std::vector<std::int32_t> shift(w);
  std::size_t since_content = 0;
  std::size_t start = 0;  // f's terms before `start` were moved to `done` (full reduction)
  while (start < f.size()) {
    const std::int32_t* lead = f.monomials.data() + start * w;
    const Reducer* r = find_reducer(ring, lead, reducers);
    if (r == nullptr) {
      if (!full) break;
      // The leading term is in normal form: move it over and go on with the rest.
      done.coefficients.push_back(std::move(f.coefficients[start]));
      done.monomials.insert(done.monomials.end(), lead, lead + w);
      ++start;
      continue;
    }
    const IntPolynomial& g = *r->polynomial;
    ring.divide(lead, g.monomials.data(), shift.data());
    if (sugar != nullptr) *sugar = std::max(*sugar, r->sugar + ring.sugar_degree(shift.data()));
    Integer d;
    mpz_gcd(d.get_mpz_t(), f.coefficients[start].get_mpz_t(), g.coefficients.front().get_mpz_t());
    const Integer fa = g.coefficients.front() / d;  // multiplies f (and the done part)
    const Integer ga = f.coefficients[start] / d;   // multiplies m·g
    combine(ring, fa, f, start + 1, ga, shift.data(), g, 1, scratch);
    std::swap(f, scratch);
    start = 0;
    std::uint64_t work = kWorkPerStep + written_work(f);
    if (fa != 1) {
      for (auto& c : done.coefficients) c *= fa;
      work += written_work(done);
    }
    ++counters.steps;
    counters.work += work;
    budget.charge_work(work, "Groebner basis reduction");
    // Coefficients grow by a factor lc(g) per step; dividing out the content now and
    // then keeps them near the size of the true remainder's. The finished part `done`
    // was scaled by the same factors, so the content is taken over both together:
    // without that, a long tail reduction multiplies `done` by every lc(g) on the way
    // and its coefficients grow without bound (thousands of limbs on biquadratic_patch).
    if (++since_content == 8) {
      since_content = 0;
      remove_common_content(f, done);
    }
    budget.check_terms(f.size() + done.size(), "Groebner basis reduction");
  }
  if (full) {
    done.coefficients.insert(done.coefficients.end(), std::make_move_iterator(f.coefficients.begin() + start),
                             std::make_move_iterator(f.coefficients.end()));
    done.monomials.insert(done.monomials.end(), f.monomials.begin() + start * w, f.monomials.end());
    f = std::move(done);
  }
  make_primitive(f);
  return f;
}

IntPolynomial s_polynomial(const Ring& ring, const IntPolynomial& f, const IntPolynomial& g) {
  const std::size_t w = ring.monomial_size();
  std::vector<std::int32_t> l(w), sf(w), sg(w);
  ring.lcm(f.monomials.data(), g.monomials.data(), l.data());
  ring.divide(l.data(), f.monomials.data(), sf.data());
  ring.divide(l.data(), g.monomials.data(), sg.data());
  Integer d;
  mpz_gcd(d.get_mpz_t(), f.coefficients.front().get_mpz_t(), g.coefficients.front().get_mpz_t());
  const Integer fa = g.coefficients.front() / d;
  const Integer ga = f.coefficients.front() / d;
  // Shift f by sf first (its leading term cancels against g's), then combine.
  IntPolynomial shifted_f;
  shifted_f.coefficients.reserve(f.size() - 1);
  shifted_f.monomials.resize((f.size() - 1) * w);
  for (std::size_t i = 1; i < f.size(); ++i) {
    shifted_f.coefficients.push_back(f.coefficients[i]);
    ring.multiply(f.monomials.data() + i * w, sf.data(), shifted_f.monomials.data() + (i - 1) * w);
  }
  IntPolynomial out;
  combine(ring, fa, shifted_f, 0, ga, sg.data(), g, 1, out);
  return out;
}

}  // namespace implicitizer::detail
