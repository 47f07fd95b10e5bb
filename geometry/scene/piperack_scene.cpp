// The "piperack" built-in scene: a plant pipe rack as a CAD exporter tessellates it. Most
// triangles are curved surfaces (pipes, elbows, flanges, valves) on a little flat-faced steel;
// pipes shade the tiers below them and the 1 km ground, which gives a huge depth range.
//
// Layout (metres, y up, right-handed): the rack runs along +x from x = -60 in 6 m bays, columns
// on the lines z = ±3.5, three tiers with their steel tops at y = 5, 7 and 9, the biggest pipes
// on the lowest. Pipes rest on the steel. Past the rack ends they drop to sleepers near the
// ground (outrigger bents carry the upper tiers out to their drops) or end in blind flanges; the
// outermost pipes of a tier may leave through the side of the rack or make an expansion loop out
// beside it. Instrument tubing runs along the -z columns.
//
// Triangle budget: the rack grows with the fourth root of the target (20 bays, 120 m, at 250k);
// the rest is tessellation, set as a CAD exporter sets it, by one chord tolerance: a circle of
// radius r gets π / acos(1 - tol / r) sides. The solids are first laid out as descriptions, the
// tolerance is then solved by bisection on their exact triangle counts (MeshBuilder's *Triangles),
// and only then is anything built. Steel and ground are ~5–18 % of the target; below ~20k
// triangles the target cannot be met.
//
// Index
//   [SECTION] Detail .................... detailFor
//   [SECTION] Solids and tessellation ... PartList, sidesFor, arcSteps, triangles, emit, solveTolerance
//   [SECTION] Steel ..................... addISection, addBent, addSteel
//   [SECTION] Fittings .................. addFlangeJoint, addEndCap, addValve
//   [SECTION] Pipe runs ................. addRun, rackEnd, sideExit, expansionLoop
//   [SECTION] Laying the pipes .......... layLanes, claimBays, layTier, layTubing
//   [SECTION] Camera and light .......... defaultCamera, defaultLight
//   [SECTION] Building the scene ........ makePiperackScene
#include "geometry/scene/builtin_scenes.h"
#include "geometry/scene/mesh_builder.h"
#include "geometry/scene/rng.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/gtc/constants.hpp>
#include <vector>

