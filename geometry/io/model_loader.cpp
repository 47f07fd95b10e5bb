// loadModel(): picks the reader by extension, then cleans and chunks.
#include "geometry/io/model_loader.h"

#include "geometry/io/gltf_loader.h"
#include "geometry/scene/chunking.h"
#include "geometry/scene/scratch_pages.h"

#include <algorithm>
#include <array>
#include <filesystem>
#include <stdexcept>

namespace geometry::io {

namespace detail {
// Defined in openmesh_io.cpp (no header of its own: loadModel() is its only caller).
scene::Mesh readOpenMeshFile(const std::string& path, const std::string& ext, CleanupReport& readerCounts,
                             const Progress& progress);
} // namespace detail

namespace {

constexpr std::array<std::string_view, 6> kExtensions{"obj", "stl", "off", "ply", "gltf", "glb"};
constexpr glm::vec3 kDefaultGrey{0.7f, 0.7f, 0.72f};

void report(const Progress& progress, float fraction, std::string_view stage) {
    if (progress) progress(fraction, stage);
}

} // namespace

/// The file as it is, in its own axes.
LoadedModel readModel(const std::string& path, const CleanupOptions& options, const Progress& progress);

std::string modelFormat(std::string_view path) {
    std::string ext = std::filesystem::path(path).extension().string();
    if (!ext.empty()) ext.erase(0, 1);
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

bool isModelFile(std::string_view path) noexcept {
    try {
        return std::find(kExtensions.begin(), kExtensions.end(), modelFormat(path)) != kExtensions.end();
    } catch (...) { // allocation failure: not worth propagating from a predicate
        return false;
    }
}

namespace {

/// Turns every mesh so that `axis` points up (+Y): the rotation goes in front of each transform, and
/// the chunks' and parts' world boxes turn with it (a quarter turn maps a box onto a box exactly).
/// An instanced mesh's placements turn instead (its chunk boxes are not in world space).
void turnUp(LoadedModel& model, UpAxis axis) {
    model.up = axis;
    if (axis == UpAxis::Y) return;
    const glm::mat4 r = rotationToYUp(axis);
    for (scene::Mesh& mesh : model.meshes) {
        if (mesh.instanced()) {
            for (glm::mat4& m : mesh.instances) m = r * m;
            continue;
        }
        mesh.transform = r * mesh.transform;
        for (scene::Chunk& chunk : mesh.chunks) chunk.bounds = chunk.bounds.transformed(r);
        for (scene::TriangleRun& part : mesh.parts) part.bounds = part.bounds.transformed(r);
    }
}

} // namespace

LoadedModel loadModel(const std::string& path, const CleanupOptions& options, const Progress& progress,
                      std::optional<UpAxis> up) {
    // The passes' temporaries reuse each other's pages; the model's own arrays are not scratch.
    const scene::ScratchScope scratch;
    LoadedModel model = readModel(path, options, progress);
    turnUp(model, up.value_or(defaultUpAxis(model.format)));
    // Finite transforms can compose to infinity (a glTF node's scale 1e38 on a translation 3e38).
    for (const scene::Mesh& mesh : model.meshes)
        if (const size_t i = mesh.firstPlacementBeyondFloat(); i < mesh.placementCount())
            throw std::runtime_error(path + ": mesh '" + mesh.name + "'" +
                                     (mesh.instanced() ? " placement " + std::to_string(i) : std::string()) +
                                     " lies beyond the float range (its node transforms are too large)");
    return model;
}

LoadedModel readModel(const std::string& path, const CleanupOptions& options, const Progress& progress) {
    const std::string ext = modelFormat(path);
    if (ext == "gltf" || ext == "glb") return loadGltf(path, options, progress);
    if (!isModelFile(path))
        throw std::runtime_error(path + ": unknown model extension '" + ext +
                                 "' (supported: .obj, .stl, .off, .ply, .gltf, .glb)");

    report(progress, 0.f, "reading");
    CleanupReport reading; // what the reader did: polygon counters, corners welded
    scene::Mesh mesh = detail::readOpenMeshFile(path, ext, reading, progress);
    report(progress, 1.f, "reading");

    LoadedModel model;
    model.format = ext;
    // A reader that welded bit-equal corners (binary STL) counts them: its positions are distinct.
    const bool welded = reading.inputVertices > 0;
    model.report = cleanMesh(mesh, options, progress, welded ? ReadPositions::Distinct : ReadPositions::MayRepeat);
    if (welded) { // the weld's corners count too
        model.report.inputVertices = reading.inputVertices;
        model.report.mergedVertices += reading.mergedVertices;
    }
    model.report.polygonsTriangulated = reading.polygonsTriangulated;
    model.report.nonPlanarFaces = reading.nonPlanarFaces;
    model.report.earClipFallbacks = reading.earClipFallbacks;
    if (model.report.inputFaces == 0) throw std::runtime_error(path + ": the file has no triangles");
    if (mesh.triangleCount() == 0) throw std::runtime_error(path + ": " + nothingLeftMessage(model.report));

    report(progress, 0.f, "chunking");
    mesh.name = std::filesystem::path(path).stem().string();
    mesh.twoSided = true; // CAD files: open surfaces are common and must cast from both faces
    mesh.color = kDefaultGrey;
    scene::chunkMesh(mesh);
    report(progress, 1.f, "chunking");
    model.meshes.push_back(std::move(mesh));
    return model;
}

} // namespace geometry::io
