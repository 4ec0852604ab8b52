// Tests of lib/src/render/image.cpp: pixels, filling, display bytes.

#include "implicitizer/render/image.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace implicitizer {
namespace {

TEST(Image, PixelsAreRowMajorFromTheTop) {
  Image image(3, 2, {1, 2, 3});
  EXPECT_EQ(image.bytes().size(), 18u);
  EXPECT_EQ(image.pixel(2, 1), (std::array<std::uint8_t, 3>{1, 2, 3}));
  image.set_pixel(2, 1, {7, 8, 9});
  EXPECT_EQ(image.bytes()[15], 7);
  EXPECT_EQ(image.pixel(2, 1), (std::array<std::uint8_t, 3>{7, 8, 9}));
  EXPECT_EQ(image.pixel(1, 1), (std::array<std::uint8_t, 3>{1, 2, 3}));
}

TEST(Image, DisplayBytesRoundAndClamp) {
  EXPECT_EQ(to_display_byte(0.95), 242);
  EXPECT_EQ(to_display_byte(-1), 0);
  EXPECT_EQ(to_display_byte(2), 255);
  EXPECT_EQ(to_display_byte(NAN), 0);
  EXPECT_EQ(to_display_byte(0.5), 128);
}

}  // namespace
}  // namespace implicitizer
