#pragma once
/// \file
/// A scene embedded in a request body (private to codec/: RapidJSON stays out of the
/// public headers). scene_json.hpp describes the form and its errors.

#include <rapidjson/document.h>

#include <string>

#include "implicitizer/scene/scene_node.hpp"

namespace implicitizer {

/// Reads the scene node `value` found at JSON path `path` (e.g. "scene"). Throws
/// InputError as scene_json.hpp describes.
SceneNode decode_scene(const rapidjson::Value& value, const std::string& path);

}  // namespace implicitizer
