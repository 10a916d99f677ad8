// Benchmark: load a binary STL of about a million triangles into a RigidBody (read, vertex
// merging, pseudo-normals, Embree BVH) against assimp alone reading the same file, in the same
// run: assimp with no post-processing (a triangle soup, the import issue's yardstick; target
// ratio at most 1.5) and with JoinIdenticalVertices (the least that gives the mesh's topology,
// which contact needs). Prints the figures and the ratios.
//   build/fabform_bench_load [TRIANGLES] [REPEATS]
#include <assimp/Importer.hpp>
#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include "fabform/geometry/rigid_body.hpp"
#include "fabform/io/mesh_reader.hpp"

namespace {

// A torus tessellated into `triangles` triangles, written as binary STL (float32, 50 bytes each).
void write_torus_stl(const std::string& path, long triangles) {
  const long around = static_cast<long>(std::sqrt(static_cast<double>(triangles) / 4.0));
  const long along = triangles / (2 * around);
  const double pi = 3.14159265358979323846, major = 0.1, minor = 0.03;
  const auto point = [&](long i, long j) {
    const double u = 2 * pi * static_cast<double>(i % along) / static_cast<double>(along);
    const double v = 2 * pi * static_cast<double>(j % around) / static_cast<double>(around);
    return std::array<float, 3>{static_cast<float>((major + minor * std::cos(v)) * std::cos(u)),
                                static_cast<float>((major + minor * std::cos(v)) * std::sin(u)),
                                static_cast<float>(minor * std::sin(v))};
  };
  std::ofstream out(path, std::ios::binary);
  char header[80] = "fabform benchmark torus";
  out.write(header, 80);
  const std::uint32_t count = static_cast<std::uint32_t>(2 * along * around);
  out.write(reinterpret_cast<const char*>(&count), 4);
  const auto facet = [&](const std::array<float, 3>& a, const std::array<float, 3>& b,
                         const std::array<float, 3>& c) {
    const float normal[3] = {0, 0, 0};
    const std::uint16_t attribute = 0;
    out.write(reinterpret_cast<const char*>(normal), 12);
    for (const auto* p : {&a, &b, &c}) out.write(reinterpret_cast<const char*>(p->data()), 12);
    out.write(reinterpret_cast<const char*>(&attribute), 2);
  };
  for (long i = 0; i < along; ++i)
    for (long j = 0; j < around; ++j) {
      facet(point(i, j), point(i + 1, j), point(i + 1, j + 1));
      facet(point(i, j), point(i + 1, j + 1), point(i, j + 1));
    }
}

double seconds_of(const std::function<void()>& work) {
  const auto start = std::chrono::steady_clock::now();
  work();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// `join`: merge corners at the same position, which assimp does only once the per-facet
// normals are removed.
std::size_t assimp_read(const std::string& path, bool join) {
  Assimp::Importer importer;
  importer.SetPropertyInteger(AI_CONFIG_PP_RVC_FLAGS, aiComponent_NORMALS);
  const aiScene* scene =
      importer.ReadFile(path, join ? aiProcess_RemoveComponent | aiProcess_JoinIdenticalVertices : 0u);
  return scene ? scene->mMeshes[0]->mNumFaces : 0;
}

}  // namespace

// The three loads take turns, and each keeps its best time, so that a machine busy for a
// moment does not favour one of them.
int main(int argc, char** argv) {
  const long triangles = argc > 1 ? std::atol(argv[1]) : 1'000'000;
  const int repeats = argc > 2 ? std::atoi(argv[2]) : 5;
  const std::string path = (std::filesystem::temp_directory_path() / "fabform_bench_torus.stl").string();
  write_torus_stl(path, triangles);
  double raw = 1e300, joined = 1e300, read = 1e300, total = 1e300;
  std::size_t loaded = 0, vertices = 0;
  for (int r = 0; r < repeats; ++r) {
    raw = std::min(raw, seconds_of([&] { loaded = assimp_read(path, false); }));
    joined = std::min(joined, seconds_of([&] { assimp_read(path, true); }));
    total = std::min(total, seconds_of([&] {
      const auto start = std::chrono::steady_clock::now();
      fabform::TriangleMesh mesh = fabform::read_mesh(path);
      read = std::min(read, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
      const fabform::RigidBody body("torus", std::move(mesh));
      vertices = body.mesh().vertices.size();
    }));
  }
  std::filesystem::remove(path);
  std::printf("triangles                                    %zu (%zu vertices once merged)\n", loaded, vertices);
  std::printf("assimp ReadFile, no post-processing (s)      %.3f\n", raw);
  std::printf("assimp ReadFile, vertices joined (s)         %.3f\n", joined);
  std::printf("fabform read_mesh (s)                        %.3f\n", read);
  std::printf("fabform read_mesh + RigidBody with BVH (s)   %.3f\n", total);
  std::printf("ratio fabform / assimp, no post-processing   %.2f   (target <= 1.5)\n", total / raw);
  std::printf("ratio fabform / assimp, joined vertices      %.2f\n", total / joined);
  return 0;
}
