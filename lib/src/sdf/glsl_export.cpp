#include "implicitizer/sdf/glsl_export.hpp"

#include "implicitizer/core/errors.hpp"
#include "implicitizer/sdf/fast_sdf.hpp"
#include "implicitizer/sdf/glsl_name.hpp"

namespace implicitizer {

SdfMode parse_sdf_mode(const std::string& text) {
  if (text == "fast") return SdfMode::fast;
  if (text == "safe") return SdfMode::safe;
  throw InputError("invalid_value", "unknown mode '" + text + "' (expected fast or safe)").in_field("mode");
}

std::string sdf_glsl(const Polynomial& f, const SdfOptions& options) {
  check_glsl_name(options.name);
  if (options.mode == SdfMode::safe) {
    throw InputError("not_built", "mode 'safe' is not built yet (available: fast)").in_field("mode");
  }
  return FastSdf::build(f, options.box).to_glsl(options.name + "_sdf");
}

}  // namespace implicitizer
