// Tests of lib/src/implicitization/interpolation.cpp: the interpolation route agrees
// with the Gröbner and resultant routes, finds degrees below the bound (base points,
// maps of degree > 1), survives unlucky small primes, and never returns a candidate
// that fails the verification.

#include "implicitizer/implicitization/interpolation.hpp"

#include <gtest/gtest.h>

#include "implicitization/surfaces.hpp"
#include "implicitizer/core/errors.hpp"
#include "implicitizer/implicitization/implicitize.hpp"
#include "implicitizer/polynomial/parser.hpp"
#include "implicitizer/polynomial/printer.hpp"

namespace implicitizer {
namespace {

std::vector<testing::Surface> public_surfaces() {
  return testing::read_surfaces(std::string(IMPLICITIZER_SHARED_DIR) + "/bench/surfaces_public.json");
}

testing::Surface hard_surface(const std::string& name) {
  for (const auto& s : testing::read_surfaces(std::string(IMPLICITIZER_SHARED_DIR) + "/bench/surfaces_hard.json")) {
    if (s.name == name) return s;
  }
  ADD_FAILURE() << name << " is not in surfaces_hard.json";
  return {};
}

Parametrization parametrization_of(const testing::Surface& s) { return parse_parametrization(s.x, s.y, s.z); }

Polynomial by_route(const Parametrization& p, ImplicitizationMethod method) {
  ImplicitizeParams options;
  options.method = method;
  return implicitize(p, options).implicit;
}

// The route's invariants on one answer: primitive with positive leading coefficient,
// the degree found within the bound, the matrix of that degree.
void expect_well_formed(const InterpolationResult& r, std::size_t coordinates) {
  EXPECT_TRUE(r.implicit.is_canonical());
  EXPECT_GT(r.implicit.leading_coefficient(), Rational(0));
  EXPECT_EQ(r.implicit.ring()->num_variables(), coordinates);
  EXPECT_EQ(r.stats.degree, r.implicit.total_degree());
  EXPECT_LE(r.stats.degree, r.stats.degree_bound);
  EXPECT_GE(r.stats.primes, 1u);
  EXPECT_GT(r.stats.columns, 0u);
  EXPECT_GT(r.stats.rows, r.stats.columns);
}

TEST(ImplicitDegreeBound, TensorTriangularAndCurveBounds) {
  // The bounds of the resultant route: 2mn for bidegree (m, n), N^2 for total degree
  // N, the smaller of the two; N for a plane curve.
  const auto bound = [](const char* x, const char* y, const char* z) {
    return implicit_degree_bound(parse_parametrization(x, y, z));
  };
  EXPECT_EQ(bound("s+t", "s", "t"), 1);
  EXPECT_EQ(bound("s^3*t^3", "s", "t"), 18);     // bidegree (3,3): 18; total degree 6: 36
  EXPECT_EQ(bound("s^2*t", "s*t^2", "s+t"), 8);  // bidegree (2,2): 8; total degree 3: 9
  EXPECT_EQ(bound("s^3+t", "s*t", "t^2"), 9);    // bidegree (3,2): 12; total degree 3: 9
  // The unit sphere: ω = 1+s²+t², bidegree (2,2), total degree 2: 4, though the
  // sphere has degree 2 (two base points at infinity, where s² + t² = 0).
  EXPECT_EQ(bound("2*s/(s^2+t^2+1)", "2*t/(s^2+t^2+1)", "(s^2+t^2-1)/(s^2+t^2+1)"), 4);
  EXPECT_EQ(implicit_degree_bound(parse_parametrization(std::vector<std::string>{"(1-t^2)/(1+t^2)", "2*t/(1+t^2)"})),
            2);
  EXPECT_EQ(bound("t", "t^2", "t^3"), 0);      // one parameter: never a surface
  EXPECT_EQ(bound("s+u", "t", "(s+u)^2"), 4);  // three parameters: N^2
}

TEST(ImplicitDegreeBound, HoldsOnEveryBenchmarkSurface) {
  auto surfaces = public_surfaces();
  for (const auto& s : testing::read_surfaces(std::string(IMPLICITIZER_SHARED_DIR) + "/bench/surfaces_hard.json")) {
    surfaces.push_back(s);
  }
  for (const auto& s : surfaces) {
    SCOPED_TRACE(s.name);
    EXPECT_GE(implicit_degree_bound(parametrization_of(s)), s.degree);
  }
  // Without base points the hard patches reach it: 2mn and n².
  EXPECT_EQ(implicit_degree_bound(parametrization_of(hard_surface("tp_33"))), 18);
  EXPECT_EQ(implicit_degree_bound(parametrization_of(hard_surface("tri_quartic"))), 16);
}

TEST(Interpolation, PublicSurfacesAgreeWithGroebnerAndSingular) {
  const auto surfaces = public_surfaces();
  ASSERT_GE(surfaces.size(), 12u);
  for (const auto& s : surfaces) {
    SCOPED_TRACE(s.name);
    const Parametrization p = parametrization_of(s);
    const InterpolationResult r = implicitize_by_interpolation(p);
    expect_well_formed(r, 3);
    EXPECT_EQ(r.stats.degree, s.degree);
    EXPECT_EQ(r.implicit, by_route(p, ImplicitizationMethod::groebner));
    const Polynomial singular = parse_polynomial(
        testing::read_text(std::string(IMPLICITIZER_SHARED_DIR) + "/bench/expected/" + s.name + ".txt"), space_ring());
    EXPECT_EQ(r.implicit, singular.primitive_part());
  }
}

TEST(Interpolation, HardSurfacesAgreeWithTheResultantAndGroebner) {
  // The resultant route answers every hard surface; Buchberger is compared where it
  // takes about a second or less (tp_22_rational and tri_cubic take it over 60 s).
  for (const char* name : {"tri_quadratic", "tp_11_rational", "tp_21", "tp_22", "tp_22_rational", "tri_cubic",
                           "tri_cubic_rational", "tp_32"}) {
    SCOPED_TRACE(name);
    const testing::Surface s = hard_surface(name);
    const Parametrization p = parametrization_of(s);
    const InterpolationResult r = implicitize_by_interpolation(p);
    expect_well_formed(r, 3);
    EXPECT_EQ(r.stats.degree, s.degree);
    EXPECT_EQ(r.stats.degree_bound, s.degree);  // no base points: the bound is reached
    EXPECT_EQ(r.implicit, by_route(p, ImplicitizationMethod::resultant));
    const std::string quick = name;
    if (quick == "tri_quadratic" || quick == "tp_11_rational" || quick == "tp_21" || quick == "tp_22") {
      EXPECT_EQ(r.implicit, by_route(p, ImplicitizationMethod::groebner));
    }
  }
}

TEST(Interpolation, TheLargestMatricesAgreeWithTheResultant) {
  // tri_quartic (977×969) and tp_33 (1338×1330, the largest of the benchmark): about
  // 1.6 s and 3.8 s on two cores.
  for (const auto& [name, columns] : {std::pair{"tri_quartic", 969u}, std::pair{"tp_33", 1330u}}) {
    SCOPED_TRACE(name);
    const testing::Surface s = hard_surface(name);
    const Parametrization p = parametrization_of(s);
    const InterpolationResult r = implicitize_by_interpolation(p);
    expect_well_formed(r, 3);
    EXPECT_EQ(r.stats.degree, s.degree);
    EXPECT_EQ(r.stats.columns, columns);
    EXPECT_EQ(r.implicit, by_route(p, ImplicitizationMethod::resultant));
  }
}

TEST(Interpolation, BasePointsLowerTheDegreeBelowTheBound) {
  // The resultant route refuses all three (its auxiliary resultant vanishes); the
  // degree is found by the search below the bound.
  const char* cases[][4] = {
      {"2*s/(1+s^2+t^2)", "2*t/(1+s^2+t^2)", "(s^2+t^2-1)/(1+s^2+t^2)", "x^2+y^2+z^2-1"},  // bound 4
      {"(2+(1-t^2)/(1+t^2))*(1-s^2)/(1+s^2)", "(2+(1-t^2)/(1+t^2))*2*s/(1+s^2)", "2*t/(1+t^2)",
       "x^4+2*x^2*y^2+y^4+2*x^2*z^2+2*y^2*z^2+z^4-10*x^2-10*y^2+6*z^2+9"},  // the torus, bound 8
      {"2*t*(1-s^2-t^2)/(1+s^2+t^2)^2", "2*s*(1-s^2-t^2)/(1+s^2+t^2)^2", "4*s*t/(1+s^2+t^2)^2", ""},  // Steiner
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c[0]);
    const Parametrization p = parse_parametrization(c[0], c[1], c[2]);
    const InterpolationResult r = implicitize_by_interpolation(p);
    expect_well_formed(r, 3);
    EXPECT_LT(r.stats.degree, r.stats.degree_bound);
    EXPECT_GE(r.stats.degree_probes, 1u);
    if (*c[3]) {
      EXPECT_EQ(to_string(r.implicit), c[3]);
    }
    EXPECT_EQ(r.implicit, by_route(p, ImplicitizationMethod::groebner));
  }
}

TEST(Interpolation, PlaneCurves) {
  const char* cases[][3] = {
      {"t^2-1", "t^3-t", "x^3+x^2-y^2"},                  // nodal cubic
      {"(1-t^2)/(1+t^2)", "2*t/(1+t^2)", "x^2+y^2-1"},    // circle
      {"3*t/(1+t^3)", "3*t^2/(1+t^3)", "x^3+y^3-3*x*y"},  // folium of Descartes
      {"t^2", "t^4", "x^2-y"},                            // covered twice: degree 2, bound 4
      {"t^3/(t^2+1)", "t^5-2*t+7", ""},                   // a rational quintic
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c[0]);
    const Parametrization p = parse_parametrization(std::vector<std::string>{c[0], c[1]});
    const InterpolationResult r = implicitize_by_interpolation(p);
    expect_well_formed(r, 2);
    EXPECT_EQ(r.implicit.ring()->variables(), (std::vector<std::string>{"x", "y"}));
    if (*c[2]) {
      EXPECT_EQ(to_string(r.implicit), c[2]);
    }
    EXPECT_EQ(r.implicit, by_route(p, ImplicitizationMethod::resultant));
  }
  const InterpolationResult twice =
      implicitize_by_interpolation(parse_parametrization(std::vector<std::string>{"t^2", "t^4"}));
  EXPECT_EQ(twice.stats.degree_bound, 4);
  EXPECT_EQ(twice.stats.degree, 2);
}

