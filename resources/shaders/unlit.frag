#version 430 core
#include "shadow_block.glsl"
#include "light.glsl"
// Unwarped light view: the scene seen from the light, shaded by how squarely it faces the light.
in vec3 vWorldPos;
in vec3 vNormal;
uniform vec3 uColor;
layout(location = 0) out vec4 oColor;
void main() {
    float facing = abs(dot(normalize(vNormal), lightDirAt(vWorldPos)));
    oColor = vec4(uColor * (0.35 + 0.65 * facing), 1.0);
}
