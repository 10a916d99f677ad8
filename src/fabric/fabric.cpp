#include "fabform/fabric/fabric.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace fabform {
namespace {

FabricLayout layout_of(const FabricSpec& spec) {
  if (spec.shape == FabricSpec::Shape::rectangle) return rectangle_layout(spec);
  if (spec.shape == FabricSpec::Shape::panels) return panel_layout(spec);
  if (spec.mesh == FabricSpec::Mesh::arc) return arc_layout(spec);
  return spec.mesh == FabricSpec::Mesh::jittered ? jittered_layout(spec) : circle_lattice_layout(spec);
}

using Edge = std::pair<int, int>;  // (lower node, higher node)

Edge edge(int p, int q) { return {std::min(p, q), std::max(p, q)}; }

// The sides of a face and the share of its area each stands for. Each family of sides that
// run the same way across the face tiles it once, as seed 003's strips do: a quadrilateral's
// opposite sides take half each; a triangle's two sides at corner 0 (the arc mesh's centre)
// half each and the side facing it all of it.
std::vector<std::pair<Edge, double>> sides_of(const Face& f, double area) {
  const auto& c = f.corner;
  if (f.corners == 3)
    return {{edge(c[0], c[1]), 0.5 * area}, {edge(c[2], c[0]), 0.5 * area}, {edge(c[1], c[2]), area}};
  return {{edge(c[0], c[1]), 0.5 * area}, {edge(c[1], c[2]), 0.5 * area},
          {edge(c[2], c[3]), 0.5 * area}, {edge(c[3], c[0]), 0.5 * area}};
}

// Every face side once, with the summed area the faces give it and how many faces share it;
// sorted by side (sorting is faster than a map at a million nodes).
struct MergedSide {
  Edge side;
  double area;
  int faces;
};

std::vector<MergedSide> merged_sides(const std::vector<Face>& faces, const std::vector<double>& areas) {
  std::vector<std::pair<Edge, double>> all;
  all.reserve(4 * faces.size());
  for (std::size_t f = 0; f < faces.size(); ++f)
    for (const auto& side : sides_of(faces[f], areas[f])) all.push_back(side);
  std::sort(all.begin(), all.end(), [](const auto& p, const auto& q) { return p.first < q.first; });
  std::vector<MergedSide> merged;
  for (const auto& [side, area] : all) {
    if (!merged.empty() && merged.back().side == side) {
      merged.back().area += area;
      ++merged.back().faces;
    } else {
      merged.push_back({side, area, 1});
    }
  }
  return merged;
}

}  // namespace

const char* to_string(SpringKind kind) {
  switch (kind) {
    case SpringKind::warp: return "warp";
    case SpringKind::weft: return "weft";
    case SpringKind::shear: return "shear";
    case SpringKind::bend: return "bend";
  }
  return "?";
}

Fabric::Fabric(const FabricSpec& spec) : spec_(spec) {
  if (const std::string why = spec.invalid_reason(); !why.empty()) throw std::invalid_argument(why);
  adopt(layout_of(spec));
  index_faces();
  add_edge_springs();
  if (spec.shear_springs || spec.mesh == FabricSpec::Mesh::triangular) add_shear_springs();
  index_springs();
  if (spec.bend_springs) {
    add_bend_springs();
    index_springs();
  }
  add_hinges();
  mark_perimeter();
  colour_nodes();
}

void Fabric::adopt(FabricLayout layout) {
  rest_ = std::move(layout.rest);
  lattice_ = std::move(layout.lattice);
  lattice_size_ = layout.lattice_size;
  spacing_ = layout.spacing;
  faces_ = std::move(layout.faces);
  moved_ = std::move(layout.moved);
  panels_ = std::move(layout.panels);
  lattice_node_.assign(static_cast<std::size_t>(lattice_size_[0]) * static_cast<std::size_t>(lattice_size_[1]), -1);
  for (int k = 0; k < node_count(); ++k)
    lattice_node_[static_cast<std::size_t>(j_of(k)) * static_cast<std::size_t>(lattice_size_[0]) +
                  static_cast<std::size_t>(i_of(k))] = k;
  // A lattice's cells are spacing × spacing exactly, as seed 003 writes them; corners at
  // rounded multiples of the spacing would give areas off by ε·(size / spacing). A panel's
  // triangle (a staircase corner dropped) is half a cell or less, measured.
  for (const Face& f : faces_) {
    const bool exact = f.corners == 4 && std::all_of(f.corner.begin(), f.corner.end(), [&](int c) { return on_lattice(c); });
    face_areas_.push_back(exact ? spacing_[0] * spacing_[1] : face_area(f, rest_));
    flat_area_ += face_areas_.back();
  }
}

