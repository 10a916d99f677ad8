#include "fabform/number_text.hpp"

#include <algorithm>
#include <charconv>

namespace fabform {

NumberText::NumberText(int precision) : precision_(std::clamp(precision, 1, 17)) {}

NumberText& NumberText::operator<<(double value) {
  char digits[32];  // "-d.dddddddddddddddde-308": 24 at 17 digits
  text_.append(digits, std::to_chars(digits, digits + sizeof digits, value, std::chars_format::general, precision_).ptr);
  return *this;
}

NumberText& NumberText::append_signed(long long value) {
  char digits[24];
  text_.append(digits, std::to_chars(digits, digits + sizeof digits, value).ptr);
  return *this;
}

NumberText& NumberText::append_unsigned(unsigned long long value) {
  char digits[24];
  text_.append(digits, std::to_chars(digits, digits + sizeof digits, value).ptr);
  return *this;
}

}  // namespace fabform
