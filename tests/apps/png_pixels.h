#pragma once
// Reads a PNG back with cairo (the library that wrote it, but through its
// decoder) and measures what a picture test asks: size, distinct colours,
// saturated pixels and their hues, pixels near a given colour.

#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <set>
#include <string>
#include <vector>

namespace hullcover::test {

/// One pixel's colour, each channel 0-255.
struct Pixel {
  int r = 0, g = 0, b = 0;
};

/// A decoded picture; empty (width 0) when the file is no readable PNG.
struct DecodedPng {
  int width = 0, height = 0;
  std::vector<Pixel> pixels; ///< row by row
};

inline DecodedPng decode_png(const std::string& path) {
  DecodedPng png;
  cairo_surface_t* surface = cairo_image_surface_create_from_png(path.c_str());
  if (cairo_surface_status(surface) == CAIRO_STATUS_SUCCESS) {
    cairo_surface_flush(surface);
    png.width = cairo_image_surface_get_width(surface);
    png.height = cairo_image_surface_get_height(surface);
    const int stride = cairo_image_surface_get_stride(surface);
    const unsigned char* data = cairo_image_surface_get_data(surface);
    const cairo_format_t format = cairo_image_surface_get_format(surface);
    for (int y = 0; y < png.height; ++y)
      for (int x = 0; x < png.width; ++x) {
        std::uint32_t word; // native-endian 0xAARRGGBB (RGB24 and ARGB32 alike)
        std::copy_n(data + y * stride + 4 * x, 4, reinterpret_cast<unsigned char*>(&word));
        const int alpha = format == CAIRO_FORMAT_ARGB32 ? static_cast<int>(word >> 24) : 255;
        // Premultiplied in ARGB32: a screenshot is opaque, so alpha is 255.
        const auto channel = [&](int shift) {
          const int v = static_cast<int>((word >> shift) & 0xff);
          return alpha == 0 ? 0 : std::min(255, v * 255 / alpha);
        };
        png.pixels.push_back({channel(16), channel(8), channel(0)});
      }
  }
  cairo_surface_destroy(surface);
  return png;
}

inline size_t distinct_colours(const DecodedPng& png) {
  std::set<std::uint32_t> seen;
  for (const Pixel& p : png.pixels) seen.insert((p.r << 16) | (p.g << 8) | p.b);
  return seen.size();
}

/// Pixels whose saturation (max - min over max) and value are both above
/// half: hull colours, never the grey scene, white or the pale background.
inline bool saturated(const Pixel& p) {
  const int hi = std::max({p.r, p.g, p.b}), lo = std::min({p.r, p.g, p.b});
  return hi > 64 && 2 * (hi - lo) > hi;
}

inline size_t saturated_pixels(const DecodedPng& png) {
  return static_cast<size_t>(std::count_if(png.pixels.begin(), png.pixels.end(), saturated));
}

/// How many of `buckets` equal slices of the hue circle saturated pixels
/// fall in, counting a slice only when at least `least` pixels do.
inline int hue_buckets(const DecodedPng& png, int buckets, size_t least) {
  std::vector<size_t> count(buckets, 0);
  for (const Pixel& p : png.pixels) {
    if (!saturated(p)) continue;
    const double r = p.r / 255.0, g = p.g / 255.0, b = p.b / 255.0;
    const double hue = std::atan2(std::sqrt(3.0) * (g - b), 2.0 * r - g - b); // radians, -pi..pi
    ++count[std::min(buckets - 1, static_cast<int>((hue + M_PI) / (2.0 * M_PI) * buckets))];
  }
  return static_cast<int>(std::count_if(count.begin(), count.end(), [&](size_t c) { return c >= least; }));
}

/// Pixels within `slack` of `colour` ("#rrggbb") on every channel.
inline size_t pixels_near(const DecodedPng& png, const std::string& colour, int slack) {
  const long rgb = std::strtol(colour.c_str() + 1, nullptr, 16);
  const Pixel want{static_cast<int>((rgb >> 16) & 0xff), static_cast<int>((rgb >> 8) & 0xff),
                   static_cast<int>(rgb & 0xff)};
  return static_cast<size_t>(std::count_if(png.pixels.begin(), png.pixels.end(), [&](const Pixel& p) {
    return std::abs(p.r - want.r) <= slack && std::abs(p.g - want.g) <= slack && std::abs(p.b - want.b) <= slack;
  }));
}

/// Fraction of pixels that differ between two pictures of one size.
inline double changed_fraction(const DecodedPng& a, const DecodedPng& b) {
  if (a.pixels.size() != b.pixels.size() || a.pixels.empty()) return 1.0;
  size_t changed = 0;
  for (size_t i = 0; i < a.pixels.size(); ++i)
    changed += a.pixels[i].r != b.pixels[i].r || a.pixels[i].g != b.pixels[i].g || a.pixels[i].b != b.pixels[i].b;
  return static_cast<double>(changed) / a.pixels.size();
}

} // namespace hullcover::test
