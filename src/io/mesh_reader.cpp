#include "fabform/io/mesh_reader.hpp"

#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <assimp/Importer.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "fabform/error.hpp"
#include "io/binary_stl.hpp"
#include "io/file_extension.hpp"
#include "io/mesh_file_check.hpp"
#include "io/obj_reader.hpp"
#include "io/vrml_reader.hpp"
#include "io/x3d_translation.hpp"

namespace fabform {
namespace {

// A name or message from a file or from assimp, fit for a one-line error or warning: printable
// ASCII only (anything else as '?'), at most 200 bytes.
std::string one_line(const std::string& text) {
  std::string out;
  for (std::size_t i = 0; i < text.size() && i < 200; ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    out += c >= 0x20 && c < 0x7F ? static_cast<char>(c) : '?';
  }
  return text.size() > 200 ? out + "..." : out;
}

// What a read left out, for the warnings and for the error when nothing is left.
struct Skipped {
  unsigned points_and_lines = 0;  // OBJ p/l records, and faces of fewer than three corners ("f 1 2")
  std::vector<std::string> empty_meshes;

  std::vector<std::string> lines() const {
    std::vector<std::string> out;
    if (points_and_lines == 1)
      out.push_back("skipped 1 point, line or face of fewer than three corners: it has no surface");
    else if (points_and_lines > 1)
      out.push_back("skipped " + std::to_string(points_and_lines) +
                    " points, lines and faces of fewer than three corners: they have no surface");
    for (const std::string& name : empty_meshes)
      out.push_back("skipped a mesh without faces" + (name.empty() ? std::string() : " ('" + one_line(name) + "')"));
    return out;
  }
};

// Appends the triangles of one assimp mesh; points and lines carry no surface and are skipped,
// and so are the vertices of a mesh that holds nothing else.
void append_triangles(const aiMesh& mesh, TriangleMesh* out, const std::string& path, Skipped* skipped) {
  unsigned triangles = 0;
  for (unsigned f = 0; f < mesh.mNumFaces; ++f) triangles += mesh.mFaces[f].mNumIndices == 3;
  skipped->points_and_lines += mesh.mNumFaces - triangles;
  if (triangles == 0) return;
  const int base = static_cast<int>(out->vertices.size());
  for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
    const aiVector3D& p = mesh.mVertices[v];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      throw InputError({path, 0, ""}, "a vertex coordinate is not finite (NaN or infinity)");
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

TriangleMesh with_triangles(TriangleMesh mesh, const std::string& path, const Skipped& skipped) {
  if (!mesh.triangles.empty()) return mesh;
  std::string why = "the mesh has no triangles";
  for (const std::string& line : skipped.lines()) why += "; " + line;
  throw InputError({path, 0, ""}, why);
}

unsigned primitive_type(unsigned corners) {
  switch (corners) {
    case 1: return aiPrimitiveType_POINT;
    case 2: return aiPrimitiveType_LINE;
    case 3: return aiPrimitiveType_TRIANGLE;
    default: return aiPrimitiveType_POLYGON;  // more than three: faces of none are gone by now
  }
}

// A PLY face of no corners ("0" in its list) comes out of assimp 5.2.5 as a face without
// indices, which ValidateDataStructure refuses, failing the whole file; it holds nothing, so it
// is dropped and counted with the points and lines.
void drop_faces_without_corners(const aiScene& scene, Skipped* skipped) {
  for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
    aiMesh& mesh = *scene.mMeshes[m];
    unsigned kept = 0;
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      if (mesh.mFaces[f].mNumIndices == 0) {
        ++skipped->points_and_lines;
        continue;
      }
      if (kept != f) std::swap(mesh.mFaces[kept], mesh.mFaces[f]);  // the empty one moves back, freed with the array
      ++kept;
    }
    mesh.mNumFaces = kept;
  }
}

// assimp 5.2.5's OBJ importer files a face of one or two corners ("f 1 2") as a polygon, and
// ValidateDataStructure then refuses the whole file; recounted from the faces, such a face is
// skipped with a warning instead, as a PLY or OFF face of two corners is.
void recount_primitive_types(const aiScene& scene) {
  for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
    aiMesh& mesh = *scene.mMeshes[m];
    unsigned types = 0;
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) types |= primitive_type(mesh.mFaces[f].mNumIndices);
    mesh.mPrimitiveTypes = types;
  }
}

