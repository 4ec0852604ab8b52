// The JSON form of scenes: decoding, errors with codes and JSON paths, injection
// attempts, limits, and the uniforms' encoding.

#include "implicitizer/codec/scene_json.hpp"

#include <gtest/gtest.h>

#include <string>
#include <utility>

#include "implicitizer/core/errors.hpp"

namespace implicitizer {
namespace {

using Failure = std::pair<std::string, std::string>;

// Decodes and compiles (fast mode, scene name "s"); returns the error's code and field.
Failure failure(const std::string& json, SdfMode mode = SdfMode::fast) {
  try {
    SceneParams options;
    options.mode = mode;
    options.name = "s";
    compile_scene(parse_scene_json(json), options);
  } catch (const InputError& e) {
    return {e.code(), e.field()};
  }
  return {"", ""};
}

CompiledScene compile_json(const std::string& json) {
  SceneParams options;
  options.name = "s";
  return compile_scene(parse_scene_json(json), options);
}

TEST(SceneJson, DecodesATreeWithEveryFieldKind) {
  const SceneNode root = parse_scene_json(R"({
    "type": "smooth_union", "k": 0.25, "n": 3, "name": "blend", "uniforms": ["k"],
    "children": [
      {"type": "translate", "offset": [1, 0, 0], "child": {"type": "sphere", "radius": 0.5}},
      {"type": "implicit", "equation": "x^2+y^2-z", "box": [-1, -1, -1, 1, 1, "3/2"]},
      {"type": "parametric", "x": "s", "y": "t", "z": "s*t", "parameters": ["s", "t"],
       "domain": [[0, 1], ["0", "1/2"]], "shape": "sheet"}
    ]})");
  EXPECT_EQ(root.kind, NodeKind::smooth_union);
  EXPECT_EQ(root.name, "blend");
  EXPECT_EQ(root.uniforms, std::vector<std::string>{"k"});
  ASSERT_EQ(root.parameters.size(), 2u);
  EXPECT_EQ(root.parameters[0].first, "k");
  EXPECT_EQ(root.parameters[1].second.value.x, 3.0);
  ASSERT_EQ(root.children.size(), 3u);
  EXPECT_EQ(root.children[0].kind, NodeKind::translate);
  EXPECT_TRUE(root.children[0].parameters[0].second.is_vector);
  EXPECT_EQ(root.children[0].children[0].kind, NodeKind::sphere);
  EXPECT_EQ(root.children[1].leaf.equation, "x^2+y^2-z");
  ASSERT_TRUE(root.children[1].leaf.box.has_value());
  EXPECT_EQ(root.children[1].leaf.box->hi[2], Rational(3) / Rational(2));
  EXPECT_EQ(root.children[2].leaf.coordinates[2], "s*t");
  ASSERT_EQ(root.children[2].leaf.domain.size(), 2u);
  EXPECT_EQ(root.children[2].leaf.domain[1].second, Rational(1) / Rational(2));
  EXPECT_EQ(root.children[2].leaf.shape, SdfShape::sheet);
  EXPECT_EQ(root.children[1].leaf.shape, SdfShape::automatic);  // the default
  // JSON numbers are read as their shortest decimal: 0.1 is exactly 1/10.
  const SceneNode tenth =
      parse_scene_json(R"({"type": "parametric", "x": "s", "y": "t", "z": "s*t", "domain": [[0.1, 1], [0, 1e-3]]})");
  EXPECT_EQ(tenth.leaf.domain[0].first, Rational(1) / Rational(10));
  EXPECT_EQ(tenth.leaf.domain[1].second, Rational(1) / Rational(1000));
}

TEST(SceneJson, DecodedScenesEvaluate) {
  const CompiledScene scene = compile_json(
      R"({"type": "union", "children": [
           {"type": "sphere", "radius": 1, "name": "ball", "uniforms": ["radius"]},
           {"type": "translate", "offset": [3, 0, 0], "child": {"type": "torus", "major": 1, "minor": 0.25}}]})");
  EXPECT_DOUBLE_EQ(scene.evaluate(Vec3<double>{0, 0, 0}), -1.0);
  EXPECT_DOUBLE_EQ(scene.evaluate(Vec3<double>{4, 0, 0}), -0.25);
  EXPECT_EQ(encode_scene_uniforms(scene.uniforms()), R"([{"name":"ball_radius","type":"float","default":1.0}])");
  const CompiledScene moved = compile_json(
      R"({"type": "translate", "offset": [3, 0, 0], "name": "m", "uniforms": ["offset"],
          "child": {"type": "sphere", "radius": 1}})");
  EXPECT_EQ(encode_scene_uniforms(moved.uniforms()), R"([{"name":"m_offset","type":"vec3","default":[3.0,0.0,0.0]}])");
}

