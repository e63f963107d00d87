#include "bezcam/link/crc32.hpp"

#include <array>
#include <cstdio>

namespace bezcam::link {

namespace {
// Sarwate's table-driven CRC ("Computation of Cyclic Redundancy Checks via
// Table Look-Up", CACM 1988): one table entry per byte value, built once at
// compile time from the reflected polynomial.
constexpr std::array<std::uint32_t, 256> make_table() {
  std::array<std::uint32_t, 256> t{};
  for (std::uint32_t i = 0; i < 256; ++i) {
    std::uint32_t c = i;
    for (int k = 0; k < 8; ++k) c = (c & 1u) ? (0xEDB88320u ^ (c >> 1)) : (c >> 1);
    t[i] = c;
  }
  return t;
}
constexpr auto kTable = make_table();
}  // namespace

void Crc32::update(const void* data, std::size_t n) noexcept {
  const auto* p = static_cast<const unsigned char*>(data);
  std::uint32_t c = state_;
  for (std::size_t i = 0; i < n; ++i) c = kTable[(c ^ p[i]) & 0xFFu] ^ (c >> 8);
  state_ = c;
}

std::uint32_t crc32(std::string_view bytes) noexcept {
  Crc32 c;
  c.update(bytes);
  return c.value();
}

std::string hex32(std::uint32_t v) {
  char b[16];
  std::snprintf(b, sizeof b, "%08X", v);
  return b;
}

}  // namespace bezcam::link
