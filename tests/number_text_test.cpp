// NumberText writes what an ostringstream with the same precision writes, byte for byte: the
// result files keep their exact text. Checked over random doubles at every scale, the values
// whose rounding is awkward, signed zeros and non-finite values, and integers of every width.
#include "fabform/number_text.hpp"

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <sstream>

#include <gtest/gtest.h>

namespace fabform::number_text_test {
namespace {

std::string streamed(double value, int precision) {
  std::ostringstream out;
  out.precision(precision);
  out << value;
  return out.str();
}

std::string written(double value, int precision) {
  NumberText text(precision);
  text << value;
  return text.str();
}

TEST(NumberText, DoublesAsAStreamWritesThem) {
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> mantissa(-10.0, 10.0);
  std::uniform_int_distribution<int> exponent(-320, 308);
  for (const int precision : {6, 10, 12, 17}) {
    for (int t = 0; t < 20000; ++t) {
      const double v = std::ldexp(mantissa(random), exponent(random) / 3);
      ASSERT_EQ(written(v, precision), streamed(v, precision)) << v;
    }
    for (const double v : {0.0, -0.0, 1.0, -1.0, 0.5, 1e-5, 1e-4, 123456789012.0, 1234567890123.0, 9.9999999999995,
                           0.1 + 0.2, 5e-324, std::numeric_limits<double>::max(), std::numeric_limits<double>::min(),
                           std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()})
      EXPECT_EQ(written(v, precision), streamed(v, precision)) << v;
  }
}

TEST(NumberText, IntegersTextAndCharacters) {
  NumberText text;
  text << "v " << 0 << ' ' << -7 << ' ' << std::size_t{18446744073709551615ULL} << ' ' << std::int64_t{-9223372036854775807LL}
       << std::string(" end") << '\n';
  EXPECT_EQ(text.str(), "v 0 -7 18446744073709551615 -9223372036854775807 end\n");
}

TEST(NumberText, PrecisionIsClampedToWhatADoubleHolds) {
  EXPECT_EQ(written(1.0 / 3.0, 0), streamed(1.0 / 3.0, 1));
  EXPECT_EQ(written(1.0 / 3.0, 40), streamed(1.0 / 3.0, 17));
}

}  // namespace
}  // namespace fabform::number_text_test
