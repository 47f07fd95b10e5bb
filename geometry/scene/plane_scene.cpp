#include "geometry/scene/builtin_scenes.h"
#include "geometry/scene/mesh_builder.h"

#include <stdexcept>

namespace geometry::scene {

const std::vector<Pole>& planeScenePoles() {
    static const std::vector<Pole> poles = {
        {{0.f, 0.f, 0.f}, 4.f, 0.15f},
        {{-6.f, 0.f, -5.f}, 6.f, 0.15f},
        {{6.f, 0.f, -10.f}, 5.f, 0.15f},
        {{-3.f, 0.f, 5.f}, 3.f, 0.10f},
    };
    return poles;
}

Scene makePlaneScene() {
    Scene scene;
    scene.name = "plane";
    MeshBuilder ground("ground", {0.75f, 0.75f, 0.72f});
    ground.addGroundGrid({0.f, 0.f, 0.f}, 2.f * kPlaneSceneHalfSize, 16);
    scene.meshes.push_back(ground.build());
    MeshBuilder poles("poles", {0.8f, 0.3f, 0.2f});
    for (const auto& p : planeScenePoles())
        poles.addCylinder(p.base, p.base + glm::vec3(0.f, p.height, 0.f), p.radius, 16);
    scene.meshes.push_back(poles.build());
    scene.camera.eye = {0.f, 7.f, 16.f};
    scene.camera.target = {0.f, 0.f, -2.f};
    scene.camera.fovYDeg = 60.f;
    scene.camera.near = 0.5f;
    scene.camera.far = 100.f;
    scene.lights[0].direction = {-0.6f, -1.f, -0.35f};
    return scene;
}

const std::vector<std::string>& builtinSceneNames() {
    static const std::vector<std::string> names = {"platform", "piperack", "plane", "overlap", "plant"};
    return names;
}

Scene makeBuiltinScene(std::string_view name) {
    if (name == "platform") return makePlatformScene();
    if (name == "piperack") return makePiperackScene();
    if (name == "plane") return makePlaneScene();
    if (name == "overlap") return makeOverlapScene();
    if (name == "plant") return makePlantScene();
    throw std::invalid_argument("unknown scene '" + std::string(name) +
                                "' (built-in scenes: platform, piperack, plane, overlap, plant)");
}

} // namespace geometry::scene
