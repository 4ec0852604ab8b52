// Tests of lib/src/resultant/curve_resultant.cpp: the Sylvester pencil of a plane
// rational curve and its determinant.

#include "implicitizer/resultant/curve_resultant.hpp"

#include <gtest/gtest.h>

#include "implicitizer/polynomial/parser.hpp"
#include "implicitizer/polynomial/printer.hpp"

namespace implicitizer {
namespace {

RingPtr t_ring() { return Ring::make({"t"}); }
RingPtr xy_ring() { return Ring::make({"x", "y"}); }

std::array<Polynomial, 3> curve(const std::string& w, const std::string& x, const std::string& y) {
  return {parse_polynomial(w, t_ring()), parse_polynomial(x, t_ring()), parse_polynomial(y, t_ring())};
}

TEST(CurveSylvesterPencil, ShapeUsesTheCommonFormalDegree) {
  // x = t, y = t^3: formal degree 3 for both rows, a 6x6 matrix.
  const MatrixPencil m = curve_sylvester_pencil(curve("1", "t", "t^3"));
  EXPECT_EQ(m.size(), 6u);
  EXPECT_EQ(m.num_variables(), 2u);
}

TEST(CurveAuxiliaryResultant, KnownCurves) {
  struct Case {
    const char *w, *x, *y, *expected;
  };
  const Case cases[] = {
      {"1", "t", "t^3", "x^3-y"},                            // the cubic y = x^3
      {"1", "t^2-1", "t^3-t", "x^3+x^2-y^2"},                // the nodal cubic
      {"1+t^2", "1-t^2", "2*t", "x^2+y^2-1"},                // the circle, rational
      {"1", "t^2", "t^4", "x^4-2*x^2*y+y^2"},                // y = x^2 covered twice: (y - x^2)^2
      {"1+t^3", "3*t", "3*t^2", "x^3+y^3-3*x*y"},            // the folium of Descartes
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.x);
    const AuxiliaryResultant aux = curve_auxiliary_resultant(curve(c.w, c.x, c.y), xy_ring());
    EXPECT_EQ(aux.stats.formulation, AuxiliaryFormulation::sylvester);
    EXPECT_TRUE(aux.stats.determinant.proven);
    EXPECT_EQ(to_string(aux.resultant.primitive_part()), to_string(parse_polynomial(c.expected, xy_ring()).primitive_part()));
  }
}

TEST(CurveAuxiliaryResultant, APointHasNoCurve) {
  EXPECT_TRUE(curve_auxiliary_resultant(curve("1", "2", "3"), xy_ring()).resultant.is_zero());
}

TEST(CurveAuxiliaryResultant, RefusesWhatDoesNotFit) {
  EXPECT_THROW(curve_auxiliary_resultant(curve("1", "t", "t"), Ring::make({"x", "y", "z"})), std::invalid_argument);
  const RingPtr st = Ring::make({"s", "t"});
  EXPECT_THROW(curve_sylvester_pencil({parse_polynomial("1", st), parse_polynomial("s", st), parse_polynomial("t", st)}),
               std::invalid_argument);
}

}  // namespace
}  // namespace implicitizer
