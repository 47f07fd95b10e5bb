// The plant: pipe-rack modules (makePiperackScene without its ground) of a few types, each type's
// meshes held once and placed many times by instancing, on one ground (docs/design.md §2
// "Instances"). With params.instanced false every placement is a mesh of its own: the same
// picture at the memory cost of an un-instanced CAD export.
#include "geometry/scene/builtin_scenes.h"
#include "geometry/scene/chunking.h"
#include "geometry/scene/instancing.h"
#include "geometry/scene/mesh_builder.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace geometry::scene {

namespace {

constexpr uint32_t kModuleTypes = 3;
constexpr uint32_t kMaxModuleTriangles = 250'000; // a module the piperack builds in about a second
constexpr uint32_t kMinModuleTriangles = 20'000;
constexpr float kRowGap = 12.f;   // between racks side by side (z), metres
constexpr float kColumnGap = 8.f; // between racks end to end (x)
const glm::vec3 kPlantGroundColor{0.56f, 0.55f, 0.50f};

/// The module types: piperacks of the same budget and different seeds, ground left out.
std::vector<Scene> moduleTypes(const PlantParams& p, uint32_t moduleTriangles) {
    std::vector<Scene> types;
    for (uint32_t t = 0; t < kModuleTypes; ++t) {
        Scene s = makePiperackScene({moduleTriangles, p.seed + t});
        s.meshes.erase(
            std::remove_if(s.meshes.begin(), s.meshes.end(), [](const Mesh& m) { return m.name == "ground"; }),
            s.meshes.end());
        types.push_back(std::move(s));
    }
    return types;
}

} // namespace

Scene makePlantScene(const PlantParams& params) {
    const uint64_t target = std::max<uint64_t>(params.targetTriangles, kMinModuleTriangles);
    const auto moduleTriangles = uint32_t(std::clamp<uint64_t>(target / 16, kMinModuleTriangles, kMaxModuleTriangles));
    std::vector<Scene> types = moduleTypes(params, moduleTriangles);
    uint64_t perModule = 0;
    Aabb footprint;
    for (const Scene& t : types) {
        perModule += t.triangleCount();
        footprint.add(t.bounds());
    }
    perModule /= types.size();
    const auto placements =
        uint32_t(std::max<uint64_t>(1, (target + perModule / 2) / std::max<uint64_t>(perModule, 1)));
    // Racks end to end along x, rows side by side along z: about as wide as long.
    const glm::vec3 e = footprint.extent();
    const float pitchX = e.x + kColumnGap, pitchZ = e.z + kRowGap;
    const auto columns = uint32_t(std::max(1.0, std::round(std::sqrt(double(placements) * pitchZ / pitchX))));

    Scene scene;
    scene.name = "plant";
    scene.camera = types[0].camera; // module 0 sits where makePiperackScene puts its rack
    scene.lights = types[0].lights;
    std::vector<std::vector<glm::mat4>> at(types.size());
    for (uint32_t i = 0; i < placements; ++i) {
        const uint32_t row = i / columns, column = i % columns;
        const glm::vec3 t(float(column) * pitchX, 0.f, -float(row) * pitchZ);
        at[(row + column) % types.size()].push_back(glm::translate(glm::mat4(1.f), t));
    }
    for (size_t t = 0; t < types.size(); ++t) {
        if (at[t].empty()) continue;
        for (Mesh& m : types[t].meshes) {
            m.name += "." + std::to_string(t);
            m.instances = at[t];
            scene.meshes.push_back(std::move(m));
        }
    }
    Aabb plant = scene.bounds();
    const glm::vec3 c = plant.center();
    const float size = 1.5f * std::max({plant.extent().x, plant.extent().z, 1000.f / 1.5f});
    MeshBuilder ground("ground", kPlantGroundColor);
    ground.addGroundGrid({c.x, 0.f, c.z}, size, 64);
    scene.meshes.insert(scene.meshes.begin(), ground.build());
    scene.camera.far = std::max(scene.camera.far, 1.2f * glm::length(scene.bounds().extent()));
    if (!params.instanced) scene = flattenInstances(scene);
    return scene;
}

} // namespace geometry::scene
