#pragma once
// What a mesh file must be before assimp (or, for OBJ, fabform's own reader) reads it. assimp
// 5.2.5 trusts what it reads: a count or an index from the file goes straight into an
// allocation or a face, a misspelt number is read as part of one, text in another encoding
// reads as an empty mesh. So the file is walked first: declared counts (binary STL, PLY, OFF)
// against the file's size and data, every index against the vertices, every coordinate for a
// finite number, ASCII STL facets for their keywords and three vertices, text for NUL bytes and
// byte order marks. Internal to the mesh reader.
#include <optional>
#include <string>

namespace fabform {

/// Throws InputError naming the file (and, in text, the line) for what no reader can use.
/// Returns the bytes assimp should read in place of the file's, in the same format, when the
/// file is good but assimp 5.2.5 would misread it: a binary PLY whose data starts with a
/// line-feed byte (assimp skips it as the header's end) comes back as the same PLY in ASCII,
/// an OBJ behind a UTF-8 byte order mark comes back without the mark. Otherwise nothing.
std::optional<std::string> check_mesh_file(const std::string& path);

}  // namespace fabform
