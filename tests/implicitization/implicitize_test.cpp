#include "implicitizer/implicitization/implicitize.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <random>

#include "implicitization/surfaces.hpp"
#include "implicitizer/core/errors.hpp"
#include "implicitizer/polynomial/parser.hpp"
#include "implicitizer/polynomial/printer.hpp"

namespace implicitizer {
namespace {

std::string implicit_of(const std::string& x, const std::string& y, const std::string& z) {
  return to_string(implicitize(parse_parametrization(x, y, z)).implicit);
}

// Equal up to a non-zero rational factor: both primitive with positive leading
// coefficient, so they must be equal.
void expect_same_surface(const std::string& ours, const std::string& theirs) {
  const Polynomial a = parse_polynomial(ours, space_ring()).primitive_part();
  const Polynomial b = parse_polynomial(theirs, space_ring()).primitive_part();
  EXPECT_EQ(to_string(a), to_string(b));
}

TEST(Implicitize, PublicSurfacesMatchSingular) {
  const auto surfaces = testing::read_surfaces(std::string(IMPLICITIZER_SHARED_DIR) + "/bench/surfaces_public.json");
  ASSERT_GE(surfaces.size(), 12u);
  for (const auto& s : surfaces) {
    SCOPED_TRACE(s.name);
    const ImplicitizeResult r = implicitize(parse_parametrization(s.x, s.y, s.z));
    EXPECT_TRUE(r.verified);
    EXPECT_EQ(r.degree, s.degree);
    expect_same_surface(to_string(r.implicit), testing::read_text(std::string(IMPLICITIZER_SHARED_DIR) +
                                                                  "/bench/expected/" + s.name + ".txt"));
  }
}

TEST(Implicitize, SeedExample13IsThePlane) {
  // Example 1.3 of the seed thesis: -x+y+z = 0, printed primitive with positive lc.
  EXPECT_EQ(implicit_of("s+t", "s", "t"), "x-y-z");
}

TEST(Implicitize, SeedTable42WithItsSlipsCorrected) {
  EXPECT_EQ(implicit_of("t^2+s^2", "t", "s"), "y^2+z^2-x");            // elliptic paraboloid
  EXPECT_EQ(implicit_of("t", "s", "t^2-s^2"), "x^2-y^2-z");            // hyperbolic paraboloid
  EXPECT_EQ(implicit_of("s", "t", "s^2+t^2"), "x^2+y^2-z");            // the "ellipsoid" is a paraboloid
  EXPECT_EQ(implicit_of("(t-s)/t", "s/t", "(s^3+t^2)/t^2"), "x+y-1");  // Sage 1
  EXPECT_EQ(implicit_of("s/t", "s/t^2", "(s+t)/s"), "x*z-x-1");        // Sage 2
  EXPECT_EQ(implicit_of("s/(s*t)", "(t^2-s)/t^2", "t/s"), "y*z+x-z");  // Sage 3 (x = s/(s t))
  EXPECT_EQ(implicit_of("(t-s^2)/(s*t)", "s^2/3", "s"), "z^2-3*y");    // Sage 4
}

TEST(Implicitize, CurvesAndPointsHaveNoSingleEquation) {
  EXPECT_THROW(implicitize(parse_parametrization("t", "t^2", "t^3")), NoSingleEquation);
  EXPECT_THROW(implicitize(parse_parametrization("1", "2", "3")), NoSingleEquation);
  try {
    implicitize(parse_parametrization("t", "t^2", "t^3"));
  } catch (const NoSingleEquation& e) {
    // The twisted cubic: its ideal has the three-element grevlex basis
    // x^2 - y, x*y - z, y^2 - x*z (CLO §1.3); every one is listed.
    ASSERT_EQ(e.generators().size(), 3u);
    EXPECT_EQ(e.generators()[0], "y^2-x*z");
    EXPECT_EQ(e.generators()[1], "x*y-z");
    EXPECT_EQ(e.generators()[2], "x^2-y");
  }
}

// The Gröbner route modulo primes (ImplicitizeParams::modular_groebner) gives
// Singular's equation on every public surface and on the hard ones it answers in
// about a second (tp_22_rational, where Buchberger over ℚ needs more than a minute;
// tri_cubic), each proven by substitution and minimality; on an image that is not a
// surface it falls back to Buchberger over ℚ, which lists the generators.
TEST(Implicitize, ModularGroebnerRouteAgreesWithSingular) {
  const std::string dir = std::string(IMPLICITIZER_SHARED_DIR) + "/bench/";
  std::vector<testing::Surface> surfaces = testing::read_surfaces(dir + "surfaces_public.json");
  for (const auto& s : testing::read_surfaces(dir + "surfaces_hard.json")) {
    if (s.name == "tp_22" || s.name == "tp_22_rational" || s.name == "tri_cubic") surfaces.push_back(s);
  }
  ImplicitizeParams options;
  options.method = ImplicitizationMethod::groebner;
  options.modular_groebner = true;
  for (const auto& s : surfaces) {
    SCOPED_TRACE(s.name);
    options.budget.set_timeout(60);  // each surface its own minute (about a second unloaded)
    const ImplicitizeResult r = implicitize(parse_parametrization(s.x, s.y, s.z), options);
    ASSERT_TRUE(r.modular_stats);
    EXPECT_TRUE(r.verified);
    EXPECT_EQ(r.degree, s.degree);
    const std::string expected = dir + "expected/" + s.name + ".txt";
    if (std::ifstream(expected)) {
      expect_same_surface(to_string(r.implicit), testing::read_text(expected));
    } else {
      ImplicitizeParams resultant;
      resultant.method = ImplicitizationMethod::resultant;
      EXPECT_EQ(r.implicit, implicitize(parse_parametrization(s.x, s.y, s.z), resultant).implicit);
    }
  }
  try {
    implicitize(parse_parametrization("t", "t^2", "t^3"), options);
    FAIL() << "the twisted cubic is a curve";
  } catch (const NoSingleEquation& e) {
    EXPECT_EQ(e.generators().size(), 3u);
  }
}

TEST(Implicitize, ThreeParametersFillSpace) {
  EXPECT_THROW(implicitize(parse_parametrization("s", "t", "u")), NoSingleEquation);
}

TEST(Implicitize, BadInput) {
  EXPECT_THROW(parse_parametrization("x*s", "t", "s"), InputError);
  try {
    parse_parametrization("s+t", "s", "1/(s-s)");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.code(), "division_by_zero");
    EXPECT_EQ(e.field(), "z");
    EXPECT_EQ(e.position(), 1u);
  }
  try {
    parse_parametrization("s+t", "s", "u", std::vector<std::string>{"s", "t"});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.code(), "unknown_variable");
    EXPECT_EQ(e.field(), "z");
  }
}

