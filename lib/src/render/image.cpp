#include "implicitizer/render/image.hpp"

#include <cmath>

namespace implicitizer {

Image::Image(std::size_t width, std::size_t height, std::array<std::uint8_t, 3> fill)
    : width_(width), height_(height), bytes_(3 * width * height) {
  for (std::size_t i = 0; i < width * height; ++i) {
    bytes_[3 * i] = fill[0];
    bytes_[3 * i + 1] = fill[1];
    bytes_[3 * i + 2] = fill[2];
  }
}

std::uint8_t to_display_byte(double value) {
  if (!(value > 0)) return 0;  // also NaN
  if (value >= 1) return 255;
  return static_cast<std::uint8_t>(std::lround(255 * value));
}

}  // namespace implicitizer
