#pragma once
// OBJ validation and reading. The rules were made for OpenMesh's OBJ reader, which trusts its
// input (it asserts on a face corner without a vertex index, skips vertices it cannot parse
// while still counting them for relative indices, is quadratic in polygon size, and opens
// whatever `mtllib` names); loading now reads the file here (readObjFile) under the same rules.
#include <glm/vec3.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace geometry::io::detail {

/// Reads the OBJ file at `path` once, in blocks (memory stays bounded whatever its size), and
/// throws std::runtime_error "PATH: line N: problem" for the first thing OpenMesh 9's OBJ reader
/// cannot handle safely.
void validateObjFile(const std::string& path);

/// An OBJ file's vertices and polygon faces as written (corners are 0-based vertex indices;
/// face f has corners[faceStarts[f] .. faceStarts[f + 1]]).
struct ObjPolygons {
    std::vector<glm::vec3> positions;
    std::vector<uint32_t> corners;
    std::vector<uint32_t> faceStarts{0};
};

/// Validates like validateObjFile() and also reads the file. Polygons keep repeated corners,
/// which OpenMesh's OBJ reader removes (breaking the bridge of a ring face).
[[nodiscard]] ObjPolygons readObjFile(const std::string& path);

} // namespace geometry::io::detail
