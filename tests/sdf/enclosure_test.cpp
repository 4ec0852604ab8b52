#include "implicitizer/sdf/enclosure.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "implicitizer/core/errors.hpp"
#include "sdf/sdf_support.hpp"

namespace implicitizer {
namespace {

using testing::exact;
using testing::parse_xyz;
using Box = std::vector<std::pair<Rational, Rational>>;

Box cube(const std::string& half, std::size_t dimension = 3) { return Box(dimension, {-exact(half), exact(half)}); }

Enclosure decide(const std::string& f, const Box& box) { return decide_enclosure(parse_xyz(f), box); }

// Closed surfaces strictly inside their box: F > 0 on every face, F < 0 at a point
// inside, so the solid F <= 0, as is.
TEST(Enclosure, SphereAndTorusInsideTheirBoxesAreSolids) {
  const Enclosure sphere = decide("x^2+y^2+z^2-1", cube("2"));
  EXPECT_EQ(sphere.shape, SdfShape::solid) << sphere.reason;
  EXPECT_FALSE(sphere.negate);
  const Enclosure torus = decide("(x^2+y^2+z^2+3)^2-16*(x^2+y^2)", cube("4"));
  EXPECT_EQ(torus.shape, SdfShape::solid) << torus.reason;
  EXPECT_FALSE(torus.negate);
  // An off-centre ellipsoid in a box that is not a cube.
  Box box{{exact("-2"), exact("4")}, {exact("-2"), exact("2")}, {exact("-1/2"), exact("1/2")}};
  const Enclosure ellipsoid = decide("(x-1)^2/4+y^2+16*z^2-1", box);
  EXPECT_EQ(ellipsoid.shape, SdfShape::solid) << ellipsoid.reason;
}

// F < 0 on the faces and > 0 inside: a solid, with F negated so that the enclosed
// ball is the inside.
TEST(Enclosure, NegativeOnTheFacesIsASolidOfMinusF) {
  const Enclosure e = decide("1-x^2-y^2-z^2", cube("2"));
  EXPECT_EQ(e.shape, SdfShape::solid) << e.reason;
  EXPECT_TRUE(e.negate);
  EXPECT_NE(e.reason.find("F < 0 on the boundary"), std::string::npos) << e.reason;
}

// Open surfaces cross the faces: sheets, each with the point that proves it.
TEST(Enclosure, SurfacesThroughTheFacesAreSheets) {
  for (const char* f : {"x+y+z", "z-x*y", "x^2+y^2-1", "x^2*y^2+y^2*z^2+z^2*x^2-x*y*z"}) {
    const Enclosure e = decide(f, cube("1"));
    EXPECT_EQ(e.shape, SdfShape::sheet) << f;
    EXPECT_NE(e.reason.find("on the boundary"), std::string::npos) << f << ": " << e.reason;
  }
  // Steiner's surface: its coordinate axes leave the cube at the faces' centres,
  // e.g. (1, 0, 0), where F vanishes exactly.
  const Enclosure steiner = decide("x^2*y^2+y^2*z^2+z^2*x^2-x*y*z", cube("1"));
  EXPECT_NE(steiner.reason.find("vanishes"), std::string::npos) << steiner.reason;
  // The same sphere in a box that cuts it.
  EXPECT_EQ(decide("x^2+y^2+z^2-1", cube("1/2")).shape, SdfShape::sheet);
}

// No zero on the boundary but nothing enclosed: F > 0 everywhere, or a sphere
// outside the box entirely. (x²+y²+z²−1)² touches 0 without a sign change: its
// surface encloses nothing that F < 0 describes, so it stays a sheet.
TEST(Enclosure, NoRegionOfTheOtherSignIsASheet) {
  for (const char* f : {"x^2+y^2+z^2+1", "(x-5)^2+y^2+z^2-1", "(x^2+y^2+z^2-1)^2"}) {
    const Enclosure e = decide(f, cube("2"));
    EXPECT_EQ(e.shape, SdfShape::sheet) << f << ": " << e.reason;
  }
  // A sphere of radius 0.01 between the finest grid's points (spacing 1/8 for 2^5
  // steps over [-2, 2]): undecided, so a sheet, and the answer says so.
  const Enclosure tiny = decide("(x-1/16)^2+(y-1/16)^2+(z-1/16)^2-1/10000", cube("2"));
  EXPECT_EQ(tiny.shape, SdfShape::sheet);
  EXPECT_NE(tiny.reason.find("undecided"), std::string::npos) << tiny.reason;
}

// A sphere 2^-30 inside the face x = 1, touching it nearly at (1, 1/3, 0) (not a
// dyadic point, so no bisection lands on it): the depth runs out before the sign is
// proven, and the answer is an honest sheet. Centred on the cube, the same near miss
// is proven (y² has Bernstein coefficients 0, 0, 1 on [0, 1]: depth 2 suffices).
TEST(Enclosure, UnresolvedNearMissIsAnUndecidedSheet) {
  const Enclosure e = decide("(x-1/3)^2+(y-1/3)^2+z^2-(2/3-1/2^30)^2", cube("1"));
  EXPECT_EQ(e.shape, SdfShape::sheet);
  EXPECT_NE(e.reason.find("undecided"), std::string::npos) << e.reason;
  const Enclosure centred = decide("x^2+y^2+z^2-(1-1/2^30)^2", cube("1"));
  EXPECT_EQ(centred.shape, SdfShape::solid) << centred.reason;
}

// Plane curves: F in x and y, decided on the square's 4 edges.
TEST(Enclosure, PlaneCurvesAreDecidedOnTheEdges) {
  const Enclosure circle = decide("x^2+y^2-1", cube("2", 2));
  EXPECT_EQ(circle.shape, SdfShape::solid) << circle.reason;
  EXPECT_FALSE(circle.negate);
  const Enclosure parabola = decide("y-x^2", cube("2", 2));
  EXPECT_EQ(parabola.shape, SdfShape::sheet);
  const Enclosure inverted = decide("1-x^2-2*y^2", cube("2", 2));
  EXPECT_EQ(inverted.shape, SdfShape::solid);
  EXPECT_TRUE(inverted.negate);
  // A curve's equation may not involve z.
  EXPECT_THROW((void)decide("x^2+y^2+z-1", cube("2", 2)), std::invalid_argument);
}

TEST(Enclosure, StopsWhenTheBudgetRunsOut) {
  Budget budget;
  budget.cancel();
  EXPECT_THROW((void)decide_enclosure(parse_xyz("x^2+y^2+z^2-1"), cube("2"), budget), LimitExceeded);
}

}  // namespace
}  // namespace implicitizer
