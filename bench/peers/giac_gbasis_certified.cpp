// Giac's reduced Gröbner basis (grevlex) with its certification on: proba_epsilon:=0
// makes Giac prove the reconstructed basis instead of checking it on random primes,
// which is what its answer costs when, like ours, it must be exact. Otherwise the
// same as ../shared/bench/peers/giac_gbasis.cpp (its README).
// Usage: giac_gbasis_certified 'p1,p2,...' 'x1,x2,...' [threads]   prints: nelements ms
// Build: g++ -O2 -o /tmp/giac_gbasis_certified bench/peers/giac_gbasis_certified.cpp -lgiac -lgmp
#include <giac/config.h>
#include <giac/giac.h>

#include <chrono>
#include <iostream>
#include <string>

int main(int argc, char** argv) {
  if (argc < 3) {
    std::cerr << "usage: giac_gbasis_certified 'polys' 'vars' [threads]\n";
    return 2;
  }
  giac::context context;
  giac::eval(giac::gen(std::string("proba_epsilon:=0"), &context), 1, &context);
  if (argc > 3) giac::eval(giac::gen(std::string("threads:=") + argv[3], &context), 1, &context);
  const giac::gen call(std::string("gbasis([") + argv[1] + "],[" + argv[2] + "],revlex)", &context);
  const auto start = std::chrono::steady_clock::now();
  const giac::gen basis = giac::eval(call, 1, &context);
  const auto end = std::chrono::steady_clock::now();
  if (basis.type != giac::_VECT) {
    std::cout << "ERR\n";
    return 1;
  }
  std::cout << basis._VECTptr->size() << " "
            << std::chrono::duration_cast<std::chrono::milliseconds>(end - start).count() << "\n";
  return 0;
}
