#version 430 core
// Separable box blur of one VSM moments layer (width = filter.kernel texels).
in vec2 vUv;
uniform sampler2DArray uMoments;
uniform int uLayer;
uniform ivec2 uStep;    // (1, 0) or (0, 1)
uniform int uRadius;    // (kernel − 1) / 2
uniform ivec2 uSize;    // texels of this split's map
layout(location = 0) out vec2 oMoments;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec2 sum = vec2(0.0);
    for (int i = -uRadius; i <= uRadius; ++i)
        sum += texelFetch(uMoments, ivec3(clamp(p + i * uStep, ivec2(0), uSize - 1), uLayer), 0).rg;
    oMoments = sum / float(2 * uRadius + 1);
}
