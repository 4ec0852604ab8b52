#include "implicitizer/sdf/glsl_export.hpp"

#include "implicitizer/core/errors.hpp"
#include "implicitizer/sdf/fast_sdf.hpp"
#include "implicitizer/sdf/glsl_name.hpp"
#include "implicitizer/sdf/safe_sdf.hpp"

namespace implicitizer {

SdfMode parse_sdf_mode(const std::string& text) {
  if (text == "fast") return SdfMode::fast;
  if (text == "safe") return SdfMode::safe;
  throw InputError("invalid_value", "unknown mode '" + text + "' (expected fast or safe)").in_field("mode");
}

std::string sdf_glsl(const Polynomial& f, const SdfParams& options) {
  check_glsl_name(options.name);
  const std::string function = options.name + "_sdf";
  switch (options.mode) {
    case SdfMode::fast:
      return FastSdf::build(f, options.box).to_glsl(function);
    case SdfMode::safe:
      return SafeSdf::build(f, options.box).to_glsl(function);
  }
  throw InputError("invalid_value", "unknown mode").in_field("mode");
}

}  // namespace implicitizer