TEST(Interpolation, MoreParametersThanTheImageNeeds) {
  // Three parameters onto a surface, two onto a plane curve: the resultant route does
  // not apply; Buchberger agrees.
  const Parametrization surface = parse_parametrization("s+u", "t*u", "(s+u)^2");
  const InterpolationResult r = implicitize_by_interpolation(surface);
  EXPECT_EQ(to_string(r.implicit), "x^2-z");
  EXPECT_EQ(r.implicit, by_route(surface, ImplicitizationMethod::groebner));
  const Parametrization curve = parse_parametrization(std::vector<std::string>{"s+t", "(s+t)^2+1"});
  EXPECT_EQ(to_string(implicitize_by_interpolation(curve).implicit), "x^2-y+1");
}

TEST(Interpolation, ImagesThatAreNotHypersurfaces) {
  // Proven from the Jacobian's rank (and for the dense images also by the empty
  // kernel at the bound); this route lists no generators, and the message says why.
  const auto message_of = [](const Parametrization& p) -> std::string {
    try {
      implicitize_by_interpolation(p);
      ADD_FAILURE() << "an equation was returned";
    } catch (const NoSingleEquation& e) {
      EXPECT_EQ(e.code(), "no_single_equation");
      EXPECT_TRUE(e.generators().empty());
      return e.what();
    }
    return "";
  };
  EXPECT_NE(message_of(parse_parametrization("t", "t^2", "t^3")).find("curve or a point"), std::string::npos);
  EXPECT_NE(message_of(parse_parametrization("s+t", "(s+t)^2", "(s+t)^3")).find("not a surface"), std::string::npos);
  EXPECT_NE(message_of(parse_parametrization("1", "2", "3")).find("curve or a point"), std::string::npos);
  EXPECT_NE(message_of(parse_parametrization("s", "t", "u")).find("dense in space"), std::string::npos);
  EXPECT_NE(message_of(parse_parametrization(std::vector<std::string>{"s", "t"})).find("dense in the plane"),
            std::string::npos);
  EXPECT_NE(message_of(parse_parametrization(std::vector<std::string>{"2", "3+0*t"})).find("not a curve"),
            std::string::npos);
}