TEST(SceneJson, TheDocumentedExamplesCompile) {
  // docs/api.md: the answer's uniforms, byte for byte.
  SceneParams options;
  options.mode = SdfMode::safe;
  options.name = "demo";
  const CompiledScene api = compile_scene(parse_scene_json(R"({"type": "smooth_union", "k": 0.2, "name": "blend",
      "uniforms": ["k"], "children": [{"type": "sphere", "radius": 1, "name": "ball", "uniforms": ["radius"]},
      {"type": "translate", "offset": [1.2, 0, 0], "child": {"type": "torus", "major": 0.8, "minor": 0.2}}]})"),
                                          options);
  EXPECT_EQ(encode_scene_uniforms(api.uniforms()),
            R"([{"name":"blend_k","type":"float","default":0.2},{"name":"ball_radius","type":"float","default":1.0}])");
  EXPECT_EQ(api.function_name(), "demo_sdf");
  EXPECT_EQ(api.root_class(), NodeClass::lipschitz);
  // docs/sdf.md, "Scenes", Format.
  const CompiledScene sdf = compile_json(R"({"type": "smooth_union", "k": 0.25, "name": "blend", "uniforms": ["k"],
   "children": [
     {"type": "translate", "offset": [1, 0, 0], "child": {"type": "sphere", "radius": 0.5}},
     {"type": "rotate", "axis": [1, 0, 0], "angle": 1.5707963, "child": {"type": "torus", "major": 1, "minor": 0.25}},
     {"type": "parametric", "x": "s", "y": "t", "z": "s*t", "domain": [[0, 1], [0, 1]]}]})");
  EXPECT_EQ(sdf.uniforms().size(), 1u);
  EXPECT_NE(sdf.to_glsl().find("s_leaf0_cover("), std::string::npos);
}

