#pragma once
/// CRC-32 as used by the Modbus program link (docs/modbus-register-map.md):
/// the IEEE 802.3 / zlib polynomial, reflected (0xEDB88320), initial value
/// and final XOR 0xFFFFFFFF. Check value: crc32("123456789") == 0xCBF43926.
#include <cstdint>
#include <string>
#include <string_view>

namespace bezcam::link {

/// Incremental CRC-32: feed bytes in any number of pieces; value() is the
/// CRC of everything fed so far (0 when nothing was fed).
class Crc32 {
 public:
  void update(const void* data, std::size_t n) noexcept;
  void update(std::string_view s) noexcept { update(s.data(), s.size()); }
  std::uint32_t value() const noexcept { return ~state_; }

 private:
  std::uint32_t state_ = 0xFFFFFFFFu;
};

/// CRC-32 of a whole byte string.
std::uint32_t crc32(std::string_view bytes) noexcept;

/// A 32-bit value as messages show CRC-32s, session ids and the magic
/// register: eight upper-case hexadecimal digits (0xCBF43926 -> "CBF43926").
std::string hex32(std::uint32_t v);

}  // namespace bezcam::link