TEST(Interpolation, UpToADegreeAnswersBelowItAndProvesTheDegreeHigherAbove) {
  // What auto's first rule relies on: the answer of the whole route when the degree
  // is at most the cap, nullopt when it is higher, whatever the bound.
  const Parametrization sphere = parse_parametrization("2*s/(1+s^2+t^2)", "2*t/(1+s^2+t^2)", "(s^2+t^2-1)/(1+s^2+t^2)");
  const std::optional<InterpolationResult> small = implicitize_by_interpolation_up_to(sphere, 4);
  ASSERT_TRUE(small);
  EXPECT_EQ(to_string(small->implicit), "x^2+y^2+z^2-1");
  EXPECT_EQ(small->stats.degree_bound, 4);
  EXPECT_FALSE(implicitize_by_interpolation_up_to(sphere, 1));  // degree 2 > 1
  for (const char* name : {"tp_22", "tri_cubic", "tp_33"}) {
    SCOPED_TRACE(name);
    const testing::Surface s = hard_surface(name);
    const Parametrization p = parametrization_of(s);
    EXPECT_FALSE(implicitize_by_interpolation_up_to(p, 4));
    // At the degree itself the capped search is the route.
    if (s.degree <= 9) {
      const std::optional<InterpolationResult> at = implicitize_by_interpolation_up_to(p, s.degree);
      ASSERT_TRUE(at);
      EXPECT_EQ(at->implicit, implicitize_by_interpolation(p).implicit);
    }
  }
  // With the cap at or above the bound, the whole route: a dense image still throws.
  EXPECT_THROW(implicitize_by_interpolation_up_to(parse_parametrization("s", "t", "u"), 4), NoSingleEquation);
  EXPECT_THROW(implicitize_by_interpolation_up_to(sphere, 0), std::invalid_argument);
}

