// Tests of server/service/src/render_request.cpp: the size limits, and the errors of
// the surface, the method and the camera with their fields.

#include "implicitizer/service/render_request.hpp"

#include <gtest/gtest.h>

#include <string>

#include "implicitizer/core/errors.hpp"
#include "service/service_support.hpp"

namespace implicitizer {
namespace {

using testing::input_error_of;

TEST(AnswerRenderRequest, LimitsAndChoices) {
  auto code = [](RenderRequest r) {
    const InputError e = input_error_of([&] { answer_render_request(r, Budget(), RenderRequestParams{}, 1); });
    return e.code() + "@" + e.field();
  };
  RenderRequest r;
  r.implicit = "x^2+y^2+z^2-1";
  r.width = 4096;
  r.height = 4096;
  EXPECT_EQ(code(r), "render_too_large@width");
  r.width = 0;
  EXPECT_EQ(code(r), "invalid_size@width");
  r = RenderRequest{};
  r.implicit = "x^2+y^2+z^2-1";
  r.antialiasing = 9;
  EXPECT_EQ(code(r), "invalid_value@aa");
  r.antialiasing = 1;
  r.implicit = "x^2+w";
  EXPECT_EQ(code(r), "unknown_variable@implicit");
  r = RenderRequest{};
  r.parametric = std::array<std::string, 3>{"s", "t", "s*"};
  EXPECT_EQ(code(r).substr(code(r).find('@')), "@z");
  r = RenderRequest{};
  r.scene = make_node(NodeKind::sphere, {{"radius", 1.0}});
  r.method = MarchMethod::exact;
  EXPECT_EQ(code(r), "method_not_applicable@method");
  r = RenderRequest{};
  r.implicit = "x+z";  // a plane in space ("x" alone is a line, drawn flat without a camera)
  r.eye = std::array<double, 3>{0, 0, 0};
  EXPECT_EQ(code(r), "invalid_camera@eye");
}

}  // namespace
}  // namespace implicitizer
