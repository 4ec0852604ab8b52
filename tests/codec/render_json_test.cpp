// Tests of server/codec/src/render_json.cpp: the decoder's fields and refusals, and
// the answer's JSON (with and without the PNG) next to the PNG it describes.

#include "implicitizer/codec/render_json.hpp"

#include <gtest/gtest.h>

#include <string>

#include "implicitizer/core/errors.hpp"
#include "implicitizer/render/png_codec.hpp"
#include "service/service_support.hpp"

namespace implicitizer {
namespace {

using testing::input_error_of;

TEST(DecodeRenderRequest, ReadsEveryField) {
  const RenderRequest r = decode_render_request(
      R"({"implicit":"x^2+y^2+z^2-1","mode":"safe","box":[-1,-1,-1,1,1,1],"name":"ball","width":64,"height":32,)"
      R"("method":"enhanced","aa":3,"eye":[1,2,3],"target":[0,0.5,0],"precision":"double","format":"json",)"
      R"("timeout_ms":1500})");
  EXPECT_EQ(r.implicit, "x^2+y^2+z^2-1");
  EXPECT_EQ(r.mode, SdfMode::safe);
  EXPECT_EQ(r.box.size(), 6u);
  EXPECT_EQ(r.name, "ball");
  EXPECT_EQ(r.width, 64u);
  EXPECT_EQ(r.height, 32u);
  EXPECT_EQ(r.method, MarchMethod::enhanced);
  EXPECT_EQ(r.antialiasing, 3u);
  EXPECT_EQ(r.eye, (std::array<double, 3>{1, 2, 3}));
  EXPECT_EQ(r.target, (std::array<double, 3>{0, 0.5, 0}));
  EXPECT_EQ(r.precision, EvaluationPrecision::double_run);
  EXPECT_EQ(r.format, RenderFormat::json);
  EXPECT_EQ(r.timeout_seconds, std::optional<double>(1.5));

  const RenderRequest p = decode_render_request(R"({"x":"s","y":"t","z":"s*t","parameters":["t","s"]})");
  ASSERT_TRUE(p.parametric.has_value());
  EXPECT_EQ((*p.parametric)[2], "s*t");
  EXPECT_EQ(p.parameters, (std::optional<std::vector<std::string>>{{"t", "s"}}));
  EXPECT_EQ(p.width, 256u);
  EXPECT_EQ(p.antialiasing, 2u);
  EXPECT_EQ(p.method, MarchMethod::sphere);
  EXPECT_FALSE(decode_render_request(R"({"scene":{"type":"sphere","radius":1}})").implicit.size());

  // The fields issue 18 adds, as for /v1/sdf: a curve (no z), its shape and domain.
  const RenderRequest c = decode_render_request(R"({"x":"t","y":"t^2","shape":"sheet","domain":[-1,"1/2"]})");
  ASSERT_TRUE(c.parametric.has_value());
  EXPECT_EQ((*c.parametric)[2], "");
  EXPECT_EQ(c.shape, SdfShape::sheet);
  EXPECT_EQ(c.domain, (std::vector<std::string>{"-1", "1/2"}));
}

TEST(DecodeRenderRequest, Refusals) {
  auto code = [](const char* body) {
    const InputError e = input_error_of([&] { decode_render_request(body); });
    return e.code() + "@" + e.field();
  };
  EXPECT_EQ(code(R"({"implicit":"x","scene":{"type":"sphere","radius":1}})"), "invalid_value@scene");
  EXPECT_EQ(code(R"({"implicit":"x","x":"s","y":"t","z":"s"})"), "invalid_value@scene");
  // x and y without z is a plane curve; without x or y it is nothing.
  EXPECT_EQ(code(R"({"x":"s","z":"t"})"), "missing_field@y");
  EXPECT_EQ(code(R"({"y":"s","z":"t"})"), "missing_field@x");
  EXPECT_EQ(code(R"({"x":"s","y":"t","z":""})"), "invalid_value@z");
  EXPECT_EQ(code(R"({"x":"s","y":"t","shape":"hollow"})"), "invalid_value@shape");
  EXPECT_EQ(code(R"({"x":"s","y":"t","domain":"0,1"})"), "invalid_domain@domain");
  EXPECT_EQ(code(R"({"x":"s","y":"t","domain":[0,null]})"), "invalid_domain@domain[1]");
  EXPECT_EQ(code(R"({})"), "missing_field@implicit");
  EXPECT_EQ(code(R"({"implicit":"x","width":-3})"), "wrong_type@width");
  EXPECT_EQ(code(R"({"implicit":"x","width":2.5})"), "wrong_type@width");
  EXPECT_EQ(code(R"({"implicit":"x","eye":[1,2]})"), "wrong_type@eye");
  EXPECT_EQ(code(R"({"implicit":"x","eye":[1,2,"3"]})"), "wrong_type@eye[2]");
  EXPECT_EQ(code(R"({"implicit":"x","size":"64x64"})"), "unknown_field@size");
  EXPECT_EQ(code(R"({"implicit":"x","method":"bisection"})"), "invalid_value@method");
  EXPECT_EQ(code(R"({"implicit":"x","precision":"half"})"), "invalid_value@precision");
}

TEST(AnswerRenderRequest, ThePngHasTheRequestedSizeAndTheJsonTheStatistics) {
  RenderRequest r;
  r.implicit = "x^2+y^2+z^2-1";
  r.width = 30;
  r.height = 20;
  r.antialiasing = 1;
  r.method = MarchMethod::exact;
  const RenderAnswer answer = answer_render_request(r, Budget(), RenderRequestParams{}, 2);
  const Image image = decode_png(answer.png);
  EXPECT_EQ(image.width(), 30u);
  EXPECT_EQ(image.height(), 20u);
  EXPECT_EQ(answer.stats.rays, 600u);
  EXPECT_GT(answer.stats.hits, 0u);
  const std::string json = encode_render_response(answer, false);
  EXPECT_EQ(json.rfind(R"({"width":30,"height":20,"method":"exact","mode":"fast","precision":"float","rays":600,)", 0),
            0u)
      << json;
  EXPECT_EQ(json.find("png_base64"), std::string::npos);
  const std::string with_png = encode_render_response(answer, true);
  EXPECT_NE(with_png.find(R"("png_base64":"iVBORw0KGgo)"), std::string::npos);  // base64 of the PNG signature
}

TEST(AnswerRenderRequest, AToleranceDrawsTheApproximationAndReportsIt) {
  // Enneper's surface: one low-degree piece is shorter GLSL than its exact equation.
  const std::string body = R"({"x": "s-s^3/3+s*t^2", "y": "t-t^3/3+s^2*t", "z": "s^2-t^2", "domain": [0, 1, 0, 1],
                               "tolerance": 0.05, "width": 24, "height": 24, "aa": 1, "format": "json"})";
  RenderRequest r = decode_render_request(body);
  EXPECT_EQ(r.tolerance, 0.05);
  const RenderAnswer answer = answer_render_request(r, Budget(), RenderRequestParams{}, 2);
  ASSERT_TRUE(answer.approximation);
  EXPECT_EQ(answer.approximation->tolerance, 0.05);
  EXPECT_GT(answer.approximation->glsl_lines, 0u);
  EXPECT_GT(answer.stats.hits, 0u);
  const std::string json = encode_render_response(answer, false);
  EXPECT_NE(json.find(R"("approximation":{"tolerance":0.05,"exact":false,)"), std::string::npos) << json;
  // No one polynomial stands for the pieces: the exact method does not apply.
  r.method = MarchMethod::exact;
  EXPECT_EQ(testing::input_error_of([&] { answer_render_request(r); }).code(), "method_not_applicable");
}

}  // namespace
}  // namespace implicitizer
