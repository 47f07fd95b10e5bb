// technique = virtual (docs/design.md §3.11): the virtual map as page_mark.comp, the eye pass and the
// light view read it. Plane coordinates are taken relative to the eye (uVEye), so they keep their
// precision far from the world's origin; level k's square starts at uVOrigin[k] in them.
uniform vec3 uVEye, uVRight, uVUp, uVLight;
uniform vec2 uVOrigin[16];
uniform float uVTexel0;   // level 0's texel, world units; level k's is 2^k times wider
uniform int uVLevels, uVPagesPerSide, uVPageSize;
uniform float uVDepthLo, uVDepthScale; // page depth = (l·x − lo) · scale
uniform int uVColumns;                 // physical pages a row of the atlas

vec2 vPlane(vec3 x) {
    vec3 r = x - uVEye;
    return vec2(dot(r, uVRight), dot(r, uVUp));
}
float vTexel(int k) { return uVTexel0 * exp2(float(k)); }
float vPageDepth(vec3 x) { return (dot(x, uVLight) - uVDepthLo) * uVDepthScale; }

/// The smallest of the pixel's footprints across the light (σ_min of the screen → light-plane
/// Jacobian, world units): texels no wider than it keep m ≤ 1 in every direction.
float vFootprint(vec3 dPdx, vec3 dPdy) {
    vec2 a = vec2(dot(dPdx, uVRight), dot(dPdx, uVUp)), b = vec2(dot(dPdy, uVRight), dot(dPdy, uVUp));
    float s = dot(a, a) + dot(b, b), det = a.x * b.y - a.y * b.x;
    return sqrt(max(0.5 * (s - sqrt(max(s * s - 4.0 * det * det, 0.0))), 0.0));
}

/// The coarsest level whose texels are no wider than `footprint` (levelFor in virtual_pages.h).
int vLevelFor(float footprint) {
    int k = 0;
    while (k + 1 < uVLevels && vTexel(k + 1) <= footprint) ++k;
    return k;
}

/// Page (x, y) of level k's square holding plane point s; outside the square when any is out of 0..pps−1.
ivec2 vPageOf(vec2 s, int k) { return ivec2(floor((s - uVOrigin[k]) / (vTexel(k) * float(uVPageSize)))); }
bool vInSquare(ivec2 page) { return all(greaterThanEqual(page, ivec2(0))) && all(lessThan(page, ivec2(uVPagesPerSide))); }

/// Where texel t (0..pageSize−1 each way) of the page a table entry names (physical page + 1) lies in
/// the atlas.
ivec2 vAtlasTexel(uint entry, ivec2 t) {
    uint physical = entry - 1u;
    return ivec2(int(physical % uint(uVColumns)), int(physical / uint(uVColumns))) * uVPageSize + t;
}
