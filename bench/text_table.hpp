#pragma once
/// \file
/// The tables the accuracy benches print: aligned text, or Markdown for the docs.

#include <string>
#include <vector>

namespace implicitizer::bench {

/// Prints `rows` (the first row the header) to standard output as a Markdown table
/// (a `|` inside a cell escaped) or as aligned columns.
void print_table(std::vector<std::vector<std::string>> rows, bool markdown);

/// `value` printed with a printf pattern that takes one double.
std::string format(const char* pattern, double value);

}  // namespace implicitizer::bench
