#include "access_log.hpp"

#include <iostream>
#include <string>

#include "implicitizer/codec/server_json.hpp"

namespace implicitizer::server {

void AccessLog::write(std::string_view method, std::string_view path, unsigned status, double ms, std::size_t bytes) {
  if (!enabled_) return;
  std::string clean(path.substr(0, path.find('?')).substr(0, 512));
  for (char& c : clean) {
    if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f) c = '?';
  }
  const std::string line = encode_access_log_entry(method, clean, status, ms, bytes);
  std::lock_guard lock(mutex_);
  std::cerr << line << '\n' << std::flush;
}

}  // namespace implicitizer::server
