#include "implicitizer/codec/server_json.hpp"

#include "json_writer.hpp"

namespace implicitizer {

std::string encode_health_status(std::string_view status) {
  return json::write_json([&](json::Writer& w) {
    w.StartObject();
    w.Key("status");
    json::write_string(w, status);
    w.EndObject();
  });
}

std::string encode_access_log_entry(std::string_view method, std::string_view path, unsigned status, double ms,
                                    std::size_t bytes) {
  return json::write_json([&](json::Writer& w) {
    w.StartObject();
    w.Key("method");
    json::write_string(w, method);
    w.Key("path");
    json::write_string(w, path);
    w.Key("status");
    w.Uint(status);
    w.Key("ms");
    json::write_milliseconds(w, ms);
    w.Key("bytes");
    w.Uint64(bytes);
    w.EndObject();
  });
}

}  // namespace implicitizer
