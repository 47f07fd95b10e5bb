"""Zhang et al. 003, Parallel-Split Shadow Maps: Figs. 3, 4, 6, 7 and 8, made again by shadowscope's commands.
The rendered numbers come from tests/papers/pssm.json (the same cases the test command runs); the split
positions and the analytic error along z from `shadowscope curves`; the timing ratios from `shadowscope bench`."""
import csv
import math

TITLE = "Zhang et al., parallel-split shadow maps (003)"
SOURCE = "Zhang, Sun, Xu & Lun (docs/references.md, 3)"
CHECK = "tests/papers/pssm.json"
PLATFORM = "resources/scenes/platform.json"
SCHEMES = ["uniform", "log", "practical", "pssm"]


def _rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def _p95(cases, name):
    return cases[name]["aliasing"]["p95"]


def _split_ends(ctx, tag, near, far, res):
    """m_z (analytic, Barroso eq 12 = Zhang 004 eq 2) at both ends of one split [near, far] with its own
    map of res texels, for the uniform map and for LiSPSM (the per-split warp standing in for TSM)."""
    out = ctx.work / f"curves_{tag}"
    ctx.run("curves", "--near", f"{near:.6g}", "--far", f"{far:.6g}", "--fov-y", 60, "--gamma", 90,
            "--gamma-step", 90, "--screen-res", 600, "--map-res", res, "--out", out)
    rows = _rows(out / "error.csv")
    ends = {}
    for method in ("uniform", "lispsm"):
        series = [r for r in rows if r["method"] == method]
        ends[method] = (float(series[0]["m_z"]), float(series[-1]["m_z"]))
    return ends


