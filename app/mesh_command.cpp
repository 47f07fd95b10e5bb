#include "mesh_command.h"

#include "render_options.h"

#include "geometry/io/model_loader.h"
#include "geometry/io/scene_file.h"
#include "geometry/io/up_axis.h"
#include "geometry/scene/compact_vertices.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <iostream>

namespace app {

namespace {

nlohmann::json reportJson(const geometry::io::LoadedModel& m) {
    const auto& r = m.report;
    geometry::scene::Aabb bounds;
    size_t triangles = 0, vertices = 0;
    uint64_t placed = 0;
    size_t compact = 0;
    float step = 0.f; // the coarsest compact mesh's
    for (const auto& mesh : m.meshes) {
        if (!mesh.instanced())
            if (const std::optional<float> s = geometry::scene::compactStep(mesh)) {
                ++compact;
                step = std::max(step, *s);
            }
        if (!mesh.instanced()) bounds.add(mesh.worldBounds()); // the vertices' box, as before instancing
        else
            for (size_t i = 0; i < mesh.instances.size(); ++i) bounds.add(mesh.placementBounds(i));
        triangles += mesh.triangleCount();
        placed += mesh.placedTriangleCount();
        vertices += mesh.positions.size();
    }
    nlohmann::json j;
    j["format"] = m.format;
    j["up"] = std::string(geometry::io::upAxisName(m.up));
    j["meshes"] = m.meshes.size();
    j["triangles"] = triangles;     // held once
    j["placed_triangles"] = placed; // a glTF mesh several nodes use, once per node
    j["vertices"] = vertices;
    j["bounds"] = {{"min", {bounds.lo.x, bounds.lo.y, bounds.lo.z}}, {"max", {bounds.hi.x, bounds.hi.y, bounds.hi.z}}};
    // What the GL buffers hold (geometry/scene/compact_vertices.h): chunk-local positions of
    // kPositionBits on a grid of `step`, each coordinate within step / 2 of the file's (after cleanup).
    j["gl_positions"] = {{"compact_meshes", compact},
                         {"float_meshes", m.meshes.size() - compact},
                         {"bits", geometry::scene::kPositionBits},
                         {"step", step},
                         {"max_error", 0.5f * step}};
    j["cleanup"] = {{"input_vertices", r.inputVertices},
                    {"input_faces", r.inputFaces},
                    {"non_finite_vertices", r.nonFiniteVertices},
                    {"non_finite_faces", r.nonFiniteFaces},
                    {"degenerate_faces", r.degenerateFaces},
                    {"merged_vertices", r.mergedVertices},
                    {"merge_tolerance", r.mergeTolerance},
                    {"duplicate_faces", r.duplicateFaces},
                    {"isolated_vertices", r.isolatedVertices},
                    {"flipped_faces", r.flippedFaces},
                    {"polygons_triangulated", r.polygonsTriangulated},
                    {"non_planar_faces", r.nonPlanarFaces},
                    {"ear_clip_fallbacks", r.earClipFallbacks},
                    {"output_vertices", r.outputVertices},
                    {"output_faces", r.outputFaces},
                    {"notes", r.notes}};
    return j;
}

void printText(const nlohmann::json& j) {
    const auto& b = j["bounds"];
    std::cout << "format     " << j["format"].get<std::string>() << "\n"
              << "up axis    " << j["up"].get<std::string>() << " (turned to +y)\n"
              << "meshes     " << j["meshes"] << "\n"
              << "triangles  " << j["triangles"] << " (placed: " << j["placed_triangles"] << ")\n"
              << "vertices   " << j["vertices"] << "\n"
              << "bounds     " << b["min"].dump() << " .. " << b["max"].dump() << "\n";
    if (const auto& g = j["gl_positions"]; g["compact_meshes"] != 0)
        std::cout << "gl         " << g["compact_meshes"] << " of " << j["meshes"] << " meshes compact: " << g["bits"]
                  << "-bit chunk-local positions, step " << g["step"] << ", error <= " << g["max_error"] << "\n";
    std::cout << "cleanup\n";
    for (const auto& [key, value] : j["cleanup"].items())
        if (key != "notes") std::cout << "  " << key << ' ' << value << "\n";
    for (const auto& note : j["cleanup"]["notes"]) std::cout << "  note: " << note.get<std::string>() << "\n";
}

/// info: turned so the file's up axis is +y, as every other command shows it; clean: the file's own
/// axes, so the cleaned file lines up with the original.
geometry::io::LoadedModel load(const MeshOptions& o, bool turnUp) {
    geometry::io::CleanupOptions c;
    c.creaseAngleDeg = o.creaseAngleDeg;
    c.mergeTolerance = o.mergeToleranceOfDiagonal.value_or(o.mergeTolerance);
    c.mergeToleranceOfDiagonal = o.mergeToleranceOfDiagonal.has_value();
    c.fixOrientation = o.fixOrientation;
    return geometry::io::loadModel(o.input, c, {}, turnUp ? o.up : std::optional(geometry::io::UpAxis::Y));
}

/// One mesh: `meshes` merged with their transforms applied, an instanced mesh once per placement.
geometry::scene::Mesh merged(const std::vector<geometry::scene::Mesh>& meshes) {
    geometry::scene::Mesh merged;
    for (const auto& m : meshes)
        for (size_t p = 0; p < m.placementCount(); ++p) {
            const glm::mat4 transform = m.placement(p);
            const auto base = static_cast<uint32_t>(merged.positions.size());
            const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(transform)));
            for (size_t i = 0; i < m.positions.size(); ++i) {
                merged.positions.push_back(glm::vec3(transform * glm::vec4(m.positions[i], 1.f)));
                merged.normals.push_back(i < m.normals.size() ? glm::normalize(normalMatrix * m.normals[i])
                                                              : glm::vec3(0, 1, 0));
            }
            for (uint32_t idx : m.indices) merged.indices.push_back(base + idx);
        }
    return merged;
}

