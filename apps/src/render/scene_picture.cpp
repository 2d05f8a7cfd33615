#include "scene_picture.h"

#include "cairo_file_output.h"

#include "hullcover/geometry/tolerances.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace hullcover::app::render {
namespace {

// Depths the painter treats as one, as fractions of the scene's diagonal:
// coplanar facets computed from different corners differ by rounding (of
// float32 files too), far below a tenth of the default tolerance; a hull
// may lie a few default tolerances behind the face it covers.
constexpr double kSameDepthFraction = 0.1 * kDefaultRelativeTolerance;
constexpr double kOverCoplanarFraction = 10.0 * kDefaultRelativeTolerance;
// The golden angle as a fraction of the colour wheel: successive hulls'
// hues never repeat and stay far apart.
constexpr double kGoldenTurn = 0.38196601125;
// Hues in degrees the hulls may take: the wheel less the reds around 0.
constexpr double kFirstHueDeg = 35.0, kLastHueDeg = 320.0;
constexpr double kHullSaturation = 0.72;
constexpr double kBrightValue = 0.96, kDarkValue = 0.78;
// How far pale hulls are mixed towards white.
constexpr double kPaleMix = 0.6;
// Pieces are filled without antialiasing (facet_painter.h); the picture is
// drawn this many times larger each way and scaled down for smooth edges,
// when the larger surface stays within kMaxSupersampledPixels.
constexpr int kSupersampling = 2;
constexpr long kMaxSupersampledPixels = 64L << 20; // 256 MiB at 4 bytes a pixel
constexpr Rgb kSceneGrey{0.8, 0.8, 0.8};
// Scene faces are outlined faintly: a dense mesh would otherwise turn black.
constexpr double kSceneOutlineShade = 0.82;
constexpr Rgb kBackgroundTop{1.0, 1.0, 1.0}, kBackgroundBottom{0.9, 0.92, 0.95};

Rgb from_hsv(double hue_deg, double saturation, double value) {
  const double h = std::fmod(hue_deg, 360.0) / 60.0;
  const double c = value * saturation, x = c * (1.0 - std::abs(std::fmod(h, 2.0) - 1.0)), m = value - c;
  const int sector = static_cast<int>(h);
  const Rgb by_sector[6] = {{c, x, 0}, {x, c, 0}, {0, c, x}, {0, x, c}, {x, 0, c}, {c, 0, x}};
  const Rgb& s = by_sector[std::clamp(sector, 0, 5)];
  return {s.r + m, s.g + m, s.b + m};
}

Rgb mixed_with_white(const Rgb& c, double white) {
  return {c.r + (1.0 - c.r) * white, c.g + (1.0 - c.g) * white, c.b + (1.0 - c.b) * white};
}

// The outward unit normal of the hull's largest facet: what the cut-away
// judges a hull by.
Eigen::Vector3d largest_facet_normal(const ConvexPolytope& shape) {
  Eigen::Vector3d best = Eigen::Vector3d::Zero();
  double best_area = -1.0;
  for (const std::vector<int>& facet : shape.facets) {
    Eigen::Vector3d newell = Eigen::Vector3d::Zero();
    for (size_t i = 0; i < facet.size(); ++i)
      newell += shape.vertices[facet[i]].cross(shape.vertices[facet[(i + 1) % facet.size()]]);
    if (newell.norm() > best_area) {
      best_area = newell.norm();
      best = newell;
    }
  }
  return best.norm() > 0.0 ? best.normalized() : best;
}

void paint_background(cairo_t* cr, const ImageSize& size) {
  cairo_pattern_t* sky = cairo_pattern_create_linear(0.0, 0.0, 0.0, size.height);
  cairo_pattern_add_color_stop_rgb(sky, 0.0, kBackgroundTop.r, kBackgroundTop.g, kBackgroundTop.b);
  cairo_pattern_add_color_stop_rgb(sky, 1.0, kBackgroundBottom.r, kBackgroundBottom.g, kBackgroundBottom.b);
  cairo_set_source(cr, sky);
  cairo_paint(cr);
  cairo_pattern_destroy(sky);
}

void add_scene(FacetPainter& painter, const Mesh& scene, const CutAway* cut, bool under_hulls) {
  std::vector<Eigen::Vector3d> corners(3);
  for (const Eigen::Vector3i& t : scene.triangles) {
    for (int k = 0; k < 3; ++k) corners[k] = scene.positions[t[k]];
    const Eigen::Vector3d normal = (corners[1] - corners[0]).cross(corners[2] - corners[0]);
    if (cut && normal.norm() > 0.0 && cut->leaves_out(corners, normal.normalized())) continue;
    PaintedFacet facet;
    facet.corners = corners;
    facet.colour = kSceneGrey;
    facet.two_sided = true;
    facet.outlined = !under_hulls;
    facet.outline_shade = kSceneOutlineShade;
    painter.add(facet);
  }
}

void add_hulls(FacetPainter& painter, const PictureContent& content, const CutAway* cut) {
  const std::vector<bvh::RuntimeHull>& hulls = *content.hulls;
  for (size_t h = 0; h < hulls.size(); ++h) {
    const ConvexPolytope& shape = hulls[h].shape;
    if (cut && cut->leaves_out(shape.vertices, largest_facet_normal(shape))) continue;
    const bool pale = content.pale_hulls && std::find(content.highlighted.begin(), content.highlighted.end(),
                                                      static_cast<int>(h)) == content.highlighted.end();
    const Rgb colour = pale ? mixed_with_white(hull_colour(h), kPaleMix) : hull_colour(h);
    for (const std::vector<int>& indices : shape.facets) {
      PaintedFacet facet;
      for (int i : indices) facet.corners.push_back(shape.vertices[i]);
      facet.colour = colour;
      facet.over_coplanar = true;
      facet.rank = static_cast<unsigned>(h + 1); // over the scene's rank 0
      facet.outlined = true;
      painter.add(facet);
    }
  }
}

} // namespace

