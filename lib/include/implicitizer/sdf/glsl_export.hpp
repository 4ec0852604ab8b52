#pragma once
/// \file
/// The GLSL a client pastes into its shader: `float NAME_sdf(vec3 p)`, negative
/// inside (where F < 0), and nothing else it does not need. The text compiles as
/// GLSL ES 3.00 (WebGL2; the shader declares `precision highp float`) and as
/// desktop GLSL 330, and calls no pow().

#include <string>

#include "implicitizer/polynomial/polynomial.hpp"
#include "implicitizer/sdf/scene_frame.hpp"

namespace implicitizer {

/// How the distance is computed.
enum class SdfMode {
  fast,  ///< F/|∇F| (fast_sdf.hpp): first order, not a bound
  safe,  ///< a proven lower bound of the distance (safe_sdf.hpp)
};

/// Parses "fast" or "safe"; throws InputError `invalid_value` (field "mode") otherwise.
SdfMode parse_sdf_mode(const std::string& text);

/// Options of sdf_glsl().
struct SdfParams {
  SdfMode mode = SdfMode::fast;
  SceneBox box = SceneBox::default_box();  ///< the scene box the frame is built from
  std::string name = "surface";            ///< the function is NAME_sdf
};

/// The GLSL source of `float NAME_sdf(vec3 p)` for the surface f = 0 (f in a ring
/// with exactly the variables x, y, z). Throws InputError: `invalid_name` (field
/// "name", see check_glsl_name), `invalid_box` (field "box"),
/// `constant_polynomial`, `degree_too_high` (mode safe: see SafeSdf::build).
std::string sdf_glsl(const Polynomial& f, const SdfParams& options);

}  // namespace implicitizer
