#include "point_list.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>

#include "arguments.hpp"
#include "implicitizer/core/errors.hpp"

namespace implicitizer::cli {
namespace {

// No number strtod reads needs more characters; a longer token is refused rather
// than kept, so that a line of one huge word costs no memory.
constexpr std::size_t kMaxTokenLength = 1024;

InputError invalid_point(std::size_t line, const std::string& message) {
  return InputError("invalid_point", "line " + std::to_string(line) + ": " + message).in_field("eval");
}

// One coordinate: the whole token is a finite number.
double parse_coordinate(const std::string& token, std::size_t line) {
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(token.c_str(), &end);
  if (end == token.c_str() || *end != '\0' || errno == ERANGE || !std::isfinite(value)) {
    throw invalid_point(line, "'" + token + "' is not a finite number");
  }
  return value;
}

bool is_blank(int c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

}  // namespace

PointListReader::PointListReader(std::istream& in, int dimension) : buffer_(in.rdbuf()), dimension_(dimension) {}

bool PointListReader::read_token() {
  token_.clear();
  constexpr int kEnd = std::char_traits<char>::eof();
  int c = buffer_->sgetc();
  while (is_blank(c)) c = buffer_->snextc();
  if (c == kEnd) {
    ended_ = true;
    return false;
  }
  if (c == '#') {
    while (c != '\n' && c != kEnd) c = buffer_->snextc();
    if (c == kEnd) ended_ = true;
  }
  if (c == '\n' || c == kEnd) {
    if (c == '\n') buffer_->sbumpc();
    else ended_ = true;
    return false;
  }
  while (c != kEnd && c != '\n' && c != '#' && !is_blank(c)) {
    if (token_.size() == kMaxTokenLength) {
      throw invalid_point(line_, "a token of more than " + std::to_string(kMaxTokenLength) +
                                     " characters is not a number");
    }
    token_.push_back(static_cast<char>(c));
    c = buffer_->snextc();
  }
  return true;
}

std::size_t PointListReader::count_rest_of_line() {
  constexpr int kEnd = std::char_traits<char>::eof();
  std::size_t count = 0;
  bool in_token = false;
  for (int c = buffer_->sgetc();; c = buffer_->snextc()) {
    if (c == kEnd || c == '\n' || c == '#') break;
    const bool blank = is_blank(c);
    if (!blank && !in_token) ++count;
    in_token = !blank;
  }
  return count;
}

std::optional<std::array<double, 3>> PointListReader::next() {
  while (!ended_) {
    ++line_;
    std::array<double, 3> point{};
    int count = 0;
    while (read_token()) {
      if (count == dimension_) {
        const std::size_t total = static_cast<std::size_t>(count) + 1 + count_rest_of_line();
        throw invalid_point(line_, "a point is " + std::string(dimension_ == 2 ? "x y (a plane curve)" : "x y z") +
                                       ", not " + std::to_string(total) + " numbers");
      }
      point[count++] = parse_coordinate(token_, line_);
    }
    if (count == 0) {
      if (ended_) --line_;  // the stream ended on this (empty) line
      continue;
    }
    if (count != dimension_) {
      throw invalid_point(line_, "a point is " + std::string(dimension_ == 2 ? "x y (a plane curve)" : "x y z") +
                                     ", not " + std::to_string(count) + " numbers");
    }
    return point;
  }
  return std::nullopt;
}

std::ifstream open_point_file(const std::string& path) {
  std::error_code ignored;
  std::ifstream in(path, std::ios::binary);
  if (!in || std::filesystem::is_directory(path, ignored)) throw UsageError("cannot read point file '" + path + "'");
  return in;
}

}  // namespace implicitizer::cli
