#pragma once
/// \file
/// The JSON form of a scene (docs/sdf.md, "Scenes"): a tree of objects
///     {"type": KIND, PARAMETER: number | [x, y, z], ..., "name": N?, "uniforms": [P..]?,
///      "children": [NODE, NODE, ...] (union, intersection, difference, smooth_*)
///      | "child": NODE (translate, rotate, scale, ...)}
/// with the leaves implicit {"equation": F, "shape": S?, "box": [x0, y0, z0, x1, y1, z1]?}
/// and parametric {"x": X, "y": Y, "z": Z, "parameters": [..]?, "domain": [[lo, hi], ..]?,
/// "shape": S?, "box": [..]?} (box and domain bounds: numbers or exact strings like
/// "1/3"; S is "auto", the default, "sheet" or "solid": sdf_shape.hpp).
/// The numeric parameters of each kind are read from the kind table (scene_node.hpp),
/// so a new kind needs no code here unless it has non-numeric fields.
///
/// Strict like the rest of the codec: unknown keys and keys given twice are refused
/// (a misspelt "raduis" must not fall back to a default). Errors are InputError
/// with the JSON path as field ("scene.children[1].radius"): `invalid_scene` (not
/// an object, unknown or repeated key, missing "type", children where none belong),
/// `unknown_node_type`, `missing_parameter`, `invalid_value` (wrong JSON type or
/// length; a shape outside its list), `invalid_domain` (a domain that is not an array
/// of [lo, hi] pairs of finite numbers with lo < hi, at "….domain[1]"; the count
/// against the parameters is the leaf's check), `invalid_name` (a name that is not a string), `scene_too_large`
/// (more than kMaxSceneNodes nodes or kMaxSceneDepth levels; checked while reading,
/// so no input recurses deeper). compile_scene() checks the rest (ranges, names,
/// uniforms, safety).
///
/// Entry points for the server and the command line:
///     SceneNode root = parse_scene_json(text);                      // a whole JSON text
///     CompiledScene scene = compile_scene(root, options, budget);
///     std::string uniforms = encode_scene_uniforms(scene.uniforms());        // for the response
/// (the request decoders read a scene embedded in a body with the same rules, through
/// the codec's private scene_value.hpp).

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "implicitizer/scene/compiled_scene.hpp"
#include "implicitizer/scene/scene_node.hpp"

namespace implicitizer {

/// The deepest JSON nesting a scene of kMaxSceneDepth levels needs: an object and a
/// "children" array per level, plus the innermost parameter arrays (domain pairs).
/// A request decoder that embeds a scene must allow at least this much nesting.
inline constexpr std::size_t kMaxSceneJsonDepth = 2 * kMaxSceneDepth + 4;

/// Parses `text` (one JSON object, the scene's root node) and decodes it with path
/// `path` (errors name "scene.children[1].radius"). Throws InputError `invalid_json`
/// (with the byte offset), `json_too_deep` (nesting beyond kMaxSceneJsonDepth,
/// refused before parsing), and those described in the file comment.
SceneNode parse_scene_json(std::string_view text, const std::string& path = "scene");

/// `root` as compact JSON in a canonical form: keys in a fixed order (parameters
/// sorted by name), numbers as the shortest decimal that reads back as the same
/// double, exact numbers (boxes, domains) as exact strings ("1/3"). Decoding it gives
/// `root` back; equal scenes give equal texts (the server's cache key).
std::string encode_scene(const SceneNode& root);

/// `uniforms` (CompiledScene::uniforms()) as a compact JSON array:
/// `[{"name": "ball_radius", "type": "float", "default": 1.5}, {"name": ..., "type":
/// "vec3", "default": [x, y, z]}]`, in declaration order.
std::string encode_scene_uniforms(const std::vector<SceneUniform>& uniforms);

}  // namespace implicitizer
