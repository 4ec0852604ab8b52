#pragma once
/// \file
/// PNG in and out through libpng: 8-bit RGB, no interlacing. The encoder is what
/// `implicitizer render` and POST /v1/render write; the decoder reads any PNG
/// libpng can (palette, grey, 16-bit and alpha are converted to 8-bit RGB), so the
/// tests can check what was written pixel by pixel.

#include <string>
#include <string_view>

#include "implicitizer/render/image.hpp"

namespace implicitizer {

/// The PNG file of `image` (8-bit RGB, zlib level 6), as bytes. Precondition: the
/// image is not empty. Throws std::runtime_error if libpng reports an error.
std::string encode_png(const Image& image);

/// Writes encode_png(image) to `path`. Throws std::runtime_error naming the path
/// when it cannot be written.
void write_png_file(const Image& image, const std::string& path);

/// Decodes a PNG file's bytes to 8-bit RGB. Throws InputError `invalid_png` when
/// the bytes are not a PNG libpng can read, or the image is larger than 2^26 pixels.
Image decode_png(std::string_view bytes);

}  // namespace implicitizer
