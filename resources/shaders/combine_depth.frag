#version 430 core
// Midpoint (z1 + z2) / 2 and dual depth z1 + min((z2 − z1) / 2, z_max) from the first two depth
// layers (Barroso Table 1), written as the map's depth.
#include "shadow_block.glsl"
in vec2 vUv;
uniform sampler2DArray uFirst;
uniform sampler2DArray uSecond;
uniform int uSplit;
void main() {
    ivec3 t = ivec3(gl_FragCoord.xy, uSplit);
    float z1 = texelFetch(uFirst, t, 0).r;
    float z2 = texelFetch(uSecond, t, 0).r;
    gl_FragDepth = settings.bias_type == BIAS_DUAL_DEPTH ? z1 + min(0.5 * (z2 - z1), shadow.splits[uSplit].dualDepthCap)
                                                 : 0.5 * (z1 + z2);
}
