#pragma once
/// \file
/// The rules every request decoder of the codec follows, and its one limit.
///
/// Decoding is strict: the body must be one UTF-8 JSON object; unknown fields are
/// refused (`unknown_field`) rather than ignored, so that a misspelt optional field
/// (`"timeout"` for `"timeout_ms"`) cannot silently fall back to a default, and a
/// field given twice is refused (`duplicate_field`). Nesting deeper than
/// JsonParams::max_depth is refused before parsing, so no input can exhaust the stack.
/// The body's shape is checked first (types, required and unknown fields), then the
/// values of its enumerated fields (method, order, mode, ...) are parsed into the
/// typed request, with the library's errors (`unknown_method`, `invalid_value`) and
/// the field's name.
///
/// Encoding writes compact JSON (no spaces, no trailing newline) with keys in the
/// order the contract lists them; times in milliseconds with at most 3 decimals.

#include <cstddef>

namespace implicitizer {

/// Limits of the decoders.
struct JsonParams {
  std::size_t max_depth = 32;  ///< deepest nesting of arrays and objects
};

}  // namespace implicitizer
