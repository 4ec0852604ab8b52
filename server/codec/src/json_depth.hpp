#pragma once
/// \file
/// The nesting guard every JSON decoder of the codec runs before RapidJSON sees a
/// text: RapidJSON builds (and later destroys) documents recursively, so a body of a
/// million '[' would exhaust the stack of a worker thread.

#include <cstddef>
#include <string_view>

namespace implicitizer {

/// Throws InputError `json_too_deep` (at the byte offset of the bracket that goes
/// too deep) when arrays and objects in `text` nest deeper than `max_depth`.
/// Brackets inside strings (with their escapes) do not count. A text that is not
/// JSON is judged only roughly here; the parser reports it properly afterwards.
void check_json_depth(std::string_view text, std::size_t max_depth);

}  // namespace implicitizer
