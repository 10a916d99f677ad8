// Grid continuation's step from one grid to the next (solver/grid_continuation.hpp): a coarse rest
// interpolated exactly where bilinear interpolation is exact, and a node interpolated onto a
// facet within rounding starting in contact.
#include "fabform/solver/grid_continuation.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "fabform/scene/model_builder.hpp"
#include "fabform/scene/scene_toml.hpp"
#include "test_paths.hpp"

namespace fabform::grid_continuation_test {
namespace {

Fabric rectangle(int divisions_warp, int divisions_weft) {
  FabricSpec spec;
  spec.width_m = 0.12;
  spec.height_m = 0.09;
  spec.divisions_warp = divisions_warp;
  spec.divisions_weft = divisions_weft;
  return Fabric(spec);
}

// An affine displacement u(p) = A p + c, which bilinear interpolation reproduces exactly.
Eigen::Vector3d affine(const Eigen::Vector3d& flat) {
  Eigen::Matrix3d a;
  a << 0.1, -0.3, 0.0, 0.2, 0.05, 0.0, 0.7, -0.4, 0.0;
  return flat + a * flat + Eigen::Vector3d(0.01, -0.02, 0.03);
}

TEST(GridContinuation, InterpolationIsExactForAnAffineDisplacement) {
  const Fabric fine = rectangle(16, 12);
  for (const int ratio : {2, 4}) {
    const Fabric coarse = rectangle(16 / ratio, 12 / ratio);
    std::vector<Eigen::Vector3d> coarse_x;
    for (int k = 0; k < coarse.node_count(); ++k) coarse_x.push_back(affine(coarse.rest_position(k)));
    const std::vector<Eigen::Vector3d> x = interpolate_rest(coarse, coarse_x, fine);
    ASSERT_EQ(static_cast<int>(x.size()), fine.node_count());
    for (int k = 0; k < fine.node_count(); ++k)
      EXPECT_LT((x[static_cast<std::size_t>(k)] - affine(fine.rest_position(k))).norm(), 1e-15)
          << fine.node_name(k) << ", ratio " << ratio;
  }
}

TEST(GridContinuation, ANodeOnAFacetWithinRoundingStartsInContact) {
  // Interpolated between two coarse nodes on one facet, a node lies on it up to rounding, above
  // as often as below; either way it starts in contact, on the surface, while a node clearly
  // above (four times the margin) stays free where it is.
  const Scene scene = load_scene(test::source_path("scenes/dome.toml"), {{"fabric.divisions", "[20,20]"}});
  const Model model = build_model(scene);
  const RigidBody& dome = model.bodies.front();
  const double margin = dome.on_surface_distance();
  const int centre = 10 * 21 + 10;
  ASSERT_EQ(model.locks[centre], 0);
  const Eigen::Vector3d above_top = model.fabric.rest_position(centre) + Eigen::Vector3d(0.001, 0.002, 0.05);
  const SurfacePoint top = dome.closest(above_top);
  for (const double height : {-0.5, 0.0, 0.5, 4.0}) {
    SCOPED_TRACE(testing::Message() << height << " margins above the surface");
    std::vector<Eigen::Vector3d> interpolated = model.start;
    interpolated[centre] = top.point + height * margin * top.normal;
    const SolverState start = continued_start(model, interpolated);
    const bool on_surface = height <= 1.0;
    EXPECT_EQ(start.contact[centre].active(), on_surface);
    if (on_surface) EXPECT_LE((start.x[centre] - top.point).norm(), 1e-12 * dome.box().diagonal());
    else EXPECT_EQ(start.x[centre], interpolated[centre]);
  }
}

}  // namespace
}  // namespace fabform::grid_continuation_test
