#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <Eigen/Geometry>

#include "fabform/angles.hpp"
#include "fabform/fabric/fabric_layout.hpp"
#include "fabform/number_text.hpp"

namespace fabform {
namespace {

using Vec2 = Eigen::Vector2d;

// The outline is traced this many times finer than the lattice, so that a node's nearest point
// and arc length along an edge are found to a small fraction of the spacing.
constexpr double kTraceFineness = 32.0;
// Nodes moved onto one edge keep at least this fraction of the spacing between them, so that no
// boundary spring shrinks to nothing.
constexpr double kMinBoundaryGap = 0.2;
// A cell whose corner triangles are smaller than this fraction of the lattice cell has turned
// (nearly) inside out on the outline.
constexpr double kMinCornerArea = 0.02;

Vec2 turned(const Vec2& p, double angle) { return Eigen::Rotation2Dd(angle) * p; }

PanelOutline turned_outline(const PanelOutline& outline, double angle) {
  PanelOutline t = outline;
  for (Vec2& v : t.vertices) v = turned(v, angle);
  for (OutlineEdge& e : t.edges)
    for (Vec2& c : e.controls) c = turned(c, angle);
  return t;
}

double grain_rad(const PanelSpec& panel) { return panel.grain_deg * kPi / 180.0; }

// One panel's lattice in its turned frame (grain along x): point (i, j) at origin + (i hx, j hy).
struct PanelGrid {
  TracedOutline outline;
  Vec2 origin;
  int cells_x = 0;
  int cells_y = 0;
};

PanelGrid panel_grid(const PanelSpec& panel, const std::array<double, 2>& h) {
  PanelGrid g;
  g.outline = trace_outline(turned_outline(panel.outline, -grain_rad(panel)), std::min(h[0], h[1]) / kTraceFineness);
  Vec2 low = g.outline.points[0], high = low;
  for (const Vec2& p : g.outline.points) low = low.cwiseMin(p), high = high.cwiseMax(p);
  g.origin = low;
  // A side that is a whole number of spacings long takes exactly that many cells.
  g.cells_x = std::max(1, static_cast<int>(std::ceil((high.x() - low.x()) / h[0] - 1e-9)));
  g.cells_y = std::max(1, static_cast<int>(std::ceil((high.y() - low.y()) / h[1] - 1e-9)));
  return g;
}

[[noreturn]] void refuse(const PanelSpec& panel, const std::string& why) {
  throw std::invalid_argument("panel '" + panel.name + "': " + why);
}

// Row by row, the cells whose centres lie between the outline's crossings of the row's centre
// line (even–odd), in time proportional to the outline's points and the cells.
void fill_rows(const PanelGrid& g, const std::array<double, 2>& h, std::vector<unsigned char>* in) {
  const std::vector<Vec2>& p = g.outline.points;
  const int nx = g.cells_x;
  std::vector<std::vector<double>> crossings(static_cast<std::size_t>(g.cells_y));
  for (std::size_t s = 0; s < p.size(); ++s) {
    const Vec2& a = p[s];
    const Vec2& b = p[(s + 1) % p.size()];
    // The rows whose centre line y_j lies in [min, max) of the segment's y, each y_j computed
    // one way only (the first row a row early, lest rounding skip it).
    const double low = std::min(a.y(), b.y()), high = std::max(a.y(), b.y());
    const int first = std::max(0, static_cast<int>(std::floor((low - g.origin.y()) / h[1] - 0.5)));
    for (int j = first; j < g.cells_y; ++j) {
      const double y = g.origin.y() + (j + 0.5) * h[1];
      if (y >= high) break;
      if (y < low) continue;
      crossings[static_cast<std::size_t>(j)].push_back(a.x() + (b.x() - a.x()) * (y - a.y()) / (b.y() - a.y()));
    }
  }
  for (int j = 0; j < g.cells_y; ++j) {
    std::vector<double>& x = crossings[static_cast<std::size_t>(j)];
    std::sort(x.begin(), x.end());
    for (std::size_t c = 0; c + 1 < x.size(); c += 2) {
      const int from = std::max(0, static_cast<int>(std::ceil((x[c] - g.origin.x()) / h[0] - 0.5)));
      const int to = std::min(nx - 1, static_cast<int>(std::ceil((x[c + 1] - g.origin.x()) / h[0] - 0.5)) - 1);
      for (int i = from; i <= to; ++i) (*in)[static_cast<std::size_t>(j) * static_cast<std::size_t>(nx) + static_cast<std::size_t>(i)] = 1;
    }
  }
}

// The cells whose centres lie inside the outline, less those that would make the boundary touch
// itself at a node (two cells meeting only at a corner), which a boundary walk cannot pass: of
// the two, the one with fewer neighbours goes, so that a tip is cut rather than the body.
std::vector<unsigned char> inside_cells(const PanelGrid& g, const std::array<double, 2>& h) {
  const int nx = g.cells_x, ny = g.cells_y;
  std::vector<unsigned char> in(static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny), 0);
  fill_rows(g, h, &in);
  const auto at = [&](int i, int j) -> unsigned char& { return in[static_cast<std::size_t>(j) * static_cast<std::size_t>(nx) + static_cast<std::size_t>(i)]; };
  const auto cell = [&](int i, int j) { return i >= 0 && j >= 0 && i < nx && j < ny && at(i, j); };
  const auto neighbours = [&](int i, int j) { return cell(i - 1, j) + cell(i + 1, j) + cell(i, j - 1) + cell(i, j + 1); };
  const auto drop_one = [&](int ia, int ja, int ib, int jb) {
    if (neighbours(ia, ja) < neighbours(ib, jb)) at(ia, ja) = 0;
    else at(ib, jb) = 0;
  };
  for (bool changed = true; changed;) {
    changed = false;
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) {
        const bool ll = cell(i - 1, j - 1), lr = cell(i, j - 1), ul = cell(i - 1, j), ur = cell(i, j);
        if (ll && ur && !lr && !ul) drop_one(i - 1, j - 1, i, j), changed = true;
        else if (lr && ul && !ll && !ur) drop_one(i, j - 1, i - 1, j), changed = true;
      }
  }
  return in;
}

