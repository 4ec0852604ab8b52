#pragma once
/// \file
/// An 8-bit RGB image, rows top to bottom: what the renderer produces and the PNG
/// codec writes. Colours are display values (already gamma-encoded).

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace implicitizer {

/// width × height pixels of three bytes (R, G, B), row-major from the top-left.
class Image {
 public:
  /// An empty image (0 × 0).
  Image() = default;
  /// A width × height image filled with `fill`.
  Image(std::size_t width, std::size_t height, std::array<std::uint8_t, 3> fill = {0, 0, 0});

  /// Width in pixels.
  std::size_t width() const { return width_; }
  /// Height in pixels.
  std::size_t height() const { return height_; }
  /// The pixel in column x, row y (row 0 at the top). Precondition: x < width, y < height.
  std::array<std::uint8_t, 3> pixel(std::size_t x, std::size_t y) const {
    const std::uint8_t* p = &bytes_[3 * (y * width_ + x)];
    return {p[0], p[1], p[2]};
  }
  /// Sets the pixel in column x, row y. Precondition as pixel().
  void set_pixel(std::size_t x, std::size_t y, std::array<std::uint8_t, 3> rgb) {
    std::uint8_t* p = &bytes_[3 * (y * width_ + x)];
    p[0] = rgb[0];
    p[1] = rgb[1];
    p[2] = rgb[2];
  }
  /// The bytes, 3·width per row, rows from the top.
  const std::vector<std::uint8_t>& bytes() const { return bytes_; }

  /// Equal sizes and bytes.
  friend bool operator==(const Image&, const Image&) = default;

 private:
  std::size_t width_ = 0, height_ = 0;
  std::vector<std::uint8_t> bytes_;
};

/// The byte of a display value in [0, 1] (clamped; NaN becomes 0): round(255·v).
std::uint8_t to_display_byte(double value);

}  // namespace implicitizer
