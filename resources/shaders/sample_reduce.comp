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
// A pixel's NDC q = (x, y, depth, 1) maps to world h.xyz / h.w with h = inverse(P V) q, so every
// quantity linear in the world point is a ratio of two dot products with q: d_k·x = (D_k·q)/(W·q),
// view depth z = (Z·q)/(W·q). The rows come from the CPU (renderer/sample_reduction.cpp).
uniform vec4 uDirRows[SAMPLE_DIRECTIONS];
uniform vec4 uZRow;
uniform vec4 uWRow;
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
    // Each invocation walks a column of ROWS pixels in runs of one bin, keeping the run's bounds in
    // registers and flushing them to shared memory once per run, outside the pixel loop: on
    // llvmpipe, atomics inside the pixel loop cost every pixel (1280×720: 31.8 → 25.4 ms).
    const ivec2 first = ivec2(gl_GlobalInvocationID.x, gl_GlobalInvocationID.y * ROWS);
    // The column's x is fixed: fold it (and q.w = 1) into each row once; a pixel then costs two
    // multiply-adds per row instead of two matrix products (25.4 → 14.0 ms).
    const float x = (float(first.x) + 0.5) / float(uSize.x) * 2.0 - 1.0;
    float dirBase[SAMPLE_DIRECTIONS];
    for (int k = 0; k < SAMPLE_DIRECTIONS; ++k) dirBase[k] = uDirRows[k].x * x + uDirRows[k].w;
    const float zBase = uZRow.x * x + uZRow.w, wBase = uWRow.x * x + uWRow.w;
    float zLo = 3.4e38, zHi = 0.0;
    int r = 0;
    while (r < ROWS) {
        int current = -1;
        uint count = 0u;
        float lo[SAMPLE_DIRECTIONS], hi[SAMPLE_DIRECTIONS];
        for (int k = 0; k < SAMPLE_DIRECTIONS; ++k) lo[k] = 3.4e38, hi[k] = -3.4e38;
        for (; r < ROWS; ++r) {
            const ivec2 p = first + ivec2(0, r);
            if (any(greaterThanEqual(p, uSize))) {
                r = ROWS;
                break;
            }
            const float depth = texelFetch(uDepth, p, 0).r;
            if (depth >= 1.0) continue;
            const vec2 yz = vec2((float(p.y) + 0.5) / float(uSize.y) * 2.0 - 1.0, depth * 2.0 - 1.0);
            const float invW = 1.0 / (wBase + dot(uWRow.yz, yz));
            const float z = (zBase + dot(uZRow.yz, yz)) * invW;
            const int bin = clamp(int(floor((log(max(z, 1e-30)) - uLogNear) * uBinScale)), 0, SAMPLE_BINS - 1);
            if (current >= 0 && bin != current) break; // this pixel starts the next run
            current = bin;
            ++count;
            for (int k = 0; k < SAMPLE_DIRECTIONS; ++k) {
                const float t = (dirBase[k] + dot(uDirRows[k].yz, yz)) * invW;
                lo[k] = min(lo[k], t);
                hi[k] = max(hi[k], t);
            }
            zLo = min(zLo, z);
            zHi = max(zHi, z);
        }
        if (current >= 0) {
            const uint base = uint(current * STRIDE);
            atomicAdd(sBins[base], count);
            for (int k = 0; k < SAMPLE_DIRECTIONS; ++k) {
                atomicMin(sBins[base + 1u + uint(k)], orderedKey(lo[k]));
                atomicMax(sBins[base + 1u + uint(SAMPLE_DIRECTIONS + k)], orderedKey(hi[k]));
            }
        }
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