// Springs along the faces' sides, warp where a side runs nearer x than y in the flat fabric (on
// a lattice exactly along one of them, on a jittered one within 24° of it: kMaxJitter), each as
// wide as the area it stands for over its length. Warp springs come first, then weft, each in
// node order.
void Fabric::add_edge_springs() {
  for (const auto& [side, share, faces] : merged_sides(faces_, face_areas_)) {
    const Eigen::Vector3d d = rest_position(side.second) - rest_position(side.first);
    const SpringKind kind = std::abs(d.x()) >= std::abs(d.y()) ? SpringKind::warp : SpringKind::weft;
    // A lattice's springs are its spacing long exactly, as seed 003 writes them (positions
    // i·spacing differ from it by rounding); a panel triangle's chord across a cell is not one.
    const bool neighbours = std::abs(i_of(side.first) - i_of(side.second)) + std::abs(j_of(side.first) - j_of(side.second)) == 1;
    const bool exact = neighbours && on_lattice(side.first) && on_lattice(side.second);
    const double length = exact ? spacing_[kind == SpringKind::warp ? 0 : 1] : d.norm();
    springs_.push_back({side.first, side.second, length, share / length, kind});
  }
  std::stable_sort(springs_.begin(), springs_.end(),
                   [](const Spring& p, const Spring& q) { return p.kind < q.kind; });
}

// Seed 000's triangular mesh and seed 004's shear springs: both diagonals of every four-sided
// face, rest length √2·l on a square lattice. Each diagonal family tiles the face once.
void Fabric::add_shear_springs() {
  for (std::size_t face = 0; face < faces_.size(); ++face) {
    const Face& f = faces_[face];
    if (f.corners != 4) continue;
    const double area = face_areas_[face];
    for (const auto& [p, q] : {edge(f.corner[0], f.corner[2]), edge(f.corner[1], f.corner[3])}) {
      const double length = (rest_position(q) - rest_position(p)).norm();
      springs_.push_back({p, q, length, area / length, SpringKind::shear});
    }
  }
}

// Seed 004's bend springs: over two warp or weft springs that continue each other through a
// node, from the node before to the node after. Each side spring's continuation is the other
// side spring at the node that turns least from it (more than 120° apart, each the other's
// choice), which on a lattice is the one straight on and on an arc mesh the next along its
// ring or radial line. A lattice's turns are its indices' (a jittered lattice's moved nodes
// would let a turn of 90° look straighter than the row's next), an arc mesh's its flat positions'.
// Its width is the mean of the two it spans.
void Fabric::add_bend_springs() {
  const auto heading = [&](int from, int to) -> Eigen::Vector3d {
    if (spec_.mesh == FabricSpec::Mesh::arc) return (rest_position(to) - rest_position(from)).normalized();
    return Eigen::Vector3d(i_of(to) - i_of(from), j_of(to) - j_of(from), 0.0).normalized();
  };
  for (int middle = 0; middle < node_count(); ++middle) {
    const auto away = [&](int s) {
      const Spring& spring = springs_[static_cast<std::size_t>(s)];
      const int other = spring.a == middle ? spring.b : spring.a;
      return std::pair<int, Eigen::Vector3d>{other, heading(middle, other)};
    };
    const auto straightest = [&](int s) {
      int best = -1;
      double best_cos = -0.5;
      for (const int t : springs_at(middle))
        if (t != s && springs_[static_cast<std::size_t>(t)].kind <= SpringKind::weft) {
          const double cos = away(s).second.dot(away(t).second);
          if (cos < best_cos) best = t, best_cos = cos;
        }
      return best;
    };
    for (const int s : springs_at(middle)) {
      if (springs_[static_cast<std::size_t>(s)].kind > SpringKind::weft) continue;
      const int t = straightest(s);
      if (t < s || straightest(t) != s) continue;  // each pair once, and only a mutual choice
      const auto [p, q] = edge(away(s).first, away(t).first);
      const double width = 0.5 * (springs_[static_cast<std::size_t>(s)].width + springs_[static_cast<std::size_t>(t)].width);
      springs_.push_back({p, q, (rest_position(q) - rest_position(p)).norm(), width, SpringKind::bend});
    }
  }
}

