#include "implicitizer/codec/error_json.hpp"

#include "json_writer.hpp"

namespace implicitizer {
namespace {

// The contract's error shape: {"error": {"code", "message", ...extra members}}.
// `extra` writes the members that only some errors carry.
template <typename WriteExtra>
std::string encode_error_object(std::string_view code, std::string_view message, WriteExtra&& extra) {
  return json::write_json([&](json::Writer& w) {
    w.StartObject();
    w.Key("error");
    w.StartObject();
    w.Key("code");
    json::write_string(w, code);
    w.Key("message");
    json::write_string(w, message);
    extra(w);
    w.EndObject();
    w.EndObject();
  });
}

}  // namespace

std::string encode_error(const InputError& error) {
  return encode_error_object(error.code(), error.what(), [&](json::Writer& w) {
    if (error.position()) {
      w.Key("position");
      w.Uint64(*error.position());
    }
    if (!error.field().empty()) {
      w.Key("field");
      json::write_string(w, error.field());
    }
  });
}

std::string encode_error(const NoSingleEquation& error) {
  return encode_error_object(error.code(), error.what(), [&](json::Writer& w) {
    w.Key("generators");
    json::write_strings(w, error.generators());
  });
}

std::string encode_error(const ToleranceNotMet& error) {
  return encode_error_object("tolerance_not_met", error.what(), [&](json::Writer& w) {
    w.Key("best_bound");
    w.SetMaxDecimalPlaces(json::Writer::kDefaultMaxDecimalPlaces);  // 2e-5 is not 0.000
    w.Double(error.best());
  });
}

std::string encode_error(const LimitExceeded& error) {
  return encode_error_object(limit_error_code(error.limit()), error.what(), [&](json::Writer& w) {
    w.Key("limit");
    json::write_string(w, to_string(error.limit()));
  });
}

std::string encode_error(std::string_view code, std::string_view message) {
  return encode_error_object(code, message, [](json::Writer&) {});
}

const char* limit_error_code(Limit limit) {
  switch (limit) {
    case Limit::time:
      return "time_limit_exceeded";
    case Limit::size:
      return "size_limit_exceeded";
    case Limit::memory:
      return "memory_limit_exceeded";
    case Limit::work:
      return "work_limit_exceeded";
    case Limit::cancelled:
      return "cancelled";
  }
  return "limit_exceeded";
}

}  // namespace implicitizer