void renumber_meshes(aiNode* node, const std::vector<int>& new_index) {
  unsigned kept = 0;
  for (unsigned i = 0; i < node->mNumMeshes; ++i)
    if (new_index[node->mMeshes[i]] >= 0) node->mMeshes[kept++] = static_cast<unsigned>(new_index[node->mMeshes[i]]);
  node->mNumMeshes = kept;
  for (unsigned c = 0; c < node->mNumChildren; ++c) renumber_meshes(node->mChildren[c], new_index);
}

// An ASCII STL may hold an empty "solid ... endsolid" beside real ones (assimp's own
// triangle_with_empty_solid.stl); assimp 5.2.5 makes it a mesh without vertices, which
// ValidateDataStructure refuses. It holds nothing, so it is dropped and named in a warning.
void drop_empty_meshes(aiScene* scene, Skipped* skipped) {
  std::vector<int> new_index(scene->mNumMeshes, -1);
  unsigned kept = 0;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    aiMesh* mesh = scene->mMeshes[m];
    if (mesh->mNumVertices > 0 && mesh->mNumFaces > 0) {
      new_index[m] = static_cast<int>(kept);
      scene->mMeshes[kept++] = mesh;
      continue;
    }
    skipped->empty_meshes.emplace_back(mesh->mName.C_Str());
    delete mesh;
  }
  scene->mNumMeshes = kept;
  if (scene->mRootNode) renumber_meshes(scene->mRootNode, new_index);
}

// Reads the file, or the mended bytes check_mesh_file gave in its place (same format).
TriangleMesh read_with_assimp(const std::string& path, const std::optional<std::string>& mended,
                              std::vector<std::string>* warnings) {
  Assimp::Importer importer;
  // Drop normals so that identical positions merge into one vertex; the BVH needs topology.
  importer.SetPropertyInteger(AI_CONFIG_PP_RVC_FLAGS, aiComponent_NORMALS | aiComponent_TEXCOORDS |
                                                          aiComponent_COLORS);
  // Read without post-processing first, to mend what assimp itself would then refuse.
  const std::string extension = lower_extension(path);  // mended bytes come only from .ply here
  const std::string hint = extension.empty() ? extension : extension.substr(1);
  const aiScene* read = mended ? importer.ReadFileFromMemory(mended->data(), mended->size(), 0, hint.c_str())
                               : importer.ReadFile(path, 0);
  if (!read) throw InputError({path, 0, ""}, "cannot read mesh: " + one_line(importer.GetErrorString()));
  Skipped skipped;
  // The importer owns the scene; we mend it.
  drop_faces_without_corners(*read, &skipped);
  drop_empty_meshes(const_cast<aiScene*>(read), &skipped);
  recount_primitive_types(*read);
  // ValidateDataStructure runs first: assimp 5.2.5 can misread a file into out-of-range
  // indices, which its later steps assert on (abort) instead of reporting.
  const unsigned flags = aiProcess_ValidateDataStructure | aiProcess_RemoveComponent | aiProcess_Triangulate |
                         aiProcess_JoinIdenticalVertices | aiProcess_PreTransformVertices |
                         aiProcess_SortByPType;
  const aiScene* scene = read->mNumMeshes > 0 ? importer.ApplyPostProcessing(flags) : read;
  if (!scene) throw InputError({path, 0, ""}, "cannot read mesh: " + one_line(importer.GetErrorString()));
  TriangleMesh mesh;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) append_triangles(*scene->mMeshes[m], &mesh, path, &skipped);
  mesh = with_triangles(std::move(mesh), path, skipped);
  if (warnings)
    for (const std::string& line : skipped.lines()) warnings->push_back(line);
  return mesh;
}

