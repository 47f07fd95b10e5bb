#pragma once
// Built-in scenes, seeded and deterministic.
#include "geometry/scene/scene.h"

#include <string>
#include <string_view>
#include <vector>

namespace geometry::scene {

struct PlatformParams {
    uint32_t targetTriangles = 250'000; // the paper's test model size (Barroso §4)
    uint32_t seed = 1;
};

/// Offshore-platform-like CAD model: lattice legs and diagonal braces of thin bars, decks with
/// grating, pipes, railings, a flare boom, on a large sea plane (depth range near 0.5, far ≥ 1000).
[[nodiscard]] Scene makePlatformScene(const PlatformParams& params = {});

struct PiperackParams {
    uint32_t targetTriangles = 250'000; // ±10 % from 50k up; builds 4M in a few seconds
    uint32_t seed = 1;
};

/// Plant pipe rack as a CAD export tessellates it: ≥ 80 % of the triangles on curved surfaces
/// (pipes, elbows, flanges, valves) over I-section steel, on a 1 km ground plane (depth range
/// near 0.5, far 1500). The budget is met by the chord tolerance and the rack's length.
[[nodiscard]] Scene makePiperackScene(const PiperackParams& params = {});

struct PlantParams {
    uint64_t targetTriangles = 8'000'000; // placed in the world; held: 3 modules of ≤ 250k
    uint32_t seed = 1;
    bool instanced = true; // false: every placement a mesh of its own (the memory test)
};

/// A plant of pipe racks: modules of three types (piperacks of different seeds), each held once and
/// placed on a grid by instancing to reach the target, on one ground; the camera and light of
/// the first module's piperack.
[[nodiscard]] Scene makePlantScene(const PlantParams& params = {});

/// Ground plane with a few thin vertical poles: checks with a known answer.
struct Pole {
    glm::vec3 base;
    float height;
    float radius;
};
[[nodiscard]] const std::vector<Pole>& planeScenePoles();
inline constexpr float kPlaneSceneHalfSize = 40.f;
[[nodiscard]] Scene makePlaneScene();

/// Light bleeding's classic case (docs/filters.md): two plates stacked over the ground, the upper one's
/// edge crossing above the lower one's umbra; the camera looks along that umbra from under the lower plate.
[[nodiscard]] Scene makeOverlapScene();

[[nodiscard]] const std::vector<std::string>& builtinSceneNames();
/// Throws std::invalid_argument naming the valid scenes for an unknown name.
[[nodiscard]] Scene makeBuiltinScene(std::string_view name);

} // namespace geometry::scene
