// Tests of lib/src/approximation/surface_distance.cpp: the tube sample's measurement of
// how far {q = 0} strays from a patch, on the paraboloid z = x² + y² over [0, 1]²:
// its own equation stays on it, a copy lifted by 1/100 is found 1/100 · (1 + 4r²)^(−1/2)
// away, and a sample measured twice (its distances cached) or afresh gives the same.

#include "surface_distance.hpp"

#include <gtest/gtest.h>

#include "implicitizer/core/budget.hpp"
#include "implicitizer/implicitization/parametrization.hpp"
#include "implicitizer/polynomial/parser.hpp"
#include "implicitizer/polynomial/ring.hpp"

namespace implicitizer::approximation {
namespace {

struct Paraboloid {
  Parametrization parametrization = parse_parametrization("s", "t", "s^2+t^2");
  PatchEvaluator patch{common_denominator_form(parametrization, Budget())};
  ParameterRect unit{0, 1, 0, 1};
  Frame frame{{0.5, 0.5, 1}, 1};  // the patch's box [0, 1]² × [0, 2]

  FramedPolynomial equation(const std::string& text) const {
    return FramedPolynomial(parse_polynomial(text, Ring::make({"x", "y", "z"})), frame);
  }
  SurfaceToPatch measure(const FramedPolynomial& q) const {
    TubeSample tube(patch, q, unit, unit, 0.1, Budget());
    return measure_surface_to_patch(tube);
  }
};

TEST(TubeSample, ThePatchsOwnEquationStaysOnIt) {
  const Paraboloid p;
  const SurfaceToPatch r = p.measure(p.equation("z-x^2-y^2"));
  EXPECT_GT(r.samples, 100u);
  EXPECT_LT(r.distance, 1e-9);
}

TEST(TubeSample, ALiftedCopyIsFoundAtItsDistance) {
  const Paraboloid p;
  const SurfaceToPatch r = p.measure(p.equation("z-x^2-y^2-1/100"));
  EXPECT_GT(r.samples, 100u);
  // 1/100 straight up is 1/100·(1 + 4r²)^(−1/2) along the normal, r² <= 2 on the patch.
  EXPECT_GT(r.distance, 0.01 / 3 - 1e-6);
  EXPECT_LT(r.distance, 0.01 + 1e-6);
}

TEST(TubeSample, ASharedSampleMeasuresAsAFreshOne) {
  const Paraboloid p;
  const FramedPolynomial q = p.equation("z-x^2-y^2-1/100");
  TubeSample shared(p.patch, q, p.unit, p.unit, 0.1, Budget());
  const SurfaceToPatch first = measure_surface_to_patch(shared);
  const SurfaceToPatch again = measure_surface_to_patch(shared);
  const SurfaceToPatch fresh = p.measure(q);
  EXPECT_EQ(first.distance, again.distance);
  EXPECT_EQ(first.samples, again.samples);
  EXPECT_EQ(first.distance, fresh.distance);
  EXPECT_EQ(first.samples, fresh.samples);
}

}  // namespace
}  // namespace implicitizer::approximation
