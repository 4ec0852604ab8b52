#include "json_reader.hpp"

#include <rapidjson/error/en.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "implicitizer/codec/scene_json.hpp"
#include "json_depth.hpp"

namespace implicitizer::json {

rapidjson::Document parse_json(std::string_view text, std::size_t max_depth) {
  check_json_depth(text, max_depth);
  rapidjson::Document document;
  // Iterative parsing: no recursion whatever the input; invalid UTF-8 is a syntax
  // error. No kParseFullPrecisionFlag: Debian's RapidJSON 1.1.0 reads out of bounds
  // in StrtodDiyFp on long decimals with it (found by fuzz/request_fuzzer), and the
  // only number of a request, timeout_ms, needs no more than double's usual rounding.
  document.Parse<rapidjson::kParseIterativeFlag | rapidjson::kParseValidateEncodingFlag>(text.data(), text.size());
  if (document.HasParseError()) {
    throw InputError("invalid_json",
                     std::string("invalid JSON: ") + rapidjson::GetParseError_En(document.GetParseError()),
                     document.GetErrorOffset());
  }
  return document;
}

rapidjson::Document parse_object(std::string_view body, const JsonParams& limits) {
  rapidjson::Document document = parse_json(body, limits.max_depth);
  if (!document.IsObject()) throw InputError("wrong_type", "the request body must be a JSON object");
  return document;
}

ObjectReader::ObjectReader(const rapidjson::Value& object) : object_(object) {
  for (auto m = object_.MemberBegin(); m != object_.MemberEnd(); ++m) {
    const std::string name(m->name.GetString(), m->name.GetStringLength());
    for (const std::string& seen : names_) {
      if (seen == name) throw InputError("duplicate_field", "field '" + name + "' is given twice").in_field(name);
    }
    names_.push_back(name);
  }
  taken_.assign(names_.size(), false);
}

const rapidjson::Value* ObjectReader::take(const char* name) {
  for (std::size_t i = 0; i < names_.size(); ++i) {
    if (names_[i] == name) {
      taken_[i] = true;
      return &(object_.MemberBegin() + static_cast<rapidjson::SizeType>(i))->value;
    }
  }
  return nullptr;
}

const rapidjson::Value& ObjectReader::require(const char* name) {
  const rapidjson::Value* v = take(name);
  if (v == nullptr) throw InputError("missing_field", std::string("field '") + name + "' is required").in_field(name);
  return *v;
}

void ObjectReader::finish(const char* allowed) const {
  for (std::size_t i = 0; i < names_.size(); ++i) {
    if (!taken_[i]) {
      throw InputError("unknown_field", "unknown field '" + names_[i] + "' (allowed: " + allowed + ")")
          .in_field(names_[i]);
    }
  }
}

InputError wrong_type(const std::string& field, const char* expected) {
  return InputError("wrong_type", "'" + field + "' must be " + expected).in_field(field);
}

std::string read_string(const rapidjson::Value& v, const std::string& field) {
  if (!v.IsString()) throw wrong_type(field, "a string");
  return std::string(v.GetString(), v.GetStringLength());
}

std::vector<std::string> read_strings(const rapidjson::Value& v, const std::string& field) {
  if (!v.IsArray()) throw wrong_type(field, "an array of strings");
  std::vector<std::string> out;
  out.reserve(v.Size());
  for (rapidjson::SizeType i = 0; i < v.Size(); ++i) {
    out.push_back(read_string(v[i], field + "[" + std::to_string(i) + "]"));
  }
  return out;
}

std::vector<int> read_ints(const rapidjson::Value& v, const std::string& field) {
  if (!v.IsArray()) throw wrong_type(field, "an array of integers");
  std::vector<int> out;
  out.reserve(v.Size());
  for (rapidjson::SizeType i = 0; i < v.Size(); ++i) {
    if (!v[i].IsInt()) throw wrong_type(field + "[" + std::to_string(i) + "]", "an integer");
    out.push_back(v[i].GetInt());
  }
  return out;
}

double read_timeout_seconds(const rapidjson::Value& v) {
  if (!v.IsNumber()) throw wrong_type("timeout_ms", "a number of milliseconds");
  const double ms = v.GetDouble();
  if (!std::isfinite(ms) || ms < 0) {
    throw InputError("invalid_value", "'timeout_ms' must be a non-negative number").in_field("timeout_ms");
  }
  return ms / 1000.0;
}

double read_tolerance(const rapidjson::Value& v, const std::string& field) {
  if (!v.IsNumber()) {
    throw InputError("invalid_tolerance", "a tolerance is a number in (0, 0.5], relative to the patch box's diagonal")
        .in_field(field);
  }
  return v.GetDouble();
}

std::vector<std::string> read_box_texts(const rapidjson::Value& v) {
  if (!v.IsArray()) throw wrong_type("box", "an array of numbers (six; four for a curve)");
  std::vector<std::string> box;
  for (rapidjson::SizeType i = 0; i < v.Size(); ++i) {
    const rapidjson::Value& x = v[i];
    if (!x.IsNumber()) throw wrong_type("box[" + std::to_string(i) + "]", "a number");
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", x.GetDouble());
    box.emplace_back(text);
  }
  return box;
}

JsonParams with_room_for_a_scene(const JsonParams& limits) {
  // A scene nests an object and a children array per level: a few hundred bytes of
  // stack per level in RapidJSON's recursive destructor.
  JsonParams scene_limits = limits;
  scene_limits.max_depth = std::max(limits.max_depth, kMaxSceneJsonDepth + 1);
  return scene_limits;
}

}  // namespace implicitizer::json
