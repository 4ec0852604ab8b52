// Tests of server/service/src/scene_request.cpp: what a request's object becomes (a
// scene of one leaf with its shape, domain, box and dimension, or the scene), and
// the request's own errors, found before the library runs.

#include "implicitizer/service/scene_request.hpp"

#include <gtest/gtest.h>

#include <string>

#include "implicitizer/core/errors.hpp"
#include "service/service_support.hpp"

namespace implicitizer {
namespace {

using testing::input_error_of;

std::string error_of(const SceneRequest& request) {
  const InputError e = input_error_of([&] { make_request_scene(request); });
  return e.code() + "@" + e.field();
}

TEST(ParseRequestBox, SixNumbersInSpaceFourForACurve) {
  const SceneBox space = parse_request_box({"-1", "-2", "-3", "1", "2", "3/2"});
  EXPECT_EQ(space.lo[2], Rational(-3));
  EXPECT_EQ(space.hi[2], Rational(3) / Rational(2));
  // A curve's box is x0, y0, x1, y1; z spans the larger half side, so the frame's
  // scale is the plane box's.
  const SceneBox plane = parse_request_box({"0", "-1", "4", "1"}, 2);
  EXPECT_EQ(plane.lo[0], Rational(0));
  EXPECT_EQ(plane.hi[0], Rational(4));
  EXPECT_EQ(plane.lo[1], Rational(-1));
  EXPECT_EQ(plane.hi[1], Rational(1));
  EXPECT_EQ(plane.lo[2], Rational(-2));
  EXPECT_EQ(plane.hi[2], Rational(2));
  // Six numbers for a curve: z is ignored.
  const SceneBox six = parse_request_box({"0", "-1", "100", "4", "1", "200"}, 2);
  EXPECT_EQ(six.hi[0], Rational(4));
  EXPECT_EQ(six.lo[2], Rational(-2));
  EXPECT_EQ(parse_request_box({}, 2).hi[2], Rational(2));  // the default box
  for (const auto& [numbers, dimension] : {std::pair{std::vector<std::string>{"0", "0", "1", "1"}, 3},
                                           std::pair{std::vector<std::string>{"0", "0", "0", "1", "1"}, 2},
                                           std::pair{std::vector<std::string>{"0", "0", "one", "1"}, 2}}) {
    const InputError e = input_error_of([&] { parse_request_box(numbers, dimension); });
    EXPECT_EQ(e.code() + "@" + e.field(), "invalid_box@box");
  }
}

TEST(ParseRequestDomain, ExactIntervalsWithLoBelowHi) {
  const auto domain = parse_request_domain({"0", "1/3", "-1", "0.5"}, 2);
  ASSERT_EQ(domain.size(), 2u);
  EXPECT_EQ(domain[0].second, Rational(1) / Rational(3));
  EXPECT_EQ(domain[1].first, Rational(-1));
  EXPECT_EQ(domain[1].second, Rational(1) / Rational(2));
  auto error = [](std::vector<std::string> numbers, std::size_t parameters) {
    const InputError e = input_error_of([&] { parse_request_domain(numbers, parameters); });
    return e.code() + "@" + e.field();
  };
  EXPECT_EQ(error({"0", "1"}, 2), "invalid_domain@domain");               // the wrong count
  EXPECT_EQ(error({"0", "1", "0"}, 2), "invalid_domain@domain");          // odd
  EXPECT_EQ(error({"0", "1", "2", "1"}, 2), "invalid_domain@domain[2]");  // lo > hi
  EXPECT_EQ(error({"1", "1"}, 1), "invalid_domain@domain[0]");            // lo = hi
  EXPECT_EQ(error({"0", "inf"}, 1), "invalid_domain@domain[1]");          // not finite
  EXPECT_EQ(error({"nan", "1"}, 1), "invalid_domain@domain[0]");
  EXPECT_EQ(error({"s", "1"}, 1), "invalid_domain@domain[0]");
}

TEST(MakeRequestScene, AnInputIsOneLeafCarryingShapeDomainAndBox) {
  SceneRequest r;
  r.parametric = std::array<std::string, 3>{"s", "t", "s*t"};
  r.shape = SdfShape::sheet;
  r.domain = {"0", "1", "0", "1/2"};
  RequestScene scene = make_request_scene(r);
  EXPECT_TRUE(scene.one_leaf);
  EXPECT_EQ(scene.root.kind, NodeKind::parametric);
  EXPECT_EQ(scene.root.leaf.shape, SdfShape::sheet);
  ASSERT_EQ(scene.root.leaf.domain.size(), 2u);
  EXPECT_EQ(scene.root.leaf.domain[1].second, Rational(1) / Rational(2));
  EXPECT_FALSE(scene.root.leaf.box.has_value());  // no box: fitted to the patch
  EXPECT_EQ(scene.params.dimension, 3);
  r.box = {"-1", "-1", "-1", "1", "1", "1"};
  scene = make_request_scene(r);
  ASSERT_TRUE(scene.root.leaf.box.has_value());  // a given box is the leaf's frame
  EXPECT_EQ(scene.root.leaf.box->hi[0], Rational(1));

  // No z: a plane curve, whose domain is one interval and whose box is four numbers.
  SceneRequest curve;
  curve.parametric = std::array<std::string, 3>{"t", "t^2", ""};
  curve.domain = {"-1", "1"};
  curve.box = {"-2", "-1", "2", "3"};
  scene = make_request_scene(curve);
  EXPECT_EQ(scene.params.dimension, 2);
  EXPECT_EQ(scene.root.leaf.domain.size(), 1u);
  EXPECT_EQ(scene.params.box.hi[1], Rational(3));
  EXPECT_EQ(scene.params.box.hi[2], Rational(2));

  SceneRequest implicit;
  implicit.implicit = "x^2+y^2-1";
  EXPECT_EQ(make_request_scene(implicit).params.dimension, 2);  // no z: the circle
  EXPECT_EQ(make_request_scene(implicit).root.kind, NodeKind::implicit);
  implicit.implicit = "x^2+y^2+z^2-1";
  implicit.shape = SdfShape::solid;
  scene = make_request_scene(implicit);
  EXPECT_EQ(scene.params.dimension, 3);
  EXPECT_EQ(scene.root.leaf.equation, "x^2+y^2+z^2-1");
  EXPECT_EQ(scene.root.leaf.shape, SdfShape::solid);
  EXPECT_FALSE(scene.root.leaf.box.has_value());  // the scene box serves

  SceneRequest s;
  s.scene = make_node(NodeKind::sphere, {{"radius", 1.0}});
  scene = make_request_scene(s);
  EXPECT_FALSE(scene.one_leaf);
  EXPECT_EQ(scene.root.kind, NodeKind::sphere);
  EXPECT_EQ(scene.params.dimension, 3);
}

TEST(MakeRequestScene, RequestErrorsNameTheRequestsFields) {
  SceneRequest r;
  EXPECT_EQ(error_of(r), "missing_field@implicit");
  r.implicit = "x";
  r.parametric = std::array<std::string, 3>{"s", "t", "s"};
  EXPECT_EQ(error_of(r), "invalid_value@scene");
  r = SceneRequest{};
  r.implicit = "x^2+";
  EXPECT_EQ(error_of(r).substr(error_of(r).find('@')), "@implicit");
  r.implicit = "x";
  r.domain = {"0", "1"};
  EXPECT_EQ(error_of(r), "invalid_domain@domain");  // a domain without a parametrization
  r = SceneRequest{};
  r.parametric = std::array<std::string, 3>{"s", "t", "s*t"};
  r.domain = {"0", "1"};
  EXPECT_EQ(error_of(r), "invalid_domain@domain");  // a surface has two parameters
  r.parameters = std::vector<std::string>{"s", "t"};
  r.domain = {"0", "1", "1", "0"};
  EXPECT_EQ(error_of(r), "invalid_domain@domain[2]");
  r.domain = {};
  r.box = {"0", "0", "0", "1", "1"};
  EXPECT_EQ(error_of(r), "invalid_box@box");
  r.box = {"1", "0", "0", "0", "1", "1"};
  EXPECT_EQ(error_of(r), "invalid_box@box");  // hi <= lo: the frame's check
  r = SceneRequest{};
  r.scene = make_node(NodeKind::sphere, {{"radius", 1.0}});
  r.shape = SdfShape::sheet;
  EXPECT_EQ(error_of(r), "invalid_value@shape");  // a scene's leaves carry their own
  r.shape = SdfShape::automatic;
  r.domain = {"0", "1"};
  EXPECT_EQ(error_of(r), "invalid_domain@domain");
}

TEST(RethrowRequestError, LeafFieldsBecomeTheRequestsAndNoSingleEquationKeepsItsIdeal) {
  SceneRequest r;
  r.parametric = std::array<std::string, 3>{"t", "t^2", "t^3"};  // the twisted cubic: a space curve
  const RequestScene scene = make_request_scene(r);
  const InputError leaf_error("no_single_equation", "the parametrization has no single implicit equation");
  try {
    rethrow_request_error(leaf_error.in_field("scene"), scene, Budget());
  } catch (const NoSingleEquation& e) {
    EXPECT_EQ(e.code(), "no_single_equation");
    EXPECT_EQ(e.generators().size(), 3u);  // y^2-x*z, x*y-z, x^2-y
  }
  auto field_of = [&](const std::string& field) {
    try {
      rethrow_request_error(InputError("invalid_domain", "m").in_field(field), scene, Budget());
    } catch (const InputError& e) {
      return e.field();
    }
    return std::string("none");
  };
  EXPECT_EQ(field_of("scene.domain"), "domain");
  EXPECT_EQ(field_of("scene.y"), "y");
  EXPECT_EQ(field_of("scene.box"), "box");
  EXPECT_EQ(field_of("scene"), "");
  SceneRequest implicit;
  implicit.implicit = "x^2+y^2+z^2-1";
  const RequestScene one = make_request_scene(implicit);
  try {
    rethrow_request_error(InputError("degree_too_high", "m").in_field("scene.equation"), one, Budget());
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "implicit");
  }
}

}  // namespace
}  // namespace implicitizer