// Whether the cells form one piece, joined side to side.
bool one_piece(const std::vector<unsigned char>& in, int nx, int ny) {
  const auto first = std::find(in.begin(), in.end(), 1);
  if (first == in.end()) return false;
  std::vector<unsigned char> seen(in.size(), 0);
  std::vector<int> todo = {static_cast<int>(first - in.begin())};
  seen[static_cast<std::size_t>(todo[0])] = 1;
  std::size_t reached = 1;
  while (!todo.empty()) {
    const int c = todo.back();
    todo.pop_back();
    const int i = c % nx, j = c / nx;
    for (const auto& [di, dj] : {std::pair{1, 0}, std::pair{-1, 0}, std::pair{0, 1}, std::pair{0, -1}}) {
      const int a = i + di, b = j + dj;
      if (a < 0 || b < 0 || a >= nx || b >= ny) continue;
      const auto k = static_cast<std::size_t>(b * nx + a);
      if (in[k] && !seen[k]) seen[k] = 1, ++reached, todo.push_back(b * nx + a);
    }
  }
  return reached == static_cast<std::size_t>(std::count(in.begin(), in.end(), 1));
}

// One panel meshed: nodes numbered row by row (j outer) from 0, its lattice (i, j) and point in
// the turned frame, its faces, its boundary walk (counter-clockwise; needed only until the
// edges' chains are taken from it) and each node's moved flag.
struct PanelNodes {
  std::vector<std::array<int, 2>> lattice;
  std::vector<Vec2> point;
  std::vector<unsigned char> moved;
  std::vector<Face> faces;
  std::vector<int> boundary;
};

