// The "platform" built-in scene: an offshore oil-platform-like CAD model. Thin bars (braces,
// grating, railings, trusses) cast fine shadow patterns, and a 2.4 km sea plane makes the depth
// range huge, which is what the shadow-mapping schemes under inspection struggle with.
//
// Layout (metres, y up, right-handed): sea at y = 0, platform centred on the origin. A tapering
// jacket of 3 × 2 legs rises to 30 m; three 40 × 30 m decks sit above it; the helideck is over
// the -x/-z corner of the top deck, the crane at +x/+z, the flare boom leans out from +x/-z.
//
// Triangle budget: the structure's detail (cylinder segments, bays, pipe runs, railing posts)
// grows with sqrt(target); the deck grating, made of many small bars, then takes whatever is left
// of the target. Grating bars are all the same kind, so their count is exact arithmetic and no
// trial builds are needed. Below ~10k triangles the target cannot be met: the structure alone
// is ~7k at its lowest detail.
//
// Index
//   [SECTION] Detail .................... detailFor
//   [SECTION] Small geometry helpers .... legPoint, bayLevel, perpendicularBasis, addTruss
//   [SECTION] Jacket and deck columns ... addJacket
//   [SECTION] Decks ..................... addDeckFrame, solveGrating, addGrating, addRailings, addModules
//   [SECTION] Pipes ..................... addPipeRun, addRiser
//   [SECTION] Top-deck equipment ........ addHelideck, addCrane, addFlareBoom
//   [SECTION] Camera and light .......... defaultCamera, defaultLight
//   [SECTION] Building the scene ........ makePlatformScene
#include "geometry/scene/builtin_scenes.h"
#include "geometry/scene/mesh_builder.h"
#include "geometry/scene/rng.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace geometry::scene {
namespace {

// ---- Layout -------------------------------------------------------------------------------

// The jacket starts a few metres under water, so legs and braces pierce the sea surface instead
// of ending on it.
constexpr float kJacketBottom = -4.f, kJacketTop = 30.f;
constexpr float kJacketBaseHalfX = 26.f, kJacketBaseHalfZ = 21.f; // leg axis (x, z) at the bottom
// At the jacket top the legs stand at the deck corners and mid long edges, so they run up as deck
// columns without crossing the module slots.
constexpr float kDeckHalfX = 20.f, kDeckHalfZ = 15.f;
constexpr std::array<float, 3> kDeckLevels{31.f, 39.f, 47.f}; // top of the grating
constexpr float kFrameHalfDepth = 0.3f;                       // primary deck beams
constexpr float kFrameSpacing = 10.f;
constexpr float kSlotSize = 10.f; // modules stand in a 4 × 3 grid of 10 m slots
constexpr int kSlotsX = 4, kSlotsZ = 3;
constexpr float kSlotMargin = 1.f; // keeps 2 m corridors along slot edges free for pipes
constexpr float kSeaSize = 2400.f;

constexpr float kLegRadius = 0.8f;
constexpr float kHorizontalBraceRadius = 0.25f;
constexpr float kDiagonalBraceRadius = 0.2f;

const glm::vec3 kUp{0.f, 1.f, 0.f};

// ---- Colours (CAD-like groups, one mesh each) ----------------------------------------------

const glm::vec3 kSeaColor{0.38f, 0.46f, 0.55f};
const glm::vec3 kSteelColor{0.86f, 0.72f, 0.25f};
const glm::vec3 kFrameColor{0.50f, 0.50f, 0.52f};
const glm::vec3 kGratingColor{0.62f, 0.63f, 0.60f};
const glm::vec3 kPlateColor{0.42f, 0.43f, 0.45f};
const glm::vec3 kModuleColor{0.82f, 0.82f, 0.78f};
const glm::vec3 kHelideckColor{0.30f, 0.45f, 0.35f};
const glm::vec3 kPipeColor{0.85f, 0.35f, 0.15f};
const glm::vec3 kRailingColor{0.95f, 0.80f, 0.10f};
const glm::vec3 kFlareTipColor{0.90f, 0.50f, 0.10f};

// Triangles per MeshBuilder::addBeam.
constexpr size_t kBeamTriangles = 12;

// ---- [SECTION] Detail -----------------------------------------------------------------------

struct Detail {
    int seaCells;
    int legSegments;
    int braceSegments; // braces, truss chords, helideck columns
    int pipeSegments;
    int jacketBays;
    int trussBays;
    int pipeRuns;
    int risers;
    float railPostSpacing;
};

/// Structure detail for a triangle target. Everything scales with q = sqrt(target / 250k) so that
/// the structure stays a modest share (≈ 5–50 %) of the target, leaving the rest to the grating.
Detail detailFor(uint32_t targetTriangles) {
    const float q = std::sqrt(std::max(static_cast<float>(targetTriangles), 1.f) / 250'000.f);
    const auto scaled = [q](float atDefault, int lo, int hi) {
        return std::clamp(static_cast<int>(std::lround(atDefault * q)), lo, hi);
    };
    Detail d{};
    // The sea takes ~2 % of the target: 2 · cells² triangles.
    d.seaCells =
        std::clamp(static_cast<int>(std::lround(std::sqrt(0.01f * static_cast<float>(targetTriangles)))), 8, 256);
    d.legSegments = scaled(24.f, 6, 48);
    d.braceSegments = scaled(12.f, 4, 24);
    d.pipeSegments = scaled(16.f, 5, 32);
    d.jacketBays = std::clamp(static_cast<int>(std::lround(4.f + q)), 4, 7);
    d.trussBays = scaled(12.f, 6, 24);
    d.pipeRuns = scaled(24.f, 6, 60);
    d.risers = scaled(4.f, 2, 8);
    d.railPostSpacing = std::clamp(2.5f / q, 1.2f, 8.f);
    return d;
}

// ---- [SECTION] Small geometry helpers -------------------------------------------------------

/// Axis of jacket leg (ix ∈ {-1, 0, 1}, iz ∈ {-1, 1}) at height y: tapers up to the jacket top,
/// vertical above it (deck columns).
glm::vec3 legPoint(int ix, int iz, float y) {
    const float s = std::clamp((y - kJacketBottom) / (kJacketTop - kJacketBottom), 0.f, 1.f);
    const float hx = kJacketBaseHalfX + (kDeckHalfX - kJacketBaseHalfX) * s;
    const float hz = kJacketBaseHalfZ + (kDeckHalfZ - kJacketBaseHalfZ) * s;
    return {static_cast<float>(ix) * hx, y, static_cast<float>(iz) * hz};
}

/// Height of jacket level `k` of `bays` (level 0 at the bottom, `bays` at the top).
float bayLevel(int k, int bays) {
    return kJacketBottom + (kJacketTop - kJacketBottom) * static_cast<float>(k) / static_cast<float>(bays);
}

/// Two unit vectors perpendicular to the unit vector w.
void perpendicularBasis(const glm::vec3& w, glm::vec3& u, glm::vec3& v) {
    const glm::vec3 helper = std::abs(w.y) < 0.9f ? kUp : glm::vec3(1.f, 0.f, 0.f);
    u = glm::normalize(glm::cross(helper, w));
    v = glm::cross(w, u);
}

/// Square lattice truss from a to b, width tapering from widthA to widthB: four chords
/// (cylinders) and, per bay, a ring of struts and one diagonal per face (thin beams).
void addTruss(MeshBuilder& mb, const glm::vec3& a, const glm::vec3& b, float widthA, float widthB, int bays,
              int segments) {
    glm::vec3 u, v;
    perpendicularBasis(glm::normalize(b - a), u, v);
    const std::array<glm::vec2, 4> corners{glm::vec2(1, 1), glm::vec2(-1, 1), glm::vec2(-1, -1), glm::vec2(1, -1)};
    const auto corner = [&](int k, int bay) {
        const float t = static_cast<float>(bay) / static_cast<float>(bays);
        const float half = 0.5f * (widthA + (widthB - widthA) * t);
        const glm::vec2 c = corners[static_cast<size_t>(k % 4)];
        return a + t * (b - a) + half * (c.x * u + c.y * v);
    };
    constexpr float chordRadius = 0.15f, strutHalfWidth = 0.05f;
    for (int k = 0; k < 4; ++k) mb.addBeam(corner(k, 0), corner(k + 1, 0), strutHalfWidth);
    for (int bay = 0; bay < bays; ++bay)
        for (int k = 0; k < 4; ++k) {
            mb.addCylinder(corner(k, bay), corner(k, bay + 1), chordRadius, segments, false);
            mb.addBeam(corner(k, bay + 1), corner(k + 1, bay + 1), strutHalfWidth);
            // Alternating diagonals give the N-pattern of a welded truss.
            if (bay % 2 == 0) mb.addBeam(corner(k, bay), corner(k + 1, bay + 1), strutHalfWidth);
            else mb.addBeam(corner(k + 1, bay), corner(k, bay + 1), strutHalfWidth);
        }
}

// ---- [SECTION] Jacket and deck columns ------------------------------------------------------

struct LegPair {
    int ix0, iz0, ix1, iz1;
};

/// Braced panels between legs: two long faces of two panels each, three transverse frames.
constexpr std::array<LegPair, 7> kJacketPanels{
    {{-1, -1, 0, -1}, {0, -1, 1, -1}, {-1, 1, 0, 1}, {0, 1, 1, 1}, {-1, -1, -1, 1}, {0, -1, 0, 1}, {1, -1, 1, 1}}};

void addJacket(MeshBuilder& steel, const Detail& d) {
    const int bays = d.jacketBays;
    for (int bay = 0; bay < bays; ++bay) {
        const float y0 = bayLevel(bay, bays), y1 = bayLevel(bay + 1, bays);
        // Legs per bay (open ends: the bays join up) keep chunks local.
        for (int ix = -1; ix <= 1; ++ix)
            for (int iz = -1; iz <= 1; iz += 2)
                steel.addCylinder(legPoint(ix, iz, y0), legPoint(ix, iz, y1), kLegRadius, d.legSegments, false);
        // Horizontal at the bay top and an X of diagonals in every face panel.
        for (const LegPair& p : kJacketPanels) {
            const glm::vec3 a0 = legPoint(p.ix0, p.iz0, y0), a1 = legPoint(p.ix0, p.iz0, y1);
            const glm::vec3 b0 = legPoint(p.ix1, p.iz1, y0), b1 = legPoint(p.ix1, p.iz1, y1);
            steel.addCylinder(a1, b1, kHorizontalBraceRadius, d.braceSegments);
            steel.addCylinder(a0, b1, kDiagonalBraceRadius, d.braceSegments);
            steel.addCylinder(b0, a1, kDiagonalBraceRadius, d.braceSegments);
        }
        // Plan bracing: an X across each of the two plan bays at the bay top.
        for (int ix = -1; ix <= 0; ++ix) {
            steel.addCylinder(legPoint(ix, -1, y1), legPoint(ix + 1, 1, y1), kDiagonalBraceRadius, d.braceSegments);
            steel.addCylinder(legPoint(ix + 1, -1, y1), legPoint(ix, 1, y1), kDiagonalBraceRadius, d.braceSegments);
        }
    }
    // Deck columns continue the legs up to the top deck's frame; capped, as the grating is open.
    const float columnTop = kDeckLevels.back() - 2.f * kFrameHalfDepth;
    for (int ix = -1; ix <= 1; ++ix)
        for (int iz = -1; iz <= 1; iz += 2)
            steel.addCylinder(legPoint(ix, iz, kJacketTop), legPoint(ix, iz, columnTop), kLegRadius, d.legSegments);
}

// ---- [SECTION] Decks ------------------------------------------------------------------------

/// Primary beams on a 10 m grid under the grating, one beam per grid edge.
void addDeckFrame(MeshBuilder& frame, float deckY) {
    const float y = deckY - kFrameHalfDepth - 0.05f;
    const int nx = static_cast<int>(2.f * kDeckHalfX / kFrameSpacing),
              nz = static_cast<int>(2.f * kDeckHalfZ / kFrameSpacing);
    const auto px = [](int i) { return -kDeckHalfX + kFrameSpacing * static_cast<float>(i); };
    const auto pz = [](int j) { return -kDeckHalfZ + kFrameSpacing * static_cast<float>(j); };
    for (int j = 0; j <= nz; ++j)
        for (int i = 0; i < nx; ++i) frame.addBeam({px(i), y, pz(j)}, {px(i + 1), y, pz(j)}, kFrameHalfDepth);
    for (int i = 0; i <= nx; ++i)
        for (int j = 0; j < nz; ++j) frame.addBeam({px(i), y, pz(j)}, {px(i), y, pz(j + 1)}, kFrameHalfDepth);
}

struct GratingSize {
    int bearingBars; // along x, spaced across z
    int crossBars;   // along z, spaced across x
};

/// Beams in one deck's grating: every bar is split where the other family crosses it.
size_t gratingBeams(const GratingSize& g) {
    const size_t nb = static_cast<size_t>(g.bearingBars), nc = static_cast<size_t>(g.crossBars);
    return nb * (nc + 1) + nc * (nb + 1);
}

/// The grating whose triangles over all decks come closest to `budget`. Cross bars are kept at
/// about twice the bearing-bar pitch, as in real pressed grating.
GratingSize solveGrating(size_t budget) {
    const float crossPerBearing = (2.f * kDeckHalfX) / (2.f * (2.f * kDeckHalfZ)); // pitch ratio 2
    const size_t perBeam = kDeckLevels.size() * kBeamTriangles;                    // every deck has the same grating
    GratingSize best{2, 2};
    size_t bestError = std::numeric_limits<size_t>::max();
    for (int nb = 2;; ++nb) {
        const int ncIdeal = std::max(2, static_cast<int>(std::lround(crossPerBearing * static_cast<float>(nb))));
        bool allAbove = true;
        for (int nc = std::max(2, ncIdeal - 1); nc <= ncIdeal + 1; ++nc) {
            const size_t tris = perBeam * gratingBeams({nb, nc});
            const size_t error = tris > budget ? tris - budget : budget - tris;
            if (error < bestError) {
                best = {nb, nc};
                bestError = error;
            }
            allAbove = allAbove && tris > budget;
        }
        if (allAbove) return best; // counts only grow with nb
    }
}

/// Grating over the whole deck, top face at deckY. Bars get thinner as the grating gets finer so
/// that it stays mostly open.
void addGrating(MeshBuilder& grating, float deckY, const GratingSize& g) {
    const float pitchZ = 2.f * kDeckHalfZ / static_cast<float>(g.bearingBars);
    const float pitchX = 2.f * kDeckHalfX / static_cast<float>(g.crossBars);
    const float hw = std::clamp(0.08f * std::min(pitchX, pitchZ), 0.012f, 0.05f);
    const float y = deckY - hw;
    // Bar positions, with the deck edges as the outer break points.
    std::vector<float> xs{-kDeckHalfX}, zs{-kDeckHalfZ};
    for (int j = 0; j < g.crossBars; ++j) xs.push_back(-kDeckHalfX + (static_cast<float>(j) + 0.5f) * pitchX);
    for (int i = 0; i < g.bearingBars; ++i) zs.push_back(-kDeckHalfZ + (static_cast<float>(i) + 0.5f) * pitchZ);
    xs.push_back(kDeckHalfX);
    zs.push_back(kDeckHalfZ);
    for (size_t i = 1; i + 1 < zs.size(); ++i) // bearing bars
        for (size_t j = 0; j + 1 < xs.size(); ++j) grating.addBeam({xs[j], y, zs[i]}, {xs[j + 1], y, zs[i]}, hw);
    for (size_t j = 1; j + 1 < xs.size(); ++j) // cross bars
        for (size_t i = 0; i + 1 < zs.size(); ++i) grating.addBeam({xs[j], y, zs[i]}, {xs[j], y, zs[i + 1]}, hw);
}

/// Posts and two continuous rails along each deck edge.
void addRailings(MeshBuilder& rails, float deckY, const Detail& d) {
    constexpr float inset = 0.1f, midRail = 0.55f, topRail = 1.1f;
    const float hx = kDeckHalfX - inset, hz = kDeckHalfZ - inset;
    const std::array<glm::vec3, 4> corners{glm::vec3(-hx, deckY, -hz), glm::vec3(hx, deckY, -hz),
                                           glm::vec3(hx, deckY, hz), glm::vec3(-hx, deckY, hz)};
    for (size_t s = 0; s < 4; ++s) {
        const glm::vec3 a = corners[s], b = corners[(s + 1) % 4];
        const int posts = std::max(1, static_cast<int>(std::ceil(glm::length(b - a) / d.railPostSpacing)));
        for (int k = 0; k < posts; ++k) { // the next side places this side's end post
            const glm::vec3 p = a + (b - a) * (static_cast<float>(k) / static_cast<float>(posts));
            rails.addBeam(p, p + glm::vec3(0.f, topRail, 0.f), 0.03f);
        }
        for (float h : {midRail, topRail})
            rails.addBeam(a + glm::vec3(0.f, h, 0.f), b + glm::vec3(0.f, h, 0.f), 0.025f);
    }
}

struct Slot {
    int ix, iz;
};

/// Process modules (boxes on deck plates) in random free slots; the cellar deck gets some plated
/// laydown areas as well.
void addModules(Rng& rng, MeshBuilder& modules, MeshBuilder& plates, size_t deck, const std::vector<Slot>& reserved) {
    const float deckY = kDeckLevels[deck];
    const bool top = deck + 1 == kDeckLevels.size();
    const float maxHeight = top ? 8.f : 6.f; // lower decks: clear of the deck frame above
    for (int iz = 0; iz < kSlotsZ; ++iz)
        for (int ix = 0; ix < kSlotsX; ++ix) {
            const bool isReserved =
                std::any_of(reserved.begin(), reserved.end(), [&](const Slot& s) { return s.ix == ix && s.iz == iz; });
            if (isReserved) continue;
            const float x0 = -kDeckHalfX + kSlotSize * static_cast<float>(ix);
            const float z0 = -kDeckHalfZ + kSlotSize * static_cast<float>(iz);
            if (!rng.chance(60)) {
                if (deck == 0 && rng.chance(50))
                    plates.addBox({x0 + 0.5f * kSlotSize, deckY - 0.03f, z0 + 0.5f * kSlotSize}, {4.f, 0.05f, 4.f});
                continue;
            }
            const float hx = rng.uniform(2.5f, 4.f), hz = rng.uniform(2.5f, 4.f);
            const float h = rng.uniform(3.f, maxHeight);
            const float cx = rng.uniform(x0 + kSlotMargin + hx, x0 + kSlotSize - kSlotMargin - hx);
            const float cz = rng.uniform(z0 + kSlotMargin + hz, z0 + kSlotSize - kSlotMargin - hz);
            // The plate's top sits 2 cm above the grating so the two never z-fight.
            plates.addBox({cx, deckY - 0.03f, cz}, {hx + 0.6f, 0.05f, hz + 0.6f});
            modules.addBox({cx, deckY + 0.02f + 0.5f * h, cz}, {hx, 0.5f * h, hz});
        }
}

// ---- [SECTION] Pipes ------------------------------------------------------------------------

/// A run along a pipe corridor (slot edges are kept free): along x, an elbow into z out to the
/// deck edge, and sometimes a drop there to the deck below. Short posts carry it above the deck.
void addPipeRun(Rng& rng, MeshBuilder& pipes, MeshBuilder& supports, size_t deck, int segments) {
    const float deckY = kDeckLevels[deck];
    const float r = rng.uniform(0.08f, 0.3f);
    const float y = deckY + rng.uniform(0.5f, 2.2f);
    const float laneZ = (rng.chance(50) ? -5.f : 5.f) + rng.uniform(-0.6f, 0.6f);
    const float x0 = -kDeckHalfX + kSlotSize * static_cast<float>(rng.below(2));
    const float laneX = -kDeckHalfX + kSlotSize * static_cast<float>(2 + rng.below(2)) + rng.uniform(-0.6f, 0.6f);
    const float z1 = rng.chance(50) ? -kDeckHalfZ : kDeckHalfZ;
    const glm::vec3 p0{x0, y, laneZ}, p1{laneX, y, laneZ}, p2{laneX, y, z1};
    pipes.addCylinder(p0, p1, r, segments);
    pipes.addCylinder(p1, p2, r, segments);
    for (float x = x0 + 3.f; x < laneX - 1.f; x += 6.f) supports.addBeam({x, deckY, laneZ}, {x, y - r, laneZ}, 0.05f);
    if (deck > 0 && rng.chance(30)) {
        const glm::vec3 p3 = p2 - glm::vec3(0.f, kDeckLevels[deck] - kDeckLevels[deck - 1], 0.f);
        pipes.addCylinder(p2, p3, r, segments);
    }
}

/// Risers: pipes up from the sea alongside a leg, clamped to it at every bay level.
void addRiser(Rng& rng, MeshBuilder& pipes, MeshBuilder& clamps, const Detail& d) {
    const int ix = rng.below(3) - 1, iz = rng.chance(50) ? -1 : 1;
    // Outboard of the leg, in plan: along z for all legs, so risers hang outside the long faces.
    const glm::vec3 offset{0.f, 0.f, static_cast<float>(iz) * 1.6f + rng.uniform(-0.2f, 0.2f)};
    const float r = rng.uniform(0.2f, 0.35f);
    const glm::vec3 bottom = legPoint(ix, iz, kJacketBottom) + offset, top = legPoint(ix, iz, kJacketTop) + offset;
    const glm::vec3 head = top + glm::vec3(0.f, kDeckLevels[0] + 1.f - kJacketTop, 0.f);
    pipes.addCylinder(bottom, top, r, d.pipeSegments);
    pipes.addCylinder(top, head, r, d.pipeSegments);
    pipes.addCylinder(head, head - glm::vec3(0.f, 0.f, static_cast<float>(iz) * 4.f), r, d.pipeSegments);
    for (int bay = 1; bay <= d.jacketBays; ++bay) {
        const float y = bayLevel(bay, d.jacketBays) - 0.5f;
        clamps.addBeam(legPoint(ix, iz, y), legPoint(ix, iz, y) + offset, 0.08f);
    }
}

// ---- [SECTION] Top-deck equipment -----------------------------------------------------------

/// Raised helideck over the -x/-z corner: a plate on a beam grid on four columns, which stand
/// inside the corner slot, clear of the pipe corridors.
void addHelideck(MeshBuilder& helideck, MeshBuilder& steel, const Detail& d) {
    constexpr float cx = -14.75f, cz = -9.75f, half = 10.f, plateY = 52.5f, columnOffset = 3.25f;
    const float deckY = kDeckLevels.back();
    helideck.addBox({cx, plateY, cz}, {half, 0.15f, half});
    for (int k = -2; k <= 2; ++k) {
        const float o = 0.5f * half * static_cast<float>(k);
        steel.addBeam({cx - half, plateY - 0.4f, cz + o}, {cx + half, plateY - 0.4f, cz + o}, 0.2f);
        steel.addBeam({cx + o, plateY - 0.4f, cz - half}, {cx + o, plateY - 0.4f, cz + half}, 0.2f);
    }
    for (float sx : {-columnOffset, columnOffset})
        for (float sz : {-columnOffset, columnOffset})
            steel.addCylinder({cx + sx, deckY, cz + sz}, {cx + sx, plateY - 0.6f, cz + sz}, 0.35f, d.braceSegments);
}

/// Crane at +x/+z: pedestal, cab, and a lattice boom reaching out over the sea.
void addCrane(MeshBuilder& steel, MeshBuilder& modules, const Detail& d) {
    const glm::vec3 base{15.f, kDeckLevels.back(), 10.f};
    const glm::vec3 pedestalTop = base + glm::vec3(0.f, 7.f, 0.f);
    steel.addCylinder(base, pedestalTop, 1.5f, d.legSegments);
    modules.addBox(pedestalTop + glm::vec3(0.f, 1.5f, 0.f), {2.f, 1.5f, 2.5f});
    const glm::vec3 heel = pedestalTop + glm::vec3(0.f, 1.f, 2.5f);
    const glm::vec3 tip = heel + 30.f * glm::normalize(glm::vec3(-0.2f, 0.45f, 1.f));
    addTruss(steel, heel, tip, 1.6f, 0.8f, std::max(4, d.trussBays / 2), d.braceSegments);
}

/// Flare boom: a ~50 m lattice truss leaning out 30° from the +x/-z corner, a flare line along
/// it, and the flare tip at its end.
void addFlareBoom(MeshBuilder& steel, MeshBuilder& pipes, MeshBuilder& flareTip, const Detail& d) {
    const glm::vec3 base{17.f, kDeckLevels.back() + 0.5f, -12.f};
    const glm::vec3 heading = glm::normalize(glm::vec3(1.f, 0.f, -0.6f));
    const float elevation = glm::radians(30.f);
    const glm::vec3 dir = std::cos(elevation) * heading + std::sin(elevation) * kUp;
    const glm::vec3 end = base + 50.f * dir;
    addTruss(steel, base, end, 3.f, 1.2f, d.trussBays, d.braceSegments);
    pipes.addCylinder(base, end, 0.3f, d.pipeSegments);
    steel.addBox(end + glm::vec3(0.f, 0.2f, 0.f), {1.5f, 0.2f, 1.5f}); // tip platform
    flareTip.addCylinder(end + glm::vec3(0.f, 0.4f, 0.f), end + glm::vec3(0.f, 4.f, 0.f), 0.6f, d.pipeSegments);
}

// ---- [SECTION] Camera and light -------------------------------------------------------------

/// Standing on the top deck near its -x/+z corner, looking along the deck (15° to the left of
/// the +z edge, 6° down): railings, pipes and grating close by, the lower decks through the
/// grating, helideck, crane and flare boom further off, and the sea out to the horizon.
Camera defaultCamera() {
    Camera c;
    c.eye = {-17.f, kDeckLevels.back() + 1.7f, 12.5f};
    c.target = {21.5f, kDeckLevels.back() - 2.5f, 2.f};
    c.fovYDeg = 60.f;
    c.near = 0.5f;
    c.far = 2000.f;
    return c;
}

/// Sun at ~49° elevation, ahead and to the left of the default view (~110° between view and
/// light): shadows of pipes, railings and modules fall across the deck towards the camera,
/// and the lower decks seen through the grating are dappled by the grating above.
Light defaultLight() {
    Light l;
    l.direction = {-0.55f, -0.75f, -0.35f};
    return l;
}

} // namespace

// ---- [SECTION] Building the scene -----------------------------------------------------------

Scene makePlatformScene(const PlatformParams& params) {
    const Detail d = detailFor(params.targetTriangles);
    Rng rng(params.seed);

    MeshBuilder sea("sea", kSeaColor);
    MeshBuilder steel("steel", kSteelColor);
    MeshBuilder frame("deck_frame", kFrameColor);
    MeshBuilder plates("deck_plates", kPlateColor);
    MeshBuilder modules("modules", kModuleColor);
    MeshBuilder helideck("helideck", kHelideckColor);
    MeshBuilder pipes("pipes", kPipeColor);
    MeshBuilder railings("railings", kRailingColor);
    MeshBuilder flareTip("flare_tip", kFlareTipColor);
    MeshBuilder grating("grating", kGratingColor);

    sea.addGroundGrid({0.f, 0.f, 0.f}, kSeaSize, d.seaCells);
    addJacket(steel, d);
    // Top deck slots kept free: under the helideck, the camera's corner and the view from it,
    // the crane, the flare boom's base.
    const std::vector<Slot> topReserved{{0, 0}, {1, 0}, {0, 1}, {1, 1}, {0, 2}, {1, 2}, {3, 2}, {3, 0}};
    for (size_t deck = 0; deck < kDeckLevels.size(); ++deck) {
        addDeckFrame(frame, kDeckLevels[deck]);
        addRailings(railings, kDeckLevels[deck], d);
        addModules(rng, modules, plates, deck, deck + 1 == kDeckLevels.size() ? topReserved : std::vector<Slot>{});
    }
    for (int i = 0; i < d.pipeRuns; ++i)
        addPipeRun(rng, pipes, steel, static_cast<size_t>(i) % kDeckLevels.size(), d.pipeSegments);
    for (int i = 0; i < d.risers; ++i) addRiser(rng, pipes, steel, d);
    addHelideck(helideck, steel, d);
    addCrane(steel, modules, d);
    addFlareBoom(steel, pipes, flareTip, d);

    // The grating takes what is left of the budget.
    std::array<MeshBuilder*, 9> structure{&sea,      &steel, &frame,    &plates,  &modules,
                                          &helideck, &pipes, &railings, &flareTip};
    size_t used = 0;
    for (const MeshBuilder* mb : structure) used += mb->triangleCount();
    const size_t target = params.targetTriangles;
    const GratingSize g = solveGrating(target > used ? target - used : 0);
    for (float deckY : kDeckLevels) addGrating(grating, deckY, g);

    Scene scene;
    scene.name = "platform";
    for (MeshBuilder* mb : structure) scene.meshes.push_back(mb->build());
    scene.meshes.push_back(grating.build());
    scene.camera = defaultCamera();
    scene.lights[0] = defaultLight();
    return scene;
}

} // namespace geometry::scene
