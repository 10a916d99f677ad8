#pragma once
// Text built from numbers the way an ostringstream with precision(p) writes them ("%.<p>g" for
// doubles), byte for byte, but through std::to_chars: a million-node fabric.vtk is 10^7
// numbers, and the stream's locale-aware formatting was most of the time spent writing results.
#include <string>
#include <string_view>
#include <type_traits>

namespace fabform {

class NumberText {
 public:
  /// `precision`: significant digits of a double, as std::ostream::precision (1 ... 17).
  explicit NumberText(int precision = 6);

  NumberText& operator<<(double value);
  NumberText& operator<<(char c) { text_ += c; return *this; }
  NumberText& operator<<(std::string_view s) { text_ += s; return *this; }
  NumberText& operator<<(const char* s) { text_ += s; return *this; }
  NumberText& operator<<(const std::string& s) { text_ += s; return *this; }
  template <class Integer, std::enable_if_t<std::is_integral_v<Integer> && !std::is_same_v<Integer, char> &&
                                                !std::is_same_v<Integer, bool>, int> = 0>
  NumberText& operator<<(Integer value) {
    if constexpr (std::is_unsigned_v<Integer>) return append_unsigned(value);
    else return append_signed(value);
  }

  const std::string& str() const { return text_; }

 private:
  NumberText& append_signed(long long value);
  NumberText& append_unsigned(unsigned long long value);

  int precision_;
  std::string text_;
};

}  // namespace fabform
