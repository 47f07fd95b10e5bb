#include "geometry/scene/chunking.h"

#include <algorithm>
#include <numeric>

namespace geometry::scene {

namespace {

struct Splitter {
    const std::vector<glm::vec3>& centroids;
    uint32_t maxTriangles;
    std::vector<std::pair<uint32_t, uint32_t>> ranges; // [begin, end) into order

    void split(std::vector<uint32_t>& order, uint32_t begin, uint32_t end) {
        if (end - begin <= maxTriangles) {
            ranges.emplace_back(begin, end);
            return;
        }
        Aabb box;
        for (uint32_t i = begin; i < end; ++i) box.add(centroids[order[i]]);
        const glm::vec3 e = box.extent();
        const int axis = e.x >= e.y && e.x >= e.z ? 0 : (e.y >= e.z ? 1 : 2);
        const uint32_t mid = begin + (end - begin) / 2;
        std::nth_element(order.begin() + begin, order.begin() + mid, order.begin() + end,
                         [&](uint32_t a, uint32_t b) { return centroids[a][axis] < centroids[b][axis]; });
        split(order, begin, mid);
        split(order, mid, end);
    }
};

} // namespace

void chunkMesh(Mesh& mesh, uint32_t maxTriangles) {
    maxTriangles = std::max<uint32_t>(maxTriangles, 1);
    const uint32_t triCount = static_cast<uint32_t>(mesh.triangleCount());
    mesh.chunks.clear();
    if (triCount == 0) return;

    std::vector<glm::vec3> centroids(triCount);
    for (uint32_t t = 0; t < triCount; ++t)
        centroids[t] = (mesh.positions[mesh.indices[3 * t]] + mesh.positions[mesh.indices[3 * t + 1]] +
                        mesh.positions[mesh.indices[3 * t + 2]]) /
                       3.f;
    std::vector<uint32_t> order(triCount);
    std::iota(order.begin(), order.end(), 0u);
    Splitter splitter{centroids, maxTriangles, {}};
    splitter.split(order, 0, triCount);

    std::vector<uint32_t> indices(mesh.indices.size());
    for (uint32_t i = 0; i < triCount; ++i)
        for (int k = 0; k < 3; ++k) indices[3 * i + k] = mesh.indices[3 * order[i] + k];
    mesh.indices = std::move(indices);

    for (const auto& [b, e] : splitter.ranges) {
        Chunk c;
        c.firstTriangle = b;
        c.triangleCount = e - b;
        // The box of the transformed vertices: a transformed local box is loose under rotation.
        for (uint32_t i = 3 * b; i < 3 * e; ++i)
            c.bounds.add(glm::vec3(mesh.transform * glm::vec4(mesh.positions[mesh.indices[i]], 1.f)));
        mesh.chunks.push_back(c);
    }
}

} // namespace geometry::scene
