#pragma once
// glTF 2.0 (.gltf with external or data-URI buffers, .glb; KHR_draco_mesh_compression primitives,
// KHR_mesh_quantization, EXT_meshopt_compression and sparse accessors: gltf_accessor.h) through
// tinygltf. The node hierarchy is flattened into one geometry::Mesh per (node instance,
// triangle primitive), each with the node's world matrix as Mesh::transform. Hostile files give
// a one-line std::runtime_error "PATH: problem"; every accessor is bounds-checked against its
// buffer before it is read, so memory stays bounded by the file's real size, not by counts the
// JSON claims. glTF 1.0 and unsupported required extensions are refused by name.
#include "geometry/io/model_loader.h"

#include <string>

namespace geometry::io {

/// Loads a .gltf or .glb file (format told by the GLB magic, not the extension), cleans every
/// triangle primitive with cleanMesh() (reports summed, skipped primitives noted in
/// report.notes) and chunks each resulting mesh. Throws std::runtime_error "PATH: problem".
[[nodiscard]] LoadedModel loadGltf(const std::string& path, const CleanupOptions& options = {},
                                   const Progress& progress = {});

} // namespace geometry::io