TEST(Implicitize, BudgetExpires) {
  // tp_22 by Buchberger takes about 0.6 s; tp_33 by the resultant about 0.3 s.
  const auto hard = testing::read_surfaces(std::string(IMPLICITIZER_SHARED_DIR) + "/bench/surfaces_hard.json");
  for (const auto& s : hard) {
    if (s.name != "tp_22" && s.name != "tp_33") continue;
    ImplicitizeParams options;
    options.method = s.name == "tp_22" ? ImplicitizationMethod::groebner : ImplicitizationMethod::resultant;
    options.budget.set_timeout(s.name == "tp_22" ? 0.05 : 0.002);
    try {
      implicitize(parse_parametrization(s.x, s.y, s.z), options);
      FAIL() << s.name << " finished within its deadline";
    } catch (const LimitExceeded& e) {
      EXPECT_EQ(e.limit(), Limit::time);
    }
  }
}

ImplicitizeResult by(ImplicitizationMethod method, const std::string& x, const std::string& y, const std::string& z) {
  ImplicitizeParams options;
  options.method = method;
  return implicitize(parse_parametrization(x, y, z), options);
}

TEST(Implicitize, MethodNames) {
  EXPECT_EQ(parse_implicitization_method("auto"), ImplicitizationMethod::automatic);
  EXPECT_EQ(parse_implicitization_method("groebner"), ImplicitizationMethod::groebner);
  EXPECT_EQ(parse_implicitization_method("resultant"), ImplicitizationMethod::resultant);
  EXPECT_EQ(parse_implicitization_method("interpolation"), ImplicitizationMethod::interpolation);
  EXPECT_THROW(parse_implicitization_method("Resultant"), InputError);
}

