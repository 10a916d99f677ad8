// PNG images through libpng: what is written reads back pixel for pixel; what is not a PNG is
// refused with an InputError naming the file.
#include <gtest/gtest.h>

#include "fabform/error.hpp"
#include "fabform/io/png_image.hpp"
#include "support/temp_dir.hpp"

namespace fabform {
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

}  // namespace
}  // namespace fabform
