#pragma once
// The painter's algorithm on a cairo image: convex polygons (scene faces,
// hull facets) are cut into pieces along a grid of screen cells, lit flat
// (Lambert, one light over the camera's shoulder), sorted far to near and
// filled in that order; markers (the audit's lost places) go on top.
//
// Why cells: a painter sorting whole facets by one depth draws a floor
// spanning the scene over the furniture standing on its far half. Within a
// cell, pieces that overlap on the image are ordered by comparing their
// planes' depths at a point of their overlap: exact unless the planes
// cross inside that overlap (then right at that point, within a cell).
// Pieces of coplanar facets (overlapping hulls of a covering, a hull facet
// on the scene face it covers) tie there, and a rank decides which is
// drawn on top instead of a patchwork of both. Pieces of one cell tile
// without gaps when filled without antialiasing; the picture is drawn
// larger and scaled down (scene_picture.cpp) for smooth edges.

#include "cell_ordering.h"
#include "scene_camera.h"

#include <cairo.h>

#include <Eigen/Core>

#include <string>
#include <vector>

namespace hullcover::app::render {

/// A colour, each channel in [0, 1].
struct Rgb {
  double r = 0.0, g = 0.0, b = 0.0;
};

/// One convex polygon to draw.
struct PaintedFacet {
  std::vector<Eigen::Vector3d> corners; ///< scene units, in order around the polygon
  Rgb colour;
  /// Lit from whichever side faces the camera (single-sided scene faces,
  /// as the paper's Fig. 8 reverses their normals). Otherwise the polygon
  /// is a facet of a closed hull, wound counter-clockwise seen from
  /// outside, and is not drawn when facing away.
  bool two_sided = false;
  /// Drawn over a scene face lying in the same plane or slightly in front
  /// (hull facets on the faces they cover): its depth counts the painter's
  /// coplanar allowance nearer.
  bool over_coplanar = false;
  /// Among pieces at the same depth, higher ranks are drawn later (on top).
  unsigned rank = 0;
  bool outlined = false;       ///< its edges drawn in a darker shade of its colour
  double outline_shade = 0.55; ///< that shade: the fill's channels times this, in [0, 1]
};

/// A disc drawn over everything at a scene point.
struct Marker {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero(); ///< scene units
  double radius = 0.0;                              ///< scene units; drawn no smaller than kMinMarkerPixels
  Rgb colour{0.85, 0.0, 0.0};
  std::string label; ///< drawn on the disc when it fits (the number of a table row)
};

/// Smallest marker radius, pixels of the final picture: a lost place is seen however shallow.
inline constexpr double kMinMarkerPixels = 6.0;
/// Side of the screen cells pieces are cut along, pixels of the surface painted.
inline constexpr int kCellPixels = 16;
/// Most pieces one cell orders pair by pair; a cell with more (a dense mesh
/// seen from afar) orders them by the depth at each piece's own centre.
inline constexpr size_t kMaxPairwisePieces = 64;

/// Depths the painter treats as equal, scene units.
struct DepthTies {
  /// Pieces whose depths differ less than this are one depth, ordered by
  /// rank: coplanar facets computed from different corners.
  double same_depth = 0.0;
  /// How much nearer an `over_coplanar` facet counts (> same_depth): hulls
  /// may lie a few tolerances behind the faces they cover.
  double over_coplanar = 0.0;
};

/// Collects polygons and markers, then paints them.
class FacetPainter {
public:
  /// Pieces of a surface of `size` seen by `camera` (both outliving the
  /// painter); `surface_scale` surface pixels make one pixel of the final
  /// picture (line widths and marker sizes are in final pixels).
  FacetPainter(const SceneCamera& camera, const ImageSize& size, const DepthTies& ties, double surface_scale);

  /// Adds `facet` (ignored when it has fewer than 3 corners, no area, faces
  /// away without being two-sided, or falls outside the image).
  void add(const PaintedFacet& facet);
  /// Adds a marker.
  void add(const Marker& marker);

  /// Paints every piece far to near, then the markers far to near, on `cr`.
  void paint(cairo_t* cr) const;

private:
  struct Corner {
    float x, y;   // surface pixels
    bool outline; // the edge to the next corner lies on the facet's outline
  };
  struct FacetPlane {
    Eigen::Vector3d normal;
    double offset;    // normal . p = offset
    double allowance; // how much nearer it counts (DepthTies::over_coplanar or 0)
    unsigned rank;
  };
  struct Piece {
    unsigned cell;         // row-major index of its screen cell
    unsigned facet;        // into planes_
    double key;            // its plane's depth at its own centre, less the allowance
    unsigned first, count; // into corners_
    Rgb fill, outline;
  };

  double depth_at(const Piece& piece, double x, double y) const;
  void fill(cairo_t* cr, const CellPiece& piece) const;
  void paint_markers(cairo_t* cr) const;

  const SceneCamera& camera_;
  ImageSize size_;
  DepthTies ties_;
  double surface_scale_;
  int columns_;           // screen cells across
  Eigen::Vector3d light_; // unit, from the scene towards the light
  std::vector<FacetPlane> planes_;
  std::vector<Piece> pieces_;
  std::vector<Corner> corners_;
  std::vector<Marker> markers_;
};

} // namespace hullcover::app::render