PanelNodes panel_nodes(const PanelGrid& g, const std::vector<unsigned char>& in, const std::array<double, 2>& h) {
  const int nx = g.cells_x, ny = g.cells_y, px = nx + 1;
  PanelNodes p;
  std::vector<int> node_of(static_cast<std::size_t>(px) * static_cast<std::size_t>(ny + 1), -1);  // -1: no node
  const auto used = [&](int i, int j) { return i >= 0 && j >= 0 && i < nx && j < ny && in[static_cast<std::size_t>(j * nx + i)]; };
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i)
      if (used(i, j) || used(i - 1, j) || used(i, j - 1) || used(i - 1, j - 1)) {
        node_of[static_cast<std::size_t>(j * px + i)] = static_cast<int>(p.point.size());
        p.lattice.push_back({i, j});
        p.point.push_back(g.origin + Vec2(i * h[0], j * h[1]));
      }
  p.moved.assign(p.point.size(), 0);
  const auto node = [&](int i, int j) { return node_of[static_cast<std::size_t>(j * px + i)]; };
  std::vector<int> next(p.point.size(), -1);
  std::size_t sides = 0;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      if (!used(i, j)) continue;
      const std::array<int, 4> c = {node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)};
      p.faces.push_back({c, 4});
      const std::array<bool, 4> open = {!used(i, j - 1), !used(i + 1, j), !used(i, j + 1), !used(i - 1, j)};
      for (std::size_t s = 0; s < 4; ++s)
        if (open[s]) next[static_cast<std::size_t>(c[s])] = c[(s + 1) % 4], ++sides;
    }
  const auto start = std::find_if(next.begin(), next.end(), [](int n) { return n >= 0; });
  for (int n = static_cast<int>(start - next.begin()); p.boundary.size() <= sides;) {
    p.boundary.push_back(n);
    n = next[static_cast<std::size_t>(n)];
    if (n == p.boundary.front()) break;
  }
  if (p.boundary.size() != sides) p.boundary.clear();  // more than one boundary: a hole
  return p;
}

// The boundary walk's positions of the nodes nearest the outline's vertices. An edge shorter
// than the spacing can find its end's nearest node taken by its start: it takes the next node
// along the walk the way the outline runs, so that every edge keeps a node at each end.
std::vector<std::size_t> corner_positions(const PanelSpec& panel, const PanelGrid& g, const PanelNodes& p, bool forward) {
  const std::size_t n = p.boundary.size();
  std::vector<std::size_t> at;
  for (std::size_t k = 0; k < g.outline.outline.vertices.size(); ++k) {
    const Vec2& v = g.outline.outline.vertices[k];
    std::size_t best = 0;
    for (std::size_t b = 1; b < n; ++b)
      if ((p.point[static_cast<std::size_t>(p.boundary[b])] - v).squaredNorm() <
          (p.point[static_cast<std::size_t>(p.boundary[best])] - v).squaredNorm())
        best = b;
    if (!at.empty() && best == at.back()) best = forward ? (best + 1) % n : (best + n - 1) % n;
    if (std::find(at.begin(), at.end(), best) != at.end())
      refuse(panel, "vertices " + std::to_string(std::find(at.begin(), at.end(), best) - at.begin()) + " and " +
                        std::to_string(k) + " fall on one lattice node: use a finer lattice spacing");
    at.push_back(best);
  }
  return at;
}

// Edge k's nodes from its start vertex's node to its end vertex's, walking the boundary the way
// the outline runs (counter-clockwise, or back along the walk for a clockwise outline).
std::vector<std::vector<int>> edge_chains(const PanelSpec& panel, const PanelGrid& g, const PanelNodes& p) {
  const bool forward = g.outline.signed_area() > 0.0;
  const std::vector<std::size_t> corner = corner_positions(panel, g, p, forward);
  const std::size_t n = p.boundary.size(), edges = corner.size();
  std::vector<std::vector<int>> chains(edges);
  std::size_t walked = 0;
  for (std::size_t k = 0; k < edges; ++k) {
    const std::size_t from = corner[k], to = corner[(k + 1) % edges];
    const std::size_t steps = forward ? (to + n - from) % n : (from + n - to) % n;
    for (std::size_t s = 0; s <= steps; ++s)
      chains[k].push_back(p.boundary[forward ? (from + s) % n : (from + n - s) % n]);
    walked += steps;
  }
  if (walked != n)
    refuse(panel, "its vertices' nearest lattice nodes do not lie in the outline's order: use a finer lattice spacing");
  return chains;
}

// The chain's nodes moved onto edge k: the corners onto its vertices, the others onto their
// nearest points in order along it, kMinBoundaryGap of the spacing apart. A node already on its
// point (to rounding) keeps its lattice point, so a straight edge along the lattice moves none.
void move_onto_edge(const PanelSpec& panel, const PanelGrid& g, int k, const std::vector<int>& chain, double spacing,
                    PanelNodes* p) {
  const double length = g.outline.edge_length[static_cast<std::size_t>(k)];
  const double gap = kMinBoundaryGap * spacing;
  const std::size_t m = chain.size() - 1;
  if (length < gap * static_cast<double>(m))
    refuse(panel, "edge " + std::to_string(k) + " is too short for the lattice nodes along it: use a finer lattice spacing");
  std::vector<double> s(chain.size(), 0.0);
  s[m] = length;
  for (std::size_t c = 1; c < m; ++c) s[c] = std::max(g.outline.nearest_s(k, p->point[static_cast<std::size_t>(chain[c])]), s[c - 1] + gap);
  for (std::size_t c = m - 1; c >= 1; --c) s[c] = std::min(s[c], s[c + 1] - gap);
  for (std::size_t c = 0; c <= m; ++c) {
    const auto node = static_cast<std::size_t>(chain[c]);
    const Vec2 target = g.outline.at(k, s[c]);
    if ((target - p->point[node]).norm() > 1e-9 * spacing) p->point[node] = target, p->moved[node] = 1;
  }
}

