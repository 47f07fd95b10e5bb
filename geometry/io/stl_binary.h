#pragma once
// Binary STL read from a memory-mapped file and welded as it is read (docs/design.md §2.1 "Loading
// at scale"): three corners per facet become shared vertices where their coordinates are equal bit
// for bit, in parallel over ranges of facets, so cleanup starts from ~0.5 vertices per triangle
// instead of 3 and the file is never copied into memory.
#include "geometry/io/model_loader.h"

#include <string>

namespace geometry::io::detail {

/// Reads a binary STL whose size (84 + 50·n bytes) the caller checked. Non-finite corners are never
/// welded (cleanup drops and counts them). `counts` receives inputVertices = 3n and, in
/// mergedVertices, the corners welded here; the mesh's positions are the distinct corners in
/// order of first use (the same with any thread count; 0: one per core for files large enough to
/// gain from it). Throws std::runtime_error "PATH: problem".
/// `progress` hears "reading" with the fraction of the first range read (the calling thread's).
[[nodiscard]] scene::Mesh readBinaryStl(const std::string& path, uint64_t size, CleanupReport& counts,
                                        unsigned threads = 0, const Progress& progress = {});

} // namespace geometry::io::detail
