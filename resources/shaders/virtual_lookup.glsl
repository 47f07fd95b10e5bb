// technique = virtual (docs/design.md §3.11): the eye pass's lookups in the virtual map, with the same
// filters as lookUp. Included by eye.frag after its Lookup, vogel, pixelAngle and planeSlack.
uniform int uVirtual;               // 1: technique = virtual (the split maps are not read)
uniform usampler2DArray uPageTable; // (page x, page y, level) → physical page + 1; 0: none
uniform sampler2D uPageAtlas;       // the physical pages' depths, uVColumns pages a row

bool vAllocated(vec2 s, int k) {
    ivec2 page = vPageOf(s, k);
    return vInSquare(page) && texelFetch(uPageTable, ivec3(page, k), 0).r != 0u;
}

/// The depth the virtual map holds at plane point s: from level k's page holding it, else from the
/// nearest coarser page allocated (a tap past the pages the pixels asked for); 2 (lit) where none is.
float vDepthAt(vec2 s, int k) {
    for (; k < uVLevels; ++k) {
        ivec2 page = vPageOf(s, k);
        if (!vInSquare(page)) continue;
        uint entry = texelFetch(uPageTable, ivec3(page, k), 0).r;
        if (entry == 0u) continue;
        ivec2 t = clamp(ivec2(floor((s - uVOrigin[k]) / vTexel(k))) - page * uVPageSize, ivec2(0), ivec2(uVPageSize - 1));
        return texelFetch(uPageAtlas, vAtlasTexel(entry, t), 0).r;
    }
    return 2.0;
}

/// The level a lookup reads: the footprint's level k when its page is allocated, else the next finer
/// (a pixel whose pre-pass footprint fell just below the threshold), else the first coarser one.
int vLevelAt(vec2 s, int k) {
    if (vAllocated(s, k)) return k;
    if (k > 0 && vAllocated(s, k - 1)) return k - 1;
    for (int j = k + 1; j < uVLevels; ++j)
        if (vAllocated(s, j)) return j;
    return uVLevels - 1;
}

/// The texel of level k whose centre is `centre` (level texels from the square's corner), compared with z.
float vTest(vec2 centre, float z, int k) { return z > vDepthAt(uVOrigin[k] + centre * vTexel(k), k) ? 0.0 : 1.0; }

/// As lookUp, in the virtual map: the same filters, each tap through the page table (a tap across a
/// page border reads the neighbour page, never another place's texels).
Lookup virtualLookUp(vec3 receiver, vec3 dPdx, vec3 dPdy, float ndotl) {
    vec2 s = vPlane(receiver);
    int k = vLevelAt(s, vLevelFor(vFootprint(dPdx, dPdy)));
    float texel = vTexel(k);
    vec2 t = (s - uVOrigin[k]) / texel;
    float z = vPageDepth(receiver);
    Lookup L;
    L.dTdx = vec2(dot(dPdx, uVRight), dot(dPdx, uVUp)) / texel;
    L.dTdy = vec2(dot(dPdy, uVRight), dot(dPdy, uVUp)) / texel;
    float dzdx = dot(dPdx, uVLight) * uVDepthScale, dzdy = dot(dPdy, uVLight) * uVDepthScale;
    L.det = L.dTdx.x * L.dTdy.y - L.dTdx.y * L.dTdy.x;
    vec2 dzdt = abs(L.det) > 1e-12 ? vec2(dzdx * L.dTdy.y - dzdy * L.dTdx.y, dzdy * L.dTdx.x - dzdx * L.dTdy.x) / L.det
                                   : vec2(0.0);
    bool receiverPlane = settings.bias_type == BIAS_RECEIVER_PLANE;
    if (!settings.bias_tangent_plane && !receiverPlane) dzdt = vec2(0.0);
    float slack = receiverPlane ? planeSlack(dzdt) : 0.0;
    float lit = 1.0;
    if (ndotl > 0.0) {
        if (settings.filter_type == FILTER_NONE) {
            vec2 c = floor(t) + 0.5;
            lit = vTest(c, z + (receiverPlane ? dot(dzdt, c - t) - slack : 0.0), k);
        } else if (settings.filter_type == FILTER_PCF) {
            vec2 first = floor(t) - float(settings.filter_kernel / 2);
            float sum = 0.0;
            for (int j = 0; j < settings.filter_kernel; ++j)
                for (int i = 0; i < settings.filter_kernel; ++i) {
                    vec2 c = first + vec2(i, j) + 0.5;
                    sum += vTest(c, z + dot(dzdt, c - t) - slack, k);
                }
            lit = sum / float(settings.filter_kernel * settings.filter_kernel);
        } else if (settings.filter_type == FILTER_DISK) {
            float angle = pixelAngle(), sum = 0.0;
            for (int n = 0; n < settings.filter_taps; ++n) {
                vec2 offset = settings.filter_radius * vogel(n, settings.filter_taps, angle);
                vec2 c = floor(t + offset) + 0.5;
                sum += vTest(c, z + (receiverPlane ? dot(dzdt, c - t) - slack : dot(dzdt, offset)), k);
            }
            lit = sum / float(settings.filter_taps);
        } else { // hw2x2, and the filters the plan turned into it: bilinear weights of four texel tests
            vec2 b = t - 0.5, f = fract(b), c = floor(b) + 0.5;
            float ref = z - 2.0 * slack;
            lit = mix(mix(vTest(c, ref, k), vTest(c + vec2(1, 0), ref, k), f.x),
                      mix(vTest(c + vec2(0, 1), ref, k), vTest(c + vec2(1, 1), ref, k), f.x), f.y);
        }
    }
    L.s = lit;
    L.texel = t;
    L.depth = z;
    L.level = k;
    return L;
}
