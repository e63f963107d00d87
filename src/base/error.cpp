#include "bezcam/error.hpp"

#include <charconv>

namespace bezcam {

namespace {
std::string compose(const std::string& where, const std::string& what) {
  return where.empty() ? what : where + ": " + what;
}
}  // namespace

Error::Error(ErrorFamily family, std::string id, std::string where, std::string what)
    : std::runtime_error(compose(where, what)),
      family_(family),
      id_(std::move(id)),
      where_(std::move(where)),
      message_(std::move(what)) {}

int Error::exit_code() const noexcept {
  switch (family_) {
    case ErrorFamily::input: return 2;
    case ErrorFamily::io: return 3;
    case ErrorFamily::controller: return 4;
  }
  return 2;
}

std::string fmt_num(double v) {
  char buf[64];
  auto res = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, res.ptr);
}

}  // namespace bezcam
