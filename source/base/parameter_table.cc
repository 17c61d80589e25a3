#include <fgimpact/base/parameter_table.h>

#include <charconv>
#include <cmath>

namespace fgimpact
{
  std::string
  prm_string(const double value)
  {
    // Plain decimals in [1e-4, 1e6), as one writes them ("0.2", "2707");
    // outside, engineering notation as SI values are written ("70e9",
    // "1e-6", "25e-6") where it needs at most one padding zero. to_chars
    // without a precision gives the shortest digits that read back as the same
    // double.
    const double magnitude = std::abs(value);
    char         buffer[64];
    if (value == 0. || (magnitude >= 1e-4 && magnitude < 1e6))
      {
        const auto end = std::to_chars(buffer,
                                       buffer + sizeof(buffer),
                                       value,
                                       std::chars_format::fixed)
                           .ptr;
        return std::string(buffer, end);
      }
    const auto end = std::to_chars(buffer,
                                   buffer + sizeof(buffer),
                                   value,
                                   std::chars_format::scientific)
                       .ptr;
    // "-3.8e+11": sign, digits "38", exponent 11.
    const std::string text(buffer, end);
    const auto        e        = text.find('e');
    const int         exponent = std::stoi(text.substr(e + 1));
    const std::string sign     = value < 0 ? "-" : "";
    std::string       digits;
    for (const char c : text.substr(0, e))
      if (c >= '0' && c <= '9')
        digits += c;
    // The mantissa in [1, 1000), exponent a multiple of 3 ("380e9"),
    // unless that pads it with two zeros ("3e8", not "300e6").
    int shift = ((exponent % 3) + 3) % 3;
    if (digits.size() + 2 <= static_cast<std::size_t>(shift) + 1)
      shift = 0;
    while (digits.size() < static_cast<std::size_t>(shift) + 1)
      digits += '0';
    std::string mantissa = digits.substr(0, shift + 1);
    if (digits.size() > static_cast<std::size_t>(shift) + 1)
      mantissa += "." + digits.substr(shift + 1);
    return sign + mantissa + "e" + std::to_string(exponent - shift);
  }



  std::string
  prm_string(const unsigned int value)
  {
    return std::to_string(value);
  }



  std::string
  prm_string(const int value)
  {
    return std::to_string(value);
  }



  std::string
  prm_string(const bool value)
  {
    return value ? "true" : "false";
  }



  std::string
  prm_string(const std::string &value)
  {
    return value;
  }
} // namespace fgimpact
