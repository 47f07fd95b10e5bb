#pragma once
// CAD meshes in: OBJ, STL (ASCII and binary), PLY (ply_reader.cpp), OFF through OpenMesh; glTF 2.0
// through tinygltf. Every mesh is cleaned (cleanup counted in a report) and chunked after
// cleanup. Bad input gives a std::runtime_error whose one-line message names the file and the
// problem; memory stays bounded by the file's real size, never by counts a header claims.
#include "geometry/io/up_axis.h"
#include "geometry/scene/scene.h"

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace geometry::io {

/// Vertices closer than this, in model units, merge by default (docs/design.md §2.1 "Merge
/// tolerance"): 10 nm in a millimetre model, 10 µm in a metre one, below any CAD feature and above
/// the rounding of six-decimal text exports. Absolute, so that one stray far-away triangle cannot
/// widen it and merge a small part away.
inline constexpr double kDefaultMergeTolerance = 1e-5;

struct CleanupOptions {
    double mergeTolerance = kDefaultMergeTolerance; // model units: duplicate vertices closer than this merge
    bool mergeToleranceOfDiagonal = false;          // mergeTolerance is a fraction of the bounds' diagonal instead
    double creaseAngleDeg = 30.0;                   // normals: faces meeting at more than this keep a sharp edge
    bool fixOrientation = false;                    // make face winding consistent per connected component
};

/// What cleanup did, step by step (each counter is what that step removed or changed).
struct CleanupReport {
    size_t inputVertices = 0, inputFaces = 0;
    size_t nonFiniteVertices = 0; // NaN/Inf vertices dropped
    size_t nonFiniteFaces = 0;    // faces dropped with them
    size_t degenerateFaces = 0;   // repeated indices or zero area
    size_t mergedVertices = 0;    // duplicates within the tolerance
    double mergeTolerance = 0;    // the tolerance used, in model units (the largest of several meshes)
    size_t duplicateFaces = 0;    // same three vertices, any order or winding
    size_t isolatedVertices = 0;  // referenced by no face
    size_t flippedFaces = 0;      // orientation fix
    // Set by the readers (OBJ, OFF, PLY), before cleanup: faces of more than three corners.
    size_t polygonsTriangulated = 0; // ear-clipped into triangles (inputFaces counts the triangles)
    size_t nonPlanarFaces = 0;       // farther than 1e-3 × their diameter from their best-fit plane
    size_t earClipFallbacks = 0;     // ear clipping got stuck (self-intersecting face): rest fanned
    size_t outputVertices = 0, outputFaces = 0;
    std::vector<std::string> notes; // e.g. skipped glTF primitive modes
    CleanupReport& operator+=(const CleanupReport& other);
};

/// Called with a fraction in [0, 1] and the stage name ("reading", "cleaning", "chunking").
using Progress = std::function<void(float fraction, std::string_view stage)>;

struct LoadedModel {
    std::vector<scene::Mesh> meshes; // world transforms applied into Mesh::transform; chunked
    CleanupReport report;
    std::string format;    // "obj", "stl", "off", "ply", "gltf", "glb"
    UpAxis up = UpAxis::Y; // the file's up axis, as used: turned to +Y in the meshes' transforms
};

/// Loads a mesh or glTF file by extension (case-insensitive). Throws std::runtime_error
/// "FILE: problem" for a missing file, an unknown extension, truncated/corrupt data, indices
/// out of range, absurd sizes, an empty result, recursive glTF nodes or missing buffers. `up`: the
/// file's up axis (default: defaultUpAxis of its format), turned to +Y.
[[nodiscard]] LoadedModel loadModel(const std::string& path, const CleanupOptions& options = {},
                                    const Progress& progress = {}, std::optional<UpAxis> up = std::nullopt);

/// A file's format as its extension names it, lower case, without the dot ("stl"; "" for none).
[[nodiscard]] std::string modelFormat(std::string_view path);

/// True for extensions loadModel() reads.
[[nodiscard]] bool isModelFile(std::string_view path) noexcept;

/// What a reader hands cleanMesh: positions that may repeat bit for bit (a glTF, OBJ or PLY file
/// repeats a position for each normal it has there), or Distinct ones, no two bit-equal (−0 as +0),
/// as the binary STL reader's weld leaves them.
enum class ReadPositions { MayRepeat, Distinct };

/// Cleans one triangle mesh in place (docs/design.md §2.1: drop NaN/Inf vertices and their faces, degenerate
/// faces, merge duplicates, remove duplicate faces and isolated vertices, crease-angle normals,
/// optional orientation fix) and returns what it did. Does not chunk.
/// `progress` hears "cleaning: STAGE" at each stage's start, the fraction of the whole cleanup done.
/// `read` Distinct skips looking for bit-equal copies first (the merge would still find them).
CleanupReport cleanMesh(scene::Mesh& mesh, const CleanupOptions& options = {}, const Progress& progress = {},
                        ReadPositions read = ReadPositions::MayRepeat);

/// "no triangles left after cleanup", with the reason when it is the merge tolerance: a model so
/// small that its faces lie within the tolerance (in model units) merges away.
[[nodiscard]] std::string nothingLeftMessage(const CleanupReport& report);

/// Writes a mesh file (format from the extension: obj, stl, off, ply), every triangle kept, so that
/// every float reads back bit for bit (mesh_save.cpp: binary STL and PLY, shortest round-trip
/// decimals in OBJ and OFF). Throws std::runtime_error naming the file on failure.
void saveMesh(const std::string& path, const scene::Mesh& mesh);

} // namespace geometry::io
