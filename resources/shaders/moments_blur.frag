#version 430 core
// Separable box blur of one moments layer (width = filter.kernel texels), for every moment filter:
// vsm, esm, evsm2, evsm4 and msm all filter linearly in their moment space.
#include "shadow_block.glsl"
in vec2 vUv;
uniform sampler2DArray uMoments;
uniform int uSplit;
uniform ivec2 uStep;    // (1, 0) or (0, 1)
layout(location = 0) out vec4 oMoments;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    int radius = settings.filter_kernel / 2;
    ivec2 size = ivec2(round(float(shadow.arrayResolution) * shadow.splits[uSplit].mapScale)); // this split's texels
    vec4 sum = vec4(0.0);
    for (int i = -radius; i <= radius; ++i)
        sum += texelFetch(uMoments, ivec3(clamp(p + i * uStep, ivec2(0), size - 1), uSplit), 0);
    oMoments = sum / float(2 * radius + 1);
}
