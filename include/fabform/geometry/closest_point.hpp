#pragma once
// Point–triangle queries in double precision: the narrow phase of contact.
#include <optional>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace fabform {

/// Which part of a triangle a closest point lies on; it selects the pseudo-normal that
/// decides inside from outside.
enum class TriangleFeature { face, edge01, edge12, edge20, vertex0, vertex1, vertex2 };

struct TriangleClosest {
  Eigen::Vector3d point;
  TriangleFeature feature = TriangleFeature::face;
};

/// Closest point of triangle abc to p (Voronoi-region method). A degenerate triangle is
/// treated as its three edges.
TriangleClosest closest_point_on_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                          const Eigen::Vector3d& b, const Eigen::Vector3d& c);

/// Closest point of segment ab to p, as a parameter in [0, 1].
double closest_parameter_on_segment(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                    const Eigen::Vector3d& b);

/// Parameter t in [0, 1] where segment from→to crosses the plane of triangle abc, if it does.
std::optional<double> segment_plane_crossing(const Eigen::Vector3d& from,
                                             const Eigen::Vector3d& to, const Eigen::Vector3d& a,
                                             const Eigen::Vector3d& b, const Eigen::Vector3d& c);

}  // namespace fabform