TEST(Interpolation, ATrialDenominatorSavesThePrimeOfSmallSurfaces) {
  // Their equations have a small leading coefficient and larger others (tri_quadratic:
  // 2209 and 2^28), beyond the balanced bound of one 62-bit prime; the lcm of the
  // denominators found so far, tried on the rest, completes the candidate from one
  // prime, and the verification proves it.
  for (const char* name : {"tri_quadratic", "tp_11_rational", "tp_21"}) {
    SCOPED_TRACE(name);
    const InterpolationResult r = implicitize_by_interpolation(parametrization_of(hard_surface(name)));
    EXPECT_EQ(r.stats.primes, 1u);
    EXPECT_EQ(r.stats.rejected_candidates, 0u);
    EXPECT_EQ(r.stats.degree_probes, 1u);  // the bound's 35 columns at once (kDirectColumns)
  }
}

TEST(Interpolation, SmallPrimesNeedManyRoundsAndGiveTheSameAnswer) {
  // Primes just above 1000: each carries 10 bits, so the reconstruction needs many
  // of them, and values that a 62-bit prime would take in one step are confirmed
  // over several.
  std::vector<testing::Surface> surfaces;
  for (const auto& s : public_surfaces()) {
    if (s.name == "unit_sphere" || s.name == "biquadratic_patch" || s.name == "torus_R2_r1") surfaces.push_back(s);
  }
  surfaces.push_back(hard_surface("tp_21"));
  surfaces.push_back(hard_surface("tp_11_rational"));
  ASSERT_EQ(surfaces.size(), 5u);
  for (const auto& s : surfaces) {
    SCOPED_TRACE(s.name);
    const Parametrization p = parametrization_of(s);
    InterpolationParams small;
    small.primes = PrimeSequence::from(1000);
    const InterpolationResult r = implicitize_by_interpolation(p, small);
    expect_well_formed(r, 3);
    const InterpolationResult large = implicitize_by_interpolation(p);
    EXPECT_EQ(r.implicit, large.implicit);
    EXPECT_GT(r.stats.primes, large.stats.primes);
    EXPECT_GE(r.stats.primes, 3u);  // even ±1 needs 21 bits: the reconstruction's margin
    EXPECT_EQ(r.implicit, by_route(p, ImplicitizationMethod::groebner));
  }
}

