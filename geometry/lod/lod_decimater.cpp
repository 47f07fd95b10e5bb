#include "geometry/lod/lod_decimater.h"

#include <algorithm>

namespace geometry::lod::detail {

LodDecimater::LodDecimater(LodMesh& mesh)
    : mesh_(mesh), flipping_(mesh), deviation_(mesh), quadric_(mesh), stamp_(mesh.n_vertices(), 0),
      checked_(mesh.n_vertices(), 0), target_(mesh.n_vertices()) {
    flipping_.initialize();
    deviation_.initialize();
    quadric_.initialize();
}

void LodDecimater::setTolerance(double tolerance) noexcept {
    deviation_.set_tolerance(tolerance);
    quadric_.set_tolerance(tolerance);
}

/// BaseDecimaterT::is_collapse_legal: what keeps the mesh a valid 2-manifold with boundary.
bool LodDecimater::topologyAllows(const CollapseInfo& ci) const {
    if (mesh_.status(ci.v0).locked() || !mesh_.is_collapse_ok(ci.v0v1)) return false;
    // Two triangles of valence-3 corners would fold onto each other.
    if (ci.vl.is_valid() && ci.vr.is_valid() && mesh_.find_halfedge(ci.vl, ci.vr).is_valid() &&
        mesh_.valence(ci.vl) == 3 && mesh_.valence(ci.vr) == 3)
        return false;
    if (mesh_.is_boundary(ci.v0)) {
        if (!mesh_.is_boundary(ci.v1)) return false;            // a boundary vertex must stay on the boundary
        if (ci.vl.is_valid() && ci.vr.is_valid()) return false; // only along a boundary edge
    }
    // v0 needs at least two faces.
    return mesh_.cw_rotated_halfedge_handle(mesh_.cw_rotated_halfedge_handle(ci.v0v1)) != ci.v0v1;
}

void LodDecimater::queueCheap(LodMesh::VertexHandle v) {
    const auto i = uint32_t(v.idx());
    ++stamp_[i];
    checked_[i] = 0;
    if (mesh_.status(v).deleted() || mesh_.status(v).locked()) return;
    float best = std::numeric_limits<float>::infinity();
    for (auto h = mesh_.voh_iter(v); h.is_valid(); ++h) {
        const float p = quadric_.collapse_priority(CollapseInfo(mesh_, *h));
        if (p >= 0.f) best = std::min(best, p);
    }
    if (best < std::numeric_limits<float>::infinity()) queue_.push({best, i, stamp_[i]});
}

void LodDecimater::queueChecked(LodMesh::VertexHandle v) {
    const auto i = uint32_t(v.idx());
    ++stamp_[i];
    checked_[i] = 0;
    candidates_.clear();
    for (auto h = mesh_.voh_iter(v); h.is_valid(); ++h) {
        const float p = quadric_.collapse_priority(CollapseInfo(mesh_, *h));
        if (p >= 0.f) candidates_.emplace_back(p, *h);
    }
    std::sort(candidates_.begin(), candidates_.end(), [](const auto& a, const auto& b) {
        return a.first != b.first ? a.first < b.first : a.second < b.second;
    });
    for (const auto& [priority, h] : candidates_) {
        const CollapseInfo ci(mesh_, h);
        // Cheapest test first; the deviation test walks the points of every face around v0.
        if (!topologyAllows(ci) || flipping_.collapse_priority(ci) < 0.f || deviation_.collapse_priority(ci) < 0.f)
            continue;
        checked_[i] = 1;
        target_[i] = h;
        queue_.push({priority, i, stamp_[i]});
        return;
    }
}

size_t LodDecimater::decimate() {
    queue_ = {};
    for (const auto v : mesh_.vertices()) queueCheap(v);
    size_t collapses = 0;
    while (!queue_.empty()) {
        const Entry e = queue_.top();
        queue_.pop();
        if (e.stamp != stamp_[e.vertex]) continue;
        const LodMesh::VertexHandle v(int(e.vertex));
        if (!checked_[e.vertex]) {
            queueChecked(v);
            continue;
        }
        CollapseInfo ci(mesh_, target_[e.vertex]);
        if (!topologyAllows(ci)) { // changed by a collapse two rings away
            queueChecked(v);
            continue;
        }
        deviation_.preprocess_collapse(ci);
        mesh_.collapse(ci.v0v1);
        ++collapses;
        ++stamp_[e.vertex];
        for (auto f = mesh_.vf_iter(ci.v1); f.is_valid(); ++f) mesh_.set_normal(*f, mesh_.calc_face_normal(*f));
        deviation_.postprocess_collapse(ci);
        quadric_.postprocess_collapse(ci);
        support_.assign(1, ci.v1);
        for (auto w = mesh_.vv_iter(ci.v1); w.is_valid(); ++w) support_.push_back(*w);
        for (const auto w : support_) queueCheap(w);
    }
    return collapses;
}

} // namespace geometry::lod::detail
