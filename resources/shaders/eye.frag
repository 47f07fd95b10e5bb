#version 430 core
// Eye pass: Lambert + ambient, hard shadow test against the split's depth map.
in vec3 vWorldPos;
in vec3 vNormal;
uniform vec3 uColor;
uniform vec3 uLightDir;           // l: from the light into the scene
uniform sampler2DArray uShadowMap;
uniform mat4 uLightViewProj[8];
uniform float uReceiverOffset;    // constant bias: receiver moved towards the light, scene units
uniform float uSplitFar[8];
uniform float uMapScale[8];      // split resolution / array resolution (per-split falloff)
uniform int uSplitCount;
uniform vec3 uEye;
uniform vec3 uViewDir;
layout(location = 0) out vec4 oColor;

const float kAmbient = 0.28;

float shadowFactor(vec3 worldPos) {
    float viewDepth = dot(worldPos - uEye, uViewDir);
    int split = 0;
    while (split < uSplitCount - 1 && viewDepth > uSplitFar[split]) ++split;
    vec4 clip = uLightViewProj[split] * vec4(worldPos - uLightDir * uReceiverOffset, 1.0);
    vec3 p = clip.xyz / clip.w * 0.5 + 0.5;
    if (any(lessThan(p, vec3(0.0))) || any(greaterThan(p, vec3(1.0)))) return 1.0;
    float stored = texture(uShadowMap, vec3(p.xy * uMapScale[split], float(split))).r;
    return p.z > stored ? 0.0 : 1.0;
}

void main() {
    vec3 n = normalize(vNormal);
    if (!gl_FrontFacing) n = -n; // CAD surfaces are seen from both sides
    float ndotl = max(dot(n, -uLightDir), 0.0);
    float s = ndotl > 0.0 ? shadowFactor(vWorldPos) : 0.0;
    vec3 c = uColor * (kAmbient + (1.0 - kAmbient) * ndotl * s);
    oColor = vec4(pow(c, vec3(1.0 / 2.2)), 1.0);
}