TEST(SceneJson, ErrorsCarryCodesAndJsonPaths) {
  EXPECT_EQ(failure(R"([1, 2])"), Failure("invalid_scene", "scene"));
  EXPECT_EQ(failure(R"({"radius": 1})"), Failure("invalid_scene", "scene.type"));
  EXPECT_EQ(failure(R"({"type": 3})"), Failure("invalid_scene", "scene.type"));
  EXPECT_EQ(failure(R"({"type": "spheroid", "radius": 1})"), Failure("unknown_node_type", "scene.type"));
  EXPECT_EQ(failure(R"({"type": "sphere"})"), Failure("missing_parameter", "scene.radius"));
  // A typo is an error, not a default.
  EXPECT_EQ(failure(R"({"type": "sphere", "raduis": 1})"), Failure("invalid_scene", "scene.raduis"));
  EXPECT_EQ(failure(R"({"type": "sphere", "radius": 1, "radius": 2})"), Failure("invalid_scene", "scene.radius"));
  EXPECT_EQ(failure(R"({"type": "sphere", "radius": "1"})"), Failure("invalid_value", "scene.radius"));
  EXPECT_EQ(failure(R"({"type": "sphere", "radius": -1})"), Failure("invalid_value", "scene.radius"));
  EXPECT_EQ(failure(R"({"type": "box", "size": [1, 2]})"), Failure("invalid_value", "scene.size"));
  EXPECT_EQ(failure(R"({"type": "box", "size": [1, 2, "3"]})"), Failure("invalid_value", "scene.size[2]"));
  EXPECT_EQ(failure(R"({"type": "smooth_union", "k": 1, "n": 2.5, "children": [
                         {"type": "sphere", "radius": 1}, {"type": "sphere", "radius": 2}]})"),
            Failure("invalid_value", "scene.n"));
  EXPECT_EQ(failure(R"({"type": "union"})"), Failure("missing_parameter", "scene.children"));
  EXPECT_EQ(failure(R"({"type": "union", "children": {"type": "sphere", "radius": 1}})"),
            Failure("invalid_scene", "scene.children"));
  EXPECT_EQ(failure(R"({"type": "translate", "offset": [0, 0, 0]})"), Failure("missing_parameter", "scene.child"));
  EXPECT_EQ(failure(R"({"type": "translate", "offset": [0, 0, 0], "children": []})"),
            Failure("invalid_scene", "scene.children"));
  EXPECT_EQ(failure(R"({"type": "sphere", "radius": 1, "child": {"type": "sphere", "radius": 1}})"),
            Failure("invalid_scene", "scene.child"));
  EXPECT_EQ(failure(R"({"type": "union", "children": [{"type": "sphere", "radius": 1},
                        {"type": "translate", "offset": [0, 0, 0], "child": {"type": "sphere", "radius": 0}}]})"),
            Failure("invalid_value", "scene.children[1].child.radius"));
  EXPECT_EQ(failure(R"({"type": "implicit"})"), Failure("missing_parameter", "scene.equation"));
  EXPECT_EQ(failure(R"({"type": "implicit", "equation": "x^2+q"})"), Failure("unknown_variable", "scene.equation"));
  EXPECT_EQ(failure(R"({"type": "implicit", "equation": "x", "box": [0, 0, 0, 1, 1]})"),
            Failure("invalid_value", "scene.box"));
  EXPECT_EQ(failure(R"({"type": "implicit", "equation": "x", "box": [0, 0, 0, 1, 1, "one"]})"),
            Failure("invalid_value", "scene.box[5]"));
  EXPECT_EQ(failure(R"({"type": "implicit", "equation": "x", "box": [0, 0, 0, 1, 1, -1]})"),
            Failure("invalid_box", "scene.box"));
  EXPECT_EQ(failure(R"({"type": "parametric", "x": "s", "y": "t"})"), Failure("missing_parameter", "scene.z"));
  // Every mistake in a domain is invalid_domain at its path (issue 18), found by the
  // decoder where it can be: the shape of the pairs, finite numbers, lo < hi.
  EXPECT_EQ(failure(R"({"type": "parametric", "x": "s", "y": "t", "z": "s*t", "domain": [[0, 1], [0]]})"),
            Failure("invalid_domain", "scene.domain[1]"));
  EXPECT_EQ(failure(R"({"type": "parametric", "x": "s", "y": "t", "z": "s*t", "domain": [[0, 1], [1, 0]]})"),
            Failure("invalid_domain", "scene.domain[1]"));
  EXPECT_EQ(failure(R"({"type": "parametric", "x": "s", "y": "t", "z": "s*t", "domain": [[0, 1], [1, 1]]})"),
            Failure("invalid_domain", "scene.domain[1]"));
  EXPECT_EQ(failure(R"({"type": "parametric", "x": "s", "y": "t", "z": "s*t", "domain": [[0, "inf"], [0, 1]]})"),
            Failure("invalid_domain", "scene.domain[0][1]"));
  EXPECT_EQ(failure(R"({"type": "parametric", "x": "s", "y": "t", "z": "s*t", "domain": [[0, 1], [0, true]]})"),
            Failure("invalid_domain", "scene.domain[1][1]"));
  EXPECT_EQ(failure(R"({"type": "parametric", "x": "s", "y": "t", "z": "s*t", "domain": {"s": [0, 1]}})"),
            Failure("invalid_domain", "scene.domain"));
  // The count against the parameters is the leaf's check, still invalid_domain.
  EXPECT_EQ(failure(R"({"type": "parametric", "x": "s", "y": "t", "z": "s*t", "domain": [[0, 1]]})").first,
            "invalid_domain");
  EXPECT_EQ(failure(R"({"type": "implicit", "equation": "x", "shape": "hollow"})"),
            Failure("invalid_value", "scene.shape"));
  EXPECT_EQ(failure(R"({"type": "implicit", "equation": "x", "shape": 1})"), Failure("invalid_value", "scene.shape"));
  EXPECT_EQ(failure(R"({"type": "sphere", "radius": 1, "shape": "sheet"})"), Failure("invalid_scene", "scene.shape"));
  EXPECT_EQ(failure(R"({"type": "implicit", "equation": "x", "domain": [[0, 1]]})"),
            Failure("invalid_scene", "scene.domain"));
  EXPECT_EQ(failure(R"({"type": "sphere", "radius": 1, "uniforms": ["radius"]})"),
            Failure("invalid_scene", "scene.uniforms"));
  EXPECT_EQ(failure(R"({"type": "sphere", "radius": 1, "name": "b", "uniforms": "radius"})"),
            Failure("invalid_value", "scene.uniforms"));
  EXPECT_EQ(failure(R"({"type": "sphere", "radius": 1, "name": 7})"), Failure("invalid_name", "scene.name"));
  EXPECT_EQ(failure(R"({"type": "union", "children": [{"type": "sphere", "radius": 1, "name": "a"},
                        {"type": "sphere", "radius": 2, "name": "a"}]})"),
            Failure("name_collision", "scene.children[1].name"));
  // Safe mode: smooth over a polynomial leaf.
  EXPECT_EQ(failure(R"({"type": "smooth_union", "k": 0.2, "children": [{"type": "sphere", "radius": 1},
                        {"type": "implicit", "equation": "x^2+y^2+z^2-1"}]})",
                    SdfMode::safe),
            Failure("unsafe_operator", "scene"));
  EXPECT_EQ(failure(R"({"type": "smooth_union", "k": 0.2, "children": [{"type": "sphere", "radius": 1},
                        {"type": "implicit", "equation": "x^2+y^2+z^2-1"}]})"),
            Failure("", ""));
  EXPECT_EQ(failure(R"({"type": "sphere", "radius": 1)"), Failure("invalid_json", ""));
}

