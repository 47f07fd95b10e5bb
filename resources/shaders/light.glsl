// The light as the shaders see it (docs/design.md §3.10); include after shadow_block.glsl.
// A directional light shines along shadow.lightDir everywhere; a spot or point light from
// shadow.lightPos, so l, linear depth and the map depend on the point.

bool positionalLight() { return shadow.lightType != LIGHT_DIRECTIONAL; }

/// l(x): the unit direction light travels to reach x.
vec3 lightDirAt(vec3 x) {
    if (!positionalLight()) return shadow.lightDir;
    vec3 d = x - shadow.lightPos;
    float len = length(d);
    return len > 0.0 ? d / len : shadow.lightDir;
}

/// What linear light depth measures: l·x for a directional light, the distance from a positional one.
float lightDistance(vec3 x) { return positionalLight() ? length(x - shadow.lightPos) : dot(x, shadow.lightDir); }

/// How much of the light reaches x (before shadowing and N·L): 1 for a directional light; a spot's cone
/// with a smooth edge; positional lights fade out over the last part of their range (Karis 2013's window).
float lightReach(vec3 x) {
    if (!positionalLight()) return 1.0;
    vec3 d = x - shadow.lightPos;
    float len = length(d);
    float r = len / max(shadow.lightRange, 1e-6);
    float window = clamp(1.0 - r * r * r * r, 0.0, 1.0);
    float reach = window * window;
    if (shadow.lightType == LIGHT_SPOT) {
        float c = len > 0.0 ? dot(d / len, shadow.lightDir) : 1.0;
        reach *= smoothstep(shadow.spotCosOuter, shadow.spotCosInner, c);
    }
    return reach;
}

/// The map a point's shadow is read from: a point light's cube face (the major axis of x − position,
/// +X, −X, +Y, −Y, +Z, −Z; geometry/shadow/positional_plan.h), a spot light's one map, or a directional
/// light's split by view depth.
int mapOf(vec3 x, float viewDepth) {
    if (shadow.lightType == LIGHT_SPOT) return 0;
    if (shadow.lightType == LIGHT_POINT) {
        vec3 d = x - shadow.lightPos, a = abs(d);
        if (a.x >= a.y && a.x >= a.z) return d.x >= 0.0 ? 0 : 1;
        if (a.y >= a.z) return d.y >= 0.0 ? 2 : 3;
        return d.z >= 0.0 ? 4 : 5;
    }
    int split = 0;
    while (split < shadow.splitCount - 1 && viewDepth > shadow.splits[split].splitFar) ++split;
    return split;
}

/// tan of the light's angular radius seen from `distance` away: the sun's, or a positional emitter's.
float lightTanHalfAngle(float distance) {
    return positionalLight() ? shadow.lightRadius / max(distance, 1e-4) : shadow.sunTanHalfAngle;
}
