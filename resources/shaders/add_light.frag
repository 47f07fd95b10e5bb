#version 430 core
// Several lights: one light's shadowed direct term, added (blend ONE, ONE) into the lights' sum in
// linear colour (docs/design.md §3.10); compose.frag adds the sum to the last light's terms.
in vec2 vUv;
uniform sampler2D uDirect; // rgb: albedo · (1 − ambient) · N·L of this light
uniform sampler2D uMask;   // r: this light's shadow factor
layout(location = 0) out vec4 oColor;
void main() { oColor = vec4(texture(uDirect, vUv).rgb * texture(uMask, vUv).r, 0.0); }
