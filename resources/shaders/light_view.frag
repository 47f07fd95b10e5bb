#version 430 core
// The shadow map as the light sees it: depth as grey (near the light bright), empty texels blue.
#include "shadow_block.glsl"
in vec2 vUv;
uniform sampler2DArray uShadowMap;
uniform int uSplit;
uniform vec2 uDepthRange; // visible depth range [black point, white point]
layout(location = 0) out vec4 oColor;
void main() {
    float d = texture(uShadowMap, vec3(vUv * shadow.splits[uSplit].mapScale, float(uSplit))).r;
    if (d >= 1.0) { oColor = vec4(0.08, 0.10, 0.22, 1.0); return; }
    float t = clamp((d - uDepthRange.x) / max(uDepthRange.y - uDepthRange.x, 1e-6), 0.0, 1.0);
    oColor = vec4(vec3(1.0 - t), 1.0);
}
