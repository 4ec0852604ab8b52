#include "implicitizer/scene/sheet_side.hpp"

#include <stdexcept>
#include <utility>

namespace implicitizer {

SheetSide::SheetSide(std::vector<FastSdf> pieces) : pieces_(std::move(pieces)) {
  if (pieces_.empty()) throw std::invalid_argument("SheetSide: no piece");
}

std::string SheetSide::to_glsl(const std::string& function) const {
  std::string out;
  for (std::size_t k = 0; k < pieces_.size(); ++k) out += pieces_[k].to_glsl(function + "_piece" + std::to_string(k));
  out += "// The side of the sheet: the signed estimate of the nearest of its " + std::to_string(pieces_.size()) +
         " pieces.\nfloat " + function + "(vec3 p) {\n  float best = " + function + "_piece0(p);\n";
  for (std::size_t k = 1; k < pieces_.size(); ++k) {
    out += "  { float v = " + function + "_piece" + std::to_string(k) + "(p); if (abs(v) < abs(best)) best = v; }\n";
  }
  return out + "  return best;\n}\n";
}

}  // namespace implicitizer
