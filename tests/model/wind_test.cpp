// Seed 004's wind: node normals on flat, rolled, moved and collapsed fabrics of every mesh; the
// force's direction, size and invariances; and the implicit drag step's limits.
#include "fabform/model/wind.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include <Eigen/Geometry>

#include "fabform/model/model.hpp"
#include "support/clamped_fabric.hpp"

namespace fabform::wind_test {
namespace {

FabricSpec circle(FabricSpec::Mesh mesh) {
  FabricSpec spec{0.3, 0.3, 12, 12, FabricSpec::Shape::circle, mesh};
  if (mesh == FabricSpec::Mesh::arc) spec.rings = 6, spec.spokes = 16;
  return spec;
}

std::vector<FabricSpec> every_mesh() {
  return {FabricSpec{0.2, 0.1, 8, 4}, circle(FabricSpec::Mesh::quadrangular), circle(FabricSpec::Mesh::triangular),
          circle(FabricSpec::Mesh::arc)};
}

std::vector<Eigen::Vector3d> flat(const Fabric& fabric) {
  std::vector<Eigen::Vector3d> x;
  for (int k = 0; k < fabric.node_count(); ++k) x.push_back(fabric.rest_position(k));
  return x;
}

Wind wind(const Eigen::Vector3d& velocity, double coefficient = 2.0) { return Wind{velocity, coefficient}; }

// Every face of every mesh is wound one way: a flat fabric's normals are all +z or all −z.
TEST(NodeNormal, FlatFabricFacesOneWay) {
  for (const FabricSpec& spec : every_mesh()) {
    const Fabric fabric(spec);
    const std::vector<Eigen::Vector3d> x = flat(fabric);
    const double side = node_normal(fabric, x, 0).z();
    ASSERT_EQ(std::abs(side), 1.0) << to_string(spec.mesh);
    for (int k = 0; k < fabric.node_count(); ++k)
      EXPECT_EQ(node_normal(fabric, x, k), Eigen::Vector3d(0, 0, side)) << to_string(spec.mesh) << " node " << k;
  }
}

// A rectangle rolled round a cylinder (axis along y, radius 0.05 m): an inner node's faces sit
// symmetrically about it, so its normal is the radius through it, to rounding (1e-14).
TEST(NodeNormal, RolledFabricPointsAlongTheRadius) {
  const Fabric fabric(FabricSpec{0.2, 0.1, 16, 8});
  const double radius = 0.05;
  std::vector<Eigen::Vector3d> x;
  for (int k = 0; k < fabric.node_count(); ++k) {
    const Eigen::Vector3d p = fabric.rest_position(k);
    x.emplace_back(radius * std::sin(p.x() / radius), p.y(), radius * std::cos(p.x() / radius));
  }
  double side = 0.0;
  for (int k = 0; k < fabric.node_count(); ++k) {
    if (fabric.on_perimeter(k)) continue;
    const Eigen::Vector3d radial = Eigen::Vector3d(x[k].x(), 0.0, x[k].z()).normalized();
    const Eigen::Vector3d n = node_normal(fabric, x, k);
    if (side == 0.0) side = n.dot(radial);
    EXPECT_LT((n - side * radial).norm(), 1e-14) << "node " << k;
  }
  EXPECT_NEAR(std::abs(side), 1.0, 1e-15);
}

TEST(NodeNormal, FollowsTheNodeMovedToAt) {
  const Fabric fabric(circle(FabricSpec::Mesh::arc));
  std::vector<Eigen::Vector3d> x = flat(fabric);
  for (int k = 0; k < fabric.node_count(); ++k) x[k].z() = 0.01 * std::sin(37.0 * k);
  for (const int node : {0, 5, fabric.node_count() - 1}) {
    const Eigen::Vector3d at = x[node] + Eigen::Vector3d(0.003, -0.002, 0.02);
    std::vector<Eigen::Vector3d> moved = x;
    moved[node] = at;
    EXPECT_EQ(node_normal(fabric, x, node, at), node_normal(fabric, moved, node)) << node;
  }
}

TEST(NodeNormal, TurnsWithTheFabric) {
  const Fabric fabric(circle(FabricSpec::Mesh::triangular));
  std::vector<Eigen::Vector3d> x = flat(fabric);
  for (int k = 0; k < fabric.node_count(); ++k) x[k].z() = 0.02 * std::cos(11.0 * k);
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(0.9, Eigen::Vector3d(1, -2, 3).normalized()).toRotationMatrix();
  std::vector<Eigen::Vector3d> turned;
  for (const auto& p : x) turned.push_back(turn * p + Eigen::Vector3d(4, 5, -6));
  for (int k = 0; k < fabric.node_count(); ++k)
    EXPECT_LT((node_normal(fabric, turned, k) - turn * node_normal(fabric, x, k)).norm(), 1e-12) << k;
}

// A fabric crushed onto a line or a point has no normal: the wind finds nothing to push.
TEST(NodeNormal, CollapsedFabricHasNone) {
  for (const FabricSpec& spec : every_mesh()) {
    const Fabric fabric(spec);
    std::vector<Eigen::Vector3d> line = flat(fabric), point(line.size(), Eigen::Vector3d(1, 2, 3));
    for (auto& p : line) p.y() = p.z() = 0.0;
    for (int k = 0; k < fabric.node_count(); ++k) {
      EXPECT_EQ(node_normal(fabric, line, k), Eigen::Vector3d::Zero());
      EXPECT_EQ(node_normal(fabric, point, k), Eigen::Vector3d::Zero());
      EXPECT_EQ(wind_force(wind({0, 0, 5}), 1e-4, node_normal(fabric, point, k), Eigen::Vector3d::Zero()),
                Eigen::Vector3d::Zero());
    }
  }
}

TEST(WindForce, PushesAlongTheNormalByTheWindAcrossIt) {
  const Eigen::Vector3d n = Eigen::Vector3d(1, 2, 2) / 3.0;
  const Wind w = wind({3, -1, 4}, 2.5);
  const double area = 4e-4;
  const Eigen::Vector3d v(0.5, 0.25, -1);
  const Eigen::Vector3d f = wind_force(w, area, n, v);
  EXPECT_LT((f - 2.5 * area * n.dot(w.velocity_m_s - v) * n).norm(), 1e-18);
  EXPECT_LT(f.cross(n).norm(), 1e-18) << "along the normal";
  EXPECT_EQ(wind_force(w, area, -n, v), f) << "either side's normal";
  EXPECT_EQ(wind_force(w, area, n, w.velocity_m_s), Eigen::Vector3d::Zero()) << "moving with the wind";
  EXPECT_EQ(wind_force(wind({1, 0, 0}), area, Eigen::Vector3d(0, 0, 1), Eigen::Vector3d::Zero()),
            Eigen::Vector3d::Zero())
      << "a wind along the fabric";
  EXPECT_LT((wind_force(w, 2.0 * area, n, v) - 2.0 * f).norm(), 1e-18) << "proportional to area";
}

// On a flat fabric at rest the nodes' forces add up to C · (fabric area) · (v_wind · z) z,
// whatever the mesh (node areas sum to the flat area; 1e-12 relative for the sum's rounding).
TEST(WindForce, OnAFlatFabricTotalsTheWindOnItsArea) {
  const Wind w = wind({0.7, -0.4, 3.0}, 1.5);
  for (const FabricSpec& spec : every_mesh()) {
    const Fabric fabric(spec);
    const std::vector<Eigen::Vector3d> x = flat(fabric);
    Eigen::Vector3d total = Eigen::Vector3d::Zero();
    for (int k = 0; k < fabric.node_count(); ++k)
      total += wind_force(w, fabric.node_areas()[k], node_normal(fabric, x, k), Eigen::Vector3d::Zero());
    const Eigen::Vector3d expected(0, 0, 1.5 * fabric.flat_area() * 3.0);
    EXPECT_LT((total - expected).norm(), 1e-12 * expected.norm()) << to_string(spec.mesh);
  }
}

TEST(WindDrag, TakesOnlyTheNormalVelocityAndNeverOvershoots) {
  const Eigen::Vector3d n(0, 0, 1), v(0.3, -0.2, 2.0);
  EXPECT_EQ(after_wind_drag(0.0, n, v), v);
  const Eigen::Vector3d half = after_wind_drag(1.0, n, v);
  EXPECT_EQ(half.head<2>(), v.head<2>()) << "the wind does not drag along the fabric";
  EXPECT_DOUBLE_EQ(half.z(), 1.0);
  for (const double a : {1e-3, 1.0, 1e3, 1e12}) {
    const double z = after_wind_drag(a, n, v).z();
    EXPECT_GT(z, 0.0) << a;
    EXPECT_LE(z, v.z()) << a;
  }
  EXPECT_EQ(after_wind_drag(1.0, Eigen::Vector3d::Zero(), v), v) << "no normal, no drag";
  // A projected normal (a node held in z, n tilted): the step solves v' = v − a·(n·v')·n.
  const Eigen::Vector3d tilted(0.6, 0.0, 0.0), free(0.5, 0.3, 0.0);
  const Eigen::Vector3d after = after_wind_drag(2.0, tilted, free);
  EXPECT_LT((after - (free - 2.0 * tilted.dot(after) * tilted)).norm(), 1e-15);
}

TEST(Wind, NeedsADirectionAndAStrength) {
  EXPECT_EQ(wind({0, 0, 1}).invalid_reason(), "");
  EXPECT_NE(wind({0, 0, 0}).invalid_reason().find("wind without a direction"), std::string::npos);
  EXPECT_NE(wind({std::nan(""), 0, 1}).invalid_reason(), "");
  EXPECT_NE(wind({0, 0, 1}, 0.0).invalid_reason(), "");
  EXPECT_NE(wind({0, 0, 1}, -1.0).invalid_reason(), "");
  EXPECT_NE(wind({0, 0, 1}, INFINITY).invalid_reason(), "");
}

// The wind as a term: at rest its force is C·A·(n·v_wind)·n on each node; it has no potential,
// so only dynamic takes it, and its drag over a step is after_wind_drag's within the node's
// free directions.
TEST(WindLoad, IsTheWindAtRestWithItsDragForDynamicAlone) {
  Model model = test::clamped_fabric(4, 0.01);
  test::lift_interior(model, 0.01);
  const Wind blowing = wind({0.5, 0.0, 3.0}, 1.5);
  const WindLoad load(blowing);
  const Positions& x = model.start;
  for (int k = 0; k < model.node_count(); ++k) {
    const double area = model.fabric.node_areas()[static_cast<std::size_t>(k)];
    const Eigen::Vector3d at = x[static_cast<std::size_t>(k)] + Eigen::Vector3d(0, 0, 1e-3);
    EXPECT_EQ(load.force_at(model, x, k, at),
              wind_force(blowing, area, node_normal(model.fabric, x, k, at), Eigen::Vector3d::Zero()));
  }
  EXPECT_EQ(load.energy(model, x), 0.0);
  EXPECT_TRUE(load.external());
  EXPECT_EQ(load.needs(), SolverNeeds(SolverNeed::velocity));
  const auto drag = load.drag(model, x);
  ASSERT_NE(drag, nullptr);
  const int inner = model.fabric.node(2, 2);
  const double area = model.fabric.node_areas()[static_cast<std::size_t>(inner)];
  const Eigen::Vector3d v(0.1, 0.2, 0.3), n = node_normal(model.fabric, x, inner);
  EXPECT_EQ(drag->after(inner, 1e-3, 2e-4, v, NodeFreedom{}), after_wind_drag(1e-3 * 1.5 * area / 2e-4, n, v));
  const Eigen::Vector3d held = drag->after(inner, 1e-3, 2e-4, Eigen::Vector3d(0.1, 0.2, 0.0), NodeFreedom{kLockZ, nullptr});
  EXPECT_EQ(held.z(), 0.0) << "the drag stays within the free directions";
  EXPECT_THROW(WindLoad(wind({0, 0, 0})), std::invalid_argument);
}

}  // namespace
}  // namespace fabform::wind_test
