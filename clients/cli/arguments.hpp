#pragma once
/// \file
/// The command line's argument syntax, small on purpose: `--name value`,
/// `--name=value`, switches (`--json`), and positional arguments. Only tokens that
/// start with `--` are options, so a polynomial such as `-x^2+y` is a positional
/// argument and `--x -s` gives x the value `-s`; `--` ends the options.

#include <cstddef>
#include <map>
#include <optional>
#include <set>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace implicitizer::cli {

/// A mistake in how the program was called (exit status 2): unknown command or
/// flag, missing or malformed flag value.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// One option a command accepts.
struct OptionSpec {
  const char* name;  ///< without the leading `--`
  bool takes_value;  ///< `--name VALUE` (true) or a switch (false)
};

/// The arguments of one command after parsing.
class Arguments {
 public:
  /// The value of `--name`, if it was given.
  std::optional<std::string> value(const std::string& name) const;
  /// Whether the switch or option `--name` was given.
  bool has(const std::string& name) const;
  /// The positional arguments, in order.
  const std::vector<std::string>& positionals() const { return positionals_; }

 private:
  friend Arguments parse_arguments(std::span<const std::string>, std::span<const OptionSpec>);
  std::map<std::string, std::string> values_;
  std::set<std::string> switches_;
  std::vector<std::string> positionals_;
};

/// Parses `args` (the words after the command name) against `spec`. Throws
/// UsageError for an unknown option, an option given twice, a switch given a value,
/// or a missing value (the end of the arguments, or a next word starting with `--`).
Arguments parse_arguments(std::span<const std::string> args, std::span<const OptionSpec> spec);

/// Splits a comma-separated list, trimming spaces: "s, t" → {"s", "t"}; "" → {}.
/// Throws UsageError naming `flag` for an empty item ("s,,t").
std::vector<std::string> split_list(const std::string& text, const char* flag);

/// The contents of the file at `path` (a `--scene FILE.json`). Throws UsageError when
/// it cannot be read: the command named the file, so that is a usage error (exit 2).
std::string read_text_file(const std::string& path);

/// A timeout in seconds: a finite number > 0 (decimals and `1e-3` allowed).
/// Throws UsageError naming `flag` otherwise.
double parse_seconds(const std::string& text, const char* flag);

/// A non-negative integer that fits std::size_t. Throws UsageError naming `flag` otherwise.
std::size_t parse_count(const std::string& text, const char* flag);

/// A memory size in bytes from `N` MiB, or `N` followed by K, M or G (KiB, MiB, GiB).
/// Throws UsageError naming `--flag` unless N is a positive integer and the size fits.
std::size_t parse_memory_size(const std::string& text, const char* flag);

/// An int (optionally negative). Throws UsageError naming `flag` otherwise.
int parse_int(const std::string& text, const char* flag);

}  // namespace implicitizer::cli
