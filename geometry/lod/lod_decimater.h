#pragma once
// Halfedge-collapse decimation in the order of ModQuadricPriorityT, each collapse checked by
// ModNormalFlippingT and ModDeviationT (decimation_modules.h). Internal to geometry/lod.
//
// OpenMesh's DecimaterT does the same eagerly: after each collapse it runs every module on every
// outgoing halfedge of every vertex around it. Here the queue holds a cheap lower bound first
// (the smallest quadric priority over a vertex's halfedges, no checks), and a vertex is checked
// only when it reaches the front: its halfedges in priority order until one passes. A checked
// entry at the front beats every other vertex's lower bound, so collapses come in the same order
// (ties aside), at a few checks per collapse instead of ~40. And after a collapse every vertex
// around v1 is queued again, not only those around v0: ModDeviationT moves points onto all of
// v1's faces, and a check made before that would be stale (DecimaterT re-checks only topology).
#include "geometry/lod/decimation_modules.h"

#include <OpenMesh/Tools/Decimater/CollapseInfoT.hh>
#include <OpenMesh/Tools/Decimater/ModNormalFlippingT.hh>

#include <cstdint>
#include <queue>
#include <vector>

namespace geometry::lod::detail {

class LodDecimater {
public:
    /// The mesh's face normals must be up to date; locked vertices are never removed.
    explicit LodDecimater(LodMesh& mesh);

    /// Object units: no vertex of the original may end up farther than this from the surface.
    void setTolerance(double tolerance) noexcept;

    /// Collapses as long as some collapse passes; returns how many. Can be called again with a
    /// larger tolerance to go on (the deviation stays measured against the original).
    size_t decimate();

private:
    using CollapseInfo = OpenMesh::Decimater::CollapseInfoT<LodMesh>;
    struct Entry {
        float key;
        uint32_t vertex, stamp;
        bool operator>(const Entry& o) const noexcept {
            return key != o.key ? key > o.key : vertex > o.vertex; // ties: the lower index, for determinism
        }
    };

    [[nodiscard]] bool topologyAllows(const CollapseInfo& ci) const;
    void queueCheap(LodMesh::VertexHandle v);
    void queueChecked(LodMesh::VertexHandle v);

    LodMesh& mesh_;
    OpenMesh::Decimater::ModNormalFlippingT<LodMesh> flipping_;
    ModDeviationT<LodMesh> deviation_;
    ModQuadricPriorityT<LodMesh> quadric_;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue_;
    std::vector<uint32_t> stamp_;                 // per vertex: entries with another stamp are stale
    std::vector<uint8_t> checked_;                // per vertex: its live entry is a checked collapse
    std::vector<LodMesh::HalfedgeHandle> target_; // per vertex: that collapse
    std::vector<std::pair<float, LodMesh::HalfedgeHandle>> candidates_;
    std::vector<LodMesh::VertexHandle> support_;
};

} // namespace geometry::lod::detail
