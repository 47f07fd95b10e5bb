#include "geometry/scene/builtin_scenes.h"
#include "geometry/scene/mesh_builder.h"

namespace geometry::scene {

Scene makeOverlapScene() {
    Scene scene;
    scene.name = "overlap";
    MeshBuilder ground("ground", {0.75f, 0.75f, 0.72f});
    ground.addGroundGrid({0.f, 0.f, 0.f}, 24.f, 4);
    scene.meshes.push_back(ground.build());
    // Plate A (8 × 8 m, 1 m up) and above it plate B (6 m up) covering x < 0: the ground under A
    // is all umbra, and where B's edge (x = 0) crosses above it a filter's window holds both depths.
    MeshBuilder plates("plates", {0.3f, 0.4f, 0.8f});
    plates.addBox({0.f, 1.f, 0.f}, {4.f, 0.02f, 4.f});
    plates.addBox({-6.f, 6.f, 0.f}, {6.f, 0.02f, 6.f});
    scene.meshes.push_back(plates.build());
    scene.camera.eye = {0.f, 0.4f, 3.8f}; // low, under plate A, looking along its umbra across B's edge
    scene.camera.target = {0.f, 0.f, -2.f};
    scene.camera.fovYDeg = 70.f;
    scene.camera.near = 0.05f;
    scene.camera.far = 60.f;
    scene.lights[0].direction = {0.05f, -1.f, 0.03f};
    return scene;
}

} // namespace geometry::scene
