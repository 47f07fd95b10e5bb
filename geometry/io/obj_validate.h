#pragma once
// Pre-validation of OBJ files for OpenMesh's OBJ reader, which trusts its input (it asserts on
// a face corner without a vertex index, skips vertices it cannot parse while still counting
// them for relative indices, is quadratic in polygon size, and opens whatever `mtllib` names).
#include <string>

namespace geometry::io::detail {

/// Reads the OBJ file at `path` once, in blocks (memory stays bounded whatever its size), and
/// throws std::runtime_error "PATH: line N: problem" for the first thing OpenMesh 9's OBJ reader
/// cannot handle safely. What passes loads through OpenMesh as written.
void validateObjFile(const std::string& path);

} // namespace geometry::io::detail
