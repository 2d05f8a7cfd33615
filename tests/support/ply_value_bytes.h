#pragma once
// A value's bytes as a binary PLY file stores it (tests that write binary
// PLY bodies by hand).

#include <cstdint>
#include <cstring>
#include <string>
#include <type_traits>

namespace hullcover::test {

/// `value`'s bytes (an integer, a float or a double) in the given byte order.
template <class T>
std::string ply_value_bytes(T value, bool big_endian) {
  std::uint64_t bits = 0;
  if constexpr (std::is_floating_point_v<T>) {
    static_assert(sizeof(T) == sizeof(std::uint32_t) || sizeof(T) == sizeof(std::uint64_t));
    if constexpr (sizeof(T) == sizeof(std::uint32_t)) {
      std::uint32_t narrow = 0;
      std::memcpy(&narrow, &value, sizeof narrow);
      bits = narrow;
    } else {
      std::memcpy(&bits, &value, sizeof bits);
    }
  } else {
    bits = static_cast<std::make_unsigned_t<T>>(value);
  }
  std::string bytes(sizeof(T), '\0');
  for (std::size_t i = 0; i < sizeof(T); ++i)
    bytes[big_endian ? sizeof(T) - 1 - i : i] = static_cast<char>(bits >> (8 * i) & 0xff);
  return bytes;
}

} // namespace hullcover::test
