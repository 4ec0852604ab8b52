#include "text_table.hpp"

#include <algorithm>
#include <cstdio>
#include <iostream>

namespace implicitizer::bench {

void print_table(std::vector<std::vector<std::string>> rows, bool markdown) {
  if (markdown) {
    for (auto& row : rows) {
      for (std::string& cell : row) {
        for (std::size_t at = cell.find('|'); at != std::string::npos; at = cell.find('|', at + 2)) {
          cell.replace(at, 1, "\\|");
        }
      }
    }
  }
  std::vector<std::size_t> widths;
  for (const auto& row : rows) {
    widths.resize(std::max(widths.size(), row.size()));
    for (std::size_t i = 0; i < row.size(); ++i) widths[i] = std::max(widths[i], row[i].size());
  }
  for (std::size_t r = 0; r < rows.size(); ++r) {
    std::string line = markdown ? "|" : "";
    for (std::size_t i = 0; i < rows[r].size(); ++i) {
      line += markdown ? " " + rows[r][i] + " |" : rows[r][i] + std::string(widths[i] - rows[r][i].size() + 2, ' ');
    }
    std::cout << line << '\n';
    if (markdown && r == 0) {
      std::string rule = "|";
      for (std::size_t i = 0; i < rows[r].size(); ++i) rule += "---|";
      std::cout << rule << '\n';
    }
  }
}

std::string format(const char* pattern, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, pattern, value);
  return buffer;
}

}  // namespace implicitizer::bench
