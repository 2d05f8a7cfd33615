#include "facet_painter.h"

#include "cell_ordering.h"
#include "polygon_clipping.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <numeric>

namespace hullcover::app::render {
namespace {

// Flat Lambert shading: what a facet facing away from the light keeps, and
// what the light adds at most.
constexpr double kAmbient = 0.42;
constexpr double kDiffuse = 0.58;
// The light sits behind the camera, up and to the left, so the three faces
// of a box seen from the iso view get three different shades.
constexpr double kLightUp = 0.6, kLightLeft = 0.4;
constexpr double kOutlinePixels = 1.0;
// Markers: a ball lit from the upper left, ringed in white so it reads on any hull.
constexpr double kHighlightOffset = 0.35, kHighlightLift = 0.45, kBallShadow = 0.7, kRingShade = 0.4;
// A marker's label: its height against the ball's radius, and the least
// that stays legible (final pixels).
constexpr double kLabelToRadius = 0.9, kLeastLabelPixels = 9.0;

Rgb scaled(const Rgb& c, double s) { return {c.r * s, c.g * s, c.b * s}; }

// Newell's normal: robust for any planar polygon, zero for one without area.
Eigen::Vector3d polygon_normal(const std::vector<Eigen::Vector3d>& corners) {
  Eigen::Vector3d n = Eigen::Vector3d::Zero();
  for (size_t i = 0; i < corners.size(); ++i) n += corners[i].cross(corners[(i + 1) % corners.size()]);
  return n;
}

} // namespace

FacetPainter::FacetPainter(const SceneCamera& camera, const ImageSize& size, const DepthTies& ties,
                           double surface_scale)
    : camera_(camera), size_(size), ties_(ties), surface_scale_(surface_scale),
      columns_((size.width + kCellPixels - 1) / kCellPixels) {
  assert(ties_.same_depth > 0.0 && surface_scale_ > 0.0);
  light_ = (-camera.forward() + kLightUp * camera.image_up() - kLightLeft * camera.image_right()).normalized();
}

void FacetPainter::add(const PaintedFacet& facet) {
  const std::vector<Eigen::Vector3d>& corners = facet.corners;
  if (corners.size() < 3) return;
  Eigen::Vector3d normal = polygon_normal(corners);
  if (!(normal.norm() > 0.0) || !normal.allFinite()) return;
  normal.normalize();
  const Eigen::Vector3d centroid =
      std::accumulate(corners.begin(), corners.end(), Eigen::Vector3d(Eigen::Vector3d::Zero())) /
      static_cast<double>(corners.size());
  Eigen::Vector3d lit = normal;
  if (normal.dot(camera_.towards_camera(centroid)) <= 0.0) {
    if (!facet.two_sided) return;
    lit = -normal;
  }
  const Rgb fill = scaled(facet.colour, kAmbient + kDiffuse * std::max(0.0, lit.dot(light_)));
  const Rgb outline = facet.outlined ? scaled(fill, facet.outline_shade) : fill;

  // In front of the camera only: what crosses the near depth is cut there.
  std::vector<SpaceCorner> space, in_front;
  for (const Eigen::Vector3d& c : corners) space.push_back({c, facet.outlined});
  const double near = camera_.near_depth();
  clip(
      space, [&](const SpaceCorner& c) { return near - camera_.project(c.p).depth; }, in_front);
  if (in_front.size() < 3) return;
  std::vector<ImageCorner> image;
  double min_x = size_.width, max_x = 0.0, min_y = size_.height, max_y = 0.0;
  for (const SpaceCorner& c : in_front) {
    const ImagePoint p = camera_.project(c.p);
    image.push_back({p.x, p.y, c.outline});
    min_x = std::min(min_x, p.x);
    max_x = std::max(max_x, p.x);
    min_y = std::min(min_y, p.y);
    max_y = std::max(max_y, p.y);
  }
  const int first_col = std::max(0, static_cast<int>(std::floor(min_x / kCellPixels)));
  const int last_col = std::min((size_.width - 1) / kCellPixels, static_cast<int>(std::floor(max_x / kCellPixels)));
  const int first_row = std::max(0, static_cast<int>(std::floor(min_y / kCellPixels)));
  const int last_row = std::min((size_.height - 1) / kCellPixels, static_cast<int>(std::floor(max_y / kCellPixels)));
  if (first_col > last_col || first_row > last_row) return;

  const unsigned facet_index = static_cast<unsigned>(planes_.size());
  planes_.push_back({normal, normal.dot(centroid), facet.over_coplanar ? ties_.over_coplanar : 0.0, facet.rank});
  std::vector<ImageCorner> upper, row, left, piece;
  for (int r = first_row; r <= last_row; ++r) {
    const double top = r * kCellPixels, bottom = top + kCellPixels;
    clip(
        image, [&](const ImageCorner& c) { return top - c.y; }, upper);
    clip(
        upper, [&](const ImageCorner& c) { return c.y - bottom; }, row);
    if (row.size() < 3) continue;
    for (int col = first_col; col <= last_col; ++col) {
      const double west = col * kCellPixels, east = west + kCellPixels;
      clip(
          row, [&](const ImageCorner& c) { return west - c.x; }, left);
      clip(
          left, [&](const ImageCorner& c) { return c.x - east; }, piece);
      if (piece.size() < 3) continue;
      Piece p{static_cast<unsigned>(r * columns_ + col), facet_index, 0.0,    static_cast<unsigned>(corners_.size()),
              static_cast<unsigned>(piece.size()),       fill,        outline};
      double cx = 0.0, cy = 0.0;
      for (const ImageCorner& c : piece) {
        cx += c.x / piece.size();
        cy += c.y / piece.size();
        corners_.push_back({static_cast<float>(c.x), static_cast<float>(c.y), c.outline});
      }
      p.key = depth_at(p, cx, cy);
      if (!std::isfinite(p.key)) p.key = camera_.project(centroid).depth; // seen edge-on
      pieces_.push_back(p);
    }
  }
}

void FacetPainter::add(const Marker& marker) { markers_.push_back(marker); }

double FacetPainter::depth_at(const Piece& piece, double x, double y) const {
  const FacetPlane& plane = planes_[piece.facet];
  return camera_.plane_depth_at(plane.normal, plane.offset, x, y) - plane.allowance;
}

void FacetPainter::fill(cairo_t* cr, const CellPiece& piece) const {
  const std::vector<ImageCorner>& c = piece.polygon;
  const Piece& p = pieces_[piece.source];
  cairo_move_to(cr, c[0].x, c[0].y);
  for (size_t k = 1; k < c.size(); ++k) cairo_line_to(cr, c[k].x, c[k].y);
  cairo_close_path(cr);
  cairo_set_source_rgb(cr, p.fill.r, p.fill.g, p.fill.b);
  const bool outlined = std::any_of(c.begin(), c.end(), [](const ImageCorner& corner) { return corner.outline; });
  if (!outlined) {
    cairo_fill(cr);
    return;
  }
  // The outline is drawn inside the piece only: a stroke reaching into a
  // neighbouring cell would land on pieces already painted there in front.
  cairo_save(cr);
  cairo_fill_preserve(cr);
  cairo_clip(cr);
  for (size_t k = 0; k < c.size(); ++k)
    if (c[k].outline) {
      cairo_move_to(cr, c[k].x, c[k].y);
      cairo_line_to(cr, c[(k + 1) % c.size()].x, c[(k + 1) % c.size()].y);
    }
  cairo_set_source_rgb(cr, p.outline.r, p.outline.g, p.outline.b);
  cairo_set_line_width(cr, 2.0 * kOutlinePixels * surface_scale_); // half of it is clipped away
  cairo_stroke(cr);
  cairo_restore(cr);
}

void FacetPainter::paint(cairo_t* cr) const {
  std::vector<unsigned> order(pieces_.size());
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(), [&](unsigned a, unsigned b) {
    const Piece &pa = pieces_[a], &pb = pieces_[b];
    return pa.cell != pb.cell ? pa.cell < pb.cell : a < b;
  });
  PieceDepths depths;
  depths.depth_at = [&](unsigned source, double x, double y) { return depth_at(pieces_[source], x, y); };
  depths.rank = [&](unsigned source) { return planes_[pieces_[source].facet].rank; };
  depths.same_depth = ties_.same_depth;
  // Without antialiasing, pieces sharing an edge leave no seam between them.
  cairo_save(cr);
  cairo_set_antialias(cr, CAIRO_ANTIALIAS_NONE);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  std::vector<CellPiece> cell;
  for (size_t begin = 0; begin < order.size();) {
    cell.clear();
    size_t end = begin;
    for (; end < order.size() && pieces_[order[end]].cell == pieces_[order[begin]].cell; ++end) {
      const Piece& p = pieces_[order[end]];
      CellPiece piece{{}, order[end], p.key};
      for (unsigned k = 0; k < p.count; ++k)
        piece.polygon.push_back({corners_[p.first + k].x, corners_[p.first + k].y, corners_[p.first + k].outline});
      cell.push_back(std::move(piece));
    }
    // A dense mesh seen from afar puts many tiny pieces in a cell: the keys
    // order them well enough, and pairwise work would grow with the square.
    if (cell.size() <= kMaxPairwisePieces) {
      split_crossing_pieces(cell, depths, kMaxPairwisePieces);
      order_cell_pieces(cell, depths);
    } else {
      std::stable_sort(cell.begin(), cell.end(), [](const CellPiece& a, const CellPiece& b) { return a.key > b.key; });
    }
    for (const CellPiece& piece : cell) fill(cr, piece);
    begin = end;
  }
  cairo_restore(cr);
  paint_markers(cr);
}