TEST(Implicitize, ResultantAndGroebnerAgreeWhereBothFinish) {
  // Every surface of ../shared/bench on which the resultant applies and Buchberger
  // finishes in about a second; the hard ones beyond are covered below.
  const std::string dir = std::string(IMPLICITIZER_SHARED_DIR) + "/bench/";
  std::vector<testing::Surface> surfaces = testing::read_surfaces(dir + "surfaces_public.json");
  for (const auto& s : testing::read_surfaces(dir + "surfaces_hard.json")) {
    if (s.name == "tri_quadratic" || s.name == "tp_11_rational" || s.name == "tp_21" || s.name == "tp_22") {
      surfaces.push_back(s);
    }
  }
  std::size_t compared = 0;
  for (const auto& s : surfaces) {
    SCOPED_TRACE(s.name);
    ImplicitizeResult resultant;
    try {
      resultant = by(ImplicitizationMethod::resultant, s.x, s.y, s.z);
    } catch (const NoSingleEquation& e) {
      EXPECT_EQ(e.code(), "base_points");
      continue;
    }
    const ImplicitizeResult groebner = by(ImplicitizationMethod::groebner, s.x, s.y, s.z);
    EXPECT_EQ(resultant.method, "resultant");
    EXPECT_EQ(groebner.method, "groebner");
    EXPECT_TRUE(resultant.verified);
    EXPECT_EQ(resultant.implicit, groebner.implicit);
    EXPECT_EQ(resultant.degree, s.degree);
    ++compared;
  }
  EXPECT_GE(compared, 7u);  // plane, enneper, biquadratic_patch and the four hard ones
}

TEST(Implicitize, EveryHardSurfaceByTheResultant) {
  // Degrees 2 to 18, polynomial and rational; Singular needs more than 300 s for
  // tp_32 and tp_33. The answer is verified by exact substitution inside. auto takes
  // interpolation on those of degree ≤ 4 (tri_quadratic, tp_11_rational, tp_21: rule
  // 1 of docs/algorithms.md) and on the triangular patches of degree 9 (rule 4), the
  // resultant on the others.
  for (const auto& s : testing::read_surfaces(std::string(IMPLICITIZER_SHARED_DIR) + "/bench/surfaces_hard.json")) {
    SCOPED_TRACE(s.name);
    const ImplicitizeResult r = by(ImplicitizationMethod::resultant, s.x, s.y, s.z);
    EXPECT_EQ(r.method, "resultant");
    const ImplicitizeResult a = implicitize(parse_parametrization(s.x, s.y, s.z));
    if (s.degree <= 4) {
      EXPECT_EQ(a.method, "interpolation") << a.route;
      EXPECT_NE(a.route.find("tried first"), std::string::npos) << a.route;
    } else if (s.name == "tri_cubic" || s.name == "tri_cubic_rational") {
      EXPECT_EQ(a.method, "interpolation") << a.route;
      EXPECT_NE(a.route.find("Macaulay"), std::string::npos) << a.route;
    } else {
      EXPECT_EQ(a.method, "resultant") << a.route;
    }
    EXPECT_EQ(a.implicit, r.implicit);
    EXPECT_TRUE(r.verified);
    EXPECT_EQ(r.degree, s.degree);
    EXPECT_EQ(r.map_degree, 1);
    ASSERT_TRUE(r.resultant_stats);
    EXPECT_EQ(r.resultant_stats->formulation,
              s.name.rfind("tp_", 0) == 0 ? AuxiliaryFormulation::dixon : AuxiliaryFormulation::macaulay);
  }
}

