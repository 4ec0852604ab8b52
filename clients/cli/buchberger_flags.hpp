#pragma once
/// \file
/// The flags both computing commands share: `--strategy`, `--criteria`,
/// `--max-terms` (Buchberger's parameters and the size limit) and `--timeout`.

#include <optional>

#include "arguments.hpp"
#include "implicitizer/groebner/buchberger.hpp"

namespace implicitizer::cli {

/// The option specs of the shared flags, to append to a command's own.
inline constexpr OptionSpec kBuchbergerOptions[] = {
    {"strategy", true}, {"criteria", true}, {"max-terms", true}, {"max-memory", true}, {"timeout", true}};

/// Buchberger's parameters from the shared flags. Defaults are the library's:
/// sugar strategy, product criterion plus Gebauer–Möller's chain criterion, no size
/// limit. Throws UsageError for a value outside its list.
///   --strategy normal|sugar
///   --criteria gm (product + Gebauer–Möller) | seed (product + Buchberger's chain
///              criterion, Theorem 1.6 of the seed thesis) | product | none
///   --max-terms N   largest number of terms of any intermediate polynomial (0 = none)
///   --max-memory SIZE  memory the computation may hold (parse_memory_size; none by default)
/// The timeout is not set here: it travels in the request (see timeout_from()).
BuchbergerParams buchberger_params_from(const Arguments& arguments);

/// The `--timeout` in seconds, if given (none by default: the command line waits).
/// Throws UsageError unless it is a positive finite number.
std::optional<double> timeout_from(const Arguments& arguments);

}  // namespace implicitizer::cli
