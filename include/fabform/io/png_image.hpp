#pragma once
// PNG images in and out, through libpng's simplified API (Debian's libpng-dev): any PNG is read
// as 8-bit RGBA, images are written as 8-bit RGBA. libpng's errors become InputError naming
// the file. Writing the bytes is the caller's (atomic_file.hpp's write_file_atomically).
#include <cstdint>
#include <string>
#include <vector>

namespace fabform {

/// Rows from the top, each pixel R, G, B, A.
struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;  // width × height × 4

  Image() = default;
  Image(int w, int h) : width(w), height(h), rgba(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 4, 0) {}
  std::uint8_t* pixel(int column, int row) {
    return rgba.data() + (static_cast<std::size_t>(row) * static_cast<std::size_t>(width) + static_cast<std::size_t>(column)) * 4;
  }
  const std::uint8_t* pixel(int column, int row) const {
    return rgba.data() + (static_cast<std::size_t>(row) * static_cast<std::size_t>(width) + static_cast<std::size_t>(column)) * 4;
  }
};

/// Reads a PNG; throws InputError naming the file when it cannot be read or is not a PNG.
Image read_png(const std::string& path);

/// The PNG file's bytes for an image.
std::string png_bytes(const Image& image);

}  // namespace fabform