// The cross product at corner c of a face: twice the area of the triangle there, positive while
// the face turns counter-clockwise at it.
double corner_turn(const PanelNodes& p, const Face& f, int c) {
  const auto at = [&](int k) { return p.point[static_cast<std::size_t>(f.corner[static_cast<std::size_t>((k + f.corners) % f.corners)])]; };
  const Vec2 u = at(c - 1) - at(c), w = at(c + 1) - at(c);
  return w.x() * u.y() - w.y() * u.x();
}

// A staircase's outer corner lands on the outline between its two neighbours, which lie on it
// too: its cell turns flat there, or folds in where the outline curves into the panel. Such a
// corner, a node of that one cell, is dropped and its cell becomes the triangle of its other
// three corners (its side along the outline a chord of it) — unless it is a vertex of the
// outline, which must stay: then the cell starts at it, so that its two triangles (split at
// corner 0, as face_area splits it) both keep their area, and only its other corners must turn.
void drop_folded_corners(std::vector<std::vector<int>>* chains, double least, PanelNodes* p) {
  std::vector<int> cells(p->point.size(), 0);
  for (const Face& f : p->faces)
    for (int c = 0; c < f.corners; ++c) ++cells[static_cast<std::size_t>(f.corner[static_cast<std::size_t>(c)])];
  std::vector<unsigned char> vertex(p->point.size(), 0);
  for (const auto& chain : *chains) vertex[static_cast<std::size_t>(chain.front())] = 1;
  std::vector<int> renumbered(p->point.size(), 0);
  for (Face& f : p->faces)
    for (int c = 0; c < 4 && f.corners == 4; ++c) {
      const auto node = static_cast<std::size_t>(f.corner[static_cast<std::size_t>(c)]);
      if (cells[node] != 1 || corner_turn(*p, f, c) >= least) continue;
      const auto corner = [&](int k) { return f.corner[static_cast<std::size_t>((c + k) % 4)]; };
      if (vertex[node]) {
        f = {{corner(0), corner(1), corner(2), corner(3)}, 4};
        break;
      }
      renumbered[node] = -1;
      // The corner facing the chord first: sides_of gives that side the triangle's whole area,
      // the two lattice sides half each, as each family tiles it once.
      f = {{corner(2), corner(3), corner(1), -1}, 3};
    }
  int next = 0;
  for (int& n : renumbered) n = n < 0 ? -1 : next++;
  PanelNodes kept;
  for (std::size_t n = 0; n < p->point.size(); ++n)
    if (renumbered[n] >= 0) kept.lattice.push_back(p->lattice[n]), kept.point.push_back(p->point[n]), kept.moved.push_back(p->moved[n]);
  for (Face f : p->faces) {
    for (int c = 0; c < f.corners; ++c) f.corner[static_cast<std::size_t>(c)] = renumbered[static_cast<std::size_t>(f.corner[static_cast<std::size_t>(c)])];
    kept.faces.push_back(f);
  }
  *p = std::move(kept);
  for (auto& chain : *chains) {
    std::vector<int> on;
    for (const int n : chain)
      if (renumbered[static_cast<std::size_t>(n)] >= 0) on.push_back(renumbered[static_cast<std::size_t>(n)]);
    chain = std::move(on);
  }
}

