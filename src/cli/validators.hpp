#pragma once
// Checks of option values that CLI11 does not say plainly enough.
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdlib>
#include <string>

namespace bezcam::cli {

/// A number > 0, said plainly ("expected a number > 0, found -1"), not as
/// CLI11's range up to the largest double.
inline CLI::Validator positive_number() {
  return CLI::Validator(
      [](std::string& s) -> std::string {
        char* end = nullptr;
        const double v = std::strtod(s.c_str(), &end);
        if (end == s.c_str() || *end != '\0' || !(v > 0) || !std::isfinite(v))
          return "expected a number > 0, found " + s;
        return {};
      },
      "NUMBER > 0");
}

}  // namespace bezcam::cli
