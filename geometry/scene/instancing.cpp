#include "geometry/scene/instancing.h"

#include "geometry/scene/chunking.h"

#include <glm/gtc/matrix_transform.hpp>

namespace geometry::scene {

std::vector<glm::mat4> gridInstances(const std::array<uint32_t, 3>& count, const glm::vec3& spacing,
                                     const glm::vec3& origin) {
    std::vector<glm::mat4> out;
    out.reserve(size_t(count[0]) * count[1] * count[2]);
    for (uint32_t k = 0; k < count[2]; ++k)
        for (uint32_t j = 0; j < count[1]; ++j)
            for (uint32_t i = 0; i < count[0]; ++i) {
                const glm::vec3 t = origin + glm::vec3(float(i), float(j), float(k)) * spacing;
                out.push_back(glm::translate(glm::mat4(1.f), t));
            }
    return out;
}

Scene flattenInstances(const Scene& scene) {
    Scene out = scene;
    out.meshes.clear();
    for (const Mesh& m : scene.meshes) {
        if (!m.instanced()) {
            out.meshes.push_back(m);
            continue;
        }
        for (size_t i = 0; i < m.instances.size(); ++i) {
            Mesh copy = m;
            copy.instances.clear();
            copy.transform = m.placement(i);
            for (Chunk& c : copy.chunks) c.bounds = c.bounds.transformed(m.instances[i]);
            for (TriangleRun& r : copy.parts) r.bounds = r.bounds.transformed(m.instances[i]);
            out.meshes.push_back(std::move(copy));
        }
    }
    for (Mesh& m : out.meshes) reserveSpareVertex(m); // copies lose it (GroundTruth::borrowing)
    return out;
}

} // namespace geometry::scene
