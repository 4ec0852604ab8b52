#pragma once
/// \file
/// The members `POST /v1/sdf` and `POST /v1/render` share (private to codec/): the
/// object (`implicit`, `x`/`y`/`z` with `parameters`, or `scene`), `shape`, `domain`,
/// `tolerance`, `mode`, `box` and `name`, read into a SceneRequest (scene_request.hpp).

#include <optional>
#include <string>

#include "implicitizer/service/scene_request.hpp"
#include "json_reader.hpp"
#include "json_writer.hpp"

namespace implicitizer::json {

/// The members read_scene_request() takes, for ObjectReader::finish()'s list.
inline constexpr const char* kSceneRequestFields =
    "implicit, x, y, z, parameters, scene, shape, domain, tolerance, mode, box, name";

/// The enumerated members, parsed after the body's shape was checked (json_params.hpp).
struct SceneRequestChoices {
  std::optional<std::string> mode, shape;

  /// Parses them into `request`; throws InputError `invalid_value` ("mode": neither
  /// fast nor safe; "shape": not auto, sheet or solid).
  void apply(SceneRequest& request) const;
};

/// `"approximation": {"tolerance", "exact", "reason"?, "degree", "pieces", "glsl_lines",
/// "patch_to_surface": {"bound", "method"}, "surface_to_patch": {"bound", "method",
/// "samples"?}}` (a member of the answers of /v1/sdf and /v1/render; bounds relative to
/// the patch box's diagonal, at full precision; samples when measured).
void write_approximation(Writer& w, const ApproximationSummary& summary);

/// Takes the shared members from `reader` into `request`. Throws InputError:
/// `invalid_value` ("scene": more than one object; "z": an empty z, which would read
/// as a plane curve), `missing_field` ("implicit": no object; "x" or "y": a
/// parametrization without it), `wrong_type`, the scene's errors ("scene.…"), and
/// `invalid_domain` ("domain": not an array; "domain[i]": an entry that is neither a
/// JSON number nor a string), `invalid_tolerance` ("tolerance": not a number). Counts and values (a domain's lo < hi,
/// the box's six numbers) are the service's to check.
SceneRequestChoices read_scene_request(ObjectReader& reader, SceneRequest& request);

}  // namespace implicitizer::json
