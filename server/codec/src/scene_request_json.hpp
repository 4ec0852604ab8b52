#pragma once
/// \file
/// The members `POST /v1/sdf` and `POST /v1/render` share (private to codec/): the
/// object (`implicit`, `x`/`y`/`z` with `parameters`, or `scene`), `shape`, `domain`,
/// `mode`, `box` and `name`, read into a SceneRequest (scene_request.hpp).

#include <optional>
#include <string>

#include "implicitizer/service/scene_request.hpp"
#include "json_reader.hpp"

namespace implicitizer::json {

/// The members read_scene_request() takes, for ObjectReader::finish()'s list.
inline constexpr const char* kSceneRequestFields =
    "implicit, x, y, z, parameters, scene, shape, domain, mode, box, name";

/// The enumerated members, parsed after the body's shape was checked (json_params.hpp).
struct SceneRequestChoices {
  std::optional<std::string> mode, shape;

  /// Parses them into `request`; throws InputError `invalid_value` ("mode": neither
  /// fast nor safe; "shape": not auto, sheet or solid).
  void apply(SceneRequest& request) const;
};

/// Takes the shared members from `reader` into `request`. Throws InputError:
/// `invalid_value` ("scene": more than one object; "z": an empty z, which would read
/// as a plane curve), `missing_field` ("implicit": no object; "x" or "y": a
/// parametrization without it), `wrong_type`, the scene's errors ("scene.…"), and
/// `invalid_domain` ("domain": not an array; "domain[i]": an entry that is neither a
/// JSON number nor a string). Counts and values (a domain's lo < hi, the box's six
/// numbers) are the service's to check.
SceneRequestChoices read_scene_request(ObjectReader& reader, SceneRequest& request);

}  // namespace implicitizer::json
