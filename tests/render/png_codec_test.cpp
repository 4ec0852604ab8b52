// Tests of lib/src/render/png_codec.cpp: what is encoded decodes to the same pixels
// (libpng's reader), the file has PNG's signature and IHDR, and garbage is refused.

#include "implicitizer/render/png_codec.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <random>
#include <sstream>

#include "implicitizer/core/errors.hpp"

namespace implicitizer {
namespace {

Image random_image(std::size_t w, std::size_t h, unsigned seed) {
  std::mt19937 rng(seed);
  Image image(w, h);
  for (std::size_t y = 0; y < h; ++y) {
    for (std::size_t x = 0; x < w; ++x) {
      image.set_pixel(
          x, y, {static_cast<std::uint8_t>(rng()), static_cast<std::uint8_t>(rng()), static_cast<std::uint8_t>(rng())});
    }
  }
  return image;
}

TEST(PngCodec, RoundTripKeepsEveryPixel) {
  for (const auto& [w, h] : {std::pair<std::size_t, std::size_t>{1, 1}, {7, 3}, {64, 48}, {300, 1}}) {
    const Image image = random_image(w, h, static_cast<unsigned>(w * 1000 + h));
    const std::string png = encode_png(image);
    const Image back = decode_png(png);
    EXPECT_EQ(back.width(), w);
    EXPECT_EQ(back.height(), h);
    EXPECT_TRUE(back == image) << w << "x" << h;
  }
}

TEST(PngCodec, HeaderStatesSizeAndRgb8) {
  const std::string png = encode_png(Image(300, 20, {242, 242, 242}));
  ASSERT_GT(png.size(), 33u);
  EXPECT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  EXPECT_EQ(png.substr(12, 4), "IHDR");
  auto be32 = [&](std::size_t at) {
    return (static_cast<unsigned char>(png[at]) << 24) | (static_cast<unsigned char>(png[at + 1]) << 16) |
           (static_cast<unsigned char>(png[at + 2]) << 8) | static_cast<unsigned char>(png[at + 3]);
  };
  EXPECT_EQ(be32(16), 300u);
  EXPECT_EQ(be32(20), 20u);
  EXPECT_EQ(png[24], 8);  // bit depth
  EXPECT_EQ(png[25], 2);  // colour type RGB
}

TEST(PngCodec, WritesFiles) {
  const Image image = random_image(5, 4, 9);
  const std::string path = ::testing::TempDir() + "png_codec_test.png";
  write_png_file(image, path);
  std::ifstream in(path, std::ios::binary);
  std::stringstream bytes;
  bytes << in.rdbuf();
  EXPECT_TRUE(decode_png(bytes.str()) == image);
  std::remove(path.c_str());
  EXPECT_THROW(write_png_file(image, "/nonexistent-directory/x.png"), std::runtime_error);
}

TEST(PngCodec, RefusesWhatIsNotPng) {
  for (const std::string& bytes : {std::string(), std::string("not a png"), encode_png(Image(4, 4)).substr(0, 40)}) {
    try {
      decode_png(bytes);
      ADD_FAILURE() << "accepted " << bytes.size() << " bytes";
    } catch (const InputError& e) {
      EXPECT_EQ(e.code(), "invalid_png");
    }
  }
  EXPECT_THROW(encode_png(Image()), std::runtime_error);
}

}  // namespace
}  // namespace implicitizer
