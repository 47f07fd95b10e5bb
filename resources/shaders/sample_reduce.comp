#version 430 core
// Sample-distribution reduction (docs/design.md §3.7): every pixel of the eye's depth pre-pass that
// hit geometry adds its view depth to the frame's [z_min, z_max], and its world position's extent
// along SAMPLE_DIRECTIONS fixed directions to its log-spaced view-depth bin. Floats are reduced as
// order-preserving uints with atomicMin/atomicMax, first in registers along each invocation's
// column of pixels, then in shared memory per 16 × 128 tile, then once per touched bin in the
// buffer (geometry/shadow/sample_bounds.h reads it back).
#include "shadow_block.glsl"
layout(local_size_x = 16, local_size_y = 16) in;
const int ROWS = 8; // pixels per invocation, down a column: a group covers 16 × 128 pixels
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
    // Each invocation walks a column of ROWS pixels, keeping the bin it is filling in registers
    // and flushing it to shared memory only when the bin changes: neighbouring pixels mostly share
    // a bin, so the shared atomics drop several-fold.
    const ivec2 first = ivec2(gl_GlobalInvocationID.x, gl_GlobalInvocationID.y * ROWS);
    int current = -1;
    uint count = 0u;
    float lo[SAMPLE_DIRECTIONS], hi[SAMPLE_DIRECTIONS];
    float zLo = 3.4e38, zHi = 0.0;
    for (int r = 0; r <= ROWS; ++r) {
        int bin = -1;
        vec3 world = vec3(0.0);
        float z = 0.0;
        const ivec2 p = first + ivec2(0, r);
        if (r < ROWS && all(lessThan(p, uSize))) {
            const float depth = texelFetch(uDepth, p, 0).r;
            if (depth < 1.0) {
                const vec4 ndc = vec4((vec2(p) + 0.5) / vec2(uSize) * 2.0 - 1.0, depth * 2.0 - 1.0, 1.0);
                const vec4 w = uInvViewProj * ndc;
                world = w.xyz / w.w;
                z = -(uView * vec4(world, 1.0)).z;
                bin = clamp(int(floor((log(max(z, 1e-30)) - uLogNear) * uBinScale)), 0, SAMPLE_BINS - 1);
            }
        }
        if (bin != current && current >= 0) { // flush the bin being filled
            const uint base = uint(current * STRIDE);
            atomicAdd(sBins[base], count);
            for (int k = 0; k < SAMPLE_DIRECTIONS; ++k) {
                atomicMin(sBins[base + 1u + uint(k)], orderedKey(lo[k]));
                atomicMax(sBins[base + 1u + uint(SAMPLE_DIRECTIONS + k)], orderedKey(hi[k]));
            }
            current = -1;
        }
        if (bin < 0) continue;
        if (current < 0) {
            current = bin;
            count = 0u;
            for (int k = 0; k < SAMPLE_DIRECTIONS; ++k) lo[k] = 3.4e38, hi[k] = -3.4e38;
        }
        ++count;
        for (int k = 0; k < SAMPLE_DIRECTIONS; ++k) {
            const float t = dot(world, uDirections[k]);
            lo[k] = min(lo[k], t);
            hi[k] = max(hi[k], t);
        }
        zLo = min(zLo, z);
        zHi = max(zHi, z);
    }
    if (zHi > 0.0) {
        atomicMin(sZ[0], orderedKey(zLo));
        atomicMax(sZ[1], orderedKey(zHi));
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
