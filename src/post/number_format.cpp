#include "bezcam/post/number_format.hpp"

#include <charconv>
#include <cmath>

namespace bezcam {

std::string format_number(double v, int decimals) {
  char buf[400];
  auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, decimals < 0 ? 6 : decimals);
  std::string s(buf, r.ptr);
  if (s.find('.') == std::string::npos) s += '.';
  while (s.back() == '0') s.pop_back();
  if (s == "-0.") s = "0.";
  return s;
}

}  // namespace bezcam
