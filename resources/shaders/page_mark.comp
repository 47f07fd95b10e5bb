#version 430 core
// technique = virtual: marks the pages the eye's depth pre-pass asks for, one bit per page of every
// level (docs/design.md §3.11). A pixel asks for the page holding it at the level its footprint asks
// (vLevelFor), or at the first coarser level whose square holds it; pixels outside every square are
// counted. The footprint comes from the neighbouring pixels' positions, taking on each axis the side
// whose depth is nearer (a silhouette's far side is another surface).
layout(local_size_x = 16, local_size_y = 16) in;
#include "virtual.glsl"
layout(std430, binding = 0) buffer Marks {
    uint uncovered;
    uint bits[];
};
uniform sampler2D uDepth;
uniform mat4 uNdcToEye; // NDC → world position relative to the eye
uniform ivec2 uSize;

bool sampleAt(ivec2 p, out vec3 x) {
    if (any(lessThan(p, ivec2(0))) || any(greaterThanEqual(p, uSize))) return false;
    float d = texelFetch(uDepth, p, 0).r;
    if (d >= 1.0) return false; // sky
    vec4 h = uNdcToEye * vec4((vec2(p) + 0.5) / vec2(uSize) * 2.0 - 1.0, d * 2.0 - 1.0, 1.0);
    x = h.xyz / h.w;
    return true;
}

/// The position step to the neighbour along `o`: the nearer of the two sides, or the one there is.
vec3 neighbourStep(ivec2 p, ivec2 o, vec3 x) {
    vec3 a, b;
    bool hasA = sampleAt(p + o, a), hasB = sampleAt(p - o, b);
    if (hasA && hasB) return length(a - x) <= length(x - b) ? a - x : x - b;
    if (hasA) return a - x;
    if (hasB) return x - b;
    return vec3(0.0);
}

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    vec3 x;
    if (!sampleAt(p, x)) return;
    float footprint = vFootprint(neighbourStep(p, ivec2(1, 0), x), neighbourStep(p, ivec2(0, 1), x));
    vec2 s = vec2(dot(x, uVRight), dot(x, uVUp)); // x is relative to the eye already
    for (int k = vLevelFor(footprint); k < uVLevels; ++k) {
        ivec2 page = vPageOf(s, k);
        if (!vInSquare(page)) continue;
        uint index = uint((k * uVPagesPerSide + page.y) * uVPagesPerSide + page.x);
        uint bit = 1u << (index & 31u);
        if ((bits[index >> 5] & bit) == 0u) atomicOr(bits[index >> 5], bit);
        return;
    }
    atomicAdd(uncovered, 1u);
}