def reproduce(ctx):
    cases = ctx.check(CHECK)
    ctx.text("""The paper's scenes (Robot War, Huge Chessboard, Knights, Mining Terrain: 51k–1.3M triangles on
0.5–2.6 km² of ground, near = 1 m, far = 800–1000 m) are not available. The built-in `platform` stands in
for them: a 250k-triangle CAD model on a 2.4 km sea with near = 0.5 m and far = 2000 m, the same kind of
large depth range that the paper's splits are meant for. The paper draws each split with a trapezoidal
shadow map (TSM); shadowscope has no TSM, and LiSPSM, which the paper calls "very similar", stands in for
it (`warp.method = lispsm`). Timings are ratios within one run on llvmpipe, never absolute.""")

    # ---- Fig. 3: SSM 1024² against PSSM(3; 512²) with 512², 256², 128² maps ------------------------------
    ssm, pssm, unwarped = _p95(cases, "fig3-ssm"), _p95(cases, "fig3-pssm"), _p95(cases, "fig3-pssm-unwarped")
    res = [s["resolution"] for s in cases["fig3-pssm"]["splits"]]
    memory = sum(r * r for r in res) / 1024 ** 2
    size = ctx.size("320x180", "800x600")
    heat = {}
    for name, args in (("ssm", ["--preset", "resources/presets/ssm.json", "--shadow-res", 1024]),
                       ("pssm", ["--preset", "resources/presets/pssm3.json", "--shadow-res", 512,
                                 "--set", "splits.scheme=pssm", "--set", "splits.resolution_falloff=true",
                                 "--set", "warp.method=lispsm"])):
        folder, _ = ctx.render(f"fig3_{name}", "--scene", PLATFORM, "--view", "deck", "--size", size, *args,
                               "--views", "eye,aliasing")
        heat[name] = (ctx.image(folder / "eye.png", f"fig3_{name}_eye.png"),
                      ctx.image(folder / "aliasing.png", f"fig3_{name}_aliasing.png"))
    ctx.entry(
        "Fig. 3", "SSM 1024² against PSSM(3; 512²)",
        "PSSM(3; 512²), three maps of 512², 256² and 128² — less than a third of a 1024² map's texels — gives "
        "better shadows in a large scene than one 1024² standard shadow map.",
        f"""| | standard map 1024² (`ssm`) | PSSM(3; 512²), LiSPSM per split |
|---|---|---|
| eye | ![ssm]({heat['ssm'][0]}) | ![pssm]({heat['pssm'][0]}) |
| aliasing m | ![ssm m]({heat['ssm'][1]}) | ![pssm m]({heat['pssm'][1]}) |
| p95 of m | {ssm:.1f} | {pssm:.2f} |

Platform `deck` view. The three maps are {res[0]}², {res[1]}² and {res[2]}² (`splits.resolution_falloff`): {memory:.3f} of
the single map's texels in use, as the paper's ≤ 1/3. PSSM's p95 of m is {pssm / ssm:.3f} of the standard map's (check:
≤ 0.25). Without the per-split warp (uniform maps on the same splits) it is {unwarped:.1f}, {unwarped / ssm:.2f} of
the standard map's (check: ≤ 0.8): the splits alone help, the warp inside each split does most of it.""",
        "agrees in shape",
        f"The quality claim holds. The memory claim holds for the texels drawn ({memory:.3f} of 1024²), not for the "
        "texels allocated: the splits are layers of one texture array, which share one size, so three 512² layers "
        "take 0.75 of 1024².")

    # ---- Fig. 4: the view frustum split into parts, each with its own map and resolution -----------------
    lights = []
    for i in range(3):
        folder, m = ctx.render(f"fig4_split{i}", "--scene", PLATFORM, "--view", "deck", "--size", size,
                               "--preset", "resources/presets/pssm3.json", "--shadow-res", 512,
                               "--set", "splits.scheme=pssm", "--set", "splits.resolution_falloff=true",
                               "--set", "warp.method=lispsm", "--light-split", i,
                               "--views", "light" + (",splits" if i == 0 else ""))
        if i == 0:
            splits_img, planned = ctx.image(folder / "splits.png", "fig4_splits.png"), m["splits"]
        lights.append(ctx.image(folder / "light.png", f"fig4_light{i}.png"))
    rows = "\n".join(f"| {i + 1} | {s['near']:.1f}–{s['far']:.1f} m | {s['resolution']}² | {s['triangles']} |"
                     for i, s in enumerate(planned))
    ctx.entry(
        "Fig. 4", "split frustum, one map per part",
        "The view frustum is cut by planes parallel to the view plane into a few depth ranges, and each part gets "
        "its own shadow map, of lower resolution the further the part lies.",
        f"""![splits]({splits_img})

| split | depth range | map | casters drawn |
|---|---|---|---|
{rows}

PSSM(3; 512²) on the platform `deck` view (`splits.scheme = pssm`, ratio 2; colours in the picture are the
splits). The light views of the three maps are under Fig. 7.""",
        "agrees")

    # ---- Fig. 6: split positions C_i along z (eqs 1–3) and the error along z they give ------------------
    out = ctx.work / "curves_splits"
    ctx.run("curves", "--near", 1, "--far", 800, "--fov-y", 60, "--gamma", 90, "--gamma-step", 90,
            "--set", "splits.count=3", "--set", "splits.ratio=2", "--set", "splits.lambda=0.5", "--out", out)
    splits_svg = ctx.image(out / "splits.svg", "fig6_splits.svg")
    bounds = {}
    for r in _rows(out / "splits.csv"):
        if float(r["gamma_deg"]) == 90 and r["scheme"] in SCHEMES:
            bounds.setdefault(r["scheme"], [float(r["near"])]).append(float(r["far"]))
    # The paper's eq 3 (δ_bias = 0, ω = 2): C_i = n + (f − n)/ω^(m−i); computed here, it is not a tool setting.
    n, f, m, omega = 1.0, 800.0, 3, 2.0
    eq3 = [n] + [n + (f - n) / omega ** (m - i) for i in range(1, m + 1)]
    table = ["| scheme | C₁ | C₂ | m at z = n (uniform maps) | m at z = f (uniform maps) | largest jump at a C_i, equal maps | with halved maps |",
             "|---|---|---|---|---|---|---|"]
    analytic = {}
    for scheme in SCHEMES + ["eq3"]:
        c = eq3 if scheme == "eq3" else bounds[scheme]
        equal = [_split_ends(ctx, f"{scheme}{i}", c[i], c[i + 1], 1024) for i in range(m)]
        halved = [_split_ends(ctx, f"{scheme}{i}h", c[i], c[i + 1], 1024 >> i) if i else equal[0] for i in range(m)]
        jump = lambda ends: max(ends[i + 1]["uniform"][0] / ends[i]["uniform"][1] for i in range(m - 1))
        analytic[scheme] = (equal[0]["uniform"][0], equal[-1]["uniform"][1], jump(equal), jump(halved))
        label = "paper eq 3 (ω = 2)" if scheme == "eq3" else f"`{scheme}`"
        table.append(f"| {label} | {c[1]:.1f} | {c[2]:.1f} | {analytic[scheme][0]:.2f} | {analytic[scheme][1]:.3f} | "
                     f"{analytic[scheme][2]:.2f}× | {analytic[scheme][3]:.2f}× |")
    # The numbers checked here (math, no render): practical below uniform at the near end and below log at the far end.
    assert analytic["practical"][0] < analytic["uniform"][0] and analytic["practical"][1] < analytic["log"][1]
    near = {s: _p95(cases, f"near-{s}") for s in SCHEMES}
    far = {s: _p95(cases, f"far-{s}") for s in SCHEMES}
    rendered = "\n".join(f"| `{s}` | {near[s]:.2f} | {far[s]:.3f} |" for s in SCHEMES)
    ctx.entry(
        "Fig. 6", "split positions along z",
        "The split planes C_i are placed so that the parts' lengths grow geometrically, L_(i+1) = ω·L_i with "
        "L_i = C_i − n (eqs 1–3), and ω is chosen so that the error is continuous across each C_i when the next map "
        "has half the resolution (eq 4): objects near the viewer need more resolution, so near parts are thin "
        "and far parts long.",
        f"""![split positions against γ]({splits_svg})

Three splits of n = 1 m to f = 800 m (the paper's Robot War frustum), 60° field of view, γ = 90°, 800×600 screen;
error m_z (Barroso eq 12, the paper's E₁) from `shadowscope curves` run on each split with its own 1024² map:

{chr(10).join(table)}

The uniform and logarithmic schemes are the two ends PSSM's idea lies between, and `practical` (their blend, as
engines ship PSSM) its usual form. Rendered on the platform (three 1024² uniform maps, n = 0.5 m, f = 2000 m),
p95 of m over a view of the deck
below the camera (near end) and over a view of the sea beyond 500 m (far end):

| scheme | near end p95 | far end p95 |
|---|---|---|
{rendered}

The practical split lies between the others as claimed: {near['practical'] / near['uniform']:.2f} of uniform's error at
the near end (check: ≤ 0.75) and {far['practical'] / far['log']:.2f} of log's at the far end (check: ≤ 0.85); log is
best near ({near['log'] / near['practical']:.2f} of practical's, check ≤ 0.5) and worst far. The paper's own geometric
scheme (`pssm`) behaves like practical (near {near['pssm'] / near['uniform']:.2f} of uniform's, far
{far['pssm'] / far['log']:.2f} of log's; checks ≤ 0.75 and ≤ 1).""",
        "agrees in shape",
        f"Two differences. The tool's `pssm` scheme grows each split's own length by the ratio (C₁ = "
        f"{bounds['pssm'][1]:.1f} m), where eq 3 grows the distance from n (C₁ = {eq3[1]:.1f} m): both put thin splits "
        f"near the viewer, at different places. And no ω makes uniform maps continuous with halved resolution: "
        f"the error jumps by {analytic['eq3'][3]:.1f}× at a boundary under eq 3 and {analytic['pssm'][3]:.1f}× under the "
        "tool's scheme, since a further part is both longer and drawn with fewer texels; eq 4 can only hold for "
        "a per-split warp that lowers the error at each part's near end.")

    # ---- Fig. 7: the light's frustum split into W_i = B_i ∩ S ---------------------------------------------
    tri = [s["triangles"] for s in cases["fig3-pssm"]["splits"]]
    total = cases["fig3-ssm"]["triangles_submitted"]["shadow"]
    ctx.entry(
        "Fig. 7", "light frustum per split, W_i = B_i ∩ S",
        "Each split gets its own light frustum W_i, the bounding box of its part V_i clipped by the scene's bounds "
        "S, holding the part and every object that can cast a shadow into it (eq 5); the per-split boxes together "
        "cover less than the one box of the whole frustum, so texels are not spent between objects.",
        f"""| split 1 ({res[0]}²) | split 2 ({res[1]}²) | split 3 ({res[2]}²) |
|---|---|---|
| ![light 1]({lights[0]}) | ![light 2]({lights[1]}) | ![light 3]({lights[2]}) |

The light's view of each map (`render --light-split i`): the split's part V_i (orange), its focus body B_i
(green: V_i clipped by S and extruded towards the light). The casters drawn into the maps are {tri[0]}, {tri[1]}
and {tri[2]} triangles (check: splits 2 and 3 ≤ 12 500 of 250 680): W_i holds only what can shadow its part.""",
        "agrees in shape",
        "shadowscope fits each map to the convex focus body B_i (Scherzer's intersection body), a tighter shape "
        "than the paper's axis-aligned box; it does not report the boxes' areas, so the area inequality is shown "
        "by the pictures and the caster counts, not measured.")

    # ---- Fig. 8: performance against the number of splits (ratios within one run) ------------------------
    out = ctx.work / "bench"
    ctx.run("bench", "--scene", PLATFORM, "--view", "deck", "--size", ctx.size("320x180", "800x600"),
            "--preset", "resources/presets/lispsm.json", "--set", "shadow_map.resolution=1024", "--set", "splits.scheme=pssm",
            "--set", "splits.resolution_falloff=true", "--sweep", "splits.count=1,2,3,4",
            "--frames", 10, "--out", out)
    bench = {int(r["config"].split("=")[-1]): r for r in _rows(out / "results.csv")}
    base = bench[1]
    lines = "\n".join(
        f"| {'single map (LiSPSM, the TSM stand-in)' if k == 1 else f'PSSM({k})'} | "
        f"{float(r['gpu_ms_median']) / float(base['gpu_ms_median']):.2f} | "
        f"{float(r['shadow_ms_median']) / float(base['shadow_ms_median']):.2f} | "
        f"{int(r['shadow_triangles']) / int(base['shadow_triangles']):.3f} | "
        f"{float(r['shadow_memory_mib']) / float(base['shadow_memory_mib']):.2f} |"
        for k, r in sorted(bench.items()))
    frame = [float(bench[k]["gpu_ms_median"]) / float(base["gpu_ms_median"]) for k in (2, 3, 4)]
    shadow = [float(bench[k]["shadow_ms_median"]) / float(base["shadow_ms_median"]) for k in (2, 3, 4)]
    ctx.entry(
        "Fig. 8", "performance against the number of splits",
        "PSSM(2–4) stays real-time: on the paper's GPU PSSM(2) ran at 58.0 fps and PSSM(4) at 47.2 fps on Huge "
        "Chessboard, 15.6 and 13.2 fps on Mining Terrain, where single-map techniques ran at 21.9 fps — a frame "
        "1.18–1.23× as long for PSSM(4) as for PSSM(2) and about 1.4× as long for PSSM(2) as for one map — "
        "while the maps take much less texture memory.",
        f"""| configuration | frame time (× one map) | shadow pass time | shadow triangles | shadow-map memory |
|---|---|---|---|---|
{lines}

Platform `deck` view, 1024² first map halved per split, LiSPSM in every split, median of
10 frames each, one `bench` run on llvmpipe; ratios to the single map, never absolute times. Extra
splits add few shadow triangles ({int(bench[4]['shadow_triangles']) / int(base['shadow_triangles']):.3f}× with four:
casters are culled per W_i; the test bounds the three-split case at ≤ 1.05×, `fig3-pssm` against `fig3-ssm`).""",
        "agrees in shape",
        f"In this run the shadow passes of PSSM(2–4) take {min(shadow):.2f}–{max(shadow):.2f}× the single map's and "
        f"the whole frame {min(frame):.2f}–{max(frame):.2f}× (the paper: PSSM(2) about 1.4× a single map's frame, "
        "PSSM(4) a further 1.18–1.23×). `bench` times the configurations one after another, on llvmpipe on a "
        "machine shared with other jobs, so these ratios move between runs by tens of percent; the test bounds "
        "triangles, not times. What holds in every run: extra splits add about 1 % shadow triangles. Memory does "
        "not shrink: the splits are layers of one texture array, which "
        "share the first map's size, so halving the resolution per split saves rendering work, not memory.")
