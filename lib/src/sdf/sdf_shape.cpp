#include "implicitizer/sdf/sdf_shape.hpp"

#include "implicitizer/core/errors.hpp"

namespace implicitizer {

SdfShape parse_sdf_shape(const std::string& text) {
  if (text == "auto") return SdfShape::automatic;
  if (text == "sheet") return SdfShape::sheet;
  if (text == "solid") return SdfShape::solid;
  throw InputError("invalid_value", "unknown shape '" + text + "' (expected auto, sheet or solid)").in_field("shape");
}

const char* to_string(SdfShape shape) {
  switch (shape) {
    case SdfShape::automatic:
      return "auto";
    case SdfShape::sheet:
      return "sheet";
    case SdfShape::solid:
      return "solid";
  }
  return "auto";
}

}  // namespace implicitizer
