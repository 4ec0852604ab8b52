#pragma once
/// \file
/// The points of `implicitizer sdf --eval FILE`: one point per line, `x y z` (or `x y`
/// for a plane curve), numbers separated by spaces or tabs; blank lines and `#`
/// comments (to the end of the line) are skipped.

#include <array>
#include <string>
#include <vector>

namespace implicitizer::cli {

/// The points of `text`, each with `dimension` (2 or 3) coordinates (z = 0 for a
/// curve). Throws InputError `invalid_point` (field "eval", status 3, like a scene
/// file's JSON errors) naming the line number: a token that is not a finite number
/// (strtod's syntax: `1`, `-0.5`, `1e-3`; not `inf`, `nan`, `1/2`), or a line with
/// another count of numbers.
std::vector<std::array<double, 3>> parse_point_list(const std::string& text, int dimension);

/// The text of `path`, or of standard input for "-". Throws UsageError (status 2)
/// when it cannot be read.
std::string read_point_file(const std::string& path);

}  // namespace implicitizer::cli
