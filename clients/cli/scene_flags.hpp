#pragma once
/// \file
/// The flags `sdf` and `render` share: the object (`--implicit E`, `--x E --y E
/// [--z E] [--params s,t]`, or `--scene FILE.json`), `--shape`, `--domain`, `--mode`,
/// `--box`, `--name` and `--tolerance`, read into a SceneRequest (scene_request.hpp), the same
/// fields POST /v1/sdf and /v1/render read from JSON.

#include <initializer_list>
#include <optional>
#include <string>
#include <vector>

#include "arguments.hpp"
#include "error_report.hpp"
#include "implicitizer/service/scene_request.hpp"

namespace implicitizer::cli {

/// The shared options followed by a command's `own`, its option table.
std::vector<OptionSpec> with_scene_options(std::initializer_list<OptionSpec> own);

/// Reads the shared flags into `request`; returns the `--scene` file's contents (its
/// JSON is parsed later: its errors are invalid input, status 3). Throws UsageError
/// (status 2) for no object or more than one, `--z` without `--x --y`, `--params`
/// without them, an unreadable scene file, and a `--mode` or `--shape` outside its
/// list (with `json`, that error's JSON is printed too, as read_choice() does).
/// Values (`--domain`, `--box`, `--tolerance`) are the service's to check (status 3).
std::optional<std::string> read_scene_flags(const Arguments& arguments, bool json, SceneRequest& request);

/// The texts behind the request's fields ("implicit", "x", …, "scene"), for the caret
/// under an error.
void note_scene_field_texts(const SceneRequest& request, const std::optional<std::string>& scene_text,
                            ErrorReport& report);

}  // namespace implicitizer::cli