TEST(SceneJson, InjectionAttemptsAreRefused) {
  // Names and uniforms reach the GLSL only as validated identifiers.
  EXPECT_EQ(failure(R"({"type": "sphere", "radius": 1, "name": "a; } void main(){"})"),
            Failure("invalid_name", "scene.name"));
  EXPECT_EQ(failure(R"({"type": "sphere", "radius": 1, "name": "gl_X"})"), Failure("invalid_name", "scene.name"));
  EXPECT_EQ(failure(R"({"type": "sphere", "radius": 1, "name": "x__y"})"), Failure("invalid_name", "scene.name"));
  EXPECT_EQ(failure(R"({"type": "sphere", "radius": 1, "name": "return"})"), Failure("invalid_name", "scene.name"));
  EXPECT_EQ(failure(R"({"type": "sphere", "radius": 1, "name": "a\nuniform"})"), Failure("invalid_name", "scene.name"));
  // The uniform list names parameters, not identifiers: anything else is refused.
  EXPECT_EQ(failure(R"({"type": "sphere", "radius": 1, "name": "a", "uniforms": ["radius; discard"]})"),
            Failure("invalid_value", "scene.uniforms[0]"));
  EXPECT_EQ(failure(R"({"type": "sphere", "radius": 1, "name": "a", "uniforms": ["gl_X"]})"),
            Failure("invalid_value", "scene.uniforms[0]"));
  // A node name that would make reserved identifiers (gl_radius, gl_sdf) is refused
  // as a name, before any identifier is derived from it (issue 16).
  EXPECT_EQ(failure(R"({"type": "sphere", "radius": 1, "name": "gl", "uniforms": ["radius"]})"),
            Failure("invalid_name", "scene.name"));
  // Equations are parsed into polynomials; their text never reaches the GLSL.
  EXPECT_EQ(failure(R"({"type": "implicit", "equation": "x); } void main() { (x"})").first, "unexpected_token");
}

TEST(SceneJson, SizeLimits) {
  // 300 children: too many nodes.
  std::string many = R"({"type": "union", "children": [)";
  for (int i = 0; i < 300; ++i) many += std::string(i ? "," : "") + R"({"type": "sphere", "radius": 1})";
  many += "]}";
  EXPECT_EQ(failure(many).first, "scene_too_large");
  // 70 nested translates: too deep (caught while reading, at level 65).
  std::string deep;
  for (int i = 0; i < 70; ++i) deep += R"({"type": "translate", "offset": [0, 0, 0], "child": )";
  deep += R"({"type": "sphere", "radius": 1})" + std::string(70, '}');
  const Failure f = failure(deep);
  EXPECT_EQ(f.first, "scene_too_large");
  EXPECT_EQ(f.second.size(), std::string("scene").size() + 64 * std::string(".child").size());
  // Nesting beyond any legal scene is refused before parsing.
  EXPECT_EQ(failure(std::string(10000, '[') + std::string(10000, ']')).first, "json_too_deep");
}

