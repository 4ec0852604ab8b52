// implicitizer-representation-bench: what the coefficient representation costs.
//
// docs/design.md records the choice of "rational content × primitive integer
// polynomial" (FLINT's fmpq_mpoly layout) over "one rational per term". This program
// measures it on the operation that dominates elimination, the sparse product, with
// rational coefficients that share denominators (as parametrizations' do):
//   1. rational per term: the schoolbook product into an ordered map, each
//      coefficient an mpq (every addition and product canonicalizes with a gcd);
//   2. content × integer: the same schoolbook product and the same map, but integer
//      coefficients and one rational content multiplication per product;
//   3. the library's Polynomial (content × primitive, Johnson's heap product).
// 1 against 2 isolates the representation; 3 shows what the product algorithm adds.
// Not a test: it prints a table; docs/design.md quotes one run.

#include <chrono>
#include <cstdio>
#include <functional>
#include <map>
#include <vector>

#include "implicitizer/core/rational.hpp"
#include "implicitizer/polynomial/polynomial.hpp"

namespace {

using implicitizer::Integer;
using implicitizer::Polynomial;
using implicitizer::Rational;
using Exponents = std::vector<int>;

// Polynomials in the schoolbook representations: monomial → coefficient.
using RationalTerms = std::map<Exponents, mpq_class>;
struct ContentTerms {
  mpq_class content;
  std::map<Exponents, Integer> terms;
};

Exponents add(const Exponents& a, const Exponents& b) {
  Exponents e(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) e[i] = a[i] + b[i];
  return e;
}

RationalTerms multiply(const RationalTerms& f, const RationalTerms& g) {
  RationalTerms out;
  for (const auto& [ef, cf] : f) {
    for (const auto& [eg, cg] : g) {
      mpq_class& c = out[add(ef, eg)];
      c += cf * cg;
    }
  }
  std::erase_if(out, [](const auto& term) { return term.second == 0; });
  return out;
}

ContentTerms multiply(const ContentTerms& f, const ContentTerms& g) {
  ContentTerms out{f.content * g.content, {}};
  for (const auto& [ef, cf] : f.terms) {
    for (const auto& [eg, cg] : g.terms) {
      Integer& c = out.terms[add(ef, eg)];
      mpz_addmul(c.get_mpz_t(), cf.get_mpz_t(), cg.get_mpz_t());
    }
  }
  std::erase_if(out.terms, [](const auto& term) { return term.second == 0; });
  return out;
}

double milliseconds(const std::function<void()>& work, int repeat) {
  double best = 1e300;
  for (int r = 0; r < repeat; ++r) {
    const auto start = std::chrono::steady_clock::now();
    work();
    best = std::min(best, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  }
  return best;
}

}  // namespace

int main() {
  // f = (x + 2y + 3z + 1)/7 + x²y/7 ... : a dense-ish polynomial of degree d in three
  // variables with coefficients k/7 (one shared denominator, like a parametrization
  // with a common denominator); g the same with k/11. We time f^a · g^a's last product.
  const auto ring = implicitizer::Ring::make({"x", "y", "z"});
  std::printf("| terms of f | terms of g | rational per term (ms) | content x integer (ms) | library (ms) | ratio 1/2 |\n");
  std::printf("|---|---|---|---|---|---|\n");
  for (int degree : {4, 6, 8, 10}) {
    RationalTerms rf, rg;
    ContentTerms cf{mpq_class(1, 7), {}}, cg{mpq_class(1, 11), {}};
    Polynomial pf(ring), pg(ring);
    int k = 1;
    for (int i = 0; i <= degree; ++i) {
      for (int j = 0; i + j <= degree; ++j) {
        for (int l = 0; i + j + l <= degree; ++l, ++k) {
          const Exponents e{i, j, l};
          const std::vector<std::int32_t> e32{i, j, l};
          const int a = (k * 37) % 19 - 9, b = (k * 53) % 23 - 11;
          if (a != 0) {
            rf[e] = mpq_class(a, 7);
            cf.terms[e] = a;
            pf += Polynomial::term(ring, Rational(a) / Rational(7), e32);
          }
          if (b != 0) {
            rg[e] = mpq_class(b, 11);
            cg.terms[e] = b;
            pg += Polynomial::term(ring, Rational(b) / Rational(11), e32);
          }
        }
      }
    }
    // Square both first so that coefficients are not tiny.
    rf = multiply(rf, rf);
    rg = multiply(rg, rg);
    cf = multiply(cf, cf);
    cg = multiply(cg, cg);
    pf *= pf;
    pg *= pg;
    const int repeat = 3;
    std::size_t sizes[3] = {0, 0, 0};
    const double t1 = milliseconds([&] { sizes[0] = multiply(rf, rg).size(); }, repeat);
    const double t2 = milliseconds([&] { sizes[1] = multiply(cf, cg).terms.size(); }, repeat);
    const double t3 = milliseconds([&] { sizes[2] = (pf * pg).num_terms(); }, repeat);
    if (sizes[0] != sizes[1] || sizes[1] != sizes[2]) {
      std::fprintf(stderr, "the three products disagree (%zu, %zu, %zu terms)\n", sizes[0], sizes[1], sizes[2]);
      return 1;
    }
    std::printf("| %zu | %zu | %.2f | %.2f | %.2f | %.2f |\n", rf.size(), rg.size(), t1, t2, t3, t1 / t2);
  }
  return 0;
}