TEST(Interpolation, TinyPrimesLoseCountedPointsAndPrimes) {
  // From p = 2 on, a rational curve of degree 7 (44 rows): modulo the primes below
  // that there are too few parameter values (those primes are unlucky), and where
  // ω = t² + 1 vanishes modulo p (p = 5, 13, 17, …) the points are rejected. The
  // answer is still the resultant's.
  const Parametrization curve = parse_parametrization(std::vector<std::string>{"t^3/(t^2+1)", "t^5-2*t+7"});
  InterpolationParams tiny;
  tiny.primes = PrimeSequence::from(2);
  const InterpolationResult r = implicitize_by_interpolation(curve, tiny);
  EXPECT_EQ(r.implicit, by_route(curve, ImplicitizationMethod::resultant));
  EXPECT_GE(r.stats.unlucky_primes, 1u);
  EXPECT_GE(r.stats.rejected_points, 1u);
  // The torus's ω = (1+s²)(1+t²) vanishes on four lines (s or t = ±√−1) modulo
  // p ≡ 1 mod 4.
  const Parametrization torus =
      parse_parametrization("(2+(1-t^2)/(1+t^2))*(1-s^2)/(1+s^2)", "(2+(1-t^2)/(1+t^2))*2*s/(1+s^2)", "2*t/(1+t^2)");
  tiny.primes = PrimeSequence::from(50);
  const InterpolationResult t = implicitize_by_interpolation(torus, tiny);
  EXPECT_EQ(to_string(t.implicit), "x^4+2*x^2*y^2+y^4+2*x^2*z^2+2*y^2*z^2+z^4-10*x^2-10*y^2+6*z^2+9");
  EXPECT_GE(t.stats.rejected_points, 1u);
}

// The implicit equation of x = s, y = t, z = zed by interpolation over the primes
// after 1000.
InterpolationResult graph_over_small_primes(const std::string& zed) {
  InterpolationParams small;
  small.primes = PrimeSequence::from(1000);
  return implicitize_by_interpolation(parse_parametrization("s", "t", zed), small);
}

