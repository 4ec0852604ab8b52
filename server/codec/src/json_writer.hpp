#pragma once
/// \file
/// What every encoder of the codec writes with (private to codec/): a compact
/// RapidJSON writer with times at 3 decimals, and the members several answers share
/// (Buchberger's and the modular computation's counters).

#include <rapidjson/stringbuffer.h>
#include <rapidjson/writer.h>

#include <string>
#include <string_view>
#include <vector>

#include "implicitizer/groebner/buchberger.hpp"
#include "implicitizer/groebner/modular_groebner.hpp"
#include "implicitizer/polynomial/polynomial.hpp"

namespace implicitizer::json {

using Writer = rapidjson::Writer<rapidjson::StringBuffer>;

/// `w` with at most 3 decimals (times in milliseconds).
Writer& configure(Writer& w);

void write_string(Writer& w, std::string_view s);

/// `["a", "b"]`.
void write_strings(Writer& w, const std::vector<std::string>& strings);

/// A non-negative finite time in milliseconds (anything else as 0).
void write_milliseconds(Writer& w, double ms);

/// The polynomials printed, as an array of strings.
void write_polynomials(Writer& w, const std::vector<Polynomial>& polynomials);

/// The members `"pairs", ..., "groebner_ms"` of a stats object (its caller opens it
/// and may add its own members).
void write_buchberger_stats_members(Writer& w, const BuchbergerStats& s);

/// What the modular Gröbner computation did (modular_groebner.hpp), as an object.
void write_modular_stats(Writer& w, const ModularGroebnerStats& s);

/// The text `buffer` holds.
std::string finish(const rapidjson::StringBuffer& buffer);

/// The text of one value written by `write(w)` with a configured writer.
template <typename Write>
std::string write_json(Write&& write) {
  rapidjson::StringBuffer buffer;
  Writer w(buffer);
  configure(w);
  write(w);
  return finish(buffer);
}

}  // namespace implicitizer::json
