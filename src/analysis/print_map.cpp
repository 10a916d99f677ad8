#include "fabform/analysis/print_map.hpp"

#include <algorithm>
#include <cmath>

namespace fabform {
namespace {

// Fills every pixel of `target` (frame [0, 1]², v up) that a triangle covers in `to`
// coordinates with the pixel of `source` its point has in `from` coordinates.
void resample(const PrintMap& map, const std::vector<Eigen::Vector2d>& from, const std::vector<Eigen::Vector2d>& to,
              const Image& source, Image& target) {
  const Eigen::Vector2d pixels(target.width, target.height);
  for (const auto& t : map.triangles) {
    const Eigen::Vector2d a = to[static_cast<std::size_t>(t[0])], b = to[static_cast<std::size_t>(t[1])],
                          c = to[static_cast<std::size_t>(t[2])];
    const double area = (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
    if (area == 0.0 || !std::isfinite(area)) continue;
    const Eigen::Vector2d lo = a.cwiseMin(b).cwiseMin(c).cwiseProduct(pixels);
    const Eigen::Vector2d hi = a.cwiseMax(b).cwiseMax(c).cwiseProduct(pixels);
    const int c0 = std::max(0, static_cast<int>(std::floor(lo.x()))), c1 = std::min(target.width - 1, static_cast<int>(hi.x()));
    const int v0 = std::max(0, static_cast<int>(std::floor(lo.y()))), v1 = std::min(target.height - 1, static_cast<int>(hi.y()));
    for (int row_up = v0; row_up <= v1; ++row_up)
      for (int column = c0; column <= c1; ++column) {
        const Eigen::Vector2d p((column + 0.5) / pixels.x(), (row_up + 0.5) / pixels.y());
        const double wb = ((p - a).x() * (c - a).y() - (p - a).y() * (c - a).x()) / area;
        const double wc = ((b - a).x() * (p - a).y() - (b - a).y() * (p - a).x()) / area;
        const double wa = 1.0 - wb - wc;
        if (wa < 0.0 || wb < 0.0 || wc < 0.0) continue;
        const Eigen::Vector2d q = wa * from[static_cast<std::size_t>(t[0])] + wb * from[static_cast<std::size_t>(t[1])] +
                                  wc * from[static_cast<std::size_t>(t[2])];
        const int sc = std::clamp(static_cast<int>(std::floor(q.x() * source.width)), 0, source.width - 1);
        const int sr = std::clamp(static_cast<int>(std::floor((1.0 - q.y()) * source.height)), 0, source.height - 1);
        std::copy_n(source.pixel(sc, sr), 4, target.pixel(column, target.height - 1 - row_up));
      }
  }
}

Image transparent(int width, int height) {
  Image image(width, height);
  for (std::size_t i = 0; i < image.rgba.size(); i += 4) std::fill_n(image.rgba.begin() + static_cast<long>(i), 3, 255);
  return image;
}

}  // namespace

BlankFrame blank_frame(const std::vector<Eigen::Vector3d>& flat) {
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(INFINITY), hi = -lo;
  for (const auto& p : flat) lo = lo.cwiseMin(p.head<2>()), hi = hi.cwiseMax(p.head<2>());
  return {lo, (hi - lo).cwiseMax(1e-12)};
}

PrintMap print_map(const Fabric& fabric, const std::vector<Eigen::Vector3d>& flat,
                   const std::vector<Eigen::Vector3d>& x) {
  const BlankFrame frame = blank_frame(flat);
  PrintMap map;
  for (std::size_t k = 0; k < flat.size(); ++k) {
    map.blank_uv.push_back(frame.uv(flat[k]));
    map.developed_uv.push_back(frame.uv(x[k]));
  }
  map.triangles = face_triangles(fabric.faces());
  return map;
}

Image predistort(const PrintMap& map, const Image& design) {
  Image print = transparent(design.width, design.height);
  resample(map, map.developed_uv, map.blank_uv, design, print);
  return print;
}

Image formed_view(const PrintMap& map, const Image& print) {
  Image view = transparent(print.width, print.height);
  resample(map, map.blank_uv, map.developed_uv, print, view);
  return view;
}

Image checkerboard(int width, int height, int squares) {
  Image image(width, height);
  for (int r = 0; r < height; ++r)
    for (int c = 0; c < width; ++c) {
      const bool dark = ((c * squares / width) + (r * squares / height)) % 2 == 0;
      std::uint8_t* p = image.pixel(c, r);
      std::fill_n(p, 3, dark ? 0 : 255);
      p[3] = 255;
    }
  return image;
}

}  // namespace fabform
