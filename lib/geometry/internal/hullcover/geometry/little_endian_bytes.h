#pragma once
/// \file little_endian_bytes.h
/// The byte order of hullcover's binary files (`.hcw` runtime files, cell
/// results): integers unsigned little-endian, reals IEEE-754 binary64
/// little-endian, whatever the host; and the FNV-1a-64 checksum they carry.

#include <cstdint>
#include <cstring>
#include <string>

namespace hullcover {

/// FNV-1a-64 of `size` bytes, continuing from `hash` (start: the offset basis).
inline std::uint64_t fnv1a(const unsigned char* data, size_t size, std::uint64_t hash = 0xcbf29ce484222325ull) {
  for (size_t i = 0; i < size; ++i) hash = (hash ^ data[i]) * 0x100000001b3ull;
  return hash;
}

/// Appends values to a byte string.
struct LittleEndianWriter {
  std::string bytes;
  void u8(std::uint8_t v) { bytes.push_back(static_cast<char>(v)); }
  void u32(std::uint32_t v) {
    for (int k = 0; k < 4; ++k) bytes.push_back(static_cast<char>(v >> (8 * k)));
  }
  void u64(std::uint64_t v) {
    for (int k = 0; k < 8; ++k) bytes.push_back(static_cast<char>(v >> (8 * k)));
  }
  void i32(std::int32_t v) { u32(static_cast<std::uint32_t>(v)); }
  void f64(double d) {
    std::uint64_t v;
    std::memcpy(&v, &d, 8);
    u64(v);
  }
};

/// Reads values from bytes it does not own. Every read first checks that
/// the bytes are there: past the end it returns 0 and sets `failed`, so a
/// caller checks once, after reading a record, instead of before each value.
struct LittleEndianReader {
  const unsigned char* data = nullptr;
  size_t size = 0;
  size_t at = 0;
  bool failed = false;

  /// Whether `n` more bytes are left.
  bool has(size_t n) const { return !failed && size - at >= n; }
  std::uint64_t unsigned_of(int bytes) {
    if (!has(static_cast<size_t>(bytes))) {
      failed = true;
      return 0;
    }
    std::uint64_t v = 0;
    for (int k = 0; k < bytes; ++k) v |= static_cast<std::uint64_t>(data[at + k]) << (8 * k);
    at += static_cast<size_t>(bytes);
    return v;
  }
  std::uint8_t u8() { return static_cast<std::uint8_t>(unsigned_of(1)); }
  std::uint32_t u32() { return static_cast<std::uint32_t>(unsigned_of(4)); }
  std::uint64_t u64() { return unsigned_of(8); }
  std::int32_t i32() { return static_cast<std::int32_t>(u32()); }
  double f64() {
    const std::uint64_t v = u64();
    double d;
    std::memcpy(&d, &v, 8);
    return d;
  }
};

} // namespace hullcover
