#include "fabform/io/mesh_reader.hpp"

#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <assimp/Importer.hpp>
#include <cmath>
#include <filesystem>

#include "fabform/error.hpp"

namespace fabform {
namespace {

// Appends the triangles of one assimp mesh; points and lines carry no surface and are skipped.
void append_triangles(const aiMesh& mesh, TriangleMesh* out, const std::string& path) {
  const int base = static_cast<int>(out->vertices.size());
  for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
    const aiVector3D& p = mesh.mVertices[v];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      throw InputError({path, 0, ""}, "vertex " + std::to_string(v) + " is not finite");
    out->vertices.emplace_back(p.x, p.y, p.z);
  }
  for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
    const aiFace& face = mesh.mFaces[f];
    if (face.mNumIndices != 3) continue;
    std::array<int, 3> triangle{};
    for (int c = 0; c < 3; ++c) {
      if (face.mIndices[c] >= mesh.mNumVertices)
        throw InputError({path, 0, ""}, "face " + std::to_string(f) + " indexes a missing vertex");
      triangle[c] = base + static_cast<int>(face.mIndices[c]);
    }
    out->triangles.push_back(triangle);
  }
}

}  // namespace

TriangleMesh read_mesh(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw InputError({path, 0, ""}, "no such mesh file");
  Assimp::Importer importer;
  // Drop normals so that identical positions merge into one vertex; the BVH needs topology.
  importer.SetPropertyInteger(AI_CONFIG_PP_RVC_FLAGS, aiComponent_NORMALS | aiComponent_TEXCOORDS |
                                                          aiComponent_COLORS);
  const unsigned flags = aiProcess_RemoveComponent | aiProcess_Triangulate |
                         aiProcess_JoinIdenticalVertices | aiProcess_PreTransformVertices |
                         aiProcess_SortByPType;
  const aiScene* scene = importer.ReadFile(path, flags);
  if (!scene) throw InputError({path, 0, ""}, std::string("cannot read mesh: ") + importer.GetErrorString());
  TriangleMesh mesh;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) append_triangles(*scene->mMeshes[m], &mesh, path);
  if (mesh.triangles.empty()) throw InputError({path, 0, ""}, "the mesh has no triangles");
  return mesh;
}

}  // namespace fabform
