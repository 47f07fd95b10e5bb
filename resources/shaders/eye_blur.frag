#version 430 core
// Scherzer §4.3: eye-space blur of the shadow mask, wider near the viewer, not across depth edges.
#include "shadow_block.glsl"
in vec2 vUv;
uniform sampler2D uMask;    // r: shadow factor
uniform sampler2D uBase;    // a: view depth
uniform vec2 uStep;         // one pixel along x or y, in uv
layout(location = 0) out vec4 oMask;
void main() {
    float depth = texture(uBase, vUv).a;
    if (depth <= 0.0) { oMask = texture(uMask, vUv); return; } // sky
    float radius = 3.0 / (1.0 + settings.filter_eye_blur_falloff * depth);              // pixels
    float sum = 0.0, weight = 0.0;
    for (int i = -3; i <= 3; ++i) {
        vec2 uv = vUv + uStep * (float(i) * radius / 3.0);
        float d = texture(uBase, uv).a;
        float w = (d > 0.0 && abs(d - depth) < 0.05 * depth) ? 1.0 : 0.0;
        sum += w * texture(uMask, uv).r;
        weight += w;
    }
    oMask = vec4(weight > 0.0 ? sum / weight : texture(uMask, vUv).r);
}
