#pragma once
// The mesh type the levels are decimated on, and two OpenMesh decimater modules:
//   ModDeviationT      binary: every vertex of the original stays within a tolerance of the mesh
//   ModQuadricPriorityT  ModQuadricT as the priority, with rounding below zero clamped
// Internal to geometry/lod.
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Decimater/ModBaseT.hh>
#include <OpenMesh/Tools/Decimater/ModQuadricT.hh>

#include <algorithm>
#include <array>
#include <limits>
#include <vector>

namespace geometry::lod::detail {

/// Points in double: tolerances are ~1e-3 of a chunk, which may sit a kilometre from the origin.
struct LodTraits : OpenMesh::DefaultTraits {
    using Point = OpenMesh::Vec3d;
    using Normal = OpenMesh::Vec3d;
    VertexAttributes(OpenMesh::Attributes::Status);
    EdgeAttributes(OpenMesh::Attributes::Status);
    FaceAttributes(OpenMesh::Attributes::Status | OpenMesh::Attributes::Normal);
};
using LodMesh = OpenMesh::TriMesh_ArrayKernelT<LodTraits>;

/// A triangle prepared for many distance queries.
struct DistanceTriangle {
    OpenMesh::Vec3d a, b, c, n; // n: unnormalized normal
    double nn = 0.;             // |n|²; 0 for a degenerate triangle (measured as its edges)
    OpenMesh::Vec3d lo, hi;     // bounding box

    DistanceTriangle() = default;
    DistanceTriangle(const OpenMesh::Vec3d& a_, const OpenMesh::Vec3d& b_, const OpenMesh::Vec3d& c_) noexcept
        : a(a_), b(b_), c(c_), n((b_ - a_) % (c_ - a_)), nn(n.sqrnorm()), lo(a_.min(b_).min(c_)),
          hi(a_.max(b_).max(c_)) {
        const double longest = std::max({(b - a).sqrnorm(), (c - b).sqrnorm(), (a - c).sqrnorm()});
        // Collinear within rounding: the plane is meaningless, the edges are not.
        if (!(nn > 1e-24 * longest * longest)) nn = 0.;
    }
};

[[nodiscard]] inline double sqrDistanceToSegment(const OpenMesh::Vec3d& p, const OpenMesh::Vec3d& a,
                                                 const OpenMesh::Vec3d& b) noexcept {
    const OpenMesh::Vec3d ab = b - a;
    const double len2 = ab.sqrnorm();
    const double t = len2 > 0. ? std::clamp(((p - a) | ab) / len2, 0., 1.) : 0.;
    return (a + ab * t - p).sqrnorm();
}

/// Squared distance from p to the closed triangle, by the Voronoi regions of its corners and
/// edges (Ericson, Real-Time Collision Detection §5.1.5). Unlike ModHausdorffT's, it answers a
/// degenerate triangle with the distance to its edges, not with -1 (which passes every test).
[[nodiscard]] inline double sqrDistance(const OpenMesh::Vec3d& p, const DistanceTriangle& t) noexcept {
    if (!(t.nn > 0.))
        return std::min(
            {sqrDistanceToSegment(p, t.a, t.b), sqrDistanceToSegment(p, t.b, t.c), sqrDistanceToSegment(p, t.c, t.a)});
    const OpenMesh::Vec3d ab = t.b - t.a, ac = t.c - t.a, ap = p - t.a;
    const double d1 = ab | ap, d2 = ac | ap;
    if (d1 <= 0. && d2 <= 0.) return ap.sqrnorm();
    const OpenMesh::Vec3d bp = p - t.b;
    const double d3 = ab | bp, d4 = ac | bp;
    if (d3 >= 0. && d4 <= d3) return bp.sqrnorm();
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0. && d1 >= 0. && d3 <= 0.) return (ap - ab * (d1 / (d1 - d3))).sqrnorm();
    const OpenMesh::Vec3d cp = p - t.c;
    const double d5 = ab | cp, d6 = ac | cp;
    if (d6 >= 0. && d5 <= d6) return cp.sqrnorm();
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0. && d2 >= 0. && d6 <= 0.) return (ap - ac * (d2 / (d2 - d6))).sqrnorm();
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0. && d4 - d3 >= 0. && d5 - d6 >= 0.)
        return (bp - (t.c - t.b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)))).sqrnorm();
    const double d = ap | t.n; // inside the prism over the triangle: the distance to its plane
    return d * d / t.nn;
}

