#include "hullcover/bvh/runtime_file.h"
#include "hullcover/geometry/little_endian_bytes.h"

#include "query_guard.h"

#include "hullcover/geometry/atomic_file.h"
#include "hullcover/geometry/regular_file.h"
#include "hullcover/geometry/tolerances.h"

#include <cmath>
#include <cstring>
#include <map>

namespace hullcover::bvh {
namespace {

constexpr char kMagic[8] = {'H', 'C', 'W', 'O', 'R', 'L', 'D', '\0'};
constexpr size_t kHeaderBytes = 8 + 4 + 4 + 8 + 8 + 8;
constexpr size_t kHullFixedBytes = 5 * 4 + 6 * 8;

struct Writer {
  std::vector<unsigned char> bytes;
  void u32(std::uint32_t v) {
    for (int k = 0; k < 4; ++k) bytes.push_back(static_cast<unsigned char>(v >> (8 * k)));
  }
  void u64(std::uint64_t v) {
    for (int k = 0; k < 8; ++k) bytes.push_back(static_cast<unsigned char>(v >> (8 * k)));
  }
  void f64(double d) {
    std::uint64_t v;
    std::memcpy(&v, &d, 8);
    u64(v);
  }
};

struct Reader {
  const unsigned char* data;
  size_t size;
  size_t at = 0;
  bool has(size_t n) const { return size - at >= n; }
  std::uint32_t u32() {
    std::uint32_t v = 0;
    for (int k = 0; k < 4; ++k) v |= static_cast<std::uint32_t>(data[at + k]) << (8 * k);
    at += 4;
    return v;
  }
  std::uint64_t u64() {
    std::uint64_t v = 0;
    for (int k = 0; k < 8; ++k) v |= static_cast<std::uint64_t>(data[at + k]) << (8 * k);
    at += 8;
    return v;
  }
  double f64() {
    const std::uint64_t v = u64();
    double d;
    std::memcpy(&d, &v, 8);
    return d;
  }
  /// n doubles at once: one copy on a little-endian host.
  void f64s(double* out, size_t n) {
    if (host_is_little_endian()) {
      std::memcpy(out, data + at, 8 * n);
      at += 8 * n;
    } else {
      for (size_t i = 0; i < n; ++i) out[i] = f64();
    }
  }
  static bool host_is_little_endian() {
    const std::uint32_t one = 1;
    unsigned char first;
    std::memcpy(&first, &one, 1);
    return first == 1;
  }
};

Status broken(const std::string& path, const std::string& what) {
  return {StatusCode::unreadable_file, path + ": broken runtime file: " + what};
}

// Each section's hulls, ascending ids and indices: one section 0 holding
// every hull when `section_of_hull` is null.
Result<std::map<std::uint32_t, std::vector<int>>> sections_of(size_t hull_count,
                                                              const std::vector<std::uint32_t>* section_of_hull) {
  if (section_of_hull && section_of_hull->size() != hull_count)
    return Status{StatusCode::invalid_argument, "section_of_hull has " + std::to_string(section_of_hull->size()) +
                                                    " entries for " + std::to_string(hull_count) + " hulls"};
  std::map<std::uint32_t, std::vector<int>> sections;
  for (size_t h = 0; h < hull_count; ++h)
    sections[section_of_hull ? (*section_of_hull)[h] : 0u].push_back(static_cast<int>(h));
  return sections;
}

Status write_hulls(const std::vector<RuntimeHull>& hulls, const std::string& path,
                   const std::vector<std::uint32_t>* section_of_hull) {
  Result<std::map<std::uint32_t, std::vector<int>>> sections = sections_of(hulls.size(), section_of_hull);
  if (!sections.ok()) return sections.status();
  Writer payload;
  for (const RuntimeHull& h : hulls) {
    const ConvexPolytope& s = h.shape;
    size_t indices = 0;
    for (const std::vector<int>& f : s.facets) indices += f.size();
    payload.u32(static_cast<std::uint32_t>(h.material));
    payload.u32(static_cast<std::uint32_t>(s.vertices.size()));
    payload.u32(static_cast<std::uint32_t>(s.facets.size()));
    payload.u32(static_cast<std::uint32_t>(s.planes.size()));
    payload.u32(static_cast<std::uint32_t>(indices));
    for (int k = 0; k < 3; ++k) payload.f64(h.box.min[k]);
    for (int k = 0; k < 3; ++k) payload.f64(h.box.max[k]);
    for (const Eigen::Vector3d& v : s.vertices)
      for (int k = 0; k < 3; ++k) payload.f64(v[k]);
    for (const Plane& p : s.planes) {
      for (int k = 0; k < 3; ++k) payload.f64(p.normal[k]);
      payload.f64(p.offset);
    }
    for (const std::vector<int>& f : s.facets) payload.u32(static_cast<std::uint32_t>(f.size()));
    for (const std::vector<int>& f : s.facets)
      for (int v : f) payload.u32(static_cast<std::uint32_t>(v));
    const bool flags = h.surface_planes.size() == s.planes.size();
    payload.u32(flags ? static_cast<std::uint32_t>(s.planes.size()) : 0u);
    if (flags)
      for (bool on_surface : h.surface_planes) payload.bytes.push_back(on_surface ? 1 : 0);
  }
  payload.u32(static_cast<std::uint32_t>(sections.value().size()));
  for (const auto& [id, members] : sections.value()) {
    payload.u32(id);
    payload.u32(static_cast<std::uint32_t>(members.size()));
    for (int h : members) payload.u32(static_cast<std::uint32_t>(h));
  }
  Writer file{std::vector<unsigned char>(kMagic, kMagic + 8)};
  file.u32(kRuntimeFileVersion);
  file.u32(0);
  file.u64(hulls.size());
  file.u64(payload.bytes.size());
  file.u64(fnv1a(payload.bytes.data(), payload.bytes.size()));
  return write_file_atomically(path, [&file, &payload](std::FILE* out) {
    std::fwrite(file.bytes.data(), 1, file.bytes.size(), out);
    std::fwrite(payload.bytes.data(), 1, payload.bytes.size(), out);
    return true; // a short write sets the stream's error flag, which the caller checks
  });
}

// A runtime file whose header, sizes, checksum and section table are
// checked, with where each hull starts: its hulls are parsed only when asked
// for, so a section's read checks that section's values alone.
struct CheckedFile {
  std::string path;
  std::string content; // the file's bytes, parsed in place (a copy would double a large file's memory)
  std::uint32_t version = 0;
  std::vector<size_t> hull_at; // offset of each hull in `content`
  std::vector<RuntimeSection> sections;
};

// Walks hull `h` from r.at by its sizes alone (values are parse_hull's).
Status skip_hull(Reader& r, const CheckedFile& f, std::uint64_t h) {
  const std::string where = "hull " + std::to_string(h) + ": ";
  if (!r.has(kHullFixedBytes)) return broken(f.path, where + "truncated");
  r.u32();
  const std::uint64_t V = r.u32(), F = r.u32(), P = r.u32(), I = r.u32();
  const std::uint64_t body = 6 * 8 + V * 24 + P * 32 + F * 4 + I * 4;
  if (!r.has(body)) return broken(f.path, where + "sizes run past the end");
  r.at += body;
  if (f.version >= 2) {
    if (!r.has(4)) return broken(f.path, where + "truncated");
    const std::uint64_t flags = r.u32();
    if (!r.has(flags)) return broken(f.path, where + "sizes run past the end");
    r.at += flags;
  }
  return Status::success();
}

// The section table after the hulls (version 3): every hull in exactly one
// section, ids and indices ascending.
Status read_sections(Reader& r, CheckedFile& f) {
  const std::uint64_t hull_count = f.hull_at.size();
  if (f.version < 3) {
    if (hull_count > 0) f.sections.push_back({0, std::vector<int>(hull_count)});
    for (std::uint64_t h = 0; h < hull_count; ++h) f.sections[0].hulls[h] = static_cast<int>(h);
    return Status::success();
  }
  if (!r.has(4)) return broken(f.path, "section table truncated");
  const std::uint64_t count = r.u32();
  if (count > (r.size - r.at) / 8) return broken(f.path, "section count larger than the section table");
  std::vector<bool> owned(hull_count, false);
  for (std::uint64_t i = 0; i < count; ++i) {
    if (!r.has(8)) return broken(f.path, "section table truncated");
    const std::uint32_t id = r.u32();
    const std::uint64_t members = r.u32();
    const std::string where = "section " + std::to_string(id) + ": ";
    if (!f.sections.empty() && id <= f.sections.back().id)
      return broken(f.path, where + "section ids not ascending (or repeated)");
    if (members == 0) return broken(f.path, where + "holds no hull");
    if (members > (r.size - r.at) / 4) return broken(f.path, where + "hull count runs past the end");
    RuntimeSection section{id, std::vector<int>(members)};
    for (std::uint64_t k = 0; k < members; ++k) {
      const std::uint32_t h = r.u32();
      if (h >= hull_count) return broken(f.path, where + "hull index " + std::to_string(h) + " out of range");
      if (k > 0 && static_cast<int>(h) <= section.hulls[k - 1])
        return broken(f.path, where + "hull indices not ascending");
      if (owned[h]) return broken(f.path, where + "hull " + std::to_string(h) + " is in two sections");
      owned[h] = true;
      section.hulls[k] = static_cast<int>(h);
    }
    f.sections.push_back(std::move(section));
  }
  for (std::uint64_t h = 0; h < hull_count; ++h)
    if (!owned[h]) return broken(f.path, "hull " + std::to_string(h) + " is in no section");
  return Status::success();
}

// Reads the file and checks everything but the hulls' values.
Result<CheckedFile> check_file(const std::string& path) {
  CheckedFile f;
  f.path = path;
  Result<std::string> content = read_regular_file(path);
  if (!content.ok()) return content.status();
  f.content = std::move(content).value();
  const auto* bytes = reinterpret_cast<const unsigned char*>(f.content.data());
  const size_t size = f.content.size();
  Reader r{bytes, size};
  if (!r.has(kHeaderBytes) || std::memcmp(bytes, kMagic, 8) != 0)
    return Status{StatusCode::unknown_format, path + ": not a hullcover runtime file (no HCWORLD header)"};
  r.at = 8;
  f.version = r.u32();
  if (f.version < kRuntimeFileFirstVersion || f.version > kRuntimeFileVersion)
    return Status{StatusCode::unknown_format,
                  path + ": runtime file version " + std::to_string(f.version) + ", this build reads versions " +
                      std::to_string(kRuntimeFileFirstVersion) + " to " + std::to_string(kRuntimeFileVersion)};
  r.u32();
  const std::uint64_t hull_count = r.u64(), payload_bytes = r.u64(), checksum = r.u64();
  if (payload_bytes != size - kHeaderBytes)
    return broken(path, "payload is " + std::to_string(size - kHeaderBytes) + " bytes, header says " +
                            std::to_string(payload_bytes));
  if (fnv1a(bytes + kHeaderBytes, payload_bytes) != checksum) return broken(path, "checksum mismatch");
  if (hull_count > payload_bytes / kHullFixedBytes) return broken(path, "hull count larger than the payload");
  f.hull_at.reserve(hull_count);
  for (std::uint64_t h = 0; h < hull_count; ++h) {
    f.hull_at.push_back(r.at);
    if (Status s = skip_hull(r, f, h); !s.ok()) return s;
  }
  if (Status s = read_sections(r, f); !s.ok()) return s;
  if (r.at != size)
    return broken(path, f.version >= 3 ? "bytes left after the section table" : "bytes left after the last hull");
  return f;
}

// Parses and checks hull `h` of a checked file.
Result<RuntimeHull> parse_hull(const CheckedFile& f, std::uint64_t h) {
  const std::string& path = f.path;
  Reader r{reinterpret_cast<const unsigned char*>(f.content.data()), f.content.size(), f.hull_at[h]};
  const std::string where = "hull " + std::to_string(h) + ": ";
  RuntimeHull hull;
  hull.material = static_cast<int>(r.u32());
  const std::uint64_t V = r.u32(), F = r.u32(), P = r.u32(), I = r.u32();
  for (int k = 0; k < 3; ++k) hull.box.min[k] = r.f64();
  for (int k = 0; k < 3; ++k) hull.box.max[k] = r.f64();
  if (V < 3 || F < 2 || P < F) return broken(path, where + "too few vertices, facets or planes");
  ConvexPolytope& s = hull.shape;
  s.vertices.resize(V);
  static_assert(sizeof(Eigen::Vector3d) == 3 * sizeof(double), "packed vertices");
  r.f64s(s.vertices.front().data(), 3 * V);
  s.planes.resize(P);
  for (Plane& p : s.planes) {
    double q[4];
    r.f64s(q, 4);
    p.normal = Eigen::Vector3d(q[0], q[1], q[2]);
    p.offset = q[3];
    if (!p.normal.allFinite() || !std::isfinite(p.offset) || std::abs(p.normal.norm() - 1.0) > kUnitNormalSlack)
      return broken(path, where + "a plane is not finite or its normal not of unit length");
  }
  for (const Eigen::Vector3d& v : s.vertices)
    if (!v.allFinite()) return broken(path, where + "a vertex is not finite");
  if (!hull.box.min.allFinite() || !hull.box.max.allFinite()) return broken(path, where + "box not finite");
  s.facets.resize(F);
  std::uint64_t total = 0;
  for (std::vector<int>& facet : s.facets) {
    const std::uint32_t n = r.u32();
    if (n < 3) return broken(path, where + "a facet has fewer than 3 corners");
    if (n > I - total) return broken(path, where + "facet sizes add up to more than the index count");
    facet.resize(n);
    total += n;
  }
  if (total != I) return broken(path, where + "facet sizes do not add up to the index count");
  for (std::vector<int>& facet : s.facets)
    for (int& v : facet) {
      const std::uint32_t index = r.u32();
      if (index >= V) return broken(path, where + "facet index " + std::to_string(index) + " out of range");
      v = static_cast<int>(index);
    }
  std::vector<bool> surface_planes;
  if (f.version >= 2) {
    const std::uint64_t flags = r.u32(); // within the file: skip_hull walked it
    if (flags != 0 && flags != P) return broken(path, where + "surface flags neither absent nor one per plane");
    for (std::uint64_t i = 0; i < flags; ++i) {
      const unsigned char flag = r.data[r.at++];
      if (flag > 1) return broken(path, where + "a surface flag is neither 0 nor 1");
      surface_planes.push_back(flag == 1);
    }
  }
  RuntimeHull full = make_runtime_hull(std::move(s), hull.material);
  full.surface_planes = std::move(surface_planes);
  if (full.box.min != hull.box.min || full.box.max != hull.box.max)
    return broken(path, where + "bounding box does not match its vertices");
  return full;
}

Result<std::vector<RuntimeHull>> read_hulls(const std::string& path) {
  Result<CheckedFile> f = check_file(path);
  if (!f.ok()) return f.status();
  std::vector<RuntimeHull> hulls;
  hulls.reserve(f.value().hull_at.size());
  for (size_t h = 0; h < f.value().hull_at.size(); ++h) {
    Result<RuntimeHull> hull = parse_hull(f.value(), h);
    if (!hull.ok()) return hull.status();
    hulls.push_back(std::move(hull).value());
  }
  return hulls;
}

Result<SectionHulls> read_section(const std::string& path, std::uint32_t id) {
  Result<CheckedFile> f = check_file(path);
  if (!f.ok()) return f.status();
  for (RuntimeSection& section : f.value().sections) {
    if (section.id != id) continue;
    SectionHulls out{id, std::move(section.hulls), {}};
    out.hulls.reserve(out.indices.size());
    for (int h : out.indices) {
      Result<RuntimeHull> hull = parse_hull(f.value(), static_cast<std::uint64_t>(h));
      if (!hull.ok()) return hull.status();
      out.hulls.push_back(std::move(hull).value());
    }
    return out;
  }
  return Status{StatusCode::invalid_argument, path + ": no section " + std::to_string(id)};
}

} // namespace

Status write_runtime_file(const std::vector<RuntimeHull>& hulls, const std::string& path,
                          const std::vector<std::uint32_t>* section_of_hull) {
  return detail::guarded("writing the runtime file", [&] { return write_hulls(hulls, path, section_of_hull); });
}

Result<std::vector<RuntimeHull>> read_runtime_file(const std::string& path) {
  return detail::guarded("reading the runtime file", [&] { return read_hulls(path); });
}

Result<std::vector<RuntimeSection>> read_runtime_sections(const std::string& path) {
  return detail::guarded("reading the runtime file's sections", [&]() -> Result<std::vector<RuntimeSection>> {
    Result<CheckedFile> f = check_file(path);
    if (!f.ok()) return f.status();
    return std::move(f.value().sections);
  });
}

Result<SectionHulls> read_runtime_section(const std::string& path, std::uint32_t id) {
  return detail::guarded("reading a runtime file section", [&] { return read_section(path, id); });
}

} // namespace hullcover::bvh
