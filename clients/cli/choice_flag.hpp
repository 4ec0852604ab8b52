#pragma once
/// \file
/// A flag whose value is one of a list (`--method`, `--order`, `--mode`,
/// `--precision`), read by the library's own parser of that choice: the one the
/// endpoint's decoder calls, so the command line and the server accept the same names.

#include <iostream>
#include <optional>
#include <string>

#include "arguments.hpp"
#include "implicitizer/codec/error_json.hpp"
#include "implicitizer/core/errors.hpp"

namespace implicitizer::cli {

/// `parse(value)` of `--flag`, or nullopt when the flag is absent. A value `parse`
/// refuses is a usage error (status 2) before anything is computed: `unknown --FLAG
/// value: ` and the parser's message; with `json`, the parser's error is also printed
/// on stdout as the endpoint answers it (field FLAG).
template <typename Parse>
auto read_choice(const Arguments& arguments, const char* flag, Parse parse, bool json)
    -> std::optional<decltype(parse(std::string()))> {
  const std::optional<std::string> value = arguments.value(flag);
  if (!value) return std::nullopt;
  try {
    return parse(*value);
  } catch (const InputError& e) {
    if (json) std::cout << encode_error(e.in_field(flag)) << '\n';
    throw UsageError(std::string("unknown --") + flag + " value: " + e.what());
  }
}

}  // namespace implicitizer::cli
