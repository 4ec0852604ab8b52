/// \file
/// libFuzzer target for the input language (lib/include/implicitizer/polynomial/parser.hpp).
///
/// On any bytes, parse_expression(), evaluate_polynomial() and
/// evaluate_rational_function() may only return or throw InputError (or LimitExceeded
/// from the fuzzer's own small budget); anything else — a crash, a sanitizer report,
/// another exception, a hang — is a bug. When an evaluation succeeds, its printed form
/// must parse back to the same value (printer.hpp promises it), and the polynomial and
/// rational-function evaluators must agree. An expression with function calls also goes
/// through substitute_trigonometric(), whose rational form must print and parse back.

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <string_view>

#include "implicitizer/core/budget.hpp"
#include "implicitizer/core/errors.hpp"
#include "implicitizer/implicitization/trigonometric_substitution.hpp"
#include "implicitizer/polynomial/expression.hpp"
#include "implicitizer/polynomial/parser.hpp"
#include "implicitizer/polynomial/printer.hpp"
#include "implicitizer/polynomial/ring.hpp"

namespace {

using namespace implicitizer;

/// More variables than this only makes monomials wide, not the parser more tested.
constexpr std::size_t kFuzzedVariables = 12;

/// Reports a broken invariant the way libFuzzer expects: print, then abort.
[[noreturn]] void fail(const char* what, std::string_view input, const std::string& detail) {
  std::fprintf(stderr, "parser_fuzzer: %s\n  input: %.*s\n  %s\n", what, static_cast<int>(input.size()), input.data(),
               detail.c_str());
  std::abort();
}

/// A budget that keeps one input well under libFuzzer's -timeout: a deadline (the
/// evaluators' powers check it) and a term limit (sums and products check it). The
/// limit also bounds what the budget does not cover: printing the result, reading it
/// back and comparing the two evaluators. At 20000 terms `((a+b1+3x-ab))^30` (5456
/// terms with 40-digit coefficients) took 16 s under ASan in those unbudgeted checks;
/// 3000 terms still exercise every code path of the parser and the evaluators.
Budget make_budget() {
  Budget budget = Budget::with_timeout(0.5);
  budget.set_max_terms(3000);
  return budget;
}

/// Limits wide enough for anything the printer writes: a product of powers prints
/// exponents beyond the input's 1000 and texts beyond 1 MiB.
ParseParams printed_text_limits() {
  ParseParams limits;
  limits.max_exponent = static_cast<unsigned>(kMaxTotalDegree);
  limits.max_length = std::size_t{1} << 30;
  return limits;
}

std::optional<Polynomial> check_polynomial(const Expression& e, const RingPtr& ring, std::string_view input) {
  Polynomial p(ring);
  try {
    p = evaluate_polynomial(e, ring, make_budget());
  } catch (const InputError&) {
    return std::nullopt;
  } catch (const LimitExceeded&) {
    return std::nullopt;
  }
  const std::string printed = to_string(p);
  Polynomial q(ring);
  try {
    q = parse_polynomial(printed, ring, Budget(), printed_text_limits());
  } catch (const InputError& error) {
    fail("printed polynomial does not parse back", input, printed + " -> " + error.code() + ": " + error.what());
  }
  if (!(q == p)) fail("print/parse round trip changed the polynomial", input, printed + " -> " + to_string(q));
  if (to_string(q) != printed) fail("printing is not stable", input, printed + " -> " + to_string(q));
  return p;
}

void check_printed_rational_function(const RationalFunction& f, const RingPtr& ring, std::string_view input);

void check_rational_function(const Expression& e, const RingPtr& ring, std::string_view input,
                             const std::optional<Polynomial>& as_polynomial) {
  std::optional<RationalFunction> f;
  try {
    f = evaluate_rational_function(e, ring, make_budget());
  } catch (const InputError&) {
    if (as_polynomial) fail("a polynomial is not a rational function", input, to_string(*as_polynomial));
    return;
  } catch (const LimitExceeded&) {
    return;
  }
  const Polynomial one = Polynomial::constant(ring, Rational(1));
  if (as_polynomial && !(f->numerator() == *as_polynomial && f->denominator() == one)) {
    fail("polynomial and rational-function evaluation disagree", input,
         to_string(*as_polynomial) + " vs (" + to_string(f->numerator()) + ")/(" + to_string(f->denominator()) + ")");
  }
  check_printed_rational_function(*f, ring, input);
}

// Lowest terms with a primitive, positively led denominator is a normal form: printing
// it (printer.hpp) and reading the text back gives it again.
void check_printed_rational_function(const RationalFunction& f, const RingPtr& ring, std::string_view input) {
  const std::string printed = to_string(f);
  std::optional<RationalFunction> g;
  try {
    // Reading a quotient back sums its terms as rational functions, a gcd each: for
    // ((a+b)^9-c/(a-c))^8 (under 3000 terms) that took 9 s under ASan, near libFuzzer's
    // -timeout. A deadline keeps the check bounded; a read that runs out is unchecked.
    g = evaluate_rational_function(*parse_expression(printed, printed_text_limits()), ring, Budget::with_timeout(2));
  } catch (const InputError& error) {
    fail("printed rational function does not parse back", input, printed + " -> " + error.code() + ": " + error.what());
  } catch (const LimitExceeded&) {
    return;
  }
  if (!(g->numerator() == f.numerator() && g->denominator() == f.denominator())) {
    fail("rational function round trip is not the identity", input,
         printed + " -> (" + to_string(g->numerator()) + ")/(" + to_string(g->denominator()) + ")");
  }
}

// Calls (cos(u), ...): the substitution may only refuse with InputError or stop at the
// budget; its rational form is a rational function like any other.
void check_substitution(const Expression& e, const RingPtr& ring, std::string_view input) {
  std::optional<RationalizedCoordinates> rational;
  try {
    rational = substitute_trigonometric({&e}, {"x"}, ring, make_budget());
  } catch (const InputError&) {
    return;
  } catch (const LimitExceeded&) {
    return;
  }
  if (rational->coordinates.size() != 1) fail("substitution lost the coordinate", input, "");
  check_printed_rational_function(rational->coordinates[0], rational->parameter_ring, input);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  std::unique_ptr<Expression> e;
  try {
    e = parse_expression(input);
  } catch (const InputError&) {
    return 0;
  }
  std::vector<std::string> names = collect_identifiers(*e);
  if (names.size() > kFuzzedVariables) return 0;
  const RingPtr ring = Ring::make(std::move(names));
  const std::optional<Polynomial> p = check_polynomial(*e, ring, input);
  check_rational_function(*e, ring, input, p);
  if (contains_call(*e)) check_substitution(*e, ring, input);
  return 0;
}
