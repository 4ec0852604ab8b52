#pragma once
/// \file
/// What a distance function describes: the solid bounded by a surface, or the surface
/// itself as a two-sided sheet (docs/sdf.md, "Shapes").
///
///   - solid: F <= 0 clipped to its box, negative inside (the only shape before
///     issue 18). Right for a closed surface inside its box (sphere, torus).
///   - sheet: the zero set itself, value >= 0 everywhere and 0 on the surface: an
///     open surface, a patch, a plane curve. Two-sided: it has no inside, so in a
///     scene it enters CSG through `shell` (|d| − thickness) as a thin solid.
///   - automatic: solid only where the zero set inside the box provably encloses a
///     region that stays away from the box's faces, sheet otherwise; the answer
///     says which was picked.

#include <cstdint>
#include <string>

namespace implicitizer {

/// The shape a request asks for.
enum class SdfShape : std::uint8_t {
  automatic,  ///< "auto": solid where the surface encloses a region inside its box, else sheet
  sheet,      ///< "sheet": the surface itself, >= 0 everywhere
  solid,      ///< "solid": F <= 0 clipped to the box, negative inside
};

/// Parses "auto", "sheet" or "solid"; throws InputError `invalid_value` (field
/// "shape") otherwise.
SdfShape parse_sdf_shape(const std::string& text);

/// "auto", "sheet" or "solid".
const char* to_string(SdfShape shape);

}  // namespace implicitizer
