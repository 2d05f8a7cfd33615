#include "ply_file_checks.h"

#include "ply_ascii_checks.h"
#include "ply_header.h"
#include "scene_file_rules.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

namespace hullcover::detail {
namespace {

// Binary real-valued lengths are clamped here before the cast to an integer
// (defined behaviour); any length this long is refused anyway.
constexpr double kRealLengthCeiling = 0x1p62;

// A binary list length as Assimp reads it: its type, in the file's byte
// order (a real one truncated). Nothing for a NaN.
std::optional<std::int64_t> binary_length(const unsigned char* raw, ScalarType type, bool big_endian) {
  std::uint64_t bits = 0;
  for (int i = 0; i < type.bytes; ++i) bits = bits << 8 | raw[big_endian ? i : type.bytes - 1 - i];
  if (type.number == Number::unsigned_integer) return static_cast<std::int64_t>(bits); // at most 32 bits
  if (type.number == Number::signed_integer) {
    const std::uint64_t sign = std::uint64_t{1} << (8 * type.bytes - 1);
    return static_cast<std::int64_t>(bits ^ sign) - static_cast<std::int64_t>(sign);
  }
  double length = 0;
  if (type.bytes == sizeof(float)) {
    const auto narrow = static_cast<std::uint32_t>(bits);
    float f = 0;
    std::memcpy(&f, &narrow, sizeof f);
    length = f;
  } else {
    std::memcpy(&length, &bits, sizeof length);
  }
  if (std::isnan(length)) return std::nullopt;
  return static_cast<std::int64_t>(std::clamp(length, -kRealLengthCeiling, kRealLengthCeiling));
}

Status walk_binary(BodyReader& body, const std::vector<Element>& elements, bool big_endian) {
  for (const Element& e : elements) {
    if (!e.has_list()) {
      // Fixed-size instances: one skip however many (the size check keeps
      // count x bytes within 64 bits).
      if (!body.skip(e.count * e.least_bytes)) return damaged_file("PLY data ends inside the " + e.name + " elements");
      continue;
    }
    for (std::uint64_t i = 0; i < e.count; ++i) {
      for (const Property& p : e.properties) {
        if (!p.is_list) {
          if (!body.skip(static_cast<std::uint64_t>(p.value.bytes))) return ends_inside(instance(e, i), e);
          continue;
        }
        unsigned char raw[sizeof(double)] = {};
        if (!body.read(raw, static_cast<std::size_t>(p.length.bytes))) return ends_inside(instance(e, i), e);
        const std::optional<std::int64_t> items = binary_length(raw, p.length, big_endian);
        if (!items)
          return damaged_file("PLY " + instance(e, i) + " has a " + p.name + " list whose length is not a number");
        if (*items < 0)
          return damaged_file("PLY " + instance(e, i) + " has a " + p.name + " list of " + std::to_string(*items) +
                              " items (a negative length)");
        const auto item_bytes = static_cast<std::uint64_t>(p.value.bytes);
        // Compared by division: items x bytes may not fit 64 bits.
        if (static_cast<std::uint64_t>(*items) > body.left() / item_bytes)
          return too_long(instance(e, i), p, std::to_string(*items), body.left(), item_bytes);
        body.skip(static_cast<std::uint64_t>(*items) * item_bytes);
      }
    }
  }
  return Status::success();
}

} // namespace

Status check_ply(std::ifstream& in, std::uint64_t file_bytes) {
  PlyHeader h;
  if (Status header = read_ply_header(in, file_bytes, h); !header.ok()) return header;
  const std::uint64_t data_at = h.ascii ? h.after_line : h.data_at;
  const std::uint64_t body = file_bytes - std::min(file_bytes, data_at);

  // Every element takes at least its scalars' bytes and each list's length
  // (binary), or two characters a property (ASCII: a digit and a separator).
  std::uint64_t needed = 0;
  for (Element& e : h.elements) {
    for (const Property& p : e.properties) {
      const int binary_bytes = p.is_list ? p.length.bytes : p.value.bytes;
      e.least_bytes += h.ascii ? kAsciiItemBytes : static_cast<std::uint64_t>(binary_bytes);
    }
    if (e.least_bytes == 0 && e.count > 0)
      return damaged_file("PLY element '" + e.name + "' has no properties but a count of " + std::to_string(e.count));
    // Compared by division: count x bytes may not fit 64 bits.
    if (e.least_bytes > 0 && e.count > (body + 1) / e.least_bytes)
      return damaged_file("PLY declares " + std::to_string(e.count) + " " + e.name + " elements, more than its " +
                          std::to_string(body) + " bytes of data can hold");
    needed += e.count * e.least_bytes;
    if (needed > body + 1)
      return damaged_file("PLY elements need at least " + std::to_string(needed) + " bytes; the data has " +
                          std::to_string(body));
  }
  // An element Assimp does not count shifts where it reads every later one.
  for (auto e = h.elements.begin(); e != h.elements.end(); ++e) {
    const bool later_data = std::any_of(e + 1, h.elements.end(), [](const Element& l) { return l.count > 0; });
    if (e->assimp_count() > e->count || (e->assimp_count() != e->count && later_data))
      return damaged_file("PLY element '" + e->name + "' (" + std::to_string(e->count) +
                          ") is not one Assimp counts (vertex, face, tristrips, edge, material): it would read " +
                          std::to_string(e->assimp_count()) + " of it and the elements after it from the wrong place");
  }

  if (std::none_of(h.elements.begin(), h.elements.end(), [](const Element& e) { return e.has_list(); }))
    return Status::success();
  if (!h.ascii) {
    BodyReader data(in, data_at, body);
    return walk_binary(data, h.elements, h.big_endian);
  }
  {
    BodyReader data(in, data_at, body);
    if (Status tokens = walk_ascii_tokens(data, h.elements); !tokens.ok()) return tokens;
  }
  BodyReader data(in, data_at, body);
  return walk_assimp_lines(data, h.elements, h.line_number, body);
}

} // namespace hullcover::detail
