#pragma once
// PLY read here, after the format's own description (Greg Turk; Paul Bourke's "PLY - Polygon File
// Format"): ASCII and both binary byte orders, any elements in any order, scalar and list
// properties of every type. Positions come from the vertex element's x, y, z and faces from the
// face element's vertex_indices (or vertex_index) list; everything else is walked over.
#include "geometry/io/model_loader.h"

#include <cstdint>
#include <string>

namespace geometry::io::detail {

/// Reads the PLY file at `path`, whose real size `size` the caller checked (non-zero), into one
/// uncleaned mesh: faces of more than three corners ear-clipped (counted in `counts`), faces of
/// fewer dropped. Counts in the header are checked against the file's size and the memory
/// available before anything is allocated by them. Bad input throws std::runtime_error
/// "PATH: problem" on one line.
[[nodiscard]] scene::Mesh readPly(const std::string& path, uint64_t size, CleanupReport& counts);

} // namespace geometry::io::detail
