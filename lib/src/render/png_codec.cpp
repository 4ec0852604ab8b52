#include "implicitizer/render/png_codec.hpp"

#include <png.h>

#include <cstdio>
#include <fstream>
#include <stdexcept>

#include "implicitizer/core/errors.hpp"

namespace implicitizer {
namespace {

// libpng's simplified API (1.6): no setjmp/longjmp crosses C++ frames, errors come
// back as a return value and a message in the control structure.
constexpr std::size_t kMaxDecodedPixels = std::size_t{1} << 26;

}  // namespace

std::string encode_png(const Image& image) {
  if (image.width() == 0 || image.height() == 0) throw std::runtime_error("encode_png: empty image");
  png_image control{};
  control.version = PNG_IMAGE_VERSION;
  control.width = static_cast<png_uint_32>(image.width());
  control.height = static_cast<png_uint_32>(image.height());
  control.format = PNG_FORMAT_RGB;
  const auto stride = static_cast<png_int_32>(3 * image.width());
  png_alloc_size_t size = 0;
  // First call: the size only (memory == NULL).
  if (!png_image_write_to_memory(&control, nullptr, &size, 0, image.bytes().data(), stride, nullptr)) {
    const std::string message = control.message;
    png_image_free(&control);
    throw std::runtime_error("encode_png: " + message);
  }
  std::string out(size, '\0');
  if (!png_image_write_to_memory(&control, out.data(), &size, 0, image.bytes().data(), stride, nullptr)) {
    const std::string message = control.message;
    png_image_free(&control);
    throw std::runtime_error("encode_png: " + message);
  }
  out.resize(size);
  return out;
}

void write_png_file(const Image& image, const std::string& path) {
  const std::string bytes = encode_png(image);
  std::ofstream file(path, std::ios::binary | std::ios::trunc);
  if (!file) throw std::runtime_error("cannot open '" + path + "' for writing");
  file.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  file.close();
  if (!file) throw std::runtime_error("cannot write '" + path + "'");
}

Image decode_png(std::string_view bytes) {
  png_image control{};
  control.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_memory(&control, bytes.data(), bytes.size())) {
    const std::string message = control.message;
    png_image_free(&control);
    throw InputError("invalid_png", "not a readable PNG: " + message);
  }
  if (std::size_t{control.width} * control.height > kMaxDecodedPixels) {
    png_image_free(&control);
    throw InputError("invalid_png", "the PNG is larger than 2^26 pixels");
  }
  control.format = PNG_FORMAT_RGB;
  Image image(control.width, control.height);
  std::vector<std::uint8_t> buffer(PNG_IMAGE_SIZE(control));
  // Files with alpha are composed onto black (the simplified API needs a colour).
  png_color background{0, 0, 0};
  if (!png_image_finish_read(&control, &background, buffer.data(), 0, nullptr)) {
    const std::string message = control.message;
    png_image_free(&control);
    throw InputError("invalid_png", "not a readable PNG: " + message);
  }
  for (std::size_t y = 0; y < image.height(); ++y) {
    for (std::size_t x = 0; x < image.width(); ++x) {
      const std::uint8_t* p = &buffer[3 * (y * image.width() + x)];
      image.set_pixel(x, y, {p[0], p[1], p[2]});
    }
  }
  return image;
}

}  // namespace implicitizer
