#include "fabform/io/mesh_reader.hpp"

#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <assimp/Importer.hpp>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <utility>

#include "fabform/error.hpp"
#include "io/binary_stl.hpp"
#include "io/declared_counts.hpp"
#include "io/vrml_reader.hpp"

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

TriangleMesh with_triangles(TriangleMesh mesh, const std::string& path) {
  if (mesh.triangles.empty()) throw InputError({path, 0, ""}, "the mesh has no triangles");
  return mesh;
}

// The file name's extension, lower case, with its dot ("" when none).
std::string lower_extension(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return extension;
}

}  // namespace

TriangleMesh read_mesh(const std::string& path, std::vector<std::string>* warnings) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw InputError({path, 0, ""}, "no such mesh file");
  // assimp 5.2.5 has no VRML97 reader; Coin3D reads it (.wrz is gzip-compressed VRML97).
  const std::string extension = lower_extension(path);
  if (extension == ".wrl" || extension == ".wrz" || extension == ".vrml") return read_vrml(path, warnings);
  // X3D goes to neither reader, because neither reads it right (checked on tests/data/vrml/x3d,
  // counts by hand in tests/data/vrml/README.md). Coin 4.0 reads no X3D at all, XML or classic
  // ("Not a valid Inventor file"). assimp 5.2.5 reads X3D XML but loses DEF/USE instances
  // (ComputerKeyboard.x3d: 100 of its 2020 triangles) and turns an IndexedLineSet into faces
  // (IndexedLineSet.x3d: 3 triangles from a line loop), and has no classic (.x3dv) reader.
  if (extension == ".x3d" || extension == ".x3dv" || extension == ".x3db" || extension == ".x3dz" ||
      extension == ".x3dvz")
    throw InputError({path, 0, ""},
                     "X3D is not read (neither assimp 5.2.5 nor Coin 4.0 reads it correctly): export the "
                     "body as VRML97 (.wrl), STL or OBJ");
  Assimp::Importer importer;
  // Drop normals so that identical positions merge into one vertex; the BVH needs topology.
  importer.SetPropertyInteger(AI_CONFIG_PP_RVC_FLAGS, aiComponent_NORMALS | aiComponent_TEXCOORDS |
                                                          aiComponent_COLORS);
  check_declared_counts(path);
  if (extension == ".stl" && is_binary_stl(path)) return with_triangles(read_binary_stl(path), path);
  // ValidateDataStructure runs first: assimp 5.2.5 can misread a file into out-of-range
  // indices, which its later steps assert on (abort) instead of reporting.
  const unsigned flags = aiProcess_ValidateDataStructure | aiProcess_RemoveComponent | aiProcess_Triangulate |
                         aiProcess_JoinIdenticalVertices | aiProcess_PreTransformVertices |
                         aiProcess_SortByPType;
  const aiScene* scene = importer.ReadFile(path, flags);
  if (!scene) throw InputError({path, 0, ""}, std::string("cannot read mesh: ") + importer.GetErrorString());
  TriangleMesh mesh;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) append_triangles(*scene->mMeshes[m], &mesh, path);
  return with_triangles(std::move(mesh), path);
}

}  // namespace fabform