namespace geometry::scene {
namespace {

// ---- Layout -------------------------------------------------------------------------------

constexpr float kBayLength = 6.f;
constexpr float kRackStartX = -60.f;
constexpr float kColumnZ = 3.5f;       // column lines at z = ±kColumnZ
constexpr float kLaneHalfWidth = 3.2f; // pipes, flanges included, keep within |z| ≤ this on the rack
constexpr float kLaneGap = 0.1f;       // between neighbouring pipes' flanges
constexpr std::array<float, 3> kTierTops{5.f, 7.f, 9.f};
constexpr float kSleeperHeight = 0.6f; // pipes near the ground run this far above it
constexpr float kGroundSize = 1000.f;
constexpr float kTubingRadius = 0.012f; // instrument tubing, 24 mm outside diameter

constexpr float kColumnSize = 0.3f;
constexpr float kBeamDepth = 0.35f, kBeamWidth = 0.2f;
constexpr float kStringerDepth = 0.25f, kStringerWidth = 0.15f;

/// Outside radii of the nominal pipe sizes 4" to 48".
constexpr std::array<float, 12> kNominalRadii{0.057f, 0.084f, 0.110f, 0.137f, 0.162f, 0.203f,
                                              0.254f, 0.305f, 0.381f, 0.457f, 0.533f, 0.610f};
struct SizeRange {
    int smallest, largest; // indices into kNominalRadii
};
/// Bottom tier 16"–48", middle 8"–30", top 8"–16".
constexpr std::array<SizeRange, 3> kTierSizes{{{5, 11}, {2, 8}, {2, 5}}};

const glm::vec3 kUp{0.f, 1.f, 0.f};

// Fitting proportions, from the pipe's outside radius r.
float bendRadius(float r) { return 3.f * r; } // long-radius elbow: 1.5 × the outside diameter
float flangeRadius(float r) { return 1.5f * r + 0.06f; }
float flangeThickness(float r) { return 0.03f + 0.12f * r; }
int boltCount(float r) { return 4 * std::max(1, static_cast<int>(std::lround(15.f * r))); }
float valveHalfLength(float r) { return 1.2f * r; } // body; its flanges lie within it

float bayMid(int bay) { return kRackStartX + kBayLength * (static_cast<float>(bay) + 0.5f); }

// ---- Colours (CAD part classes, one mesh each) ---------------------------------------------

const glm::vec3 kGroundColor{0.56f, 0.55f, 0.50f};
const glm::vec3 kSteelColor{0.36f, 0.45f, 0.55f};
const glm::vec3 kPipeColor{0.80f, 0.78f, 0.72f};
const glm::vec3 kElbowColor{0.74f, 0.72f, 0.66f};
const glm::vec3 kFlangeColor{0.48f, 0.49f, 0.52f};
const glm::vec3 kValveColor{0.78f, 0.22f, 0.16f};

// ---- [SECTION] Detail -----------------------------------------------------------------------

struct Detail {
    int bays;
    int groundCells;
    int valvePercent;  // of the places that may take a valve; valves and their flanges are costly
    float spoolLength; // between flange joints along the rack (long runs are mostly welded)
    bool bolts;        // flange bolts, from 400k triangles: below that they would crowd out the pipes
    bool outriggers;   // bents past the rack ends, from 50k: below that the steel's share is too large
};

/// Layout detail for a triangle target; the chord tolerance takes care of the rest. The rack's
/// length grows with q^½ (q = sqrt(target / 250k)), valves and flange joints with q up to the
/// default size, so that small targets are not all fittings.
Detail detailFor(uint32_t targetTriangles) {
    const float target = std::max(static_cast<float>(targetTriangles), 1.f);
    const float q = std::sqrt(target / 250'000.f);
    Detail d{};
    d.bays = std::clamp(static_cast<int>(std::lround(20.f * std::sqrt(q))), 10, 40);
    // The ground takes ~1 % of the target: 2 · cells² triangles.
    d.groundCells = std::clamp(static_cast<int>(std::lround(std::sqrt(0.005f * target))), 8, 160);
    d.valvePercent = std::clamp(static_cast<int>(std::lround(100.f * q)), 25, 100);
    d.spoolLength = kBayLength * static_cast<float>(std::clamp(static_cast<int>(std::lround(4.f / q)), 4, 8));
    d.bolts = targetTriangles >= 400'000;
    d.outriggers = targetTriangles >= 50'000;
    return d;
}

// ---- [SECTION] Solids and tessellation ------------------------------------------------------

struct TubePart {
    std::vector<glm::vec3> path;
    float radius;
};
struct TorusPart {
    glm::vec3 center, axis, start;
    float majorRadius, minorRadius, sweepRad;
};
struct RingPart {
    glm::vec3 a, b;
    float innerRadius, outerRadius;
};
struct CylinderPart {
    glm::vec3 a, b;
    float radius;
    bool caps;
};

/// One CAD part class's solids, described until the chord tolerance is known. Tubes meet elbows
/// and fittings, and elbows are torus sections, so neither has caps.
struct PartList {
    std::vector<TubePart> tubes;
    std::vector<TorusPart> tori;
    std::vector<RingPart> rings;
    std::vector<CylinderPart> cylinders;
};

constexpr int kMinSides = 6, kMaxSides = 1024;

/// Sides of a polygon within `tol` of a circle of `radius` (its chords' sagitta ≤ tol).
int sidesFor(float radius, float tol) {
    const float c = 1.f - tol / radius;
    if (c <= 0.f) return kMinSides;
    const float sides = std::ceil(glm::pi<float>() / std::acos(c));
    return static_cast<int>(std::clamp(sides, static_cast<float>(kMinSides), static_cast<float>(kMaxSides)));
}

/// Steps along an arc of `radius` and `sweepRad` within `tol`, and of at most 30° each (an
/// exporter's angle tolerance, which keeps coarse elbows round).
int arcSteps(float radius, float sweepRad, float tol) {
    const float c = 1.f - tol / radius;
    const float step = std::min(c <= 0.f ? glm::pi<float>() : 2.f * std::acos(c), glm::pi<float>() / 6.f);
    const float steps = std::ceil(sweepRad / step - 1e-4f);
    return static_cast<int>(std::clamp(steps, 1.f, static_cast<float>(kMaxSides)));
}

int majorSteps(const TorusPart& t, float tol) { return arcSteps(t.majorRadius + t.minorRadius, t.sweepRad, tol); }

size_t triangles(const PartList& parts, float tol) {
    size_t n = 0;
    for (const TubePart& t : parts.tubes)
        n += MeshBuilder::tubeTriangles(t.path.size(), sidesFor(t.radius, tol), false);
    for (const TorusPart& t : parts.tori)
        n += MeshBuilder::torusTriangles(t.sweepRad, majorSteps(t, tol), sidesFor(t.minorRadius, tol), false);
    for (const RingPart& r : parts.rings) n += MeshBuilder::ringTriangles(sidesFor(r.outerRadius, tol));
    for (const CylinderPart& c : parts.cylinders) n += MeshBuilder::cylinderTriangles(sidesFor(c.radius, tol), c.caps);
    return n;
}

void emit(const PartList& parts, float tol, MeshBuilder& mb) {
    for (const TubePart& t : parts.tubes) mb.addTube(t.path, t.radius, sidesFor(t.radius, tol), false);
    for (const TorusPart& t : parts.tori)
        mb.addTorus(t.center, t.axis, t.start, t.majorRadius, t.minorRadius, t.sweepRad, majorSteps(t, tol),
                    sidesFor(t.minorRadius, tol), false);
    for (const RingPart& r : parts.rings)
        mb.addRing(r.a, r.b, r.innerRadius, r.outerRadius, sidesFor(r.outerRadius, tol));
    for (const CylinderPart& c : parts.cylinders) mb.addCylinder(c.a, c.b, c.radius, sidesFor(c.radius, tol), c.caps);
}

/// The chord tolerance whose triangles come closest to `budget` (counts fall as it grows).
float solveTolerance(const std::vector<const PartList*>& lists, size_t budget) {
    const auto count = [&](float tol) {
        size_t n = 0;
        for (const PartList* l : lists) n += triangles(*l, tol);
        return n;
    };
    float fine = 1e-6f, coarse = 1.f;
    for (int i = 0; i < 40; ++i) {
        const float mid = std::sqrt(fine * coarse);
        (count(mid) > budget ? fine : coarse) = mid;
    }
    const auto error = [&](float tol) {
        const size_t n = count(tol);
        return n > budget ? n - budget : budget - n;
    };
    return error(fine) < error(coarse) ? fine : coarse;
}

// ---- [SECTION] Steel ------------------------------------------------------------------------

/// I-section member from a to b, which differ along one axis only: web along `depthAxis`,
/// flanges across it; three boxes.
void addISection(MeshBuilder& steel, const glm::vec3& a, const glm::vec3& b, int depthAxis, float depth, float width) {
    constexpr float flange = 0.025f, web = 0.015f;
    const glm::vec3 center = 0.5f * (a + b), half = 0.5f * glm::abs(b - a);
    const int along = half.x >= half.y && half.x >= half.z ? 0 : (half.y >= half.z ? 1 : 2);
    const int across = 3 - along - depthAxis;
    glm::vec3 webHalf = half;
    webHalf[depthAxis] = 0.5f * depth - flange;
    webHalf[across] = 0.5f * web;
    steel.addBox(center, webHalf);
    for (float side : {-1.f, 1.f}) {
        glm::vec3 c = center, h = half;
        c[depthAxis] += side * 0.5f * (depth - flange);
        h[depthAxis] = 0.5f * flange;
        h[across] = 0.5f * width;
        steel.addBox(c, h);
    }
}

/// Portal frame at x: two columns, a cross-beam for each tier from `firstTier` up.
void addBent(MeshBuilder& steel, float x, size_t firstTier) {
    for (float side : {-1.f, 1.f}) {
        const float z = side * kColumnZ;
        addISection(steel, {x, 0.f, z}, {x, kTierTops.back(), z}, 2, kColumnSize, kColumnSize);
        steel.addBox({x, 0.02f, z}, {0.3f, 0.02f, 0.3f}); // base plate
    }
    for (size_t tier = firstTier; tier < kTierTops.size(); ++tier) {
        const float y = kTierTops[tier] - 0.5f * kBeamDepth;
        const float z = kColumnZ + 0.5f * kColumnSize;
        addISection(steel, {x, y, -z}, {x, y, z}, 1, kBeamDepth, kBeamWidth);
    }
}

/// A bent every bay, stringers along both column lines at every tier, X-bracing below the lowest
/// tier in the end bays. Outriggers: past each end, bents between the tiers' drops (rackEnd)
/// carry the tiers that run on.
void addSteel(MeshBuilder& steel, const Detail& d) {
    const float xEnd = kRackStartX + kBayLength * static_cast<float>(d.bays);
    for (int bent = 0; bent <= d.bays; ++bent) addBent(steel, kRackStartX + kBayLength * static_cast<float>(bent), 0);
    if (d.outriggers)
        for (size_t tier = 1; tier < kTierTops.size(); ++tier) {
            const float out = 6.f * static_cast<float>(tier);
            addBent(steel, kRackStartX - out, tier);
            addBent(steel, xEnd + out, tier);
        }
    const float halfSpan = 0.5f * (kBayLength - kColumnSize);
    for (int bay = 0; bay < d.bays; ++bay)
        for (float tierTop : kTierTops)
            for (float side : {-1.f, 1.f})
                steel.addBox({bayMid(bay), tierTop - 0.5f * kStringerDepth, side * kColumnZ},
                             {halfSpan, 0.5f * kStringerDepth, 0.5f * kStringerWidth});
    for (int bay : {0, d.bays - 1}) {
        const float x0 = bayMid(bay) - halfSpan, x1 = bayMid(bay) + halfSpan;
        const float y0 = 0.3f, y1 = kTierTops.front() - kBeamDepth;
        for (float side : {-1.f, 1.f}) {
            const float z = side * kColumnZ;
            steel.addBeam({x0, y0, z}, {x1, y1, z}, 0.05f);
            steel.addBeam({x1, y0, z}, {x0, y1, z}, 0.05f);
        }
    }
}

// ---- [SECTION] Fittings ---------------------------------------------------------------------

/// What the pipe-laying functions add to: one part list per CAD part class.
struct Plant {
    PartList pipes, elbows, flanges, valves;
    bool bolts = false;
    int valvePercent = 100;
    float spoolLength = 4.f * kBayLength;
};

/// A pair of flanges meeting at p on a pipe along `dir`, bolted together; `blind`: the second is
/// a blind flange closing the pipe's end.
void addFlangeJoint(Plant& plant, const glm::vec3& p, const glm::vec3& dir, float r, bool blind) {
    const float t = flangeThickness(r), outer = flangeRadius(r);
    plant.flanges.rings.push_back({p - t * dir, p, r, outer});
    if (blind) plant.flanges.cylinders.push_back({p, p + t * dir, outer, true});
    else plant.flanges.rings.push_back({p, p + t * dir, r, outer});
    if (!plant.bolts) return;
    glm::vec3 u, v;
    orthonormalBasis(dir, u, v);
    const int bolts = boltCount(r);
    const float circle = r + 0.6f * (outer - r), boltRadius = 0.008f + 0.015f * r, reach = t + 0.025f;
    for (int k = 0; k < bolts; ++k) {
        const float a = glm::two_pi<float>() * (static_cast<float>(k) + 0.5f) / static_cast<float>(bolts);
        const glm::vec3 c = p + circle * (std::cos(a) * u + std::sin(a) * v);
        plant.flanges.cylinders.push_back({c - reach * dir, c + reach * dir, boltRadius, true});
    }
}

/// Screwed cap closing a tube's end at p (facing `dir`).
void addEndCap(Plant& plant, const glm::vec3& p, const glm::vec3& dir, float r) {
    plant.pipes.cylinders.push_back({p - 2.f * r * dir, p + r * dir, 1.4f * r, true});
}

/// Gate valve centred at c on a pipe along `axis`: body, bonnet towards `bonnet`, stem and a
/// spoked handwheel; the flange joints at its ends are flanges.
void addValve(Plant& plant, const glm::vec3& c, const glm::vec3& axis, const glm::vec3& bonnet, float r) {
    const float half = valveHalfLength(r), body = 1.15f * r, t = flangeThickness(r);
    PartList& v = plant.valves;
    v.cylinders.push_back({c - half * axis, c + half * axis, body, true});
    for (float side : {-1.f, 1.f}) addFlangeJoint(plant, c + side * half * axis, side * axis, r, false);
    const glm::vec3 bonnetTop = c + (body + 0.9f * r) * bonnet;
    v.cylinders.push_back({c, bonnetTop, 0.6f * r, true});
    v.rings.push_back({c + body * bonnet, c + (body + t) * bonnet, 0.6f * r, 0.85f * r});
    const float stemRadius = std::max(0.012f, 0.05f * r);
    const glm::vec3 wheel = bonnetTop + (0.25f + 0.6f * r) * bonnet;
    v.cylinders.push_back({bonnetTop, wheel + 0.03f * bonnet, stemRadius, true});
    const float rim = std::max(0.12f, 0.8f * r), rimTube = std::max(0.012f, 0.06f * rim);
    glm::vec3 u, w;
    orthonormalBasis(bonnet, u, w);
    v.tori.push_back({wheel, bonnet, u, rim, rimTube, glm::two_pi<float>()});
    v.cylinders.push_back({wheel - 0.03f * bonnet, wheel + 0.03f * bonnet, 2.5f * stemRadius, true}); // hub
    for (int k = 0; k < 3; ++k) {
        const float a = glm::two_pi<float>() * static_cast<float>(k) / 3.f;
        const glm::vec3 spoke = std::cos(a) * u + std::sin(a) * w;
        v.cylinders.push_back({wheel, wheel + rim * spoke, 0.6f * rimTube, false}); // both ends buried
    }
}

// ---- [SECTION] Pipe runs --------------------------------------------------------------------

/// Straight pipe from p to q with a ring of vertices at least every bay, so that chunks stay local.
std::vector<glm::vec3> straightPath(const glm::vec3& p, const glm::vec3& q) {
    const int steps = std::max(1, static_cast<int>(std::ceil(glm::length(q - p) / kBayLength)));
    std::vector<glm::vec3> path;
    for (int i = 0; i <= steps; ++i) path.push_back(p + (q - p) * (static_cast<float>(i) / static_cast<float>(steps)));
    return path;
}

/// A pipe of radius r along the polyline `corners`, an elbow at every inner corner. Flanged runs
/// have a flange joint wherever a leg along x longer than a spool crosses x = jointPhase + k ·
/// spool length, and blind flanges at both ends; the others (tubing) end in caps. Shorter legs
/// (stubs, loops) are one piece, so joints never meet the valves on them.
void addRun(Plant& plant, const std::vector<glm::vec3>& corners, float r, bool flanged, float jointPhase) {
    const float bend = bendRadius(r), spool = plant.spoolLength;
    const size_t n = corners.size();
    std::vector<float> cut(n, 0.f); // the bend at a corner starts and ends this far from it
    for (size_t i = 1; i + 1 < n; ++i) {
        const glm::vec3 in = glm::normalize(corners[i] - corners[i - 1]);
        const glm::vec3 out = glm::normalize(corners[i + 1] - corners[i]);
        const float turn = std::acos(std::clamp(glm::dot(in, out), -1.f, 1.f));
        if (turn < 1e-3f) continue;
        cut[i] = bend * std::tan(0.5f * turn);
        const glm::vec3 inward = glm::normalize(out - glm::dot(out, in) * in); // towards the bend's centre
        const glm::vec3 center = corners[i] - cut[i] * in + bend * inward;
        plant.elbows.tori.push_back({center, glm::cross(in, out), -inward, bend, r, turn});
    }
    for (size_t i = 0; i + 1 < n; ++i) {
        const glm::vec3 dir = glm::normalize(corners[i + 1] - corners[i]);
        const glm::vec3 p = corners[i] + cut[i] * dir, q = corners[i + 1] - cut[i + 1] * dir;
        plant.pipes.tubes.push_back({straightPath(p, q), r});
        if (!flanged || std::abs(dir.x) < 0.99f || glm::length(q - p) < spool) continue;
        // Joints keep clear of the leg's ends (bends, fittings).
        const float margin = 0.3f + flangeThickness(r);
        const float lo = std::min(p.x, q.x) + margin, hi = std::max(p.x, q.x) - margin;
        for (float k = std::ceil((lo - jointPhase) / spool); jointPhase + k * spool <= hi; ++k) {
            const float x = jointPhase + k * spool;
            addFlangeJoint(plant, p + dir * ((x - p.x) / dir.x), dir, r, false);
        }
    }
    const glm::vec3 startDir = glm::normalize(corners[0] - corners[1]);
    const glm::vec3 endDir = glm::normalize(corners[n - 1] - corners[n - 2]);
    if (flanged) {
        addFlangeJoint(plant, corners[0], startDir, r, true);
        addFlangeJoint(plant, corners[n - 1], endDir, r, true);
    } else {
        addEndCap(plant, corners[0], startDir, r);
        addEndCap(plant, corners[n - 1], endDir, r);
    }
}

/// A pipe on the rack: its tier's steel top and the lane's position across the rack.
struct Lane {
    float z, radius;
};

float runHeight(size_t tier, const Lane& lane) { return kTierTops[tier] + lane.radius; }

/// From the run's corner `top` down to the sleepers, then a stub along `outward`, with a valve on
/// the drop (bonnet along `outward`) when it is long enough, else on the stub (bonnet up), or
/// none. Corners from the run outwards.
std::vector<glm::vec3> dropAndStub(Rng& rng, Plant& plant, const glm::vec3& top, const glm::vec3& outward, float r) {
    const float bend = bendRadius(r), yLow = kSleeperHeight + r;
    const float valveSpan = 2.f * (valveHalfLength(r) + flangeThickness(r)) + 0.2f;
    const glm::vec3 low{top.x, yLow, top.z};
    float stub = 1.2f;
    const int valve = rng.chance(plant.valvePercent) ? rng.below(3) : 2; // 0: on the drop, 1: on the stub, 2: none
    if (valve == 0 && top.y - yLow - 2.f * bend >= valveSpan) {
        addValve(plant, 0.5f * (top + low), kUp, outward, r);
    } else if (valve != 2) {
        stub = valveSpan + 1.f;
        addValve(plant, low + (bend + 0.5f + 0.5f * valveSpan) * outward, outward, kUp, r);
    }
    return {top, low, low + (bend + stub) * outward};
}

/// Past the rack end at xEnd (side -1: the -x end): a blind flange just past the last bent, or a
/// drop. Tiers drop 6 m apart, so no pipe crosses another's drop, and the outrigger bents (6 and
/// 12 m out) stand between the drops. Corners from the run outwards.
std::vector<glm::vec3> rackEnd(Rng& rng, Plant& plant, float side, float xEnd, size_t tier, const Lane& lane) {
    const float y = runHeight(tier, lane);
    if (rng.chance(35)) return {{xEnd + side * 1.f, y, lane.z}};
    const glm::vec3 top{xEnd + side * (2.5f + 6.f * static_cast<float>(tier)), y, lane.z};
    return dropAndStub(rng, plant, top, {side, 0.f, 0.f}, lane.radius);
}

/// Out through the side (sideZ = ±1) at the middle of `bay`: a bend out past the column line, a
/// drop outside the rack and a stub away from it. Corners from the run outwards.
std::vector<glm::vec3> sideExit(Rng& rng, Plant& plant, float sideZ, int bay, size_t tier, const Lane& lane) {
    const float r = lane.radius, y = runHeight(tier, lane), x = bayMid(bay);
    const float outZ = sideZ * std::max(std::abs(lane.z) + 2.f * bendRadius(r) + 0.3f,
                                        kColumnZ + 0.5f + flangeRadius(r) + 0.5f * kColumnSize);
    std::vector<glm::vec3> corners{{x, y, lane.z}};
    const std::vector<glm::vec3> down = dropAndStub(rng, plant, {x, y, outZ}, {0.f, 0.f, sideZ}, r);
    corners.insert(corners.end(), down.begin(), down.end());
    return corners;
}

/// Expansion loop out beside the rack (sideZ = ±1), from the middle of `bay` to that of bay + 2.
std::vector<glm::vec3> expansionLoop(float sideZ, int bay, size_t tier, const Lane& lane) {
    const float y = runHeight(tier, lane), xa = bayMid(bay), xb = bayMid(bay + 2);
    const float outZ = sideZ * std::max(std::abs(lane.z) + 2.f * bendRadius(lane.radius) + 0.3f, kColumnZ + 2.f);
    return {{xa, y, lane.z}, {xa, y, outZ}, {xb, y, outZ}, {xb, y, lane.z}};
}

// ---- [SECTION] Laying the pipes -------------------------------------------------------------

/// A tier's pipes side by side across the rack: random nominal sizes, flanges clear of each
/// other, the space left over shared out evenly between them.
std::vector<Lane> layLanes(Rng& rng, size_t tier) {
    const SizeRange sizes = kTierSizes[tier];
    std::vector<Lane> lanes;
    float edge = -kLaneHalfWidth; // where the next pipe's flange may start
    for (;;) {
        const float r =
            kNominalRadii[static_cast<size_t>(sizes.smallest + rng.below(sizes.largest - sizes.smallest + 1))];
        const float flange = flangeRadius(r);
        if (edge + 2.f * flange > kLaneHalfWidth) break;
        lanes.push_back({edge + flange, r});
        edge += 2.f * flange + kLaneGap;
    }
    const float slack = kLaneHalfWidth - (edge - kLaneGap);
    for (size_t i = 0; i < lanes.size(); ++i)
        lanes[i].z += slack * static_cast<float>(i + 1) / static_cast<float>(lanes.size() + 1);
    return lanes;
}

/// Claims `count` consecutive free bays starting somewhere in [lo, hi] (random, then onwards);
/// the first bay, or -1 when none is free. A bay taken on one side is for one pipe leaving or
/// looping there, on any tier, so that none crosses another.
int claimBays(Rng& rng, std::vector<bool>& taken, int count, int lo, int hi) {
    if (hi < lo) return -1;
    const int span = hi - lo + 1, first = rng.below(span);
    for (int k = 0; k < span; ++k) {
        const int bay = lo + (first + k) % span;
        bool free = true;
        for (int b = bay; b < bay + count; ++b) free = free && !taken[static_cast<size_t>(b)];
        if (!free) continue;
        for (int b = bay; b < bay + count; ++b) taken[static_cast<size_t>(b)] = true;
        return bay;
    }
    return -1;
}

/// Concatenates corner lists: `from` reversed (it runs outwards from the start), then the rest.
std::vector<glm::vec3> joinCorners(std::vector<glm::vec3> from, const std::vector<std::vector<glm::vec3>>& rest) {
    std::reverse(from.begin(), from.end());
    for (const auto& part : rest) from.insert(from.end(), part.begin(), part.end());
    return from;
}

/// Sides of the rack for the side exits and expansion loops: which bays each has taken.
struct SideBays {
    std::vector<bool> minusZ, plusZ;
    std::vector<bool>& of(float sideZ) { return sideZ < 0.f ? minusZ : plusZ; }
};

/// One tier's pipes. Inner pipes run the whole rack; the outermost on each side may instead be
/// split in two (each part leaving through the side), or loop out beside the rack. Valves stand
/// on the top tier's pipes, where nothing is above them.
void layTier(Rng& rng, Plant& plant, SideBays& sideBays, size_t tier, const Detail& d) {
    const float xStart = kRackStartX, xEnd = kRackStartX + kBayLength * static_cast<float>(d.bays);
    const std::vector<Lane> lanes = layLanes(rng, tier);
    for (size_t i = 0; i < lanes.size(); ++i) {
        const Lane& lane = lanes[i];
        // Neighbours' joints are a bay apart, so their flanges never meet.
        const float phase = bayMid(static_cast<int>(i % 4));
        const bool edge = lanes.size() >= 2 && (i == 0 || i + 1 == lanes.size());
        const float sideZ = i == 0 ? -1.f : 1.f;
        const std::vector<glm::vec3> start = rackEnd(rng, plant, -1.f, xStart, tier, lane);
        const std::vector<glm::vec3> end = rackEnd(rng, plant, 1.f, xEnd, tier, lane);
        const int style = edge ? rng.below(3) : 2; // 0: split, 1: loop, 2: straight through
        if (style == 0) {
            std::vector<bool>& taken = sideBays.of(sideZ);
            const int out = claimBays(rng, taken, 1, 1, d.bays / 2 - 1);
            const int in = out < 0 ? -1 : claimBays(rng, taken, 1, d.bays / 2, d.bays - 2);
            if (in >= 0) {
                addRun(plant, joinCorners(start, {sideExit(rng, plant, sideZ, out, tier, lane)}), lane.radius, true,
                       phase);
                addRun(plant, joinCorners(sideExit(rng, plant, sideZ, in, tier, lane), {end}), lane.radius, true,
                       phase);
                continue;
            }
            if (out >= 0) taken[static_cast<size_t>(out)] = false;
        }
        std::vector<glm::vec3> loop;
        if (style == 1) {
            const int bay = claimBays(rng, sideBays.of(sideZ), 3, 1, d.bays - 4);
            if (bay >= 0) loop = expansionLoop(sideZ, bay, tier, lane);
        }
        addRun(plant, joinCorners(start, {loop, end}), lane.radius, true, phase);
        if (tier + 1 == kTierTops.size() && !edge && rng.chance(plant.valvePercent * 2 / 5)) {
            const float x =
                kRackStartX + kBayLength * static_cast<float>(1 + rng.below(d.bays - 2)) + 0.25f * kBayLength;
            addValve(plant, {x, runHeight(tier, lane), lane.z}, {1.f, 0.f, 0.f}, kUp, lane.radius);
        }
    }
}

/// Instrument tubing clipped to the outside of the -z columns below the top tier, turning down
/// past both rack ends.
void layTubing(Plant& plant, const Detail& d) {
    const float y = kTierTops.back() - 0.6f, yLow = 1.2f;
    const float xStart = kRackStartX - 0.8f, xEnd = kRackStartX + kBayLength * static_cast<float>(d.bays) + 0.8f;
    for (int k = 0; k < 3; ++k) {
        const float z = -(kColumnZ + 0.5f * kColumnSize + 0.03f + 0.05f * static_cast<float>(k));
        const float yk = y - 0.05f * static_cast<float>(k);
        addRun(plant, {{xStart, yLow, z}, {xStart, yk, z}, {xEnd, yk, z}, {xEnd, yLow, z}}, kTubingRadius, false, 0.f);
    }
}

// ---- [SECTION] Camera and light -------------------------------------------------------------

/// Standing at eye height just outside the +z column line in the first bay, looking along the
/// rack and a little up: columns and pipe drops close by, the tiers receding, the ground beside
/// the rack out to the horizon.
Camera defaultCamera() {
    Camera c;
    c.eye = {kRackStartX + 2.f, 1.7f, 5.5f};
    c.target = {kRackStartX + 62.f, 5.f, 0.f};
    c.fovYDeg = 60.f;
    c.near = 0.5f;
    c.far = 1500.f;
    return c;
}

/// Sun at ~46° elevation from the +z side, a little behind the camera: the pipes' shadows fall
/// across the lower tiers and onto the ground beside the rack, in view.
Light defaultLight() {
    Light l;
    l.direction = {0.35f, -0.72f, -0.6f};
    return l;
}

} // namespace

// ---- [SECTION] Building the scene -----------------------------------------------------------

Scene makePiperackScene(const PiperackParams& params) {
    const Detail d = detailFor(params.targetTriangles);
    Rng rng(params.seed);

    MeshBuilder ground("ground", kGroundColor);
    MeshBuilder steel("steel", kSteelColor);
    ground.addGroundGrid({0.f, 0.f, 0.f}, kGroundSize, d.groundCells);
    addSteel(steel, d);

    Plant plant;
    plant.bolts = d.bolts;
    plant.valvePercent = d.valvePercent;
    plant.spoolLength = d.spoolLength;
    SideBays sideBays{std::vector<bool>(static_cast<size_t>(d.bays), false),
                      std::vector<bool>(static_cast<size_t>(d.bays), false)};
    for (size_t tier = 0; tier < kTierTops.size(); ++tier) layTier(rng, plant, sideBays, tier, d);
    layTubing(plant, d);

    // The curved parts take what the steel and the ground leave of the budget.
    const size_t flat = ground.triangleCount() + steel.triangleCount();
    const size_t target = params.targetTriangles;
    const std::vector<const PartList*> curved{&plant.pipes, &plant.elbows, &plant.flanges, &plant.valves};
    const float tol = solveTolerance(curved, target > flat ? target - flat : 0);

    MeshBuilder pipes("pipes", kPipeColor);
    MeshBuilder elbows("elbows", kElbowColor);
    MeshBuilder flanges("flanges", kFlangeColor);
    MeshBuilder valves("valves", kValveColor);
    emit(plant.pipes, tol, pipes);
    emit(plant.elbows, tol, elbows);
    emit(plant.flanges, tol, flanges);
    emit(plant.valves, tol, valves);

    Scene scene;
    scene.name = "piperack";
    for (MeshBuilder* mb : {&ground, &steel, &pipes, &elbows, &flanges, &valves}) scene.meshes.push_back(mb->build());
    scene.camera = defaultCamera();
    scene.lights[0] = defaultLight();
    return scene;
}

} // namespace geometry::scene
