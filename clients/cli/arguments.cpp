#include "arguments.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>

namespace implicitizer::cli {
namespace {

const OptionSpec* find_option(std::span<const OptionSpec> spec, const std::string& name) {
  for (const OptionSpec& o : spec) {
    if (name == o.name) return &o;
  }
  return nullptr;
}

std::string trim(const std::string& s) {
  const auto first = s.find_first_not_of(" \t");
  if (first == std::string::npos) return "";
  return s.substr(first, s.find_last_not_of(" \t") - first + 1);
}

}  // namespace

std::optional<std::string> Arguments::value(const std::string& name) const {
  const auto it = values_.find(name);
  if (it == values_.end()) return std::nullopt;
  return it->second;
}

bool Arguments::has(const std::string& name) const { return values_.count(name) != 0 || switches_.count(name) != 0; }

Arguments parse_arguments(std::span<const std::string> args, std::span<const OptionSpec> spec) {
  Arguments out;
  bool options_ended = false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& word = args[i];
    if (options_ended || word.size() < 2 || word.compare(0, 2, "--") != 0) {
      // `-h` is the one short form, as everyone types it.
      if (!options_ended && word == "-h") {
        out.switches_.insert("help");
      } else {
        out.positionals_.push_back(word);
      }
      continue;
    }
    if (word == "--") {
      options_ended = true;
      continue;
    }
    std::string name = word.substr(2);
    std::optional<std::string> inline_value;
    if (const auto eq = name.find('='); eq != std::string::npos) {
      inline_value = name.substr(eq + 1);
      name.resize(eq);
    }
    const OptionSpec* option = find_option(spec, name);
    if (option == nullptr) throw UsageError("unknown option --" + name);
    if (out.has(name)) throw UsageError("option --" + name + " given twice");
    if (!option->takes_value) {
      if (inline_value) throw UsageError("option --" + name + " takes no value");
      out.switches_.insert(name);
      continue;
    }
    if (inline_value) {
      out.values_[name] = *inline_value;
    } else if (i + 1 < args.size() && args[i + 1].compare(0, 2, "--") != 0) {
      out.values_[name] = args[++i];
    } else {
      throw UsageError("option --" + name + " needs a value");
    }
  }
  return out;
}

std::vector<std::string> split_list(const std::string& text, const char* flag) {
  std::vector<std::string> items;
  if (trim(text).empty()) return items;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = text.find(',', start);
    std::string item = trim(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (item.empty()) throw UsageError(std::string("--") + flag + ": empty item in the list '" + text + "'");
    items.push_back(std::move(item));
    if (comma == std::string::npos) return items;
    start = comma + 1;
  }
}

double parse_seconds(const std::string& text, const char* flag) {
  const std::string t = trim(text);
  char* end = nullptr;
  errno = 0;
  const double seconds = t.empty() ? 0.0 : std::strtod(t.c_str(), &end);
  if (t.empty() || end != t.c_str() + t.size() || errno == ERANGE || !std::isfinite(seconds) || seconds <= 0) {
    throw UsageError(std::string("--") + flag + " needs a positive number of seconds, not '" + text + "'");
  }
  return seconds;
}

std::size_t parse_count(const std::string& text, const char* flag) {
  const std::string t = trim(text);
  char* end = nullptr;
  errno = 0;
  const bool digits = !t.empty() && t.find_first_not_of("0123456789") == std::string::npos;
  const unsigned long long n = digits ? std::strtoull(t.c_str(), &end, 10) : 0;
  if (!digits || errno == ERANGE || n > std::numeric_limits<std::size_t>::max()) {
    throw UsageError(std::string("--") + flag + " needs a non-negative integer, not '" + text + "'");
  }
  return static_cast<std::size_t>(n);
}

std::size_t parse_memory_size(const std::string& text, const char* flag) {
  std::string t = trim(text);
  unsigned shift = 20;  // MiB without a suffix
  if (!t.empty()) {
    switch (t.back()) {
      case 'K':
      case 'k':
        shift = 10;
        t.pop_back();
        break;
      case 'M':
      case 'm':
        t.pop_back();
        break;
      case 'G':
      case 'g':
        shift = 30;
        t.pop_back();
        break;
      default:
        break;
    }
  }
  const bool digits = !t.empty() && t.find_first_not_of("0123456789") == std::string::npos;
  errno = 0;
  const unsigned long long n = digits ? std::strtoull(t.c_str(), nullptr, 10) : 0;
  if (!digits || errno == ERANGE || n == 0 || n > (std::numeric_limits<std::size_t>::max() >> shift)) {
    throw UsageError(std::string("--") + flag + " needs a size such as 512 (MiB), 512M or 2G, not '" + text + "'");
  }
  return static_cast<std::size_t>(n) << shift;
}

int parse_int(const std::string& text, const char* flag) {
  const std::string t = trim(text);
  char* end = nullptr;
  errno = 0;
  const long n = t.empty() ? 0 : std::strtol(t.c_str(), &end, 10);
  if (t.empty() || end != t.c_str() + t.size() || errno == ERANGE || n < std::numeric_limits<int>::min() ||
      n > std::numeric_limits<int>::max()) {
    throw UsageError(std::string("--") + flag + " needs integers, not '" + text + "'");
  }
  return static_cast<int>(n);
}

std::string read_text_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw UsageError("cannot read scene file '" + path + "'");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw UsageError("cannot read scene file '" + path + "'");
  return text.str();
}

}  // namespace implicitizer::cli