TEST(Interpolation, PrimesDividingTheLeadingCoefficientAreDropped) {
  // z = c·s³ + s²t + t has the equation c·x³ + x²y + y − z; c is the product of the
  // eight primes after 1000, which come first: modulo each of them the kernel vector
  // leads with x²y instead of x³. Those images agree with each other and are
  // reconstructed into the candidate x²y + y − z, which the verification rejects;
  // the first prime that does not divide c shows the larger leading monomial, and
  // every image before it is dropped.
  const std::string c = "1234384785740842318568899";
  const InterpolationResult first = graph_over_small_primes(c + "*s^3+s^2*t+t");
  EXPECT_EQ(to_string(first.implicit), c + "*x^3+x^2*y+y-z");
  EXPECT_GE(first.stats.unlucky_primes, 4u);
  // The plane z = c·s + t with c = 1013·1019·1021·1031: the first prime (1009) is
  // good, the next four lead with y instead of x and are dropped one by one, and
  // nothing else is (the degree bound is 1: no search).
  const InterpolationResult later = graph_over_small_primes("1086595836797*s+t");
  EXPECT_EQ(to_string(later.implicit), "1086595836797*x+y-z");
  EXPECT_EQ(later.stats.unlucky_primes, 4u);
}

TEST(Interpolation, KernelsOfTheWrongDimensionAreDropped) {
  // z = 1009·s² + t: modulo 1009 (the first prime after 1000) the image lies in the
  // plane y = z, so the search first reads degree 1; the next prime has no kernel
  // there, which proves the degree is higher.
  const InterpolationResult early = graph_over_small_primes("1009*s^2+t");
  EXPECT_EQ(to_string(early.implicit), "1009*x^2+y-z");
  EXPECT_GE(early.stats.unlucky_primes, 1u);
  // z = c·s² + t with c = 1019·1021·1031: once 1009 and 1013 have found degree 2,
  // modulo each of these three the kernel at degree 2 has dimension 4 (the plane
  // y = z times 1, x, y, z) and is dropped.
  const InterpolationResult late = graph_over_small_primes("1072651369*s^2+t");
  EXPECT_EQ(to_string(late.implicit), "1072651369*x^2+y-z");
  EXPECT_GE(late.stats.unlucky_primes, 3u);
}

TEST(Interpolation, ACorruptedCandidateIsRejectedAndTheRouteGoesOn) {
  // The first candidate gets one coefficient changed before its verification: the
  // route must reject it, take more primes, and return the true equation.
  for (const char* name : {"tp_21", "tp_11_rational"}) {
    SCOPED_TRACE(name);
    const Parametrization p = parametrization_of(hard_surface(name));
    const Polynomial truth = by_route(p, ImplicitizationMethod::resultant);
    int calls = 0;
    InterpolationParams options;
    options.tamper_candidate = [&](Polynomial& candidate) {
      if (calls++ == 0) candidate = candidate + Polynomial::constant(candidate.ring(), Rational(1));
    };
    const InterpolationResult r = implicitize_by_interpolation(p, options);
    EXPECT_EQ(calls, 2);
    EXPECT_EQ(r.stats.rejected_candidates, 1u);
    EXPECT_GE(r.stats.primes, 2u);  // the rejected candidate's, and one more
    EXPECT_EQ(r.implicit, truth);
  }
  // A tamperer that corrupts every candidate leaves the route nothing to return.
  InterpolationParams always;
  always.max_primes = 30;
  always.tamper_candidate = [](Polynomial& candidate) {
    candidate = candidate + Polynomial::variable(candidate.ring(), 0);
  };
  EXPECT_THROW(implicitize_by_interpolation(parse_parametrization("s^2+t", "s*t", "t^2-s"), always), LimitExceeded);
}

