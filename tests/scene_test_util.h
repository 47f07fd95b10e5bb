#pragma once
// Checks every built-in scene must pass (well formed, chunked, deterministic), shared by the
// platform and piperack tests.
#include "geometry/scene/chunking.h"
#include "geometry/scene/scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace testutil {

inline glm::vec3 toWorld(const geometry::scene::Mesh& m, const glm::vec3& p) {
    return glm::vec3(m.transform * glm::vec4(p, 1.f));
}

inline bool sameGeometry(const geometry::scene::Scene& a, const geometry::scene::Scene& b) {
    if (a.meshes.size() != b.meshes.size()) return false;
    for (size_t i = 0; i < a.meshes.size(); ++i) {
        const auto &ma = a.meshes[i], &mb = b.meshes[i];
        if (ma.name != mb.name || ma.positions != mb.positions || ma.normals != mb.normals || ma.indices != mb.indices)
            return false;
    }
    return true;
}

/// Every triangle lies in exactly one chunk, within its bounds; no chunk is empty or too large.
inline void expectChunksCoverEveryTriangleOnce(const geometry::scene::Scene& scene) {
    for (const geometry::scene::Mesh& m : scene.meshes) {
        SCOPED_TRACE(m.name);
        const size_t triangles = m.triangleCount();
        ASSERT_GT(triangles, 0u);
        ASSERT_FALSE(m.chunks.empty());
        std::vector<int> covered(triangles, 0);
        for (const geometry::scene::Chunk& c : m.chunks) {
            EXPECT_GT(c.triangleCount, 0u);
            EXPECT_LE(c.triangleCount, geometry::scene::kMaxChunkTriangles);
            ASSERT_LE(static_cast<size_t>(c.firstTriangle) + c.triangleCount, triangles);
            for (uint32_t t = c.firstTriangle; t < c.firstTriangle + c.triangleCount; ++t) {
                ++covered[t];
                for (int k = 0; k < 3; ++k) {
                    const glm::vec3 p = toWorld(m, m.positions[m.indices[3 * size_t(t) + k]]);
                    ASSERT_TRUE(c.bounds.contains(p, 1e-3f)) << "triangle " << t;
                }
            }
        }
        for (size_t t = 0; t < triangles; ++t) ASSERT_EQ(covered[t], 1) << "triangle " << t;
    }
}

inline void expectIndicesInRange(const geometry::scene::Scene& scene) {
    for (const geometry::scene::Mesh& m : scene.meshes) {
        ASSERT_EQ(m.indices.size() % 3, 0u) << m.name;
        ASSERT_EQ(m.positions.size(), m.normals.size()) << m.name;
        for (uint32_t i : m.indices) ASSERT_LT(i, m.positions.size()) << m.name;
    }
}

inline void expectFinitePositionsAndUnitNormals(const geometry::scene::Scene& scene) {
    for (const geometry::scene::Mesh& m : scene.meshes) {
        SCOPED_TRACE(m.name);
        for (const glm::vec3& p : m.positions)
            ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
        for (const glm::vec3& n : m.normals) {
            ASSERT_TRUE(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z));
            ASSERT_NEAR(glm::length(n), 1.f, 1e-3f);
        }
    }
}

} // namespace testutil