void Fabric::index_springs() {
  const auto n = static_cast<std::size_t>(node_count());
  spring_offset_.assign(n + 1, 0);
  for (const Spring& s : springs_) ++spring_offset_[static_cast<std::size_t>(s.a) + 1], ++spring_offset_[static_cast<std::size_t>(s.b) + 1];
  for (std::size_t k = 0; k < n; ++k) spring_offset_[k + 1] += spring_offset_[k];
  spring_ids_.assign(spring_offset_[n], -1);
  std::vector<std::size_t> next(spring_offset_.begin(), spring_offset_.end() - 1);
  for (std::size_t s = 0; s < springs_.size(); ++s) {
    spring_ids_[next[static_cast<std::size_t>(springs_[s].a)]++] = static_cast<int>(s);
    spring_ids_[next[static_cast<std::size_t>(springs_[s].b)]++] = static_cast<int>(s);
  }
}

// The affine dependency of a hinge's four flat points (hinge.hpp): a far point at distance d
// from the edge's line weighs 1/d, and the edge's nodes balance the far points' positions
// along the edge, t from 0 at edge[0] to 1 at edge[1]. The far points lie on either side of
// the edge, so their weights balance across it as well.
std::array<double, 4> Fabric::bend_weights(const Hinge& h) const {
  const Eigen::Vector3d q0 = rest_position(h.edge[0]), edge = rest_position(h.edge[1]) - q0;
  std::array<double, 4> weight = {0.0, 0.0, 0.0, 0.0};
  for (std::size_t w = 0; w < 2; ++w) {
    const Eigen::Vector3d r = 0.5 * (rest_position(h.wing[w][0]) + rest_position(h.wing[w][1])) - q0;
    const double t = r.dot(edge) / edge.squaredNorm();
    weight[2 + w] = 1.0 / (r - t * edge).norm();
    weight[0] -= weight[2 + w] * (1.0 - t);
    weight[1] -= weight[2 + w] * t;
  }
  return weight;
}

// Hinges: one across every side two faces share, each face's far point the midpoint of its far
// side (a triangle's far corner). Indexed by every node a hinge reaches.
void Fabric::add_hinges() {
  const auto n = static_cast<std::size_t>(node_count());
  hinge_offset_.assign(n + 1, 0);
  if (spec_.hinges) {
    std::vector<std::pair<Edge, int>> sides;  // (side, face)
    for (std::size_t face = 0; face < faces_.size(); ++face)
      for (const auto& [side, share] : sides_of(faces_[face], 0.0)) sides.push_back({side, static_cast<int>(face)});
    std::sort(sides.begin(), sides.end());
    for (std::size_t k = 0; k + 1 < sides.size(); ++k) {
      if (sides[k].first != sides[k + 1].first) continue;
      const auto [p, q] = sides[k].first;
      Hinge h;
      h.edge = {p, q};
      double area = 0.0;
      for (int w = 0; w < 2; ++w) {
        const auto face = static_cast<std::size_t>(sides[k + static_cast<std::size_t>(w)].second);
        const Face& f = faces_[face];
        std::vector<int> far;
        for (int c = 0; c < f.corners; ++c)
          if (f.corner[static_cast<std::size_t>(c)] != p && f.corner[static_cast<std::size_t>(c)] != q)
            far.push_back(f.corner[static_cast<std::size_t>(c)]);
        h.wing[static_cast<std::size_t>(w)] = {far.front(), far.back()};
        area += face_areas_[face];
      }
      h.shape_factor = (rest_position(q) - rest_position(p)).squaredNorm() / area;
      h.weight = bend_weights(h);
      hinges_.push_back(h);
    }
  }
  const auto reach = [](const Hinge& h) {
    return std::array<int, 6>{h.edge[0], h.edge[1], h.wing[0][0], h.wing[0][1], h.wing[1][0], h.wing[1][1]};
  };
  std::vector<std::vector<int>> at(n);
  for (std::size_t i = 0; i < hinges_.size(); ++i)
    for (const int node : reach(hinges_[i]))
      if (at[static_cast<std::size_t>(node)].empty() || at[static_cast<std::size_t>(node)].back() != static_cast<int>(i))
        at[static_cast<std::size_t>(node)].push_back(static_cast<int>(i));
  for (std::size_t k = 0; k < n; ++k) {
    hinge_offset_[k + 1] = hinge_offset_[k] + at[k].size();
    hinge_ids_.insert(hinge_ids_.end(), at[k].begin(), at[k].end());
  }
}