void addCleanupOptions(CLI::App& cmd, MeshOptions& o) {
    cmd.add_option("--crease-angle", o.creaseAngleDeg, "Normals: sharper edges than this stay sharp (degrees)")
        ->check(CLI::Range(0.0, 180.0))
        ->capture_default_str();
    CLI::Option* absolute =
        cmd.add_option("--merge-tolerance", o.mergeTolerance, "Merge vertices closer than this, in model units")
            ->check(CLI::Range(0.0, 1e30))
            ->capture_default_str();
    cmd.add_option("--merge-tolerance-of-diagonal", o.mergeToleranceOfDiagonal,
                   "Instead: merge vertices closer than this fraction of the bounds' diagonal (one far-away "
                   "triangle widens it)")
        ->check(CLI::Range(0.0, 0.1))
        ->excludes(absolute);
    cmd.add_flag("--fix-orientation", o.fixOrientation, "Make face winding consistent per connected part");
}

} // namespace

CLI::App* addMeshCommand(CLI::App& cli, MeshOptions& o) {
    CLI::App* mesh = cli.add_subcommand("mesh", "Inspect or clean a mesh file (OBJ, STL, OFF, PLY, glTF)");
    mesh->require_subcommand(1);
    CLI::App* info = mesh->add_subcommand("info", "Counts, bounds and the cleanup report of a mesh file");
    info->add_option("FILE", o.input, "Mesh file")->required();
    info->add_flag("--json", o.json, "Print JSON");
    addCleanupOptions(*info, o);
    addUpOption(*info, o.up,
                "The file's up axis (y, z, -y, -z, x, -x; default: z for STL, y for the others); bounds are given "
                "with it turned to +y");
    CLI::App* clean = mesh->add_subcommand("clean", "Load, clean and write a mesh (format from OUT's extension)");
    clean
        ->add_option("IN", o.input,
                     "Mesh file to read, or a built-in scene or scene file (its meshes written as one, uncleaned, "
                     "e.g. a large test file from a piperack scene with params.triangles)")
        ->required();
    clean->add_option("OUT", o.output, "Mesh file to write (.obj, .stl, .off, .ply)")->required();
    addCleanupOptions(*clean, o);
    return mesh;
}

int runMesh(const CLI::App& mesh, const MeshOptions& o) {
    const bool info = mesh.get_subcommand("info")->parsed();
    if (!info && !geometry::io::isModelFile(o.input)) {
        // A scene is +y up; the file gets its format's up axis (z for STL), so that loading it back
        // without --up shows the scene as it was.
        geometry::io::SceneFile file = geometry::io::resolveScene(o.input, {}, o.up);
        const glm::mat4 fromYUp =
            glm::inverse(geometry::io::rotationToYUp(geometry::io::defaultUpAxis(geometry::io::modelFormat(o.output))));
        for (geometry::scene::Mesh& m : file.scene.meshes) m.transform = fromYUp * m.transform;
        geometry::io::saveMesh(o.output, merged(file.scene.meshes));
        std::cout << o.output << '\n';
        return 0;
    }
    const geometry::io::LoadedModel model = load(o, info);
    if (info) {
        const nlohmann::json j = reportJson(model);
        if (o.json) std::cout << j.dump(2) << '\n';
        else printText(j);
        return 0;
    }
    geometry::io::saveMesh(o.output, merged(model.meshes));
    std::cout << o.output << '\n';
    return 0;
}

} // namespace app
