#pragma once
/// \file
/// The flags both computing commands share: `--strategy`, `--criteria`,
/// `--max-terms` (Buchberger's parameters and the size limit) and `--timeout`.

#include <optional>

#include "arguments.hpp"
#include "implicitizer/core/budget.hpp"
#include "implicitizer/groebner/buchberger.hpp"

namespace implicitizer::cli {

/// The option specs of the shared flags, to append to a command's own.
inline constexpr OptionSpec kBuchbergerOptions[] = {
    {"strategy", true}, {"criteria", true}, {"max-terms", true}, {"max-memory", true}, {"timeout", true}};

/// How Buchberger's algorithm runs, from the shared flags. Defaults are the
/// library's: automatic strategy, product criterion plus Gebauer–Möller's chain
/// criterion. Throws UsageError for a value outside its list.
///   --strategy auto|normal|sugar
///   --criteria gm (product + Gebauer–Möller) | seed (product + Buchberger's chain
///              criterion, Theorem 1.6 of the seed thesis) | product | none
BuchbergerVariant buchberger_variant_from(const Arguments& arguments);

/// The budget of the size flags (none by default):
///   --max-terms N   largest number of terms of any intermediate polynomial (0 = none)
///   --max-memory SIZE  memory the computation may hold (parse_memory_size)
/// The timeout is not set here: it travels in the request (see timeout_from()).
Budget budget_from(const Arguments& arguments);

/// The `--timeout` in seconds, if given (none by default: the command line waits).
/// Throws UsageError unless it is a positive finite number.
std::optional<double> timeout_from(const Arguments& arguments);

}  // namespace implicitizer::cli