// Every cell keeps its area once its boundary nodes have moved: both triangles of a
// quadrilateral split at corner 0, and every corner but the first turning the right way.
void check_cells(const PanelSpec& panel, const PanelNodes& p, double least) {
  for (const Face& f : p.faces) {
    int bad = -1;
    for (int c = 1; c < f.corners && bad < 0; ++c)
      if (corner_turn(p, f, c) < least) bad = c;
    if (f.corners == 4 && bad < 0) {
      const Face first = {{f.corner[0], f.corner[1], f.corner[2], -1}, 3}, second = {{f.corner[0], f.corner[2], f.corner[3], -1}, 3};
      if (corner_turn(p, first, 0) < least || corner_turn(p, second, 0) < least) bad = 0;
    }
    if (bad < 0) continue;
    const Vec2 at = turned(p.point[static_cast<std::size_t>(f.corner[static_cast<std::size_t>(bad)])], grain_rad(panel));
    refuse(panel, (NumberText(4) << "a lattice cell at (" << at.x() << ", " << at.y()
                                 << ") m folds over where its nodes meet the outline: use a finer lattice spacing")
                      .str());
  }
}

struct MeshedPanel {
  PanelGrid grid;
  PanelNodes nodes;
  std::vector<std::vector<int>> chains;
};

MeshedPanel mesh_panel(const PanelSpec& panel, const std::array<double, 2>& h) {
  MeshedPanel m;
  m.grid = panel_grid(panel, h);
  const std::vector<unsigned char> in = inside_cells(m.grid, h);
  if (!one_piece(in, m.grid.cells_x, m.grid.cells_y))
    refuse(panel, "its lattice cells do not form one piece (a part narrower than the spacing): use a finer lattice spacing");
  m.nodes = panel_nodes(m.grid, in, h);
  if (m.nodes.boundary.empty())
    refuse(panel, "its lattice cells enclose a hole (a notch narrower than the spacing): use a finer lattice spacing");
  m.chains = edge_chains(panel, m.grid, m.nodes);
  for (std::size_t k = 0; k < m.chains.size(); ++k)
    move_onto_edge(panel, m.grid, static_cast<int>(k), m.chains[k], std::min(h[0], h[1]), &m.nodes);
  const double least = 2.0 * kMinCornerArea * h[0] * h[1];
  drop_folded_corners(&m.chains, least, &m.nodes);
  check_cells(panel, m.nodes, least);
  return m;
}

}  // namespace

Eigen::Vector2d PanelMesh::plane_point(const Eigen::Vector3d& flat) const {
  return turned(flat.head<2>() + flat_to_plane, grain_rad);
}

Eigen::Vector3d placed_point(const PanelSpec& panel, const Eigen::Vector2d& plane_point) {
  return panel.rotation * Eigen::Vector3d(plane_point.x(), plane_point.y(), 0.0) + panel.translation_m;
}

std::array<int, 2> panel_lattice_extent(const FabricSpec& spec) {
  std::array<int, 2> size = {-1, 0};
  for (const PanelSpec& panel : spec.panels) {
    const PanelGrid g = panel_grid(panel, spec.panel_spacing_m);
    size = {size[0] + g.cells_x + 2, std::max(size[1], g.cells_y + 1)};
  }
  return size;
}

FabricLayout panel_layout(const FabricSpec& spec) {
  const std::array<double, 2>& h = spec.panel_spacing_m;
  FabricLayout layout;
  layout.spacing = h;
  int column = 0;
  for (const PanelSpec& panel : spec.panels) {
    const MeshedPanel m = mesh_panel(panel, h);
    const int first = static_cast<int>(layout.rest.size());
    const Vec2 shift(column * h[0], 0.0);
    for (std::size_t n = 0; n < m.nodes.point.size(); ++n) {
      const Vec2 flat = m.nodes.point[n] - m.grid.origin + shift;
      layout.rest.emplace_back(flat.x(), flat.y(), 0.0);
      layout.lattice.push_back({column + m.nodes.lattice[n][0], m.nodes.lattice[n][1]});
      layout.moved.push_back(m.nodes.moved[n]);
    }
    for (Face f : m.nodes.faces) {
      for (int c = 0; c < f.corners; ++c) f.corner[static_cast<std::size_t>(c)] += first;
      layout.faces.push_back(f);
    }
    PanelMesh mesh{panel.name, first, static_cast<int>(m.nodes.point.size()), m.chains, m.grid.origin - shift, grain_rad(panel)};
    for (auto& chain : mesh.edge_nodes)
      for (int& node : chain) node += first;
    layout.panels.push_back(std::move(mesh));
    layout.lattice_size = {column + m.grid.cells_x + 1, std::max(layout.lattice_size[1], m.grid.cells_y + 1)};
    column += m.grid.cells_x + 2;
  }
  return layout;
}

}  // namespace fabform
