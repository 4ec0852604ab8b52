#pragma once
/// \file
/// The points of `implicitizer sdf --eval FILE`: one point per line, `x y z` (or `x y`
/// for a plane curve), numbers separated by spaces or tabs; blank lines and `#`
/// comments (to the end of the line) are skipped. Read as a stream: whatever the
/// file's size or the length of its lines, the reader holds one number's text.

#include <array>
#include <cstddef>
#include <fstream>
#include <istream>
#include <optional>
#include <string>

namespace implicitizer::cli {

/// Reads the points of a point list one at a time from `in` (which must outlive it),
/// each with `dimension` (2 or 3) coordinates (z = 0 for a curve).
class PointListReader {
 public:
  PointListReader(std::istream& in, int dimension);

  /// The next point, or nullopt after the last. Throws InputError `invalid_point`
  /// (field "eval", status 3, like a scene file's JSON errors) naming the line
  /// number: a token that is not a finite number (strtod's syntax: `1`, `-0.5`,
  /// `1e-3`; not `inf`, `nan`, `1/2`), or a line with another count of numbers.
  std::optional<std::array<double, 3>> next();

  /// Lines read so far (the line of the last point returned, or the last line).
  std::size_t line() const { return line_; }

 private:
  // Reads the next token of the current line into token_; false at the line's end
  // (the line's newline or comment is consumed then, or the stream has ended).
  bool read_token();
  // Skips the rest of the current line, counting its tokens (without keeping them).
  std::size_t count_rest_of_line();

  std::streambuf* buffer_;
  int dimension_;
  std::size_t line_ = 0;
  bool ended_ = false;
  std::string token_;
};

/// Opens the point file `path` for reading. Throws UsageError (status 2) when it
/// cannot be opened or is a directory. ("-", standard input, is the caller's.)
std::ifstream open_point_file(const std::string& path);

}  // namespace implicitizer::cli