void FacetPainter::paint_markers(cairo_t* cr) const {
  struct Disc {
    double radius; // surface pixels
    ImagePoint at;
    const Marker* marker;
  };
  std::vector<Disc> discs;
  for (const Marker& m : markers_) {
    const ImagePoint p = camera_.project(m.centre);
    if (p.depth > camera_.near_depth())
      discs.push_back(
          {std::max(kMinMarkerPixels * surface_scale_, m.radius * camera_.pixels_per_unit(p.depth)), p, &m});
  }
  std::stable_sort(discs.begin(), discs.end(), [](const Disc& a, const Disc& b) { return a.at.depth > b.at.depth; });
  for (const Disc& disc : discs) {
    const double radius = disc.radius;
    const ImagePoint& p = disc.at;
    const Rgb& c = disc.marker->colour;
    cairo_pattern_t* ball = cairo_pattern_create_radial(p.x - kHighlightOffset * radius,
                                                        p.y - kHighlightOffset * radius, 0.0, p.x, p.y, radius);
    cairo_pattern_add_color_stop_rgb(ball, 0.0, std::min(1.0, c.r + kHighlightLift),
                                     std::min(1.0, c.g + kHighlightLift), std::min(1.0, c.b + kHighlightLift));
    cairo_pattern_add_color_stop_rgb(ball, 1.0, c.r * kBallShadow, c.g * kBallShadow, c.b * kBallShadow);
    cairo_new_path(cr); // a label's text leaves a current point the arc would join
    cairo_arc(cr, p.x, p.y, radius, 0.0, 2.0 * M_PI);
    cairo_set_source(cr, ball);
    cairo_fill_preserve(cr);
    cairo_pattern_destroy(ball);
    cairo_set_source_rgb(cr, 1.0, 1.0, 1.0);
    cairo_set_line_width(cr, 2.0 * kOutlinePixels * surface_scale_);
    cairo_stroke_preserve(cr);
    cairo_set_source_rgb(cr, c.r * kRingShade, c.g * kRingShade, c.b * kRingShade);
    cairo_set_line_width(cr, kOutlinePixels * surface_scale_);
    cairo_stroke(cr);
    if (disc.marker->label.empty()) continue;
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_BOLD);
    cairo_set_font_size(cr, std::max(kLeastLabelPixels * surface_scale_, kLabelToRadius * radius));
    cairo_text_extents_t extents;
    cairo_text_extents(cr, disc.marker->label.c_str(), &extents);
    if (extents.width > 2.0 * radius) continue; // it would hide the ball
    cairo_move_to(cr, p.x - extents.x_bearing - 0.5 * extents.width, p.y - extents.y_bearing - 0.5 * extents.height);
    cairo_set_source_rgb(cr, 1.0, 1.0, 1.0);
    cairo_show_text(cr, disc.marker->label.c_str());
  }
}

} // namespace hullcover::app::render