// A random polynomial of bidegree (m, n) (tensor) or total degree n (triangular).
std::string random_patch_polynomial(std::mt19937_64& rng, int m, int n, bool tensor, int constant) {
  std::uniform_int_distribution<int> c(-5, 5);
  std::string out = std::to_string(constant);
  for (int i = 0; i <= m; ++i) {
    for (int j = 0; j <= n; ++j) {
      if (!tensor && i + j > n) continue;
      const int a = c(rng);
      if (a == 0 && !(i == m && j == n)) continue;
      out += "+(" + std::to_string(a == 0 ? 1 : a) + ")*s^" + std::to_string(i) + "*t^" + std::to_string(j);
    }
  }
  return out;
}

TEST(Implicitize, RandomPatchesByBothRoutes) {
  // Random tensor-product (bidegree (m,n)) and triangular (degree n) patches,
  // polynomial and with a common denominator: the resultant route gives degree
  // 2mn or n^2 (generic patches have no base points) and, where Buchberger is quick,
  // the same equation.
  std::mt19937_64 rng(2026);
  struct Shape {
    int m, n;
    bool tensor, rational, compare;
  };
  // Buchberger is compared where it takes well under a second (the rational
  // bidegree-(1,2), bidegree-(3,1) and degree-2 patches take it from 5 s to over 20 s).
  const Shape shapes[] = {{1, 1, true, false, true},  {1, 1, true, true, true},   {2, 1, true, false, true},
                          {1, 2, true, true, false},  {2, 2, true, true, false},  {3, 1, true, false, false},
                          {0, 2, false, false, true}, {0, 2, false, true, false}, {0, 3, false, false, false},
                          {0, 3, false, true, false}, {3, 2, true, false, false}};
  for (const Shape& shape : shapes) {
    for (int trial = 0; trial < 2; ++trial) {
      std::array<std::string, 3> p;
      for (auto& q : p) q = random_patch_polynomial(rng, shape.tensor ? shape.m : shape.n, shape.n, shape.tensor, 0);
      if (shape.rational) {
        const std::string w = random_patch_polynomial(rng, shape.tensor ? shape.m : shape.n, shape.n, shape.tensor, 50);
        for (auto& q : p) q = "(" + q + ")/(" + w + ")";
      }
      SCOPED_TRACE(p[0] + " | " + p[1] + " | " + p[2]);
      const ImplicitizeResult r = by(ImplicitizationMethod::resultant, p[0], p[1], p[2]);
      EXPECT_EQ(r.method, "resultant");
      EXPECT_TRUE(r.verified);
      EXPECT_EQ(r.degree, shape.tensor ? 2 * shape.m * shape.n : shape.n * shape.n);
      if (shape.compare) {
        EXPECT_EQ(r.implicit, by(ImplicitizationMethod::groebner, p[0], p[1], p[2]).implicit);
      }
    }
  }
}

TEST(Implicitize, HugeAndTinyCoefficientsByBothRoutes) {
  // Coefficients from 10^-30 to 10^30 in one patch: the modular determinant scales
  // rows to integers and needs more primes, never an approximation.
  const char* x = "(10^30*s+t+s*t)/(1+s/10^25+t+s*t)";
  const char* y = "(s*t/10^30+1-s)/(1+s/10^25+t+s*t)";
  const char* z = "(s-t/10^20+3*s*t)/(1+s/10^25+t+s*t)";
  const ImplicitizeResult r = by(ImplicitizationMethod::resultant, x, y, z);
  EXPECT_TRUE(r.verified);
  EXPECT_EQ(r.degree, 2);
  EXPECT_GT(r.resultant_stats->determinant.modulus_bits, 200u);
  EXPECT_EQ(r.implicit, by(ImplicitizationMethod::groebner, x, y, z).implicit);
}

