#pragma once
// The map between the flat blank and the formed part that printing needs. Both ends are seen in
// one frame, the blank's: the rectangle that bounds the flat fabric's nodes in its plane (x to
// the right, y up), scaled to [0, 1]². A node's blank coordinate is where it sits in the flat
// blank; its developed coordinate is where the formed part puts it seen along the blank's normal
// (the press direction, −z): the formed position projected on the blank's plane. So the
// developed view is the top view of the formed part, drawn to the blank's own scale and frame:
// a blank that stayed flat is its own developed view, and a design drawn on a picture of the
// blank's outline shows, after forming, where its strokes land seen from above the press.
// Walls steeper than the view (a part's sides) are foreshortened in it: a design meant for
// them must be drawn compressed there.
#include <array>
#include <vector>

#include <Eigen/Core>

#include "fabform/fabric/fabric.hpp"
#include "fabform/io/png_image.hpp"

namespace fabform {

struct PrintMap {
  std::vector<Eigen::Vector2d> blank_uv;      // per node
  std::vector<Eigen::Vector2d> developed_uv;  // per node
  std::vector<std::array<int, 3>> triangles;  // the fabric's faces, a four-sided one as two
};

/// The frame of a set of flat positions: their bounding box in x and y (min, size).
struct BlankFrame {
  Eigen::Vector2d min = Eigen::Vector2d::Zero();
  Eigen::Vector2d size = Eigen::Vector2d::Ones();
  Eigen::Vector2d uv(const Eigen::Vector3d& p) const { return (p.head<2>() - min).cwiseQuotient(size); }
};
BlankFrame blank_frame(const std::vector<Eigen::Vector3d>& flat);

/// The map of a fabric formed to `x`, its flat blank at `flat` (the fabric's rest positions
/// where the scene lays the blank).
PrintMap print_map(const Fabric& fabric, const std::vector<Eigen::Vector3d>& flat,
                   const std::vector<Eigen::Vector3d>& x);

/// The image to print on the blank so that the formed part shows `design` in its developed
/// view; the print has the design's size, its pixels off the blank transparent.
Image predistort(const PrintMap& map, const Image& design);

/// What a print on the blank looks like on the formed part, in its developed view: the inverse
/// of predistort (where the view sees the part, a pixel off it transparent).
Image formed_view(const PrintMap& map, const Image& print);

/// A black-and-white checkerboard of `squares` × `squares` (the texture the map's OBJ files
/// show until a design replaces it).
Image checkerboard(int width, int height, int squares);

}  // namespace fabform
