// One chunk's levels, decimated in cascade on one OpenMesh mesh (decimation_modules.h for the
// bound). Each level continues from the one before with a larger tolerance; the deviation
// module keeps the removed vertices of the original, so every level stays bounded to the
// original, not to its predecessor, and the whole cascade costs about one decimation.
//
// What cannot be decimated is copied: triangles OpenMesh refuses (non-manifold edges, faces
// wound against their neighbours) go verbatim into every level and their vertices are locked,
// so the decimated surface stays attached to them. Parts thinner than thinFactor × a level's
// error go into that level as their original triangles, whatever earlier levels did to them.
#include "geometry/lod/chunk_levels.h"

#include "geometry/lod/lod_decimater.h"
#include "geometry/lod/lod_geometry.h"

#include <array>
#include <cmath>

namespace geometry::lod::detail {

namespace {

/// Per part: the first level in which it is thin (kept exact from there on), or errors.size().
std::vector<uint32_t> firstThinLevels(const ChunkTriangles& chunk, std::span<const uint32_t> part,
                                      const LevelSettings& s) {
    const uint32_t parts = part.empty() ? 0 : *std::max_element(part.begin(), part.end()) + 1;
    std::vector<std::vector<glm::vec3>> world(parts);
    for (size_t v = 0; v < chunk.positions.size(); ++v)
        world[part[v]].push_back(glm::vec3(s.transform * glm::vec4(chunk.positions[v], 1.f)));
    std::vector<uint32_t> first(parts, uint32_t(s.errors.size()));
    for (uint32_t p = 0; p < parts; ++p) {
        const float thickness = partThickness(world[p]);
        for (uint32_t k = 0; k < s.errors.size() && first[p] == s.errors.size(); ++k)
            if (!(thickness >= s.thinFactor * s.errors[k])) first[p] = k; // NaN: thin, kept exact
    }
    return first;
}

/// Whether mesh.add_face(v) would succeed: OpenMesh's own tests (PolyConnectivity::add_face),
/// asked first because add_face reports each refusal on the process-wide omerr() stream, which
/// worker threads should not write to (nor should a CAD model with many bad faces spam it).
bool canAddFace(const LodMesh& mesh, const std::array<LodMesh::VertexHandle, 3>& v) {
    std::array<LodMesh::HalfedgeHandle, 3> h;
    for (int i = 0; i < 3; ++i) {
        if (!mesh.is_boundary(v[i])) return false; // complex vertex: its fan is closed
        h[i] = mesh.find_halfedge(v[i], v[(i + 1) % 3]);
        if (h[i].is_valid() && !mesh.is_boundary(h[i])) return false; // complex edge: already has this face side
    }
    for (int i = 0; i < 3; ++i) {
        const LodMesh::HalfedgeHandle innerPrev = h[i], innerNext = h[(i + 1) % 3];
        if (!innerPrev.is_valid() || !innerNext.is_valid() || mesh.next_halfedge_handle(innerPrev) == innerNext)
            continue;
        // The patch between them must move to another gap in the fan; there must be one.
        LodMesh::HalfedgeHandle gap = mesh.opposite_halfedge_handle(innerNext);
        do gap = mesh.opposite_halfedge_handle(mesh.next_halfedge_handle(gap));
        while (!mesh.is_boundary(gap));
        if (gap == innerPrev) return false; // patch re-linking would fail
    }
    return true;
}

} // namespace

std::vector<glm::vec3> smoothNormals(std::span<const glm::vec3> positions, std::span<const uint32_t> triangles) {
    std::vector<glm::vec3> sum(positions.size(), glm::vec3(0.f));
    for (size_t t = 0; t + 2 < triangles.size(); t += 3) {
        const glm::vec3 p[3] = {positions[triangles[t]], positions[triangles[t + 1]], positions[triangles[t + 2]]};
        const glm::vec3 n = glm::cross(p[1] - p[0], p[2] - p[0]);
        const float len = glm::length(n);
        if (!(len > 0.f) || !std::isfinite(len)) continue;
        for (int k = 0; k < 3; ++k) {
            const glm::vec3 e1 = p[(k + 1) % 3] - p[k], e2 = p[(k + 2) % 3] - p[k];
            const float l1 = glm::length(e1), l2 = glm::length(e2);
            if (!(l1 > 0.f && l2 > 0.f)) continue;
            const float angle = std::acos(std::clamp(glm::dot(e1, e2) / (l1 * l2), -1.f, 1.f));
            sum[triangles[t + k]] += angle / len * n;
        }
    }
    for (glm::vec3& n : sum) {
        const float len = glm::length(n);
        n = len > 0.f && std::isfinite(len) ? n / len : glm::vec3(0.f, 0.f, 1.f);
    }
    return sum;
}

ChunkLevels buildChunkLevels(const ChunkTriangles& chunk, const LevelSettings& s, const std::atomic<bool>& cancel) {
    ChunkLevels out;
    const auto& tri = chunk.triangles;
    const size_t triangleCount = tri.size() / 3;
    if (triangleCount == 0 || s.errors.empty() || !(s.stretch > 0.f) || !std::isfinite(s.stretch)) return out;

    const std::vector<uint32_t> part = connectedParts(chunk.positions.size(), tri);
    const std::vector<uint32_t> thinFrom = firstThinLevels(chunk, part, s);
    auto thinAt = [&](uint32_t vertex, size_t level) { return thinFrom[part[vertex]] <= level; };

    LodMesh mesh;
    std::vector<LodMesh::VertexHandle> vh(chunk.positions.size());
    for (size_t v = 0; v < chunk.positions.size(); ++v)
        vh[v] = mesh.add_vertex(OpenMesh::Vec3d(chunk.positions[v].x, chunk.positions[v].y, chunk.positions[v].z));
    std::vector<size_t> refused;
    for (size_t t = 0; t < triangleCount; ++t) {
        const std::array<LodMesh::VertexHandle, 3> face = {vh[tri[3 * t]], vh[tri[3 * t + 1]], vh[tri[3 * t + 2]]};
        if (!canAddFace(mesh, face) || !mesh.add_face(face[0], face[1], face[2]).is_valid()) refused.push_back(t);
    }
    for (size_t v = 0; v < chunk.positions.size(); ++v)
        if (chunk.locked[v]) mesh.status(vh[v]).set_locked(true);
    for (size_t t : refused)
        for (int k = 0; k < 3; ++k) mesh.status(vh[tri[3 * t + k]]).set_locked(true);
    mesh.update_face_normals();

    LodDecimater decimater(mesh);

    std::vector<uint32_t> level, remap(chunk.positions.size(), UINT32_MAX);
    size_t previous = s.sourceTriangles;
    for (size_t k = 0; k < s.errors.size(); ++k) {
        if (cancel.load(std::memory_order_relaxed)) return {};
        for (size_t v = 0; v < chunk.positions.size(); ++v)
            if (thinFrom[part[v]] == k) mesh.status(vh[v]).set_locked(true);
        decimater.setTolerance(double(s.errors[k]) / double(s.stretch)); // object units
        decimater.decimate();

        level.clear();
        for (const auto f : mesh.faces()) {
            if (mesh.status(f).deleted()) continue;
            auto fv = mesh.cfv_iter(f);
            const uint32_t a = uint32_t(fv->idx()), b = uint32_t((++fv)->idx()), c = uint32_t((++fv)->idx());
            if (!thinAt(a, k)) level.insert(level.end(), {a, b, c});
        }
        for (size_t t : refused)
            if (!thinAt(tri[3 * t], k)) level.insert(level.end(), tri.begin() + 3 * t, tri.begin() + 3 * t + 3);
        for (size_t t = 0; t < triangleCount; ++t)
            if (thinAt(tri[3 * t], k)) level.insert(level.end(), tri.begin() + 3 * t, tri.begin() + 3 * t + 3);

        const size_t count = level.size() / 3;
        if (count == 0 || double(count) > (1.0 - double(s.minReduction)) * double(previous)) continue;
        previous = count;

        // The level's own vertices, so its smooth normals are its own.
        const uint32_t firstVertex = uint32_t(out.positions.size());
        std::vector<uint32_t> local;
        local.reserve(level.size());
        for (uint32_t v : level) {
            if (remap[v] == UINT32_MAX) {
                remap[v] = uint32_t(out.positions.size()) - firstVertex;
                out.positions.push_back(chunk.positions[v]);
            }
            local.push_back(remap[v]);
        }
        for (uint32_t v : level) remap[v] = UINT32_MAX;
        const std::span<const glm::vec3> levelPositions(out.positions.data() + firstVertex,
                                                        out.positions.size() - firstVertex);
        const std::vector<glm::vec3> normals = smoothNormals(levelPositions, local);
        out.normals.insert(out.normals.end(), normals.begin(), normals.end());
        out.levels.push_back({uint32_t(out.indices.size() / 3), uint32_t(count), s.errors[k]});
        for (uint32_t v : local) out.indices.push_back(firstVertex + v);
    }
    return out;
}

} // namespace geometry::lod::detail
