#include "geometry/embree_scene.hpp"

#include <embree3/rtcore.h>

#include <limits>
#include <stdexcept>
#include <string>

namespace fabform {
namespace {

RTCDevice as_device(void* p) { return static_cast<RTCDevice>(p); }
RTCScene as_scene(void* p) { return static_cast<RTCScene>(p); }

struct VisitContext {
  const std::function<double(int)>* visitor;
};

bool finite_as_float(const Eigen::Vector3d& v) {
  return (v.array().abs() < static_cast<double>(std::numeric_limits<float>::max())).all();
}

bool visit_candidate(RTCPointQueryFunctionArguments* args) {
  auto* context = static_cast<VisitContext*>(args->userPtr);
  const double radius = (*context->visitor)(static_cast<int>(args->primID));
  if (radius >= static_cast<double>(args->query->radius)) return false;
  args->query->radius = static_cast<float>(radius);
  return true;
}

const char* error_name(RTCError code) {
  switch (code) {
    case RTC_ERROR_INVALID_ARGUMENT: return "invalid argument";
    case RTC_ERROR_INVALID_OPERATION: return "invalid operation";
    case RTC_ERROR_OUT_OF_MEMORY: return "out of memory";
    case RTC_ERROR_UNSUPPORTED_CPU: return "unsupported CPU";
    case RTC_ERROR_CANCELLED: return "cancelled";
    default: return "unknown error";
  }
}

}  // namespace

EmbreeScene::EmbreeScene(const std::vector<Eigen::Vector3d>& vertices,
                         const std::vector<std::array<int, 3>>& triangles) {
  device_ = rtcNewDevice(nullptr);
  if (!device_) throw std::runtime_error("Embree: cannot create a device");
  try {
    build(vertices, triangles);
  } catch (...) {  // a constructor that throws runs no destructor: release here
    release();
    throw;
  }
}

void EmbreeScene::build(const std::vector<Eigen::Vector3d>& vertices,
                        const std::vector<std::array<int, 3>>& triangles) {
  scene_ = rtcNewScene(as_device(device_));
  check("creating a scene");
  rtcSetSceneFlags(as_scene(scene_), RTC_SCENE_FLAG_ROBUST);
  RTCGeometry geometry = rtcNewGeometry(as_device(device_), RTC_GEOMETRY_TYPE_TRIANGLE);
  check("creating a triangle geometry");
  auto* vb = static_cast<float*>(rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), vertices.size()));
  auto* ib = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), triangles.size()));
  if (!vb || !ib) {
    rtcReleaseGeometry(geometry);
    check("allocating geometry buffers");
    throw std::runtime_error("Embree: cannot allocate geometry buffers");
  }
  for (std::size_t v = 0; v < vertices.size(); ++v)
    for (int c = 0; c < 3; ++c) vb[3 * v + c] = static_cast<float>(vertices[v][c]);
  for (std::size_t t = 0; t < triangles.size(); ++t)
    for (int c = 0; c < 3; ++c) ib[3 * t + c] = static_cast<unsigned>(triangles[t][c]);
  rtcCommitGeometry(geometry);
  rtcAttachGeometry(as_scene(scene_), geometry);
  rtcReleaseGeometry(geometry);
  rtcCommitScene(as_scene(scene_));
  check("building the BVH");
}

void EmbreeScene::release() {
  if (scene_) rtcReleaseScene(as_scene(scene_));
  if (device_) rtcReleaseDevice(as_device(device_));
  scene_ = device_ = nullptr;
}

EmbreeScene::~EmbreeScene() { release(); }

void EmbreeScene::check(const char* doing) const {
  const RTCError code = rtcGetDeviceError(as_device(device_));
  if (code != RTC_ERROR_NONE)
    throw std::runtime_error(std::string("Embree: ") + error_name(code) + " while " + doing);
}

void EmbreeScene::visit_near(const Eigen::Vector3d& p, double radius,
                             const std::function<double(int)>& visitor) const {
  if (!finite_as_float(p)) return;  // a broken node is reported by the solver, not crashed on
  RTCPointQuery query;
  query.x = static_cast<float>(p.x());
  query.y = static_cast<float>(p.y());
  query.z = static_cast<float>(p.z());
  query.time = 0.0f;
  query.radius = radius >= static_cast<double>(std::numeric_limits<float>::max())
                     ? std::numeric_limits<float>::infinity()
                     : static_cast<float>(radius);
  RTCPointQueryContext context;
  rtcInitPointQueryContext(&context);
  VisitContext user{&visitor};
  rtcPointQuery(as_scene(scene_), &query, &context, visit_candidate, &user);
}

std::optional<EmbreeScene::RayHit> EmbreeScene::first_hit(const Eigen::Vector3d& origin,
                                                          const Eigen::Vector3d& direction,
                                                          double t_near, double t_far) const {
  // Embree asserts on rays that are not finite; a broken node's query sees nothing instead.
  if (!finite_as_float(origin) || !finite_as_float(direction) || !(t_near >= 0.0 && t_near <= t_far))
    return std::nullopt;
  RTCRayHit ray_hit{};
  ray_hit.ray.org_x = static_cast<float>(origin.x());
  ray_hit.ray.org_y = static_cast<float>(origin.y());
  ray_hit.ray.org_z = static_cast<float>(origin.z());
  ray_hit.ray.dir_x = static_cast<float>(direction.x());
  ray_hit.ray.dir_y = static_cast<float>(direction.y());
  ray_hit.ray.dir_z = static_cast<float>(direction.z());
  ray_hit.ray.tnear = static_cast<float>(t_near);
  ray_hit.ray.tfar = static_cast<float>(t_far);
  ray_hit.ray.mask = 0xFFFFFFFFu;
  ray_hit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  rtcIntersect1(as_scene(scene_), &context, &ray_hit);
  if (ray_hit.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
  return RayHit{static_cast<int>(ray_hit.hit.primID), static_cast<double>(ray_hit.ray.tfar)};
}

}  // namespace fabform