/// Binary module: a collapse is legal only if every vertex and every edge midpoint of the
/// original mesh stays within the tolerance of the collapsed surface. Like ModHausdorffT, each
/// such point (a removed vertex, a midpoint) is attached to a face within the tolerance, and a
/// collapse must find, for every point on the faces around v0, a face of the new one-ring within
/// the tolerance. Differences: edge midpoints are sampled too; degenerate faces are measured, not
/// waved through; a point is tried first against its own face and stays on it while it is within
/// the tolerance; and the points live on across decimation runs (only initialize() attaches), so
/// levels decimated in cascade stay bounded to the original. The caller must re-check every
/// vertex around v1 after a collapse (LodDecimater does), since points move onto all its faces.
template <class MeshT> class ModDeviationT : public OpenMesh::Decimater::ModBaseT<MeshT> {
public:
    DECIMATING_MODULE(ModDeviationT, MeshT, Deviation);
    using Point = typename MeshT::Point;
    using FaceHandle = typename MeshT::FaceHandle;

    /// A collapse whose faces carry more points is refused: a check costs points × faces, and
    /// faces this heavy are already few and large (a flat deck near its last triangles).
    static constexpr size_t kMaxPoints = 1024;

    explicit ModDeviationT(MeshT& mesh) : Base(mesh, true) { mesh.add_property(points_); }
    ~ModDeviationT() override { Base::mesh().remove_property(points_); }
    ModDeviationT(const ModDeviationT&) = delete;
    ModDeviationT& operator=(const ModDeviationT&) = delete;

    /// Object units. A vertex still in the mesh deviates by 0, so no point needs attaching yet.
    void set_tolerance(double tolerance) noexcept {
        tolerance_ = tolerance;
        sqrTolerance_ = tolerance * tolerance;
    }

    /// Attaches the midpoint of every edge to a face of it. Vertices alone miss a corner cut
    /// across a long crease (a box's edge, a flange's rim), which has no vertex inside it.
    void initialize() override {
        MeshT& mesh = Base::mesh();
        for (const auto e : mesh.edges()) {
            const auto h = mesh.halfedge_handle(e, 0);
            const FaceHandle f = mesh.is_boundary(h) ? mesh.opposite_face_handle(h) : mesh.face_handle(h);
            if (f.is_valid())
                mesh.property(points_, f)
                    .push_back(0.5 * (mesh.point(mesh.from_vertex_handle(h)) + mesh.point(mesh.to_vertex_handle(h))));
        }
    }

    float collapse_priority(const CollapseInfo& ci) override {
        MeshT& mesh = Base::mesh();
        // The one-ring of v0 after the collapse: its faces but fl and fr, with v0 moved to p1.
        ring_.clear();
        ringFaces_.clear();
        for (auto vf = mesh.cvf_iter(ci.v0); vf.is_valid(); ++vf) {
            if (*vf == ci.fl || *vf == ci.fr) continue;
            auto fv = mesh.cfv_iter(*vf);
            std::array<Point, 3> p;
            for (auto& q : p) {
                q = *fv == ci.v0 ? ci.p1 : mesh.point(*fv);
                ++fv;
            }
            ring_.emplace_back(p[0], p[1], p[2]);
            ringFaces_.push_back(*vf);
        }
        if (!within(ci.p0, ring_.size())) return Base::ILLEGAL_COLLAPSE;
        size_t points = 0;
        for (auto vf = mesh.cvf_iter(ci.v0); vf.is_valid(); ++vf) points += mesh.property(points_, *vf).size();
        if (points > kMaxPoints) return Base::ILLEGAL_COLLAPSE;
        for (auto vf = mesh.cvf_iter(ci.v0); vf.is_valid(); ++vf) {
            const size_t own = size_t(std::find(ringFaces_.begin(), ringFaces_.end(), *vf) - ringFaces_.begin());
            auto& pts = mesh.property(points_, *vf);
            for (auto p = pts.begin(); p != pts.end(); ++p)
                if (!within(*p, own)) {
                    // To the front: the points that block one collapse tend to block the next
                    // ones tried around here, and a refusal is cheap only if it comes early.
                    std::iter_swap(pts.begin(), p);
                    return Base::ILLEGAL_COLLAPSE;
                }
        }
        return Base::LEGAL_COLLAPSE;
    }

    void preprocess_collapse(const CollapseInfo& ci) override {
        changed_.clear();
        for (auto vf = Base::mesh().cvf_iter(ci.v0); vf.is_valid(); ++vf)
            if (*vf != ci.fl && *vf != ci.fr) changed_.push_back(*vf);
    }

    void postprocess_collapse(const CollapseInfo& ci) override {
        MeshT& mesh = Base::mesh();
        auto triangle = [&](FaceHandle f) {
            auto fv = mesh.cfv_iter(f);
            const Point& a = mesh.point(*fv);
            const Point& b = mesh.point(*++fv);
            const Point& c = mesh.point(*++fv);
            return DistanceTriangle(a, b, c);
        };
        // Points stay on their face while it is within the tolerance (faces that did not touch
        // v0 did not move at all); the others, v0 and those of the deleted faces move to their
        // nearest face around v1.
        moving_.clear();
        moving_.push_back(ci.p0);
        for (FaceHandle f : changed_) {
            auto& pts = mesh.property(points_, f);
            if (pts.empty()) continue;
            const DistanceTriangle t = triangle(f);
            const auto away = std::partition(pts.begin(), pts.end(), [&](const Point& p) { return within(p, t); });
            moving_.insert(moving_.end(), away, pts.end());
            pts.erase(away, pts.end());
        }
        for (FaceHandle f : {ci.fl, ci.fr}) {
            if (!f.is_valid()) continue;
            auto& pts = mesh.property(points_, f);
            moving_.insert(moving_.end(), pts.begin(), pts.end());
            std::vector<Point>().swap(pts);
        }
        ring_.clear();
        ringFaces_.clear();
        for (auto vf = mesh.cvf_iter(ci.v1); vf.is_valid(); ++vf) {
            ring_.push_back(triangle(*vf));
            ringFaces_.push_back(*vf);
        }
        if (ring_.empty()) return; // v1 lost its last face: nothing left to attach to
        for (const Point& p : moving_) {
            size_t best = 0;
            double bestD = std::numeric_limits<double>::infinity();
            for (size_t i = 0; i < ring_.size(); ++i) {
                const double d = sqrDistance(p, ring_[i]);
                if (d < bestD) bestD = d, best = i;
            }
            mesh.property(points_, ringFaces_[best]).push_back(p);
        }
    }

private:
    /// Whether p lies within the tolerance of t: two cheap refusals (its box, its plane) first.
    [[nodiscard]] bool within(const Point& p, const DistanceTriangle& t) const noexcept {
        for (int i = 0; i < 3; ++i)
            if (p[i] < t.lo[i] - tolerance_ || p[i] > t.hi[i] + tolerance_) return false;
        if (t.nn > 0.) {
            const double d = (p - t.a) | t.n;
            if (d * d > sqrTolerance_ * t.nn) return false;
        }
        return sqrDistance(p, t) <= sqrTolerance_;
    }

    /// Whether p lies within the tolerance of a face of ring_, trying ring_[first] first.
    [[nodiscard]] bool within(const Point& p, size_t first) const noexcept {
        if (first < ring_.size() && within(p, ring_[first])) return true;
        for (size_t i = 0; i < ring_.size(); ++i)
            if (i != first && within(p, ring_[i])) return true;
        return false;
    }

    OpenMesh::FPropHandleT<std::vector<Point>> points_;
    double tolerance_ = 0., sqrTolerance_ = 0.;
    std::vector<DistanceTriangle> ring_;
    std::vector<FaceHandle> ringFaces_, changed_;
    std::vector<Point> moving_;
};

