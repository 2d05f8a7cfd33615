#include "bench_plot.h"

#include "bench_report.h"

#include "render/cairo_file_output.h"

#include "hullcover/geometry/atomic_file.h"

#include <cairo-svg.h>
#include <cairo.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>

namespace hullcover::app::bench {
namespace {

constexpr double kWidth = 1200.0, kHeight = 860.0; // points (SVG) or pixels (PNG)
constexpr double kMargin = 60.0, kLegendHeight = 70.0;

struct Colour {
  double r, g, b;
};
// Distinct on white and for the common colour blindnesses (Okabe-Ito).
constexpr std::array<Colour, 8> kPalette = {{{0.0, 0.45, 0.70},
                                             {0.90, 0.62, 0.0},
                                             {0.0, 0.62, 0.45},
                                             {0.80, 0.47, 0.65},
                                             {0.34, 0.71, 0.91},
                                             {0.84, 0.37, 0.0},
                                             {0.4, 0.4, 0.4},
                                             {0.94, 0.89, 0.26}}};

// Distinct values of `key` in the order rows first show them.
std::vector<std::string> first_seen(const std::vector<BenchRow>& rows,
                                    const std::function<std::string(const BenchRow&)>& key) {
  std::vector<std::string> out;
  for (const BenchRow& r : rows)
    if (std::find(out.begin(), out.end(), key(r)) == out.end()) out.push_back(key(r));
  return out;
}

// A tick step of 1, 2 or 5 times a power of ten giving about 5 ticks to `top`.
double tick_step(double top) {
  const double rough = top / 5.0;
  const double power = std::pow(10.0, std::floor(std::log10(rough)));
  for (double m : {1.0, 2.0, 5.0})
    if (m * power >= rough) return m * power;
  return 10.0 * power;
}

struct Panel {
  const char* title;
  std::function<double(const BenchRow&, const std::vector<BenchRow>&)> value; // NaN: no point
  bool reference_line_at_one; // speed-ups: 1 is "as fast as the triangles"
};

double hulls_percent(const BenchRow& row, const std::vector<BenchRow>& rows) {
  const BenchRow* base = exact_row_of(rows, row.scene); // the scene's exact row, else its first
  if (!base || base->hulls == 0)
    base = &*std::find_if(rows.begin(), rows.end(), [&](const BenchRow& r) { return r.scene == row.scene; });
  return base->hulls > 0 ? 100.0 * static_cast<double>(row.hulls) / static_cast<double>(base->hulls) : NAN;
}

void text_at(cairo_t* cr, double x, double y, const std::string& text, double align) {
  cairo_text_extents_t e;
  cairo_text_extents(cr, text.c_str(), &e);
  cairo_move_to(cr, x - align * e.width - e.x_bearing, y);
  cairo_show_text(cr, text.c_str());
}

// Setting labels wider than the space between two settings are drawn
// slanted by this angle, each ending under its setting.
constexpr double kSlantedLabelAngle = 35.0 * M_PI / 180.0;

void draw_panel(cairo_t* cr, const Panel& panel, const std::vector<BenchRow>& rows,
                const std::vector<std::string>& scenes, const std::vector<std::string>& settings, double x0, double y0,
                double w, double h, bool slanted) {
  double top = panel.reference_line_at_one ? 1.0 : 100.0;
  for (const BenchRow& r : rows)
    if (const double v = panel.value(r, rows); std::isfinite(v)) top = std::max(top, v);
  const double step = tick_step(top * 1.1);
  top = std::ceil(top * 1.1 / step) * step;
  const auto px = [&](size_t i) {
    return settings.size() > 1 ? x0 + w * (0.05 + 0.9 * i / (settings.size() - 1.0)) : x0 + w / 2;
  };
  const auto py = [&](double v) { return y0 + h - h * v / top; };

  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_set_font_size(cr, 15);
  text_at(cr, x0 + w / 2, y0 - 12, panel.title, 0.5);
  cairo_set_font_size(cr, 11);
  cairo_set_line_width(cr, 1);
  for (double v = 0; v <= top + step / 2; v += step) { // grid and y labels
    cairo_set_source_rgb(cr, 0.88, 0.88, 0.88);
    cairo_move_to(cr, x0, py(v));
    cairo_line_to(cr, x0 + w, py(v));
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    char label[32];
    std::snprintf(label, sizeof label, "%g", v);
    text_at(cr, x0 - 6, py(v) + 4, label, 1.0);
  }
  if (panel.reference_line_at_one) {
    cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
    const double dash = 4;
    cairo_set_dash(cr, &dash, 1, 0);
    cairo_move_to(cr, x0, py(1.0));
    cairo_line_to(cr, x0 + w, py(1.0));
    cairo_stroke(cr);
    cairo_set_dash(cr, nullptr, 0, 0);
  }
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_rectangle(cr, x0, y0, w, h);
  cairo_stroke(cr);
  for (size_t i = 0; i < settings.size(); ++i) {
    if (!slanted) {
      text_at(cr, px(i), y0 + h + 16, settings[i], 0.5);
      continue;
    }
    cairo_save(cr);
    cairo_translate(cr, px(i) + 4, y0 + h + 12);
    cairo_rotate(cr, -kSlantedLabelAngle);
    text_at(cr, 0, 0, settings[i], 1.0);
    cairo_restore(cr);
  }

  for (size_t s = 0; s < scenes.size(); ++s) {
    const Colour c = kPalette[s % kPalette.size()];
    cairo_set_source_rgb(cr, c.r, c.g, c.b);
    cairo_set_line_width(cr, 2.2);
    bool drawing = false;
    for (size_t i = 0; i < settings.size(); ++i) {
      for (const BenchRow& r : rows) {
        if (r.scene != scenes[s] || r.setting != settings[i]) continue;
        const double v = panel.value(r, rows);
        if (!std::isfinite(v)) continue;
        if (drawing)
          cairo_line_to(cr, px(i), py(v));
        else
          cairo_move_to(cr, px(i), py(v));
        drawing = true;
      }
    }
    cairo_stroke(cr);
    for (size_t i = 0; i < settings.size(); ++i) // markers
      for (const BenchRow& r : rows)
        if (r.scene == scenes[s] && r.setting == settings[i] && std::isfinite(panel.value(r, rows))) {
          cairo_arc(cr, px(i), py(panel.value(r, rows)), 3.5, 0, 2 * M_PI);
          cairo_fill(cr);
        }
  }
}

void draw(cairo_t* cr, const std::vector<BenchRow>& rows) {
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  const std::vector<std::string> scenes = first_seen(rows, [](const BenchRow& r) { return r.scene; });
  const std::vector<std::string> settings = first_seen(rows, [](const BenchRow& r) { return r.setting; });
  const Panel panels[] = {{"yes/no speed-up (triangles / hulls)",
                           [](const BenchRow& r, const auto&) { return r.queries.touches.speedup(); }, true},
                          {"contacts speed-up (triangles / hulls)",
                           [](const BenchRow& r, const auto&) { return r.queries.contacts.speedup(); }, true},
                          {"ray speed-up (triangles / hulls)",
                           [](const BenchRow& r, const auto&) { return r.queries.ray.speedup(); }, true},
                          {"hulls, % of exact", hulls_percent, false}};
  const double pw = (kWidth - 3 * kMargin) / 2;
  // Long labels (movement settings) are slanted, and the rows of panels
  // move apart to make room for them.
  cairo_set_font_size(cr, 11);
  double widest = 0.0;
  for (const std::string& setting : settings) {
    cairo_text_extents_t e;
    cairo_text_extents(cr, setting.c_str(), &e);
    widest = std::max(widest, e.width);
  }
  const double spacing = settings.size() > 1 ? 0.9 * pw / (settings.size() - 1.0) : pw;
  const bool slanted = widest > 0.9 * spacing;
  const double labels = slanted ? widest * std::sin(kSlantedLabelAngle) + 16 : kMargin / 2;
  const double ph = (kHeight - kLegendHeight - kMargin / 1.5 - 2 * labels - kMargin / 2) / 2;
  for (int p = 0; p < 4; ++p)
    draw_panel(cr, panels[p], rows, scenes, settings, kMargin + (p % 2) * (pw + kMargin),
               kMargin / 1.5 + (p / 2) * (ph + labels + kMargin / 2), pw, ph, slanted);
  cairo_set_font_size(cr, 12); // legend
  const double legend_y = kHeight - kLegendHeight + 20, column = (kWidth - 2 * kMargin) / 4;
  for (size_t s = 0; s < scenes.size(); ++s) {
    const double x = kMargin + column * (s % 4), y = legend_y + 22 * (s / 4);
    const Colour c = kPalette[s % kPalette.size()];
    cairo_set_source_rgb(cr, c.r, c.g, c.b);
    cairo_rectangle(cr, x, y - 9, 18, 10);
    cairo_fill(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    text_at(cr, x + 24, y, scenes[s], 0.0);
  }
}

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

} // namespace

Status write_bench_plot(const std::vector<BenchRow>& rows, const std::string& path) {
  if (rows.empty()) return {StatusCode::invalid_argument, "nothing to plot: no bench rows"};
  const bool svg = ends_with(path, ".svg");
  bool drawing_failed = false;
  // Cairo writes through the stream of the atomic writer: an SVG surface as
  // it is finished, an image surface once it is drawn (finishing it first
  // would leave nothing to write). A failed write sets the stream's error
  // flag, which the atomic writer reports with the system's reason.
  const Status written = write_file_atomically(path, [&](std::FILE* out) {
    std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> surface(
        svg ? cairo_svg_surface_create_for_stream(write_cairo_bytes_to_stream, out, kWidth, kHeight)
            : cairo_image_surface_create(CAIRO_FORMAT_RGB24, static_cast<int>(kWidth), static_cast<int>(kHeight)),
        cairo_surface_destroy);
    if (cairo_surface_status(surface.get()) != CAIRO_STATUS_SUCCESS) {
      drawing_failed = true;
      return false;
    }
    cairo_t* cr = cairo_create(surface.get());
    draw(cr, rows);
    drawing_failed = cairo_status(cr) != CAIRO_STATUS_SUCCESS;
    cairo_destroy(cr);
    if (drawing_failed) return false;
    if (svg)
      cairo_surface_finish(surface.get());
    else
      cairo_surface_write_to_png_stream(surface.get(), write_cairo_bytes_to_stream, out);
    return true;
  });
  if (drawing_failed) return {StatusCode::internal_error, path + ": cairo could not draw the plot"};
  return written;
}

} // namespace hullcover::app::bench
