#pragma once
// A picture of a scene and its hulls as in the paper's figures: the scene's
// faces in grey, each hull in a saturated colour of its own (never red: red
// is kept for the audit's lost space), flat shaded, optionally cut away.

#include "cut_away.h"
#include "facet_painter.h"
#include "scene_camera.h"

#include "hullcover/bvh/runtime_hull.h"
#include "hullcover/geometry/mesh.h"
#include "hullcover/geometry/status.h"

#include <cairo.h>

#include <memory>
#include <string>
#include <vector>

namespace hullcover::app::render {

/// How to look at the scene.
struct PictureOptions {
  ViewAngles view;
  ImageSize size;
  UpAxis up = UpAxis::y;
  bool cut = false; ///< leave out roofs and front walls (cut_away.h)
};

/// What to draw. The camera frames the scene's bounding box.
struct PictureContent {
  const Mesh* scene = nullptr;                          ///< required
  const std::vector<bvh::RuntimeHull>* hulls = nullptr; ///< none: the scene alone
  std::vector<Marker> markers;                          ///< drawn over everything
  /// Hulls drawn pale, so markers over them stand out (the audit's picture
  /// of lost space), but for the `highlighted` ones (indices into `hulls`).
  bool pale_hulls = false;
  std::vector<int> highlighted;
};

/// An image surface, destroyed with its owner.
using SurfacePtr = std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)>;

/// The colour of hull `index`: hues a golden angle apart, red left out,
/// lightness alternating so that neighbours in index differ twice.
Rgb hull_colour(size_t index);

/// Draws the picture. Fails with `invalid_argument` for no scene or an
/// empty one, `internal_error` when cairo cannot make or draw the image
/// (out of memory).
[[nodiscard]] Result<SurfacePtr> draw_scene_picture(const PictureContent& content, const PictureOptions& options);

/// Draws the picture and writes it as a PNG file at `path`, atomically.
[[nodiscard]] Status write_scene_picture_png(const PictureContent& content, const PictureOptions& options,
                                             const std::string& path);

/// Draws the picture and returns its PNG bytes.
[[nodiscard]] Result<std::string> scene_picture_png(const PictureContent& content, const PictureOptions& options);

} // namespace hullcover::app::render