/// ModQuadricT as the priority module, with two changes. The quadric error of a collapse within
/// a plane rounds to a tiny negative now and then, which the decimater reads as "illegal": it is
/// clamped to 0. And ties are broken towards short edges: on a tessellated tube every collapse
/// along the tube costs exactly 0, and taken in heap order they pile whole rows into one vertex,
/// whose valence then makes each later collapse quadratic; shortest first halves the rows evenly.
template <class MeshT> class ModQuadricPriorityT : public OpenMesh::Decimater::ModQuadricT<MeshT> {
public:
    using Base = OpenMesh::Decimater::ModQuadricT<MeshT>;
    using Base::Base;

    /// Weight of |p1 - p0|² in the priority: small against the quadric error of a collapse that
    /// moves the surface by the tolerance (≈ edge² × tolerance²).
    void set_tolerance(double tolerance) noexcept { lengthWeight_ = 1e-3 * tolerance * tolerance; }

    float collapse_priority(const typename Base::CollapseInfo& ci) override {
        const float e = Base::collapse_priority(ci);
        // Without a max error set, ModQuadricT answers ILLEGAL_COLLAPSE (-1) only for NaN.
        if (e == float(Base::ILLEGAL_COLLAPSE)) return e;
        return std::max(e, 0.f) + float(lengthWeight_ * (ci.p1 - ci.p0).sqrnorm());
    }

private:
    double lengthWeight_ = 0.;
};

} // namespace geometry::lod::detail