TEST(Implicitize, AutoGivesBuchbergerAHeadStartOnTriangularPatches) {
  // enneper (Macaulay's 36x36 quotient, about 15 ms) is answered by Buchberger in
  // about 1 ms; tri_cubic (the same matrix) is not, and goes to interpolation (degree
  // 9, below which it beats Macaulay's quotient); tri_quartic (degree 16) to the
  // resultant.
  for (const auto& s : testing::read_surfaces(std::string(IMPLICITIZER_SHARED_DIR) + "/bench/surfaces_public.json")) {
    if (s.name != "enneper") continue;
    const ImplicitizeResult r = implicitize(parse_parametrization(s.x, s.y, s.z));
    EXPECT_EQ(r.method, "groebner");
    EXPECT_NE(r.route.find("head start"), std::string::npos) << r.route;
    ASSERT_TRUE(r.resultant_stats);
    EXPECT_EQ(r.resultant_stats->formulation, AuxiliaryFormulation::macaulay);
  }
  for (const auto& s : testing::read_surfaces(std::string(IMPLICITIZER_SHARED_DIR) + "/bench/surfaces_hard.json")) {
    if (s.name != "tri_cubic" && s.name != "tri_quartic") continue;
    SCOPED_TRACE(s.name);
    const ImplicitizeResult r = implicitize(parse_parametrization(s.x, s.y, s.z));
    EXPECT_EQ(r.method, s.name == "tri_cubic" ? "interpolation" : "resultant");
    EXPECT_NE(r.route.find("head start"), std::string::npos) << r.route;
    ASSERT_TRUE(r.resultant_stats);
    EXPECT_EQ(r.resultant_stats->formulation, AuxiliaryFormulation::macaulay);
  }
}

TEST(Implicitize, BasePointsMakeAutoFallBackAndResultantRefuse) {
  const char* cases[][3] = {
      {"2*s/(1+s^2+t^2)", "2*t/(1+s^2+t^2)", "(s^2+t^2-1)/(1+s^2+t^2)"},  // stereographic sphere
      {"(2+(1-t^2)/(1+t^2))*(1-s^2)/(1+s^2)", "(2+(1-t^2)/(1+t^2))*2*s/(1+s^2)", "2*t/(1+t^2)"},  // torus
      {"s*t", "t", "s^2"},                                                                        // Whitney's umbrella
  };
  const char* expected[] = {"x^2+y^2+z^2-1", "x^4+2*x^2*y^2+y^4+2*x^2*z^2+2*y^2*z^2+z^4-10*x^2-10*y^2+6*z^2+9",
                            "x^2-y^2*z"};
  for (std::size_t i = 0; i < 3; ++i) {
    SCOPED_TRACE(cases[i][0]);
    // auto: degree ≤ 4, so interpolation first, and no resultant probed.
    const ImplicitizeResult r = by(ImplicitizationMethod::automatic, cases[i][0], cases[i][1], cases[i][2]);
    EXPECT_EQ(r.method, "interpolation") << r.route;
    EXPECT_TRUE(r.verified);
    EXPECT_FALSE(r.resultant_stats);
    expect_same_surface(to_string(r.implicit), expected[i]);
    // The Gröbner route modulo primes, proven by substitution and minimality.
    ImplicitizeParams modular;
    modular.method = ImplicitizationMethod::groebner;
    modular.modular_groebner = true;
    const ImplicitizeResult m = implicitize(parse_parametrization(cases[i][0], cases[i][1], cases[i][2]), modular);
    EXPECT_EQ(m.method, "groebner");
    ASSERT_TRUE(m.modular_stats) << "the modular elimination answered";
    EXPECT_TRUE(m.verified);
    EXPECT_EQ(to_string(m.implicit), to_string(r.implicit));
    try {
      by(ImplicitizationMethod::resultant, cases[i][0], cases[i][1], cases[i][2]);
      FAIL() << "the resultant route answered despite base points";
    } catch (const NoSingleEquation& e) {
      EXPECT_EQ(e.code(), "base_points");
      EXPECT_NE(std::string(e.what()).find("base points"), std::string::npos);
    }
  }
}

TEST(Implicitize, BasePointsOnlyOnTheProjectivePlaneStillAllowTheResultant) {
  // x = st, y = s, z = t has base points on P² (the seed's Theorem 1.14 setting) but
  // none on P1xP1, where Dixon's determinant is exactly x - yz.
  const ImplicitizeResult r = by(ImplicitizationMethod::resultant, "s*t", "s", "t");
  EXPECT_EQ(to_string(r.implicit), "y*z-x");
  EXPECT_EQ(r.resultant_stats->formulation, AuxiliaryFormulation::dixon);
  EXPECT_TRUE(r.resultant_stats->macaulay_vanishes);
}

