#version 430 core
// Final eye colour: ambient + direct · shadow factor (+ the other lights' shadowed direct terms),
// gamma encoded.
in vec2 vUv;
uniform sampler2D uBase;    // rgb: albedo · ambient, a: view depth (0 = sky)
uniform sampler2D uDirect;  // rgb: albedo · (1 − ambient) · N·L
uniform sampler2D uMask;    // r: shadow factor s
uniform sampler2D uOtherLights; // rgb: Σ direct · s of the other lights (add_light.frag)
uniform int uAddOtherLights;
uniform vec3 uSky;
layout(location = 0) out vec4 oColor;
void main() {
    vec4 base = texture(uBase, vUv);
    if (base.a <= 0.0) { oColor = vec4(uSky, 1.0); return; } // already display-encoded
    vec3 c = base.rgb + texture(uDirect, vUv).rgb * texture(uMask, vUv).r;
    if (uAddOtherLights != 0) c += texture(uOtherLights, vUv).rgb;
    oColor = vec4(pow(c, vec3(1.0 / 2.2)), 1.0);
}
