#pragma once
/// \file
/// The command-line pieces the accuracy benches share: flags read one by one, counts
/// in a range, comma-separated lists. Errors are InputError `invalid_argument` with
/// the flag as the field, which each bench prints beside its usage.

#include <functional>
#include <string>
#include <vector>

namespace implicitizer::bench {

/// Walks argv: `while (flags.next())` then flag() and, for flags with a value, value().
class FlagReader {
 public:
  FlagReader(int argc, char** argv) : argc_(argc), argv_(argv) {}
  /// Moves to the next flag; false after the last.
  bool next() {
    if (++index_ >= argc_) return false;
    flag_ = argv_[index_];
    return true;
  }
  /// The current flag.
  const std::string& flag() const { return flag_; }
  /// The argument after the flag (consumed). Throws when there is none.
  std::string value();

 private:
  int argc_;
  char** argv_;
  int index_ = 0;
  std::string flag_;
};

/// A whole number in [low, high] from `text`; InputError `invalid_argument` naming `flag` otherwise.
long parse_count(const std::string& flag, const std::string& text, long low, long high);

/// The non-empty parts of `text` between commas.
std::vector<std::string> split_commas(const std::string& text);

/// What a bench's main() does around its work: returns `run()`'s status; on an
/// InputError prints "PROGRAM: FIELD: message" and the usage and returns 2 (a bad
/// command line); on any other exception prints it and returns 1.
int run_bench(const char* program, const char* usage, const std::function<int()>& run);

}  // namespace implicitizer::bench