TEST(Implicitize, PlaneCurvesByBothRoutes) {
  // Two coordinates in one parameter: the implicit curve f(x, y), by Sylvester's
  // resultant (auto) and by Buchberger, which must agree.
  const char* cases[][3] = {
      {"t^2-1", "t^3-t", "x^3+x^2-y^2"},                  // nodal cubic
      {"(1-t^2)/(1+t^2)", "2*t/(1+t^2)", "x^2+y^2-1"},    // circle
      {"3*t/(1+t^3)", "3*t^2/(1+t^3)", "x^3+y^3-3*x*y"},  // folium of Descartes
      {"t^2", "t^4", "x^2-y"},                            // covered twice: map degree 2
      {"t^3/(t^2+1)", "t^5-2*t+7", ""},                   // a rational quintic, checked by agreement
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c[0]);
    ImplicitizeParams options;
    const Parametrization p = parse_parametrization(std::vector<std::string>{c[0], c[1]});
    const ImplicitizeResult r = implicitize(p, options);
    EXPECT_EQ(r.method, "resultant");
    EXPECT_TRUE(r.verified);
    EXPECT_EQ(r.implicit.ring()->variables(), (std::vector<std::string>{"x", "y"}));
    if (*c[2]) {
      EXPECT_EQ(to_string(r.implicit), c[2]);
    }
    options.method = ImplicitizationMethod::groebner;
    EXPECT_EQ(implicitize(p, options).implicit, r.implicit);
  }
  EXPECT_EQ(implicitize(parse_parametrization(std::vector<std::string>{"t^2", "t^4"})).map_degree, 2);
}

TEST(Implicitize, PlaneParametrizationsThatAreNotCurves) {
  ImplicitizeParams resultant;
  resultant.method = ImplicitizationMethod::resultant;
  EXPECT_THROW(implicitize(parse_parametrization(std::vector<std::string>{"s", "t"})), NoSingleEquation);
  EXPECT_THROW(implicitize(parse_parametrization(std::vector<std::string>{"s", "t"}), resultant), InputError);
  EXPECT_THROW(implicitize(parse_parametrization(std::vector<std::string>{"2", "3+0*t"}), resultant), NoSingleEquation);
  EXPECT_THROW(parse_parametrization(std::vector<std::string>{"t"}), std::invalid_argument);
}

TEST(Implicitize, ResultantMatricesHaveASizeLimit) {
  // Total degree 12: Macaulay's matrix would have C(36, 2) = 630 rows, over the
  // limit, and the bidegree-(12,12) Dixon matrix vanishes (base points on P1xP1).
  // resultant says which limit stopped it; auto goes to Buchberger.
  const char* x = "s^12+t";
  const char* y = "t^12+s";
  const char* z = "s*t";
  try {
    by(ImplicitizationMethod::resultant, x, y, z);
    FAIL() << "no size limit";
  } catch (const LimitExceeded& e) {
    EXPECT_EQ(e.limit(), Limit::size);
    EXPECT_NE(std::string(e.what()).find("rows"), std::string::npos);
  }
  ImplicitizeParams options;
  options.budget.set_timeout(0.2);
  try {
    const ImplicitizeResult r = implicitize(parse_parametrization(x, y, z), options);
    EXPECT_EQ(r.method, "groebner");
    EXPECT_TRUE(r.resultant_stats->matrix_too_large);
  } catch (const LimitExceeded& e) {
    EXPECT_EQ(e.limit(), Limit::time);  // Buchberger may need longer: the budget says so
  }
}

TEST(Implicitize, ResultantNeedsTwoParameters) {
  try {
    by(ImplicitizationMethod::resultant, "s", "t", "u");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.code(), "method_not_applicable");
  }
  EXPECT_THROW(by(ImplicitizationMethod::resultant, "t", "t^2", "t^3"), InputError);
}

}  // namespace
}  // namespace implicitizer