TEST(CheckImplicitEquation, RejectsCorruptedCandidatesAndMultiples) {
  for (const char* name : {"tp_21", "tri_quadratic", "tp_11_rational"}) {
    SCOPED_TRACE(name);
    const Parametrization p = parametrization_of(hard_surface(name));
    const Polynomial f = by_route(p, ImplicitizationMethod::resultant);
    const ImplicitEquationCheck good = check_implicit_equation(f, p);
    EXPECT_TRUE(good.vanishes);
    EXPECT_TRUE(good.minimal);
    // One coefficient changed: neither vanishes nor spans the kernel.
    const Polynomial changed = f + Polynomial::constant(f.ring(), Rational(1)) * Polynomial::variable(f.ring(), 2);
    const ImplicitEquationCheck bad = check_implicit_equation(changed, p);
    EXPECT_FALSE(bad.vanishes);
    EXPECT_FALSE(bad.minimal);
    // A multiple vanishes, but its degree's kernel has more than one dimension.
    const ImplicitEquationCheck multiple = check_implicit_equation(f * Polynomial::variable(f.ring(), 0), p);
    EXPECT_TRUE(multiple.vanishes);
    EXPECT_FALSE(multiple.minimal);
  }
}

TEST(Interpolation, OneOrTwoThreadsGiveTheSameAnswer) {
  const Parametrization p = parametrization_of(hard_surface("tp_22"));
  InterpolationParams one, two;
  one.threads = 1;
  two.threads = 2;
  const InterpolationResult a = implicitize_by_interpolation(p, one);
  const InterpolationResult b = implicitize_by_interpolation(p, two);
  EXPECT_EQ(a.implicit, b.implicit);
  EXPECT_EQ(a.stats.threads, 1u);
  EXPECT_EQ(b.stats.threads, 2u);
}

TEST(Interpolation, LimitsStopItAndSayWhich) {
  const Parametrization tp33 = parametrization_of(hard_surface("tp_33"));
  InterpolationParams quick;
  quick.budget.set_timeout(0.05);
  try {
    implicitize_by_interpolation(tp33, quick);
    FAIL() << "tp_33 finished in 50 ms";
  } catch (const LimitExceeded& e) {
    EXPECT_EQ(e.limit(), Limit::time);
  }
  InterpolationParams cancelled;
  cancelled.budget.cancel();
  try {
    implicitize_by_interpolation(tp33, cancelled);
    FAIL() << "a cancelled budget ran";
  } catch (const LimitExceeded& e) {
    EXPECT_EQ(e.limit(), Limit::cancelled);
  }
  // Degree 18 needs 1330 columns; the search goes up to the limit and stops there.
  InterpolationParams narrow;
  narrow.max_columns = 500;
  try {
    implicitize_by_interpolation(tp33, narrow);
    FAIL() << "no size limit";
  } catch (const LimitExceeded& e) {
    EXPECT_EQ(e.limit(), Limit::size);
    EXPECT_NE(std::string(e.what()).find("columns"), std::string::npos) << e.what();
  }
  // A bound over the limit does not matter when the degree is found below it: the
  // sphere's bound 4 needs 35 columns, its degree 2 only 10.
  InterpolationParams tight;
  tight.max_columns = 10;
  EXPECT_EQ(to_string(implicitize_by_interpolation(
                          parse_parametrization("2*s/(1+s^2+t^2)", "2*t/(1+s^2+t^2)", "(s^2+t^2-1)/(1+s^2+t^2)"), tight)
                          .implicit),
            "x^2+y^2+z^2-1");
}

TEST(Interpolation, ThroughImplicitize) {
  ImplicitizeParams options;
  options.method = parse_implicitization_method("interpolation");
  const ImplicitizeResult r =
      implicitize(parse_parametrization("2*s/(1+s^2+t^2)", "2*t/(1+s^2+t^2)", "(s^2+t^2-1)/(1+s^2+t^2)"), options);
  EXPECT_EQ(r.method, "interpolation");
  EXPECT_TRUE(r.verified);
  EXPECT_EQ(r.degree, 2);
  EXPECT_EQ(to_string(r.implicit), "x^2+y^2+z^2-1");
  ASSERT_TRUE(r.interpolation_stats);
  EXPECT_EQ(r.interpolation_stats->degree_bound, 4);
  EXPECT_FALSE(r.resultant_stats);
}

}  // namespace
}  // namespace implicitizer
