#include "point_list.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>

#include "arguments.hpp"
#include "implicitizer/core/errors.hpp"

namespace implicitizer::cli {
namespace {

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

}  // namespace

std::vector<std::array<double, 3>> parse_point_list(const std::string& text, int dimension) {
  std::vector<std::array<double, 3>> points;
  std::istringstream lines(text);
  std::string line;
  for (std::size_t number = 1; std::getline(lines, line); ++number) {
    line = line.substr(0, line.find('#'));
    std::istringstream tokens(line);
    std::vector<std::string> words;
    for (std::string w; tokens >> w;) words.push_back(w);
    if (words.empty()) continue;
    if (words.size() != static_cast<std::size_t>(dimension)) {
      throw invalid_point(number, "a point is " + std::string(dimension == 2 ? "x y (a plane curve)" : "x y z") +
                                      ", not " + std::to_string(words.size()) + " numbers");
    }
    std::array<double, 3> p{};
    for (std::size_t i = 0; i < words.size(); ++i) p[i] = parse_coordinate(words[i], number);
    points.push_back(p);
  }
  return points;
}

std::string read_point_file(const std::string& path) {
  std::ostringstream text;
  if (path == "-") {
    text << std::cin.rdbuf();
    if (std::cin.bad()) throw UsageError("cannot read the points from standard input");
    return text.str();
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw UsageError("cannot read point file '" + path + "'");
  text << in.rdbuf();
  if (in.bad()) throw UsageError("cannot read point file '" + path + "'");
  return text.str();
}

}  // namespace implicitizer::cli
