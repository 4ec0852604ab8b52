// Oracle: the reproduce scripts that implicitize() hands to the user
// (reproduce_scripts(), the answer's "reproduce") run unchanged in real
// Singular and Macaulay2, print exactly one line, the implicit equation, and that
// equation is ours up to a rational factor. Covers polynomial and rational surfaces,
// rational coefficients (enneper), parameters the scripts must rename because the
// systems reserve their names, and trigonometric and hyperbolic inputs (converted).

#include <gtest/gtest.h>

#include <ostream>
#include <string>
#include <vector>

#include "implicitizer/implicitization/implicitize.hpp"
#include "implicitizer/implicitization/reproduce.hpp"
#include "implicitizer/polynomial/parser.hpp"
#include "oracle/oracle_support.hpp"

namespace implicitizer {
namespace {

std::vector<testing::Surface> reproduce_surfaces() {
  const std::vector<std::string> chosen = {"unit_sphere", "torus_R2_r1", "whitney_umbrella", "steiner_roman",
                                           "enneper"};
  std::vector<testing::Surface> out;
  for (const auto& s : testing::read_surfaces(std::string(IMPLICITIZER_SHARED_DIR) + "/bench/surfaces_public.json")) {
    for (const auto& name : chosen) {
      if (s.name == name) out.push_back(s);
    }
  }
  // Parameters named like Singular's and Macaulay2's own words (`ring`, `e`): the
  // scripts rename them t1, t2. Degree 0: not stated, only compared with the oracles.
  out.push_back({"reserved_parameter_names", "ring/(ring+e)", "e^2", "ring*e/3", 0});
  // A plane curve (no z): the folium of Descartes, answered by Sylvester's resultant;
  // the scripts eliminate t and w in the ring (w, t, x, y).
  out.push_back({"plane_curve_folium", "3*t/(1+t^3)", "3*t^2/(1+t^3)", "", 3});
  // Issue 20: trigonometric and hyperbolic inputs. The scripts hold the rational form
  // (tan(θ/2), exp(θ)), so Singular and Macaulay2 check the conversion as well.
  out.push_back({"trig_sphere", "cos(u)*cos(v)", "cos(u)*sin(v)", "sin(u)", 2});
  out.push_back({"trig_torus", "(2+cos(v))*cos(u)", "(2+cos(v))*sin(u)", "sin(v)", 4});
  out.push_back({"hyperbolic_hyperboloid", "cosh(u)*cos(v)", "cosh(u)*sin(v)", "sinh(u)", 2});
  out.push_back({"trig_curve_double_angle", "cos(2*t)", "sin(t)", "", 2});
  out.push_back({"trig_astroid", "cos(t)^3", "sin(t)^3", "", 6});
  out.push_back({"trig_multiple_angles", "cos(u+2*v)", "sin(u-v)", "tan(v)", 0});
  return out;
}

// Whether the output of a reproduce script is exactly one line, our equation up to a factor.
void expect_prints_our_equation(const testing::ScriptRun& run, const std::string& script, const Polynomial& ours) {
  ASSERT_EQ(run.exit_code, 0) << script << run.describe();
  const std::vector<std::string> lines = testing::non_empty_lines(run.out);
  ASSERT_EQ(lines.size(), 1u) << "expected one generator\n" << script << run.describe();
  Polynomial theirs = Polynomial(ours.ring());
  try {
    theirs = parse_polynomial(lines[0], ours.ring());
  } catch (const std::exception& e) {
    FAIL() << "cannot parse the output (" << e.what() << ")\n" << script << run.describe();
  }
  EXPECT_TRUE(testing::equal_up_to_scalar(ours, theirs)) << script;
}

class ReproduceOracle : public ::testing::TestWithParam<testing::Surface> {
 protected:
  // The answer as the codec writes it: the result and its reproduce scripts.
  struct Answer {
    ImplicitizeResult result;
    ReproduceScripts scripts;
  };

  Answer implicitize_surface() const {
    const testing::Surface& s = GetParam();
    ImplicitizeParams options;
    options.budget.set_timeout(30);
    const Parametrization p = s.z.empty() ? parse_parametrization(std::vector<std::string>{s.x, s.y})
                                          : parse_parametrization(s.x, s.y, s.z);
    const ImplicitizeResult result = implicitize(p, options);
    EXPECT_TRUE(result.verified);
    if (s.degree > 0) {
      EXPECT_EQ(result.degree, s.degree);
    }
    ReproduceScripts scripts = reproduce_scripts(p);
    if (s.name.rfind("trig_", 0) == 0 || s.name.rfind("hyperbolic_", 0) == 0) {
      EXPECT_FALSE(p.substitutions.empty());
      EXPECT_NE(scripts.singular.find("made rational by"), std::string::npos) << scripts.singular;
    }
    if (s.name == "reserved_parameter_names") {
      EXPECT_NE(scripts.singular.find("(w,t1,t2,x,y,z)"), std::string::npos) << scripts.singular;
      EXPECT_NE(scripts.macaulay2.find("[w,t1,t2,x,y,z]"), std::string::npos) << scripts.macaulay2;
    }
    return {result, std::move(scripts)};
  }
};

TEST_P(ReproduceOracle, SingularScriptPrintsOurEquation) {
  if (!testing::is_runnable(testing::kSingular)) {
    GTEST_SKIP() << "Singular not found (SINGULAR_EXECUTABLE=\"" << testing::kSingular << "\")";
  }
  const Answer answer = implicitize_surface();
  expect_prints_our_equation(testing::run_singular(answer.scripts.singular), answer.scripts.singular,
                             answer.result.implicit);
}

TEST_P(ReproduceOracle, Macaulay2ScriptPrintsOurEquation) {
  if (!testing::is_runnable(testing::kMacaulay2)) {
    GTEST_SKIP() << "Macaulay2 not found (MACAULAY2_EXECUTABLE=\"" << testing::kMacaulay2 << "\")";
  }
  const Answer answer = implicitize_surface();
  expect_prints_our_equation(testing::run_macaulay2(answer.scripts.macaulay2), answer.scripts.macaulay2,
                             answer.result.implicit);
}

INSTANTIATE_TEST_SUITE_P(Surfaces, ReproduceOracle, ::testing::ValuesIn(reproduce_surfaces()),
                         [](const auto& test) { return test.param.name; });

}  // namespace
}  // namespace implicitizer
