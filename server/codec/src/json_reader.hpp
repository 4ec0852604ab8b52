#pragma once
/// \file
/// What every request decoder of the codec reads with (private to codec/): the body
/// as a RapidJSON object, a reader that takes each member once and refuses the rest,
/// and the readers of the contract's value types, each naming its field in errors.

#include <rapidjson/document.h>

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "implicitizer/codec/json_params.hpp"
#include "implicitizer/core/errors.hpp"

namespace implicitizer::json {

/// `text` parsed as one JSON value, after the nesting guard (check_json_depth with
/// `max_depth`). Throws InputError `json_too_deep` or `invalid_json` (at the byte
/// offset of the syntax error).
rapidjson::Document parse_json(std::string_view text, std::size_t max_depth);

/// `body` parsed as one JSON object, after the nesting guard. Throws InputError
/// `json_too_deep`, `invalid_json` (at the byte offset of the syntax error) or
/// `wrong_type` (not an object).
rapidjson::Document parse_object(std::string_view body, const JsonParams& limits);

/// Walks the members of a request object: each field is taken at most once, and
/// whatever was not taken at the end is an unknown field.
class ObjectReader {
 public:
  /// Throws InputError `duplicate_field` for a member given twice.
  explicit ObjectReader(const rapidjson::Value& object);

  /// The member `name`, or nullptr when absent.
  const rapidjson::Value* take(const char* name);

  /// The member `name`; throws InputError `missing_field` when absent.
  const rapidjson::Value& require(const char* name);

  /// Throws `unknown_field` for the first member never taken, listing `allowed`.
  void finish(const char* allowed) const;

 private:
  const rapidjson::Value& object_;
  std::vector<std::string> names_;
  std::vector<bool> taken_;
};

/// InputError `wrong_type`: "'field' must be `expected`".
InputError wrong_type(const std::string& field, const char* expected);

/// A string member; throws `wrong_type` otherwise.
std::string read_string(const rapidjson::Value& v, const std::string& field);

/// An array of strings; throws `wrong_type` naming the array or the element ("parameters[1]").
std::vector<std::string> read_strings(const rapidjson::Value& v, const std::string& field);

/// An array of integers; throws `wrong_type` naming the array or the element.
std::vector<int> read_ints(const rapidjson::Value& v, const std::string& field);

/// `timeout_ms` in seconds: a non-negative finite number of milliseconds (0: no
/// limit). Throws `wrong_type` or `invalid_value`.
double read_timeout_seconds(const rapidjson::Value& v);

/// A tolerance (a fraction of a patch box's diagonal): a JSON number, passed on as
/// is; its range is the leaf's to check (polynomial_leaf.hpp). Throws
/// `invalid_tolerance` at `field` for anything but a number.
double read_tolerance(const rapidjson::Value& v, const std::string& field);

/// A scene box: six JSON numbers, passed on as the exact decimal value of each double
/// (17 significant digits round-trip; the SDF frame reads it as an exact rational).
/// The count is the service's to check (parse_request_box).
std::vector<std::string> read_box_texts(const rapidjson::Value& v);

/// `parse(text)`: the typed value of an enumerated field (the library's parser of that
/// choice), its InputError naming `field`.
template <typename Parse>
auto parse_choice(const std::string& text, const char* field, Parse parse) -> decltype(parse(text)) {
  try {
    return parse(text);
  } catch (const InputError& e) {
    throw e.in_field(field);
  }
}

/// The nesting a body that may embed a scene needs: the deepest scene the scene
/// decoder accepts (kMaxSceneJsonDepth), whatever the caller's limit.
JsonParams with_room_for_a_scene(const JsonParams& limits);

}  // namespace implicitizer::json
