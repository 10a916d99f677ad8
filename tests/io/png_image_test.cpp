// PNG images through libpng: what is written reads back pixel for pixel; what is not a PNG is
// refused with an InputError naming the file.
#include <gtest/gtest.h>

#include <cstdint>

#include "fabform/error.hpp"
#include "fabform/io/png_image.hpp"
#include "support/temp_dir.hpp"

namespace fabform::png_image_test {
namespace {

TEST(PngImage, WrittenImageReadsBackPixelForPixel) {
  Image image(7, 3);
  for (std::size_t i = 0; i < image.rgba.size(); ++i) image.rgba[i] = static_cast<std::uint8_t>(i * 37 % 256);
  test::TempDir dir;
  const std::string path = dir.write("a.png", png_bytes(image));
  const Image back = read_png(path);
  EXPECT_EQ(back.width, 7);
  EXPECT_EQ(back.height, 3);
  EXPECT_EQ(back.rgba, image.rgba);
}

TEST(PngImage, RefusesWhatIsNotAPngNamingTheFile) {
  test::TempDir dir;
  const std::string text = dir.write("not.png", "hello, not an image\n");
  const std::string cut = dir.write("cut.png", png_bytes(Image(40, 40)).substr(0, 60));
  for (const std::string& path : {text, cut, dir.path("missing.png")}) {
    try {
      read_png(path);
      ADD_FAILURE() << path << " was read";
    } catch (const InputError& error) {
      EXPECT_EQ(error.where().file, path);
      EXPECT_EQ(std::string(error.what()).find('\n'), std::string::npos);
    }
  }
}

// The chunk checksum PNG uses (CRC-32, ISO 3309), to forge a header.
std::uint32_t crc32(const std::string& bytes) {
  std::uint32_t crc = 0xFFFFFFFFu;
  for (const unsigned char b : bytes) {
    crc ^= b;
    for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
  }
  return ~crc;
}

std::string big_endian(std::uint32_t v) {
  return {char(v >> 24), char((v >> 16) & 0xFF), char((v >> 8) & 0xFF), char(v & 0xFF)};
}

// A 1 × 1 image whose header claims 20000 × 20000 pixels (1.6 GB): refused before allocating.
TEST(PngImage, RefusesAHeaderClaimingBillionsOfBytes) {
  test::TempDir dir;
  std::string bytes = png_bytes(Image(1, 1));
  const std::string claimed = big_endian(20000) + big_endian(20000);
  bytes.replace(16, 8, claimed);                       // IHDR's width and height
  bytes.replace(29, 4, big_endian(crc32(bytes.substr(12, 17))));  // its type and data
  try {
    read_png(dir.write("forged.png", bytes));
    ADD_FAILURE() << "read";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("more than 67108864 pixels"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace fabform::png_image_test