Rgb hull_colour(size_t index) {
  const double turn = std::fmod(static_cast<double>(index) * kGoldenTurn, 1.0);
  const double hue = kFirstHueDeg + turn * (kLastHueDeg - kFirstHueDeg);
  return from_hsv(hue, kHullSaturation, index % 2 == 0 ? kBrightValue : kDarkValue);
}

Result<SurfacePtr> draw_scene_picture(const PictureContent& content, const PictureOptions& options) {
  if (content.scene == nullptr || content.scene->triangles.empty())
    return Status{StatusCode::invalid_argument, "nothing to draw: the scene has no triangle"};
  const Aabb box = referenced_bounding_box(*content.scene);
  if (box.empty()) return Status{StatusCode::invalid_argument, "nothing to draw: the scene has no extent"};
  try {
    const ImageSize& size = options.size;
    const int factor =
        static_cast<long>(size.width) * size.height * kSupersampling * kSupersampling <= kMaxSupersampledPixels
            ? kSupersampling
            : 1;
    const ImageSize drawn_size{size.width * factor, size.height * factor};
    SurfacePtr drawn(cairo_image_surface_create(CAIRO_FORMAT_RGB24, drawn_size.width, drawn_size.height),
                     cairo_surface_destroy);
    SurfacePtr picture(factor == 1 ? nullptr : cairo_image_surface_create(CAIRO_FORMAT_RGB24, size.width, size.height),
                       cairo_surface_destroy);
    if (cairo_surface_status(drawn.get()) != CAIRO_STATUS_SUCCESS ||
        (picture && cairo_surface_status(picture.get()) != CAIRO_STATUS_SUCCESS))
      return Status{StatusCode::internal_error, "cairo could not make a " + std::to_string(size.width) + "x" +
                                                    std::to_string(size.height) + " image"};
    const SceneAxes axes = scene_axes(options.up);
    const SceneCamera camera(box, axes, options.view, drawn_size);
    const CutAway cut(box, axes, camera.forward());
    const CutAway* cutting = options.cut ? &cut : nullptr;
    // A scene of one point still gets depths to compare.
    const double diagonal = box.diagonal() > 0.0 ? box.diagonal() : 1.0;
    FacetPainter painter(camera, drawn_size, DepthTies{kSameDepthFraction * diagonal, kOverCoplanarFraction * diagonal},
                         factor);
    const bool with_hulls = content.hulls != nullptr && !content.hulls->empty();
    add_scene(painter, *content.scene, cutting, with_hulls);
    if (with_hulls) add_hulls(painter, content, cutting);
    for (const Marker& m : content.markers) painter.add(m);

    cairo_t* cr = cairo_create(drawn.get());
    paint_background(cr, drawn_size);
    painter.paint(cr);
    cairo_status_t status = cairo_status(cr);
    cairo_destroy(cr);
    if (status == CAIRO_STATUS_SUCCESS && picture) {
      cairo_surface_flush(drawn.get());
      cr = cairo_create(picture.get());
      cairo_scale(cr, 1.0 / factor, 1.0 / factor);
      cairo_set_source_surface(cr, drawn.get(), 0.0, 0.0);
      cairo_pattern_set_filter(cairo_get_source(cr), CAIRO_FILTER_GOOD);
      cairo_paint(cr);
      status = cairo_status(cr);
      cairo_destroy(cr);
    }
    if (status != CAIRO_STATUS_SUCCESS)
      return Status{StatusCode::internal_error, std::string("cairo could not draw: ") + cairo_status_to_string(status)};
    SurfacePtr& result = picture ? picture : drawn;
    cairo_surface_flush(result.get());
    return Result<SurfacePtr>(std::move(result));
  } catch (const std::exception& e) { // out of memory collecting pieces
    return Status{StatusCode::internal_error, std::string("could not draw the picture: ") + e.what()};
  }
}

Status write_scene_picture_png(const PictureContent& content, const PictureOptions& options, const std::string& path) {
  Result<SurfacePtr> drawn = draw_scene_picture(content, options);
  if (!drawn.ok()) return Status{drawn.status().code(), path + ": " + drawn.status().message()};
  return write_png_atomically(drawn.value().get(), path);
}

Result<std::string> scene_picture_png(const PictureContent& content, const PictureOptions& options) {
  Result<SurfacePtr> drawn = draw_scene_picture(content, options);
  if (!drawn.ok()) return drawn.status();
  return png_bytes(drawn.value().get());
}

} // namespace hullcover::app::render
