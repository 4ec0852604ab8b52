#pragma once
/// \file
/// The benchmark surfaces of shared/bench: named parametrizations with the degree of
/// their implicit equation, read from the suite's JSON files.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace implicitizer::bench {

/// One surface of a suite, as written in its file (the texts are not parsed here).
struct Surface {
  std::string suite;        ///< "public" or "hard": the file it came from
  std::string name;         ///< unique within the suite, e.g. "tp_22"
  std::string x, y, z;      ///< the coordinates in the contract's syntax
  std::int32_t degree = 0;  ///< the implicit degree the file states (0 when absent)
};

/// The surfaces of `file` (a JSON array of objects with string members name, x, y, z
/// and an optional integer member degree), in file order, tagged with `suite`.
/// Throws std::runtime_error naming the file when it cannot be read or is not of
/// that shape; members other than those are ignored.
std::vector<Surface> read_surface_suite(const std::filesystem::path& file, const std::string& suite);

/// The public then the hard surfaces of `bench_dir` (surfaces_public.json,
/// surfaces_hard.json); with `names`, only those, in that order. An unknown name is
/// InputError `invalid_argument` at field `--surface` (the benches' flag).
std::vector<Surface> read_public_and_hard(const std::filesystem::path& bench_dir,
                                          const std::vector<std::string>& names);

}  // namespace implicitizer::bench
