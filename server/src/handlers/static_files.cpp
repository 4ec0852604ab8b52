#include "handlers/static_files.hpp"

#include <array>
#include <fstream>
#include <iterator>
#include <string>
#include <system_error>
#include <utility>

namespace implicitizer::server {
namespace {

int hex_value(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// Decodes one path segment; nullopt for a malformed escape or a byte that must never
// reach the filesystem inside a segment (NUL, `/`, `\`).
std::optional<std::string> decode_segment(std::string_view segment) {
  std::string out;
  out.reserve(segment.size());
  for (std::size_t i = 0; i < segment.size(); ++i) {
    char c = segment[i];
    if (c == '%') {
      if (i + 2 >= segment.size()) return std::nullopt;
      const int hi = hex_value(segment[i + 1]);
      const int lo = hex_value(segment[i + 2]);
      if (hi < 0 || lo < 0) return std::nullopt;
      c = static_cast<char>(hi * 16 + lo);
      i += 2;
    }
    if (c == '\0' || c == '/' || c == '\\') return std::nullopt;
    out.push_back(c);
  }
  return out;
}

bool is_inside(const std::filesystem::path& root, const std::filesystem::path& file) {
  auto r = root.begin();
  auto f = file.begin();
  for (; r != root.end(); ++r, ++f) {
    if (f == file.end() || *r != *f) return false;
  }
  return true;
}

}  // namespace

std::variant<std::filesystem::path, StaticPathError> resolve_static_path(const std::filesystem::path& root,
                                                                         std::string_view target) {
  namespace fs = std::filesystem;
  if (target.empty() || target.front() != '/') return StaticPathError::invalid;  // absolute-form, `*`
  if (const std::size_t q = target.find_first_of("?#"); q != std::string_view::npos) target = target.substr(0, q);
  fs::path relative;
  bool directory = target.back() == '/';
  std::size_t start = 1;
  while (start <= target.size()) {
    const std::size_t slash = target.find('/', start);
    const std::size_t stop = slash == std::string_view::npos ? target.size() : slash;
    const std::string_view raw = target.substr(start, stop - start);
    if (!raw.empty()) {
      const std::optional<std::string> segment = decode_segment(raw);
      // `.` and `..` (however spelt) are refused rather than normalised: a client
      // that sends them is probing, and refusing keeps the rule trivially correct.
      if (!segment || *segment == "." || *segment == "..") return StaticPathError::invalid;
      relative /= *segment;
    }
    if (slash == std::string_view::npos) break;
    start = slash + 1;
  }
  std::error_code ec;
  const fs::path canonical_root = fs::canonical(root, ec);
  if (ec) return StaticPathError::not_found;
  fs::path candidate = canonical_root / relative;
  if (directory || relative.empty() || fs::is_directory(candidate, ec)) candidate /= "index.html";
  // canonical() resolves every symlink; a link that leads outside the root is treated
  // as if the file were not there.
  const fs::path file = fs::canonical(candidate, ec);
  if (ec || !is_inside(canonical_root, file) || !fs::is_regular_file(file, ec)) return StaticPathError::not_found;
  return file;
}

std::string_view content_type_for(const std::filesystem::path& file) {
  static constexpr std::array<std::pair<std::string_view, std::string_view>, 16> kTypes = {{
      {".html", "text/html; charset=utf-8"},
      {".htm", "text/html; charset=utf-8"},
      {".css", "text/css; charset=utf-8"},
      {".js", "text/javascript; charset=utf-8"},
      {".mjs", "text/javascript; charset=utf-8"},
      {".json", "application/json"},
      {".map", "application/json"},
      {".svg", "image/svg+xml"},
      {".png", "image/png"},
      {".jpg", "image/jpeg"},
      {".jpeg", "image/jpeg"},
      {".ico", "image/x-icon"},
      {".txt", "text/plain; charset=utf-8"},
      {".wasm", "application/wasm"},
      {".glsl", "text/plain; charset=utf-8"},
      {".woff2", "font/woff2"},
  }};
  const std::string extension = file.extension().string();
  for (const auto& [ext, type] : kTypes) {
    if (ext == extension) return type;
  }
  return "application/octet-stream";
}

Response handle_static_file(const Request& request, const HandlerContext& context) {
  if (context.config.static_dir.empty()) {
    return make_error_response(http::status::not_found, "not_found", "no such endpoint or file");
  }
  const auto resolved = resolve_static_path(context.config.static_dir,
                                            std::string_view(request.target().data(), request.target().size()));
  if (const auto* error = std::get_if<StaticPathError>(&resolved)) {
    if (*error == StaticPathError::invalid) {
      return make_error_response(http::status::bad_request, "invalid_path",
                                 "the path must not contain '.' or '..' segments, encoded slashes or NUL");
    }
    return make_error_response(http::status::not_found, "not_found", "no such endpoint or file");
  }
  const std::filesystem::path& file = std::get<std::filesystem::path>(resolved);
  std::error_code ec;
  const auto size = std::filesystem::file_size(file, ec);
  if (ec || size > context.config.max_static_file_bytes) {
    return make_error_response(http::status::not_found, "not_found", "no such endpoint or file");
  }
  std::ifstream in(file, std::ios::binary);
  std::string body(static_cast<std::size_t>(size), '\0');
  if (!in.read(body.data(), static_cast<std::streamsize>(body.size()))) {
    return make_error_response(http::status::not_found, "not_found", "no such endpoint or file");
  }
  Response response = make_response(http::status::ok, std::move(body), content_type_for(file));
  response.set(http::field::cache_control, "no-cache");
  response.set("X-Content-Type-Options", "nosniff");
  return response;
}

}  // namespace implicitizer::server
