#pragma once
/// \file
/// The contract's error bodies, `{"error": {"code", "message", ...}}`: what every
/// endpoint answers when it refuses, and what the command line prints with `--json`.

#include <string>
#include <string_view>

#include "implicitizer/approximation/patch_approximation.hpp"
#include "implicitizer/core/errors.hpp"

namespace implicitizer {

/// `{"error": {"code", "message", "position"?, "field"?}}`: position when the error
/// has one, field when it is not empty.
std::string encode_error(const InputError& error);

/// `{"error": {"code": "no_single_equation", "message", "generators": [..]}}`.
std::string encode_error(const NoSingleEquation& error);

/// `{"error": {"code": "tolerance_not_met", "message", "best_bound"}}`: best_bound is
/// the smallest two-sided bound reached, relative to the patch box's diagonal.
std::string encode_error(const ToleranceNotMet& error);

/// `{"error": {"code", "message", "limit"}}` with code `time_limit_exceeded`,
/// `size_limit_exceeded` or `cancelled` and limit `time`, `size` or `cancelled`.
std::string encode_error(const LimitExceeded& error);

/// `{"error": {"code", "message"}}` for errors of no library type (`internal_error`,
/// `not_found`, ...).
std::string encode_error(std::string_view code, std::string_view message);

/// The `code` encode_error() writes for `limit`: `time_limit_exceeded`,
/// `size_limit_exceeded` or `cancelled`.
const char* limit_error_code(Limit limit);

}  // namespace implicitizer
