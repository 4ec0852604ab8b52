#include "surface_suite.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "implicitizer/core/errors.hpp"

// The benchmark reads data files, not requests: the server's codec has no notion of
// a suite, so RapidJSON is used directly here, as a private dependency of the bench.
#include <rapidjson/document.h>
#include <rapidjson/error/en.h>

namespace implicitizer::bench {

namespace {

std::string read_file(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + file.string());
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string string_member(const rapidjson::Value& object, const char* name, const std::string& where) {
  const auto it = object.FindMember(name);
  if (it == object.MemberEnd() || !it->value.IsString()) {
    throw std::runtime_error(where + ": member '" + name + "' missing or not a string");
  }
  return {it->value.GetString(), it->value.GetStringLength()};
}

}  // namespace

std::vector<Surface> read_surface_suite(const std::filesystem::path& file, const std::string& suite) {
  const std::string text = read_file(file);
  rapidjson::Document document;
  document.Parse(text.data(), text.size());
  if (document.HasParseError()) {
    throw std::runtime_error(file.string() + ": invalid JSON at offset " + std::to_string(document.GetErrorOffset()) +
                             ": " + rapidjson::GetParseError_En(document.GetParseError()));
  }
  if (!document.IsArray()) throw std::runtime_error(file.string() + ": expected an array of surfaces");
  std::vector<Surface> surfaces;
  for (rapidjson::SizeType i = 0; i < document.Size(); ++i) {
    const rapidjson::Value& entry = document[i];
    const std::string where = file.string() + "[" + std::to_string(i) + "]";
    if (!entry.IsObject()) throw std::runtime_error(where + ": expected an object");
    Surface s;
    s.suite = suite;
    s.name = string_member(entry, "name", where);
    s.x = string_member(entry, "x", where);
    s.y = string_member(entry, "y", where);
    s.z = string_member(entry, "z", where);
    const auto degree = entry.FindMember("degree");
    if (degree != entry.MemberEnd()) {
      if (!degree->value.IsInt()) throw std::runtime_error(where + ": member 'degree' is not an integer");
      s.degree = degree->value.GetInt();
    }
    surfaces.push_back(std::move(s));
  }
  return surfaces;
}

std::vector<Surface> read_public_and_hard(const std::filesystem::path& bench_dir,
                                          const std::vector<std::string>& names) {
  std::vector<Surface> all = read_surface_suite(bench_dir / "surfaces_public.json", "public");
  for (Surface& s : read_surface_suite(bench_dir / "surfaces_hard.json", "hard")) all.push_back(std::move(s));
  if (names.empty()) return all;
  std::vector<Surface> chosen;
  for (const std::string& name : names) {
    const auto it = std::find_if(all.begin(), all.end(), [&](const Surface& s) { return s.name == name; });
    if (it == all.end()) throw InputError("invalid_argument", "no surface '" + name + "'").in_field("--surface");
    chosen.push_back(*it);
  }
  return chosen;
}

}  // namespace implicitizer::bench