// OBJ by fabform's own reader (see obj_reader.hpp), from the mended text when there is one.
TriangleMesh read_obj(const std::string& path, const std::optional<std::string>& mended,
                      std::vector<std::string>* warnings) {
  std::string text;
  if (mended) {
    text = *mended;
  } else {
    std::ifstream in(path, std::ios::binary);
    text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    if (!in) throw InputError({path, 0, ""}, "cannot read the file");
  }
  ObjMesh read = read_obj_text(text);
  Skipped skipped;
  skipped.points_and_lines = read.points_and_lines;
  TriangleMesh mesh = with_triangles(std::move(read.mesh), path, skipped);
  if (warnings)
    for (const std::string& line : skipped.lines()) warnings->push_back(line);
  return mesh;
}

// A binary STL by fabform's own reader; bytes after its declared triangles are left out, as
// common readers do, and said.
TriangleMesh read_stl(const std::string& path, std::uintmax_t trailing_bytes, std::vector<std::string>* warnings) {
  TriangleMesh mesh = with_triangles(read_binary_stl(path), path, {});
  const std::size_t triangles = mesh.triangles.size();
  if (warnings && trailing_bytes > 0)
    warnings->push_back("ignored " + std::to_string(trailing_bytes) + (trailing_bytes == 1 ? " byte" : " bytes") +
                        " after the " + std::to_string(triangles) + (triangles == 1 ? " triangle" : " triangles") +
                        " the binary STL declares");
  return mesh;
}

// X3D XML through its VRML97 translation; what was left out is said, as the VRML reader says
// what it skips.
TriangleMesh read_x3d(const std::string& path, std::vector<std::string>* warnings) {
  const X3dTranslation translation = translate_x3d(path);
  std::string left_out;
  for (const auto& [name, count] : translation.left_out)
    left_out += (left_out.empty() ? "" : ", ") + name + (count > 1 ? " x" + std::to_string(count) : "");
  if (!left_out.empty()) left_out = "X3D: left out what shapes no surface: " + left_out;
  try {
    TriangleMesh mesh = read_vrml_text(translation.vrml, path, warnings);
    if (warnings && !left_out.empty()) warnings->push_back(left_out);
    return mesh;
  } catch (const InputError& error) {  // "no triangles" says more with what was left out
    if (left_out.empty()) throw;
    throw InputError(error.where(), error.message() + "; " + left_out);
  }
}

}  // namespace

TriangleMesh read_mesh(const std::string& path, std::vector<std::string>* warnings) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw InputError({path, 0, ""}, "is a folder, not a mesh file");
  if (!std::filesystem::is_regular_file(path, ec)) throw InputError({path, 0, ""}, "no such mesh file");
  // assimp 5.2.5 has no VRML97 reader; Coin3D reads it (.wrz is gzip-compressed VRML97).
  const std::string extension = lower_extension(path);
  if (extension == ".wrl" || extension == ".wrz" || extension == ".vrml") return read_vrml(path, warnings);
  // X3D goes to neither reader as it is: Coin 4.0 reads no X3D ("Not a valid Inventor file"),
  // and assimp 5.2.5 loses DEF/USE instances (ComputerKeyboard.x3d: 100 of its 2020
  // triangles) and turns an IndexedLineSet into faces. X3D's XML encoding is translated to the
  // VRML97 it extends and read by Coin; the classic and binary encodings are refused.
  if (extension == ".x3d") return read_x3d(path, warnings);
  if (extension == ".x3dv" || extension == ".x3db" || extension == ".x3dz" || extension == ".x3dvz")
    throw InputError({path, 0, ""},
                     "X3D's classic and binary encodings are not read (X3D XML, .x3d, is): export the body "
                     "as .x3d, VRML97 (.wrl), STL or OBJ");
  const std::optional<std::string> mended = check_mesh_file(path);
  if (extension == ".obj") return read_obj(path, mended, warnings);
  if (extension == ".stl")
    if (const auto trailing = binary_stl_trailing_bytes(path)) return read_stl(path, *trailing, warnings);
  return read_with_assimp(path, mended, warnings);
}

}  // namespace fabform
