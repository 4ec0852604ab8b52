#include "command_line.hpp"

#include <iostream>
#include <sstream>

#include "implicitizer/core/errors.hpp"

namespace implicitizer::bench {

std::string FlagReader::value() {
  if (index_ + 1 >= argc_) throw InputError("invalid_argument", flag_ + " needs a value").in_field(flag_);
  return argv_[++index_];
}

long parse_count(const std::string& flag, const std::string& text, long low, long high) {
  try {
    std::size_t used = 0;
    const long value = std::stol(text, &used);
    if (used == text.size() && value >= low && value <= high) return value;
  } catch (const std::exception&) {
  }
  throw InputError("invalid_argument", flag + " needs a whole number in [" + std::to_string(low) + ", " +
                                           std::to_string(high) + "], not '" + text + "'")
      .in_field(flag);
}

std::vector<std::string> split_commas(const std::string& text) {
  std::vector<std::string> parts;
  std::istringstream in(text);
  for (std::string part; std::getline(in, part, ',');) {
    if (!part.empty()) parts.push_back(part);
  }
  return parts;
}

int run_bench(const char* program, const char* usage, const std::function<int()>& run) {
  try {
    return run();
  } catch (const InputError& e) {
    std::cerr << program << ": " << (e.field().empty() ? "" : e.field() + ": ") << e.what() << "\n\n" << usage;
    return 2;
  } catch (const std::exception& e) {
    std::cerr << program << ": " << e.what() << '\n';
    return 1;
  }
}

}  // namespace implicitizer::bench
