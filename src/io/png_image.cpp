#include "fabform/io/png_image.hpp"

#include <png.h>

#include <filesystem>
#include <stdexcept>

#include "fabform/error.hpp"

namespace fabform {
namespace {

// libpng's simplified API keeps its own error handling (its longjmp stays inside libpng) and
// reports failure through the return value and image.message; this owns one png_image and
// frees it however the caller leaves.
class PngImage {
 public:
  PngImage() {
    image_.version = PNG_IMAGE_VERSION;
    image_.opaque = nullptr;
  }
  ~PngImage() { png_image_free(&image_); }
  PngImage(const PngImage&) = delete;
  PngImage& operator=(const PngImage&) = delete;
  png_image* get() { return &image_; }
  std::string message() const { return image_.message[0] ? image_.message : "unknown libpng error"; }

 private:
  png_image image_{};
};

constexpr int kMaxSide = 1 << 15;  // a side beyond this is a damaged header, not an image to print
// A few bytes of header can claim gigabytes of pixels; a design beyond 64 megapixels (8192² at
// 4 bytes, 256 MB) is refused before anything is allocated.
constexpr double kMaxPixels = double(1 << 26);

}  // namespace

Image read_png(const std::string& path) {
  if (!std::filesystem::is_regular_file(path)) throw InputError({path, 0, ""}, "no such image file");
  PngImage png;
  if (!png_image_begin_read_from_file(png.get(), path.c_str()))
    throw InputError({path, 0, ""}, "cannot read as PNG: " + png.message());
  png.get()->format = PNG_FORMAT_RGBA;
  if (png.get()->width == 0 || png.get()->height == 0 || png.get()->width > kMaxSide || png.get()->height > kMaxSide)
    throw InputError({path, 0, ""}, "cannot read as PNG: an image must have 1 to 32768 pixels a side");
  if (double(png.get()->width) * png.get()->height > kMaxPixels)
    throw InputError({path, 0, ""}, "cannot read as PNG: more than 67108864 pixels (a design to print needs far fewer)");
  Image image(static_cast<int>(png.get()->width), static_cast<int>(png.get()->height));
  if (!png_image_finish_read(png.get(), nullptr, image.rgba.data(), 0, nullptr))
    throw InputError({path, 0, ""}, "cannot read as PNG: " + png.message());
  return image;
}

std::string png_bytes(const Image& image) {
  PngImage png;
  png.get()->width = static_cast<png_uint_32>(image.width);
  png.get()->height = static_cast<png_uint_32>(image.height);
  png.get()->format = PNG_FORMAT_RGBA;
  png_alloc_size_t size = 0;
  if (!png_image_write_to_memory(png.get(), nullptr, &size, 0, image.rgba.data(), 0, nullptr))
    throw std::runtime_error("cannot encode a PNG: " + png.message());
  std::string bytes(size, '\0');
  if (!png_image_write_to_memory(png.get(), bytes.data(), &size, 0, image.rgba.data(), 0, nullptr))
    throw std::runtime_error("cannot encode a PNG: " + png.message());
  bytes.resize(size);
  return bytes;
}

}  // namespace fabform
