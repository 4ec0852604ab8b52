#pragma once
/// \file
/// GET (and HEAD) of the web client's files under the --static directory. The one
/// promise that matters: no request ever reads a file outside that directory.

#include <filesystem>
#include <optional>
#include <string_view>
#include <variant>

#include "handlers/handler.hpp"

namespace implicitizer::server {

/// Why a request target does not name a servable file.
enum class StaticPathError {
  invalid,    ///< not a clean relative path: `..`, encoded dots or slashes, NUL, backslash, bad %-escape
  not_found,  ///< no such regular file inside the root (symlinks leading outside count as absent)
};

/// The file `target` (an origin-form request target, query string allowed) names
/// under `root`, or the reason it names none. `/` and paths ending in `/` mean
/// `index.html` there. Percent-escapes are decoded once; a decoded `/`, `\`, NUL or
/// a `.`/`..` segment (literal or encoded) is refused as invalid, and the final file's
/// canonical path (all symlinks resolved) must lie inside the canonical root.
/// Touches the filesystem (stat and realpath) but reads no file.
std::variant<std::filesystem::path, StaticPathError> resolve_static_path(const std::filesystem::path& root,
                                                                         std::string_view target);

/// The Content-Type for a file name, by extension (`application/octet-stream` when unknown).
std::string_view content_type_for(const std::filesystem::path& file);

/// 200 with the file's bytes and its Content-Type; 400 `invalid_path`, 404
/// `not_found` (also when no static directory is configured or the file is larger
/// than ServerConfig::max_static_file_bytes).
Response handle_static_file(const Request& request, const HandlerContext& context);

}  // namespace implicitizer::server