// encode_scene is the server's cache key: it must read back as the same scene, and
// two spellings of one scene (key order, 0.5 vs "1/2" in a box) must give one text.
TEST(SceneJson, EncodeSceneIsCanonicalAndReadsBack) {
  const std::string a = R"({"type": "union", "children": [
    {"type": "round_box", "radius": 0.1, "size": [1, 2, 3], "name": "b", "uniforms": ["radius"]},
    {"type": "parametric", "x": "s", "y": "t", "z": "s*t", "parameters": ["s", "t"],
     "domain": [[0, "1/3"], [-1, 1]], "box": [-2, -2, -2, 2, 2, 0.5], "shape": "sheet"},
    {"type": "rotate", "angle": 0.7, "axis": [0, 0, 1], "child": {"type": "implicit", "equation": "x^2+y^2-z"}}]})";
  const std::string b = R"({"children": [
    {"size": [1, 2, 3], "uniforms": ["radius"], "name": "b", "radius": 0.1, "type": "round_box"},
    {"domain": [["0", "2/6"], [-1, 1.0]], "type": "parametric", "parameters": ["s", "t"], "z": "s*t", "y": "t",
     "x": "s", "shape": "sheet", "box": [-2, -2, -2, 2, 2, "1/2"]},
    {"child": {"equation": "x^2+y^2-z", "type": "implicit", "shape": "auto"}, "axis": [0, 0, 1], "type": "rotate",
     "angle": 0.7}],
    "type": "union"})";
  const std::string text = encode_scene(parse_scene_json(a));
  EXPECT_EQ(text, encode_scene(parse_scene_json(b)));
  EXPECT_EQ(encode_scene(parse_scene_json(text)), text);
  EXPECT_NE(text.find(R"("domain":[["0","1/3"],["-1","1"]])"), std::string::npos) << text;
  // The shape is part of the key; auto, the default, is left out.
  EXPECT_NE(text.find(R"("shape":"sheet")"), std::string::npos) << text;
  EXPECT_EQ(text.find(R"("shape":"auto")"), std::string::npos) << text;
  // A different value is a different text.
  std::string c = a;
  c.replace(c.find("0.7"), 3, "0.8");
  EXPECT_NE(encode_scene(parse_scene_json(c)), text);
  std::string d = a;
  d.replace(d.find("sheet"), 5, "solid");
  EXPECT_NE(encode_scene(parse_scene_json(d)), text);
}

// A parametric leaf's tolerance is read, kept in the key at full precision, and one
// that is not a number is refused by name.
TEST(SceneJson, LeafToleranceIsReadAndPartOfTheKey) {
  const std::string a = R"({"type": "parametric", "x": "s", "y": "t", "z": "s*t", "domain": [[0, 1], [0, 1]],
                            "tolerance": 0.001})";
  const SceneNode node = parse_scene_json(a);
  EXPECT_EQ(node.leaf.tolerance, 0.001);
  const std::string text = encode_scene(node);
  EXPECT_NE(text.find(R"("tolerance":0.001)"), std::string::npos) << text;
  EXPECT_EQ(encode_scene(parse_scene_json(text)), text);
  std::string b = a;
  b.replace(b.find("0.001"), 5, "0.0010000000000000002");
  EXPECT_NE(encode_scene(parse_scene_json(b)), text);
  const std::string none = R"({"type": "parametric", "x": "s", "y": "t", "z": "s*t"})";
  EXPECT_EQ(encode_scene(parse_scene_json(none)).find("tolerance"), std::string::npos);
  try {
    parse_scene_json(R"({"type": "union", "children": [{"type": "sphere", "radius": 1},
                       {"type": "parametric", "x": "s", "y": "t", "z": "s*t", "tolerance": "small"}]})");
    ADD_FAILURE() << "a tolerance that is not a number was read";
  } catch (const InputError& e) {
    EXPECT_EQ(e.code(), "invalid_tolerance");
    EXPECT_EQ(e.field(), "scene.children[1].tolerance");
  }
}

}  // namespace
}  // namespace implicitizer
