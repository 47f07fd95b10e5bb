#include "gpu_scene.h"

namespace renderer {

namespace {

template <class T> GLsizeiptr bytes(const std::vector<T>& v) noexcept {
    return static_cast<GLsizeiptr>(v.size() * sizeof(T));
}

/// A VAO whose one buffer holds `positions` then `normals` (attributes 0 and 1, normals packed:
/// geometry::scene::packNormal) and which draws from index buffer `ebo`.
template <class Position>
void vertexArray(GLuint& vao, GLuint& vbo, GLuint ebo, const std::vector<Position>& positions,
                 const std::vector<uint32_t>& normals, GLenum positionType) {
    glGenVertexArrays(1, &vao);
    glBindVertexArray(vao);
    glGenBuffers(1, &vbo);
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glBufferData(GL_ARRAY_BUFFER, bytes(positions) + bytes(normals), nullptr, GL_STATIC_DRAW);
    glBufferSubData(GL_ARRAY_BUFFER, 0, bytes(positions), positions.data());
    glBufferSubData(GL_ARRAY_BUFFER, bytes(positions), bytes(normals), normals.data());
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, positionType, GL_FALSE, sizeof(Position), nullptr);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 4, GL_INT_2_10_10_10_REV, GL_TRUE, sizeof(uint32_t),
                          reinterpret_cast<void*>(uintptr_t(bytes(positions))));
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo);
    glBindVertexArray(0);
}

/// A VAO as vertexArray's, with a new index buffer holding `indices` (filled through a target that
/// no vertex array owns).
template <class Position, class Index>
void upload(GLuint& vao, GLuint& vbo, GLuint& ebo, const std::vector<Position>& positions,
            const std::vector<uint32_t>& normals, const std::vector<Index>& indices, GLenum positionType) {
    glGenBuffers(1, &ebo);
    glBindBuffer(GL_COPY_WRITE_BUFFER, ebo);
    glBufferData(GL_COPY_WRITE_BUFFER, bytes(indices), indices.data(), GL_STATIC_DRAW);
    glBindBuffer(GL_COPY_WRITE_BUFFER, 0);
    vertexArray(vao, vbo, ebo, positions, normals, positionType);
}

/// Float positions, normals packed on the way (a vertex without one gets +y).
void uploadFloat(GLuint& vao, GLuint& vbo, GLuint& ebo, const std::vector<glm::vec3>& positions,
                 const std::vector<glm::vec3>& normals, const std::vector<uint32_t>& indices) {
    std::vector<uint32_t> packed(positions.size());
    for (size_t i = 0; i < packed.size(); ++i)
        packed[i] = geometry::scene::packNormal(i < normals.size() ? normals[i] : glm::vec3(0.f, 1.f, 0.f));
    upload(vao, vbo, ebo, positions, packed, indices, GL_FLOAT);
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
        // Chunked meshes that are placed once go compact (12 bytes a vertex, 6 a triangle, not 16 and 12);
        // an instanced mesh keeps floats (aDecode is one value per draw, not per instance).
        std::optional<geometry::scene::CompactVertices> compact;
        if (!mesh.instanced()) compact = geometry::scene::compactVertices(mesh);
        if (compact) {
            upload(g.vao, g.vbo, g.ebo, compact->positions, compact->normals, compact->indices, GL_UNSIGNED_SHORT);
            if (!compact->floatPositions.empty())
                vertexArray(g.wideVao, g.wideVbo, g.ebo, compact->floatPositions, compact->floatNormals, GL_FLOAT);
            g.compact = std::move(compact->chunks);
            g.step = compact->step;
            compact.reset();
        } else uploadFloat(g.vao, g.vbo, g.ebo, mesh.positions, mesh.normals, mesh.indices);
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
        glDeleteBuffers(1, &g.wideVbo);
        glDeleteVertexArrays(1, &g.wideVao);
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
        uploadFloat(g.lod.vao, g.lod.vbo, g.lod.ebo, m.positions, m.normals, m.indices);
        g.lod.chunkLevels = m.chunkLevels;
    }
}

} // namespace renderer
