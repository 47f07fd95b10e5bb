#version 430 core
// Sample-distribution reduction (docs/design.md §3.7): every pixel of the eye's depth pre-pass that
// hit geometry adds its view depth to the frame's [z_min, z_max], and its world position's extent
// along SAMPLE_DIRECTIONS fixed directions to its log-spaced view-depth bin. Floats are reduced as
// order-preserving uints with atomicMin/atomicMax, first in shared memory per 16x16 tile, then
// once per touched bin in the buffer (geometry/shadow/sample_bounds.h reads it back).
#include "shadow_block.glsl"
layout(local_size_x = 16, local_size_y = 16) in;
layout(binding = 0) uniform sampler2D uDepth;
uniform mat4 uInvViewProj;
uniform mat4 uView;
uniform vec3 uDirections[SAMPLE_DIRECTIONS];
uniform float uLogNear;  // log(n)
uniform float uBinScale; // SAMPLE_BINS / log(f / n)
uniform ivec2 uSize;
const int STRIDE = 1 + 2 * SAMPLE_DIRECTIONS; // count, lo[], hi[]
layout(std430, binding = 0) buffer Reduction { uint zKeys[2]; uint bins[]; } reduction;
shared uint sBins[SAMPLE_BINS * STRIDE];
shared uint sZ[2];

uint orderedKey(float f) {
    uint u = floatBitsToUint(f);
    return (u & 0x80000000u) != 0u ? ~u : (u | 0x80000000u);
}

void main() {
    const uint local = gl_LocalInvocationIndex, threads = gl_WorkGroupSize.x * gl_WorkGroupSize.y;
    for (uint i = local; i < uint(SAMPLE_BINS * STRIDE); i += threads) {
        const uint slot = i % uint(STRIDE);
        sBins[i] = slot == 0u ? 0u : (slot <= uint(SAMPLE_DIRECTIONS) ? 0xFFFFFFFFu : 0u);
    }
    if (local == 0u) sZ[0] = 0xFFFFFFFFu, sZ[1] = 0u;
    barrier();
    const ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (all(lessThan(p, uSize))) {
        const float depth = texelFetch(uDepth, p, 0).r;
        if (depth < 1.0) {
            const vec4 ndc = vec4((vec2(p) + 0.5) / vec2(uSize) * 2.0 - 1.0, depth * 2.0 - 1.0, 1.0);
            const vec4 w = uInvViewProj * ndc;
            const vec3 world = w.xyz / w.w;
            const float z = -(uView * vec4(world, 1.0)).z;
            const int bin = clamp(int(floor((log(max(z, 1e-30)) - uLogNear) * uBinScale)), 0, SAMPLE_BINS - 1);
            const uint base = uint(bin * STRIDE);
            atomicAdd(sBins[base], 1u);
            for (int k = 0; k < SAMPLE_DIRECTIONS; ++k) {
                const uint key = orderedKey(dot(world, uDirections[k]));
                atomicMin(sBins[base + 1u + uint(k)], key);
                atomicMax(sBins[base + 1u + uint(SAMPLE_DIRECTIONS + k)], key);
            }
            atomicMin(sZ[0], orderedKey(z));
            atomicMax(sZ[1], orderedKey(z));
        }
    }
    barrier();
    for (uint b = local; b < uint(SAMPLE_BINS); b += threads) {
        const uint base = b * uint(STRIDE);
        if (sBins[base] == 0u) continue;
        atomicAdd(reduction.bins[base], sBins[base]);
        for (int k = 0; k < SAMPLE_DIRECTIONS; ++k) {
            atomicMin(reduction.bins[base + 1u + uint(k)], sBins[base + 1u + uint(k)]);
            atomicMax(reduction.bins[base + 1u + uint(SAMPLE_DIRECTIONS + k)],
                      sBins[base + 1u + uint(SAMPLE_DIRECTIONS + k)]);
        }
    }
    if (local == 0u && sZ[1] != 0u) {
        atomicMin(reduction.zKeys[0], sZ[0]);
        atomicMax(reduction.zKeys[1], sZ[1]);
    }
}
