// Moment shadow maps, shared by the moments pass (depth.frag, MOMENTS) and the eye pass: what each
// moment filter stores for a linear light depth z in [0,1], and the lit fraction it reads back from
// blurred moments (docs/filters.md). Include after shadow_block.glsl.

/// EVSM's two warps of z (Lauritzen & McCool 2008): z to [-1,1], then exp(c+ w) and -exp(-c- w).
vec2 evsmWarp(float z) {
    float w = 2.0 * z - 1.0;
    return vec2(exp(settings.filter_evsm_positive_exponent * w), -exp(-settings.filter_evsm_negative_exponent * w));
}

/// What the moments pass writes for linear depth z.
vec4 momentsOf(float z) {
    if (settings.filter_type == FILTER_ESM) return vec4(exp(settings.filter_esm_exponent * z), 0.0, 0.0, 0.0);
    if (settings.filter_type == FILTER_EVSM2 || settings.filter_type == FILTER_EVSM4) {
        vec2 w = evsmWarp(z);
        return vec4(w.x, w.x * w.x, w.y, w.y * w.y);
    }
    float z2 = z * z;
    if (settings.filter_type == FILTER_MSM) return vec4(z, z2, z2 * z, z2 * z2); // Hamburger: 4 power moments
    return vec4(z, z2, 0.0, 0.0);
}

/// Light-bleeding reduction: lit fractions below filter.bleed_reduction become 0, the rest rescale.
float reduceBleeding(float lit) {
    return clamp((lit - settings.filter_bleed_reduction) / (1.0 - settings.filter_bleed_reduction), 0.0, 1.0);
}

/// Chebyshev's one-sided upper bound on the lit fraction for a receiver at t, given the mean and
/// mean square of the occluders' depth (Donnelly & Lauritzen 2006).
float chebyshevUpperBound(vec2 m, float t, float minVariance) {
    if (t <= m.x) return 1.0;
    float variance = max(m.y - m.x * m.x, minVariance);
    float d = t - m.x;
    return variance / (variance + d * d);
}

/// ESM (Annen et al. 2008): E[exp(c z_o)] exp(-c z), the filtered exp(c (z_o - z)).
float esmLit(vec4 m, float z) { return clamp(m.x * exp(-settings.filter_esm_exponent * z), 0.0, 1.0); }

/// EVSM: Chebyshev on each warp, the smaller bound. The variance floor follows the warp's slope, so
/// it is the same small depth tolerance (~1e-4 of the range) at every depth.
float evsmLit(vec4 m, float z, bool four) {
    vec2 w = evsmWarp(z);
    vec2 floorDepth = 1e-4 * vec2(settings.filter_evsm_positive_exponent, settings.filter_evsm_negative_exponent) * w;
    float lit = chebyshevUpperBound(m.xy, w.x, floorDepth.x * floorDepth.x);
    if (four) lit = min(lit, chebyshevUpperBound(m.zw, w.y, floorDepth.y * floorDepth.y));
    return reduceBleeding(lit);
}

/// Hamburger four-moment shadow map (Peters & Klein 2015, algorithm 3): the moments, pulled towards
/// (0.5, 0.5, 0.5, 0.5) by alpha, bound the occluders' depth distribution; the lit fraction is one
/// minus the least shadow any distribution with these moments can cast on z.
float msmLit(vec4 moments, float z) {
    vec4 b = mix(moments, vec4(0.5), settings.filter_msm_moment_bias);
    // Solve B c = (1, z, z^2) for the Hankel matrix B = [1 b1 b2; b1 b2 b3; b2 b3 b4] by LDL^T.
    float d22 = b.y - b.x * b.x;
    float l32 = (b.z - b.x * b.y) / d22;
    float d33 = b.w - b.y * b.y - l32 * l32 * d22;
    float y2 = z - b.x;
    float y3 = z * z - b.y - l32 * y2;
    y2 /= d22;
    y3 /= d33;
    float c3 = y3;
    float c2 = y2 - l32 * c3;
    float c1 = 1.0 - b.x * c2 - b.y * c3;
    // The other two support points: the roots of c1 + c2 x + c3 x^2.
    float p = c2 / c3, q = c1 / c3;
    float r = sqrt(max(0.25 * p * p - q, 0.0));
    float z2 = -0.5 * p - r, z3 = -0.5 * p + r;
    float shadowed;
    if (z <= z2) shadowed = 0.0;
    else if (z <= z3) shadowed = (z * z3 - b.x * (z + z3) + b.y) / ((z3 - z2) * (z - z2));
    else shadowed = 1.0 - (z2 * z3 - b.x * (z2 + z3) + b.y) / ((z - z2) * (z - z3));
    return reduceBleeding(1.0 - clamp(shadowed, 0.0, 1.0));
}

/// The lit fraction of a receiver at linear depth z from blurred moments m, for the current filter.
float momentLit(vec4 m, float z) {
    if (settings.filter_type == FILTER_VSM) return reduceBleeding(chebyshevUpperBound(m.xy, z, 1e-7));
    if (settings.filter_type == FILTER_ESM) return esmLit(m, z);
    if (settings.filter_type == FILTER_EVSM2) return evsmLit(m, z, false);
    if (settings.filter_type == FILTER_EVSM4) return evsmLit(m, z, true);
    return msmLit(m, z);
}
