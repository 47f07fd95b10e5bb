#include "gpu_scene.h"

namespace renderer {

namespace {

/// A VAO over interleaved positions and normals (attributes 0 and 1) and a triangle index buffer.
void upload(GLuint& vao, GLuint& vbo, GLuint& ebo, const std::vector<glm::vec3>& positions,
            const std::vector<glm::vec3>& normals, const std::vector<uint32_t>& indices) {
    std::vector<float> interleaved;
    interleaved.reserve(positions.size() * 6);
    for (size_t i = 0; i < positions.size(); ++i) {
        const glm::vec3& p = positions[i];
        const glm::vec3 n = i < normals.size() ? normals[i] : glm::vec3(0, 1, 0);
        interleaved.insert(interleaved.end(), {p.x, p.y, p.z, n.x, n.y, n.z});
    }
    glGenVertexArrays(1, &vao);
    glBindVertexArray(vao);
    glGenBuffers(1, &vbo);
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(interleaved.size() * sizeof(float)), interleaved.data(),
                 GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), nullptr);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), reinterpret_cast<void*>(3 * sizeof(float)));
    glGenBuffers(1, &ebo);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(indices.size() * sizeof(uint32_t)), indices.data(),
                 GL_STATIC_DRAW);
    glBindVertexArray(0);
}

/// An instanced mesh's placement matrices as aModel, one per instance, in its vertex array.
GLuint uploadInstances(GLuint vao, const std::vector<glm::mat4>& placements) {
    GLuint vbo = 0;
    glBindVertexArray(vao);
    glGenBuffers(1, &vbo);
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(placements.size() * sizeof(glm::mat4)), placements.data(),
                 GL_STATIC_DRAW);
    for (GLuint c = 0; c < 4; ++c) {
        const GLuint a = GpuScene::kModelAttribute + c;
        glEnableVertexAttribArray(a);
        glVertexAttribPointer(a, 4, GL_FLOAT, GL_FALSE, sizeof(glm::mat4),
                              reinterpret_cast<void*>(uintptr_t(c) * sizeof(glm::vec4)));
        glVertexAttribDivisor(a, 1);
    }
    glBindVertexArray(0);
    return vbo;
}

void release(GLuint& vao, GLuint& vbo, GLuint& ebo) noexcept {
    glDeleteBuffers(1, &vbo);
    glDeleteBuffers(1, &ebo);
    glDeleteVertexArrays(1, &vao);
    vao = vbo = ebo = 0;
}

} // namespace

GpuScene::GpuScene(const geometry::scene::Scene& scene) {
    for (size_t index = 0; index < scene.meshes.size(); ++index) {
        const auto& mesh = scene.meshes[index];
        if (mesh.indices.empty()) continue;
        GpuMesh g;
        g.sceneIndex = index;
        g.transform = mesh.transform;
        g.color = mesh.color;
        g.chunks = mesh.chunks;
        g.parts = mesh.parts;
        g.triangles = mesh.triangleCount();
        g.twoSided = mesh.twoSided;
        upload(g.vao, g.vbo, g.ebo, mesh.positions, mesh.normals, mesh.indices);
        if (g.chunks.empty()) g.chunks.push_back({{0, static_cast<uint32_t>(g.triangles), mesh.worldBounds()}});
        if (mesh.instanced()) {
            std::vector<glm::mat4> placements(mesh.placementCount());
            g.placementBounds.resize(placements.size());
            for (size_t i = 0; i < placements.size(); ++i) {
                placements[i] = mesh.placement(i);
                g.placementBounds[i] = mesh.placementBounds(i);
            }
            g.instanceVbo = uploadInstances(g.vao, placements);
        }
        meshes_.push_back(g);
    }
}

GpuScene::~GpuScene() {
    for (auto& g : meshes_) {
        release(g.vao, g.vbo, g.ebo);
        glDeleteBuffers(1, &g.instanceVbo);
        if (g.lod.vao) release(g.lod.vao, g.lod.vbo, g.lod.ebo);
    }
}

void GpuScene::setCasterLod(const geometry::lod::SceneLod& lod) {
    hasLod_ = true;
    for (auto& g : meshes_) {
        if (g.lod.vao) release(g.lod.vao, g.lod.vbo, g.lod.ebo);
        g.lod.chunkLevels.clear();
        if (g.sceneIndex >= lod.meshes.size()) continue;
        const geometry::lod::MeshLod& m = lod.meshes[g.sceneIndex];
        if (g.instanced() || m.indices.empty() || m.chunkLevels.size() != g.chunks.size()) continue;
        upload(g.lod.vao, g.lod.vbo, g.lod.ebo, m.positions, m.normals, m.indices);
        g.lod.chunkLevels = m.chunkLevels;
    }
}

} // namespace renderer
