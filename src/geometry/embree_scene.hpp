#pragma once
// The one place fabform talks to Embree: a device and a triangle scene in RAII, Embree's
// errors turned into exceptions. Embree's BVH is single precision, so it only finds
// candidates; callers decide in double.
#include <array>
#include <functional>
#include <optional>
#include <vector>

#include <Eigen/Core>

namespace fabform {

class EmbreeScene {
 public:
  EmbreeScene(const std::vector<Eigen::Vector3d>& vertices,
              const std::vector<std::array<int, 3>>& triangles);
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  /// Visits every triangle whose box lies within `radius` of p. The visitor returns the
  /// radius to keep searching in, so it can shrink the search as it finds closer triangles.
  void visit_near(const Eigen::Vector3d& p, double radius,
                  const std::function<double(int triangle)>& visitor) const;

  /// First triangle the ray origin + t·direction crosses for t in [t_near, t_far].
  struct RayHit {
    int triangle = -1;
    double t = 0.0;
  };
  std::optional<RayHit> first_hit(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                                  double t_near, double t_far) const;

 private:
  void build(const std::vector<Eigen::Vector3d>& vertices,
             const std::vector<std::array<int, 3>>& triangles);
  void release();
  void check(const char* doing) const;

  void* device_ = nullptr;  // RTCDevice
  void* scene_ = nullptr;   // RTCScene
};

}  // namespace fabform
