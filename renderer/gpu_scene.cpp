#include "gpu_scene.h"

namespace renderer {

GpuScene::GpuScene(const geometry::scene::Scene& scene) {
    for (const auto& mesh : scene.meshes) {
        if (mesh.indices.empty()) continue;
        GpuMesh g;
        g.transform = mesh.transform;
        g.color = mesh.color;
        g.chunks = mesh.chunks;
        g.triangles = mesh.triangleCount();
        g.twoSided = mesh.twoSided;
        std::vector<float> interleaved;
        interleaved.reserve(mesh.positions.size() * 6);
        for (size_t i = 0; i < mesh.positions.size(); ++i) {
            const glm::vec3& p = mesh.positions[i];
            const glm::vec3 n = i < mesh.normals.size() ? mesh.normals[i] : glm::vec3(0, 1, 0);
            interleaved.insert(interleaved.end(), {p.x, p.y, p.z, n.x, n.y, n.z});
        }
        glGenVertexArrays(1, &g.vao);
        glBindVertexArray(g.vao);
        glGenBuffers(1, &g.vbo);
        glBindBuffer(GL_ARRAY_BUFFER, g.vbo);
        glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(interleaved.size() * sizeof(float)), interleaved.data(),
                     GL_STATIC_DRAW);
        glEnableVertexAttribArray(0);
        glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), nullptr);
        glEnableVertexAttribArray(1);
        glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), reinterpret_cast<void*>(3 * sizeof(float)));
        glGenBuffers(1, &g.ebo);
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, g.ebo);
        glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.indices.size() * sizeof(uint32_t)),
                     mesh.indices.data(), GL_STATIC_DRAW);
        glBindVertexArray(0);
        if (g.chunks.empty()) g.chunks.push_back({0, static_cast<uint32_t>(g.triangles), mesh.worldBounds()});
        meshes_.push_back(g);
    }
}

GpuScene::~GpuScene() {
    for (auto& g : meshes_) {
        glDeleteBuffers(1, &g.vbo);
        glDeleteBuffers(1, &g.ebo);
        glDeleteVertexArrays(1, &g.vao);
    }
}

} // namespace renderer