// The perimeter is where a face's side has no face on its other side.
void Fabric::mark_perimeter() {
  perimeter_.assign(static_cast<std::size_t>(node_count()), 0);
  for (const auto& [side, area, faces] : merged_sides(faces_, face_areas_))
    if (faces == 1) perimeter_[static_cast<std::size_t>(side.first)] = perimeter_[static_cast<std::size_t>(side.second)] = 1;
}

// Greedy colouring in node order: each node takes the lowest colour none of its spring
// neighbours has. On a lattice of warp and weft springs this is the checkerboard.
void Fabric::colour_nodes() {
  std::vector<int> colour(static_cast<std::size_t>(node_count()), -1);
  std::vector<char> taken;
  for (int k = 0; k < node_count(); ++k) {
    taken.assign(taken.size(), 0);
    const auto take = [&](int other) {
      const int c = colour[static_cast<std::size_t>(other)];
      if (c < 0) return;
      if (static_cast<std::size_t>(c) >= taken.size()) taken.resize(static_cast<std::size_t>(c) + 1, 0);
      taken[static_cast<std::size_t>(c)] = 1;
    };
    for (const int s : springs_at(k)) {
      const Spring& spring = springs_[static_cast<std::size_t>(s)];
      take(spring.a == k ? spring.b : spring.a);
    }
    for (const int i : hinges_at(k)) {
      const Hinge& h = hinges_[static_cast<std::size_t>(i)];
      for (const int other : {h.edge[0], h.edge[1], h.wing[0][0], h.wing[0][1], h.wing[1][0], h.wing[1][1]})
        if (other != k) take(other);
    }
    const auto free = std::find(taken.begin(), taken.end(), 0);
    const int c = static_cast<int>(free - taken.begin());
    colour[static_cast<std::size_t>(k)] = c;
    if (static_cast<std::size_t>(c) >= colours_.size()) colours_.resize(static_cast<std::size_t>(c) + 1);
    colours_[static_cast<std::size_t>(c)].push_back(k);
  }
}

// Each node's faces, and its share of their areas.
void Fabric::index_faces() {
  const auto n = static_cast<std::size_t>(node_count());
  face_offset_.assign(n + 1, 0);
  node_areas_.assign(n, 0.0);
  for (std::size_t face = 0; face < faces_.size(); ++face) {
    const Face& f = faces_[face];
    for (int c = 0; c < f.corners; ++c) {
      const auto k = static_cast<std::size_t>(f.corner[static_cast<std::size_t>(c)]);
      ++face_offset_[k + 1];
      node_areas_[k] += face_areas_[face] / f.corners;
    }
  }
  for (std::size_t k = 0; k < n; ++k) face_offset_[k + 1] += face_offset_[k];
  face_ids_.assign(face_offset_[n], -1);
  std::vector<std::size_t> next(face_offset_.begin(), face_offset_.end() - 1);
  for (std::size_t face = 0; face < faces_.size(); ++face)
    for (int c = 0; c < faces_[face].corners; ++c)
      face_ids_[next[static_cast<std::size_t>(faces_[face].corner[static_cast<std::size_t>(c)])]++] = static_cast<int>(face);
}

int Fabric::node(int i, int j) const {
  if (i < 0 || j < 0 || i >= lattice_size_[0] || j >= lattice_size_[1]) return -1;
  return lattice_node_[static_cast<std::size_t>(j) * static_cast<std::size_t>(lattice_size_[0]) + static_cast<std::size_t>(i)];
}

std::string Fabric::node_name(int node) const {
  if (spec_.mesh == FabricSpec::Mesh::arc)
    return "node (ring " + std::to_string(i_of(node)) + ", spoke " + std::to_string(j_of(node)) + ")";
  return "node (" + std::to_string(i_of(node)) + ", " + std::to_string(j_of(node)) + ")";
}

int Fabric::divisions_across() const {
  if (spec_.mesh == FabricSpec::Mesh::arc) return 2 * spec_.rings;
  return std::max(lattice_size_[0], lattice_size_[1]) - 1;
}

}  // namespace fabform
