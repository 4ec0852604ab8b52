#pragma once
// The benchmark surfaces of ../shared/bench, read for tests.

#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace implicitizer::testing {

struct Surface {
  std::string name, x, y, z;
  int degree = 0;
};

// Reads surfaces_public.json / surfaces_hard.json: one object per surface with string
// fields name, x, y, z and an integer degree. The files are flat, so a small scanner
// is enough (the JSON library belongs to the server's codec).
inline std::vector<Surface> read_surfaces(const std::string& path) {
  std::ifstream in(path);
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  std::vector<Surface> out;
  const std::regex object(R"(\{[^{}]*\})");
  const std::regex field(R"x("(\w+)"\s*:\s*("([^"]*)"|(-?\d+)))x");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), object); it != std::sregex_iterator(); ++it) {
    Surface s;
    const std::string obj = it->str();
    for (auto f = std::sregex_iterator(obj.begin(), obj.end(), field); f != std::sregex_iterator(); ++f) {
      const std::string key = (*f)[1];
      const std::string value = (*f)[3].matched ? (*f)[3].str() : (*f)[4].str();
      if (key == "name") s.name = value;
      if (key == "x") s.x = value;
      if (key == "y") s.y = value;
      if (key == "z") s.z = value;
      if (key == "degree") s.degree = std::stoi(value);
    }
    out.push_back(s);
  }
  return out;
}

inline std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  return line;
}

}  // namespace implicitizer::testing
