"""Barroso & Celes, Improved Real-Time Shadow Mapping for CAD Models: every figure and table that shows
something shadowscope does (Figs. 2-9, Tables 1-2), made again on the built-in platform and plane.
The numeric claims are the cases of tests/papers/barroso.json; the pure-math ones (Figs. 4, 6-7) are
read from `shadowscope curves` and checked here."""
import csv
import re
import subprocess
import sys
import time

TITLE = "Barroso & Celes, Improved Real-Time Shadow Mapping for CAD Models"
SOURCE = "Barroso & Celes (docs/references.md, 1)"

PLATFORM = "resources/scenes/platform.json"
PLANE = "resources/scenes/plane.json"
PAPER = "resources/presets/paper.json"
SSM = "resources/presets/ssm.json"
CHECK = "tests/papers/barroso.json"
# The deck camera with the light 40 degrees from the view direction, behind the camera (Fig. 8).
LIGHT_40 = "0.5916,-0.6261,-0.508"
# The plane's gamma90 camera with the light 10 degrees from the view direction (Fig. 5b).
LIGHT_10 = "0,-0.819,-0.573"
# Table 2: scripts/reproduce-table2 (frame_benchmark's Table2/*) is measured by default: on the idle 2-core
# machine this module took 79 s with it and the whole page 134 s (89-166 s for the table alone while other
# jobs shared the machine). False carries the last table forward unless --full or the page has none.
TABLE2_BY_DEFAULT = True


def pct(x):
    return f"{100 * x:.2f} %"


def reproduce(ctx):
    cases = ctx.check(CHECK)
    check_cmd = ctx.commands[-1]

    def case(name):
        if name not in cases:
            sys.exit(f"reproduce-papers: barroso: the check case {name} wrote no metrics.json")
        return cases[name]

    def folder(name):
        return ctx.work / "check_barroso" / name

    small = ctx.size("320x180", "800x600")
    heat = ctx.size("480x270", "800x600")  # heatmaps: room for the legend

    ctx.text("Stand-ins: the paper's oil platform (250k triangles) is not available; the built-in `platform` "
             "(250k triangles, a 2.4 km sea, thin gratings, lattice towers and pipes) stands in for it, with its "
             "canonical views (`deck`: close-up on the top deck, γ ≈ 69°; `overview`: γ ≈ 90°; `grazing`: "
             "γ ≈ 6°). The frustum diagrams (Figs. 4–5) use the `plane` scene, whose short frustum "
             "(n = 0.5, f = 100) can be seen whole from the light. The paper's settings are `paper.json`: "
             "constant bias, GLiSPSM, two adaptive splits with α = 2, 5×5 texel-space PCF, 2048² maps. "
             f"Numbers are from `{check_cmd}` (320×180, the cases of `{CHECK}`, which the test command "
             "runs as `papers_barroso`), unless an entry says otherwise.")

    fig2(ctx, case, folder, small)
    fig3(ctx, case, heat)
    figs45(ctx, case, small)
    figs67(ctx)
    fig8(ctx, case, heat)
    fig9(ctx, case, heat)
    table1(ctx, case)
    table2(ctx)


# ---- Fig. 2: VSM's light bleeding ---------------------------------------------------------------

def fig2(ctx, case, folder, small):
    pcf, vsm = case("deck-paper")["truth"], case("deck-vsm")["truth"]
    if ctx.full:
        a, _ = ctx.render("fig2_pcf", "--scene", PLATFORM, "--view", "deck", "--size", small, "--preset", PAPER,
                          "--views", "eye")
        b, _ = ctx.render("fig2_vsm", "--scene", PLATFORM, "--view", "deck", "--size", small, "--preset", PAPER,
                          "--set", "filter.type=vsm", "--set", "filter.kernel=5", "--set", "filter.bleed_reduction=0",
                          "--views", "eye")
    else:
        a, b = folder("deck-paper"), folder("deck-vsm")
    img_pcf, img_vsm = ctx.image(a / "eye.png", "fig2_pcf.png"), ctx.image(b / "eye.png", "fig2_vsm.png")
    bleed = vsm["umbra_light"] / max(pcf["umbra_light"], 1e-9)
    lit = vsm["false_lit"] / max(pcf["false_lit"], 1e-9)
    rows = "\n".join(f"| {k} | {pct(pcf[k])} | {pct(vsm[k])} |" for k in
                     ("umbra_light", "false_lit", "contact_false_lit", "interior_false_lit", "interior_false_shadow"))
    ctx.entry(
        "Fig. 2", "light bleeding with VSM on a CAD model",
        "Variance shadow maps bleed light on CAD models, worse than elsewhere because of the high depth range "
        "and depth complexity: a tower's silhouette shows through a shadow, filtered depths mix with far "
        "objects, and where z − μ is small the shadow fades. PCF is recommended instead.",
        f"The `deck` view with the paper's settings, 5×5 PCF (left) against VSM with a 5-texel blur and no "
        f"bleeding reduction (right):\n\n| 5×5 PCF | VSM |\n|---|---|\n| ![pcf]({img_pcf}) | ![vsm]({img_vsm}) |\n\n"
        f"Against ray-traced truth (fractions of receiver pixels; `umbra_light` is the mean light inside "
        f"the truth's umbrae):\n\n| truth | PCF | VSM |\n|---|---|---|\n{rows}\n\n"
        f"VSM lets {bleed:.0f}× as much light into the umbrae and lights {lit:.1f}× as many pixels wrongly; "
        f"the check bounds both (`deck-vsm`: umbra_light ≥ 5×, false_lit ≥ 1.5× those of `deck-paper`).",
        "agrees" if bleed >= 5 and lit >= 1.5 else "disagrees",
        "" if bleed >= 5 and lit >= 1.5 else f"VSM bled only {bleed:.1f}× (umbra) and {lit:.1f}× (false lit) "
        "as much as PCF on this view.")


# ---- Fig. 3: the aliasing error metric m -----------------------------------------------------------

def fig3(ctx, case, small):
    imgs = {}
    for name, preset in (("ssm", SSM), ("paper", PAPER)):
        out, _ = ctx.render(f"fig3_{name}", "--scene", PLATFORM, "--view", "deck", "--size", small,
                            "--preset", preset, "--views", "aliasing")
        imgs[name] = ctx.image(out / "aliasing.png", f"fig3_{name}_aliasing.png")
    s, p = case("deck-ssm")["aliasing"], case("deck-paper")["aliasing"]
    rows = "\n".join(f"| {label} | {a['p50']:.2f} | {a['p95']:.1f} | {pct(a['undersampled'])} |"
                     for label, a in (("uniform map (`ssm.json`)", s), ("paper's settings (`paper.json`)", p)))
    ok = p["p95"] <= 0.1 * s["p95"]
    ctx.entry(
        "Fig. 3", "the aliasing error metric m",
        "A shadow-map texel covers w_L on a surface, an image pixel w_c; the aliasing error is "
        "m = w_L'/w_c ≈ w_L·cos θ_c / (w_c·cos θ_L) (eq 3): above 1 one texel decides several pixels. It "
        "splits into perspective aliasing w_L/w_c, which warping reduces, and projection aliasing "
        "cos θ_L/cos θ_c, which it cannot.",
        "The tool measures m per pixel as 1/σ_min of the Jacobian of map texels over screen pixels (docs/design.md "
        "§4), i.e. eq 3 with projection aliasing included; heatmaps (log scale: red m > 1, white 1, blue "
        f"m < 1) on `deck`:\n\n| uniform map | paper's settings |\n|---|---|\n| ![ssm]({imgs['ssm']}) | "
        f"![paper]({imgs['paper']}) |\n\n| configuration | p50 m | p95 m | pixels with m > 1 |\n|---|---|---|---|\n"
        f"{rows}\n\nThe check bounds `deck-paper`'s p95 m to at most 0.1× `deck-ssm`'s "
        f"(now {p['p95'] / s['p95']:.3f}×).",
        "agrees" if ok else "disagrees",
        "" if ok else "the paper's settings no longer cut p95 m tenfold on this view.")


# ---- Figs. 4-5: P fit to V; the frustum with z-partitioning as the light sees it -------------------

def figs45(ctx, case, small):
    a, _ = ctx.render("fig4", "--scene", PLANE, "--view", "gamma90", "--size", small, "--preset", PAPER,
                      "--set", "splits.count=1", "--views", "light_unwarped")
    b, _ = ctx.render("fig5a", "--scene", PLANE, "--view", "gamma90", "--size", small, "--preset", PAPER,
                      "--set", "splits.scheme=log", "--set", "splits.count=3", "--views", "light",
                      "--light-split", "1")
    c, _ = ctx.render("fig5b", "--scene", PLANE, "--view", "gamma90", "--light", LIGHT_10, "--size", small,
                      "--preset", PAPER, "--set", "splits.scheme=log", "--set", "splits.count=3", "--views", "light",
                      "--light-split", "1")
    img4 = ctx.image(a / "light_unwarped.png", "fig4_light_unwarped.png")
    img5a = ctx.image(b / "light.png", "fig5a_light.png")
    img5b = ctx.image(c / "light.png", "fig5b_light.png")
    ctx.run("curves", "--near", 1, "--far", 100, "--fov-y", 60, "--gamma", 90, "--out", ctx.work / "curves90")
    mz = read_error(ctx.work / "curves90" / "error.csv")
    psm, lis = mz["psm"], mz["lispsm"]
    psm_growth = psm[-1][1] / psm[0][1]
    lis_ratio = lis[0][1] / lis[-1][1]
    n_prime = case("plane-gamma90")["splits"][0]["n_prime"]
    log_far = case("grazing-log")["splits"][0]["far"]
    ok = abs(psm_growth - 100) < 1 and abs(lis_ratio - 1) < 1e-3 and abs(n_prime - 7.5711) < 0.01 \
        and abs(log_far - 31.62) < 0.3
    ctx.entry(
        "Figs. 4–5", "P fit to V; the frustum with z-partitioning as the light sees it",
        "With light and view perpendicular, a perspective frustum P (near plane n') is fitted around the view "
        "frustum V and applied before the shadow map is drawn. n' = n is PSM, whose error along z grows "
        "linearly with z; n' → ∞ is the uniform map; LiSPSM's n' = n + √(fn) minimizes the maximum error "
        "along z and makes it equal at the near and far planes. z-partitioning cuts V along z into k "
        "self-similar parts, n_i = n·(f/n)^((i−1)/k) (eq 5), one map each (Fig. 5: (a) perpendicular, (b) "
        "parallel light).",
        "The `plane` scene's `gamma90` view (γ = 90°) as the light sees it, with the tool's overlays: the view "
        "frustum V (yellow), the split's part V_i (orange), the focus body B_i (green), P as fitted (cyan), "
        "scene bounds (grey). Fig. 4 is the unwarped light view of one map: P drawn around V. Fig. 5 is the "
        "map of the second of three log splits (eq 5) with the light perpendicular (a) and 10° from the view "
        "direction (b), where the warp is nearly uniform and the splits nest inside each other:\n\n"
        f"| Fig. 4: P around V | Fig. 5a: perpendicular | Fig. 5b: near parallel |\n|---|---|---|\n"
        f"| ![fig4]({img4}) | ![fig5a]({img5a}) | ![fig5b]({img5b}) |\n\n"
        f"From `shadowscope curves` (n = 1, f = 100, φ_y = 30°, γ = 90°, pure math, checked by this "
        f"script): PSM's m_z grows {psm_growth:.1f}× from z = n to z = f (= f/n, linear in z); LiSPSM's m_z "
        f"at n and f: {lis[0][1]:.3f} and {lis[-1][1]:.3f}. Rendered (check cases): the generalized "
        f"parameter at γ = 90° on `plane` is n' = {n_prime:.4f} = 0.5 + √(0.5·100) (`plane-gamma90`, bounded "
        f"7.56–7.58), and the log split of `grazing` (n = 0.5, f = 2000, k = 2) ends at {log_far:.2f} m = "
        f"√(nf) (`grazing-log`, bounded 31.3–31.9).",
        "agrees" if ok else "disagrees",
        "" if ok else "one of the analytic values above is off: see the numbers.")


def read_error(path):
    """error.csv of `curves` -> {method: [(z, m_z), ...] sorted by z}."""
    out = {}
    with open(path) as f:
        for r in csv.DictReader(f):
            out.setdefault(r["method"], []).append((float(r["z"]), float(r["m_z"])))
    return {k: sorted(v) for k, v in out.items()}


# ---- Figs. 6-7: the generalized parameterization and n'(gamma) -------------------------------------

def figs67(ctx):
    out = ctx.work / "curves"
    ctx.run("curves", "--near", 1, "--far", 100, "--fov-y", 60, "--gamma", 60, "--gamma-step", 0.5, "--out", out)
    warp = {}
    with open(out / "warp.csv") as f:
        for r in csv.DictReader(f):
            warp.setdefault(r["method"], {})[float(r["gamma_deg"])] = float(r["n_prime"])
    g = warp["glispsm"]
    low = min((v, k) for k, v in g.items() if k > 0)
    mz = read_error(out / "error.csv")
    gl, li = mz["glispsm"], mz["lispsm"]
    gl_ends = gl[-1][1] / gl[0][1]
    gl_max, li_max = max(v for _, v in gl), max(v for _, v in li)
    img_warp = ctx.image(out / "warp.svg", "fig7_warp.svg")
    img_err = ctx.image(out / "error.svg", "fig6_error.svg")
    ok = (abs(g[90.0] - 11) < 1e-6 and abs(low[1] - 30.5) <= 0.5 and abs(low[0] - 5.09) < 0.05
          and g[5.0] > 1000 and abs(gl_ends - 1) < 1e-3 and gl_max < li_max)
    ctx.entry(
        "Figs. 6–7", "generalized parameterization; n'(γ) for n = 1, f = 100, φ_y = π/6",
        "For a light tilted by γ from the view direction, z' and f' follow Fig. 6's two cases (eqs 10–11) and "
        "the error along z is m_z = ξ·ψ²/z (eq 12); making it equal at the near and far planes gives "
        "n'_1(γ) = (n + √(fn))·sin γ − a·cos γ (eq 13), used down to γ_lim = atan((a + b)/(f − n)) (eq 15), "
        "below which n' = n'_1(γ_lim)/r(γ) grows to ∞ (eqs 16, 18). Fig. 7: the warp first gets stronger as "
        "the light tilts, then below γ_lim quickly converges to the uniform map.",
        f"`shadowscope curves` (pure math, no render; the numbers are checked by this script): n'(γ) for every "
        f"warp (Fig. 7) and m_z(z) at γ = 60° (Fig. 6's first case):\n\n![n' of every warp]({img_warp})\n\n"
        f"![m_z at 60 degrees]({img_err})\n\n"
        f"Generalized LiSPSM (glispsm): n'(90°) = {g[90.0]:.2f} (= n + √(fn)); its minimum {low[0]:.2f} at "
        f"γ = {low[1]:.1f}° (γ_lim = 30.5°, n'_1(γ_lim) = 5.09); n'(5°) = {g[5.0]:.0f}. At γ = 60° its m_z is "
        f"the same at z = n and z = f (ratio {gl_ends:.4f}) and its maximum {gl_max:.2f} is below standard "
        f"LiSPSM's {li_max:.2f} (n' = (n + √(fn))/sin γ, error {li[0][1]:.2f} at n, {li[-1][1]:.2f} at f).",
        "agrees" if ok else "disagrees",
        "" if ok else "n'(γ) or m_z no longer has the paper's shape: see the numbers.")


# ---- Fig. 8: standard vs generalized LiSPSM ------------------------------------------------------------

def fig8(ctx, case, small):
    imgs = {}
    for method in ("lispsm", "glispsm"):
        out, _ = ctx.render(f"fig8_{method}", "--scene", PLATFORM, "--view", "deck", "--light", LIGHT_40,
                            "--size", small, "--preset", PAPER, "--set", "splits.count=1",
                            "--set", f"warp.method={method}", "--views", "eye,aliasing")
        imgs[method] = (ctx.image(out / "eye.png", f"fig8_{method}_eye.png"),
                        ctx.image(out / "aliasing.png", f"fig8_{method}_aliasing.png"))
    sweep = ctx.work / "fig8_sweep"
    ctx.run("sweep", "gamma", "--scene", PLATFORM, "--view", "deck", "--size", ctx.size("240x135", "800x600"),
            "--preset", PAPER, "--set", "splits.count=1", "--from", 10, "--to", 170,
            "--step", 10, "--methods", "lispsm,glispsm", "--out", sweep)
    by = {}
    with open(sweep / "sweep.csv") as f:
        for r in csv.DictReader(f):
            by.setdefault(float(r["angle_deg"]), {})[r["method"]] = float(r["p95"])
    angles = sorted(a for a in by if {"lispsm", "glispsm"} <= set(by[a]))
    ratio = {a: by[a]["glispsm"] / by[a]["lispsm"] for a in angles}
    better = [a for a in angles if ratio[a] < 1]
    worse = [a for a in angles if ratio[a] >= 1]
    chart = ctx.image(sweep / "p95.svg", "fig8_sweep_p95.svg")
    li, gl = case("f8-lispsm")["aliasing"], case("f8-glispsm")["aliasing"]
    rows = "\n".join(f"| {a:.0f}° | {min(a, 180 - a):.0f}° | {by[a]['lispsm']:.1f} | {by[a]['glispsm']:.1f} | "
                     f"{ratio[a]:.2f} |" for a in angles)
    ok = gl["p95"] < li["p95"] and len(better) > len(angles) / 2
    best = min(angles, key=lambda a: ratio[a])
    worst = max(angles, key=lambda a: ratio[a])
    ctx.entry(
        "Fig. 8", "standard vs generalized LiSPSM",
        "The generalized parameter gives better shadows than the other parameterizations for most light "
        "directions; Fig. 8 shows a lattice's shadow close to the near plane, where the improvement is most "
        "noticeable. Minimizing the maximum error does not minimize it everywhere, so plain LiSPSM may win in "
        "some cases.",
        f"The `deck` camera over the grating with the light 40° from the view direction (γ = 40°, behind the "
        f"camera), one map, the paper's other settings; eye view and aliasing m:\n\n"
        f"| | standard LiSPSM | generalized LiSPSM |\n|---|---|---|\n"
        f"| eye | ![lispsm]({imgs['lispsm'][0]}) | ![glispsm]({imgs['glispsm'][0]}) |\n"
        f"| m | ![lispsm m]({imgs['lispsm'][1]}) | ![glispsm m]({imgs['glispsm'][1]}) |\n\n"
        f"Check cases `f8-lispsm`/`f8-glispsm`: p95 m {li['p95']:.2f} → {gl['p95']:.2f}, p50 m "
        f"{li['p50']:.2f} → {gl['p50']:.2f} (bounded: glispsm's p95 and p50 at most 0.95× LiSPSM's).\n\n"
        f"Over light directions (`sweep gamma` on `deck`, one map; the light-view angle runs from the light "
        f"behind the camera, 0°, to facing it, 180°; γ is the smaller angle between the two directions):\n\n"
        f"![p95 over the light-view angle]({chart})\n\n"
        f"| light-view angle | γ | p95 m LiSPSM | p95 m generalized | ratio |\n|---|---|---|---|---|\n{rows}",
        "agrees in shape" if ok else "disagrees",
        (f"The generalized parameter has the lower p95 m at {len(better)} of {len(angles)} light directions, "
         f"most at {best:.0f}° (ratio {ratio[best]:.2f}), and on the check's view (γ = 40°), as claimed; it is "
         f"higher at {', '.join(f'{a:.0f}°' for a in worse)} (worst {worst:.0f}°: {ratio[worst]:.2f}). Near "
         "γ = 90° both should give n' = n + √(fn), but the tool's LiSPSM takes Δz from the focus body clipped "
         "to the scene (Scherzer eq 1) rather than f − n, so the two n' differ there; facing the light at a "
         "small γ both maps fail (p95 m in the thousands). The paper shows one picture, no numbers.")
        if ok else "On the check's view or over most light directions the generalized parameter no longer "
        "lowers p95 m.")


# ---- Fig. 9: adaptive vs optimal partitioning: the seam ----------------------------------------------

def fig9(ctx, case, small):
    imgs = {}
    for scheme in ("log", "adaptive"):
        out, _ = ctx.render(f"fig9_{scheme}", "--scene", PLATFORM, "--view", "grazing", "--size", small,
                            "--preset", PAPER, "--set", f"splits.scheme={scheme}", "--views", "aliasing,splits")
        imgs[scheme] = (ctx.image(out / "aliasing.png", f"fig9_{scheme}_aliasing.png"),
                        ctx.image(out / "splits.png", f"fig9_{scheme}_splits.png"))
    seams = {}
    for count, size in ((2, ctx.size("640x360", "800x600")), (4, ctx.size("320x180", "800x600"))):
        for scheme in ("log", "adaptive"):
            out = ctx.work / f"fig9_path_{scheme}_{count}"
            ctx.run("sweep", "path", "--scene", PLATFORM, "--path", "grazing_walk", "--frames", 6, "--size", size,
                    "--preset", PAPER, "--set", f"splits.scheme={scheme}", "--set", f"splits.count={count}",
                    "--out", out)
            with open(out / "path.csv") as f:
                rows = [r for r in csv.DictReader(f) if int(r["seam_pairs"]) > 0]
            seam = sum(float(r["seam_median"]) for r in rows) / len(rows) if rows else float("nan")
            pairs = sum(int(r["seam_pairs"]) for r in rows)
            with open(out / "path.csv") as f:
                p95 = [float(r["p95"]) for r in csv.DictReader(f)]
            seams[(scheme, count)] = (seam, pairs, sum(p95) / len(p95))
    log, ada = case("grazing-log"), case("grazing-adaptive")
    table = "\n".join(
        f"| {count} | {scheme} | {seams[(scheme, count)][0]:.2f} | {seams[(scheme, count)][1]} | "
        f"{seams[(scheme, count)][2]:.1f} |" for count in (2, 4) for scheme in ("log", "adaptive"))
    ok = all(seams[("adaptive", k)][0] < seams[("log", k)][0] for k in (2, 4))
    ls, as_ = log["splits"], ada["splits"]
    sl, sa = case("seam-log")["seam"], case("seam-adaptive")["seam"]

    def seam_text(seam, digits):  # null when no crossing is on screen
        median = "none" if seam["median"] is None else f"{seam['median']:.{digits}f}"
        return f"{median} over {seam['pairs']} crossings"
    ctx.entry(
        "Fig. 9", "adaptive vs optimal partitioning: the seam",
        "With the light near parallel to the view, optimal (log) z-partitioning leaves a visible seam where the "
        "first partition's fine shadows meet the next one's coarse ones. Adaptive partitioning (eq 19) "
        "interpolates each boundary between the log one and f_i/α with λ = γ/(π/2), so every partition but "
        "the first has f_i/n_i near α; with 2 partitions and α = 2 the seam becomes almost unnoticeable, at "
        "the price of less aliasing reduction in the first partition.",
        f"The `grazing` view (γ = 6°), two splits, the paper's settings; aliasing m and split colours:\n\n"
        f"| | optimal (log) | adaptive, α = 2 |\n|---|---|---|\n"
        f"| m | ![log m]({imgs['log'][0]}) | ![adaptive m]({imgs['adaptive'][0]}) |\n"
        f"| splits | ![log splits]({imgs['log'][1]}) | ![adaptive splits]({imgs['adaptive'][1]}) |\n\n"
        f"Boundaries (check cases): log [{ls[0]['near']:.1f}, {ls[0]['far']:.1f}], [{ls[1]['near']:.1f}, "
        f"{ls[1]['far']:.0f}] m; adaptive [{as_[0]['near']:.1f}, {as_[0]['far']:.0f}], [{as_[1]['near']:.0f}, "
        f"{as_[1]['far']:.0f}] m, so the last split's f/n = {as_[1]['far'] / as_[1]['near']:.2f} (bounded: "
        f"n_2 ≥ 800 m); p95 m {log['aliasing']['p95']:.1f} (log) against {ada['aliasing']['p95']:.1f} "
        f"(adaptive; bounded ≥ 2× log's: the price in the first split).\n\n"
        f"The seam (docs/design.md §4 \"Seams\": the jump of m across a split boundary beyond its local slope, "
        f"1 = none; docs/stability.md) is measured by `sweep path` along `grazing_walk` (8 m along the deck "
        f"under the grazing sun, 6 frames), the mean of the frames' medians:\n\n"
        f"| splits | scheme | seam | crossings (all frames) | mean p95 m |\n|---|---|---|---|---|\n{table}\n\n"
        f"The seam is a check case too (`render`'s metrics.json `seam.median`, one frame at 640×360): "
        f"`seam-log` and `seam-adaptive` see the grazing sun from the walk's last camera, where surfaces "
        f"straddle the log boundary (from the `grazing` view itself no same-surface pixels do): log "
        f"{seam_text(sl, 1)} (bounded ≥ 2), adaptive {seam_text(sa, 2)} (bounded ≤ 0.2× log's, p95 ≤ 1.5).",
        "agrees" if ok else "disagrees",
        (f"The seam all but vanishes with two adaptive splits ({seams[('log', 2)][0]:.1f} → "
         f"{seams[('adaptive', 2)][0]:.2f}; with four, {seams[('log', 4)][0]:.1f} → {seams[('adaptive', 4)][0]:.1f}, "
         f"about α), as in the paper. The price is steeper on this view than the paper's picture suggests: the "
         f"first split reaches from {as_[0]['near']:.1f} m to the sea {as_[0]['far']:.0f} m out, and p95 m is "
         f"{ada['aliasing']['p95'] / log['aliasing']['p95']:.0f}× log's; the adaptive boundary also lies on "
         "the open sea, where there is little to see a seam on.")
        if ok else "adaptive splits no longer lower the seam below log's.")


# ---- Table 1: the z-bias functions -------------------------------------------------------------------

def table1(ctx, case):
    names = [("(a) constant z_offset = 0.05", "bias-constant"), ("(b) second depth", "bias-second-depth"),
             ("(c) midpoint", "bias-midpoint"), ("(d) dual depth, z_max = 0.5", "bias-dual-depth"),
             ("(a) + 5×5 PCF on the tangent plane (`paper.json`)", "deck-paper")]
    rows = []
    for label, name in names:
        m = case(name)
        t = m["truth"]
        rows.append(f"| {label} | {pct(t['interior_false_shadow'])} | {pct(t['interior_false_lit'])} | "
                    f"{pct(t['contact_false_lit'])} | {pct(t['umbra_light'])} | {m['triangles_submitted']['shadow']:,} |")
    c, s, mp, d, p = (case(n)["truth"] for _, n in names)
    leaky = [k for k, v in sorted(case("bias-second-depth").get("meshes", {}).items())
             if v["truth"]["interior_false_lit"] > 0.001]
    tri = case("bias-midpoint")["triangles_submitted"]["shadow"] / case("bias-constant")["triangles_submitted"]["shadow"]
    ordering = (mp["interior_false_shadow"] < s["interior_false_shadow"] < c["interior_false_shadow"]
                and s["interior_false_lit"] > c["interior_false_lit"] and d["interior_false_lit"] < mp["interior_false_lit"]
                and p["interior_false_shadow"] <= 0.001 and tri > 1.9)
    ctx.entry(
        "Table 1", "z-bias functions: acne and peter-panning",
        "The stored depth is z_1 + z_bias(z_1, z_2) with (a) a constant z_offset, (b) second depth z_2 − z_1, "
        "(c) midpoint (z_2 − z_1)/2, (d) dual depth min((z_2 − z_1)/2, z_max). Second depth needs solid "
        "objects, which CAD models often lack; the midpoint variants give the best results in a general scene "
        "but need a second (depth-peeling) pass; z_max avoids self-unshadowing. The paper recommends a small "
        "constant bias, with PCF's virtual samples on the tangent plane to prevent self-shadowing.",
        "The `deck` view, the paper's settings, each bias function with one tap (no filter, no sample "
        "alignment) so the function alone decides, and last the paper's recommendation. Truth classes "
        "(docs/design.md §4): `interior_false_shadow` is acne, `interior_false_lit` leaks far from an edge, "
        "`contact_false_lit` peter-panning next to the occluder, `umbra_light` light inside the truth's "
        "umbrae; the shadow pass's triangles show the second layer:\n\n"
        "| z_bias | acne (interior false shadow) | leaks (interior false lit) | peter-panning (contact false lit) "
        "| light in umbrae | shadow-pass triangles |\n|---|---|---|---|---|---|\n" + "\n".join(rows) + "\n\n"
        "Check bounds: midpoint's acne ≤ 0.2× constant's, second depth's ≤ 0.5×; second depth and midpoint "
        "leak (interior false lit ≥ 0.02 %), constant and dual depth do not (≤ 0.01 %); midpoint and dual "
        "depth submit ≥ 1.9× the shadow triangles; the paper's recommendation has acne ≤ 0.1 %.",
        "agrees in shape" if ordering else "disagrees",
        ("Midpoint has the least acne and second depth leaks light through the platform's open, non-solid "
         "parts ("
         f"{', '.join(f'`{k}`' for k in leaky) or 'none found'}), as the paper says, and both midpoint variants cost a second layer. Two "
         "differences: midpoint leaks too (self-unshadowing; dual depth's cap removes it, as the paper "
         "intends), and with z_max = 0.5 m (the paper gives no value) dual depth keeps most of constant "
         f"bias's acne ({pct(d['interior_false_shadow'])}). A constant bias alone leaves "
        f"{pct(c['interior_false_shadow'])} acne with one tap; with the tangent-plane PCF the paper recommends "
         f"it is {pct(p['interior_false_shadow'])}.")
        if ordering else "the measured ordering no longer matches the paper's: see the table.")


# ---- Table 2: frame-time ratios, one and two lights -----------------------------------------------

BEGIN, END = "<!-- reproduce-table2: begin", "<!-- reproduce-table2: end -->"


def table2(ctx):
    """Runs scripts/reproduce-table2 --print (with --full, or by default where TABLE2_BY_DEFAULT) and
    keeps its marked block in the entry, so that scripts/reproduce-table2 alone updates it in place;
    otherwise carries the last measured block forward from docs/papers.md."""
    old = ctx.papers_md.read_text() if ctx.papers_md.exists() else ""
    measured = ctx.full or TABLE2_BY_DEFAULT or BEGIN not in old or END not in old
    if measured:
        t0 = time.monotonic()
        done = subprocess.run([str(ctx.root / "scripts" / "reproduce-table2"), "--print",
                               "--build", str(ctx.exe.parent.parent.relative_to(ctx.root))],
                              cwd=ctx.root, text=True, capture_output=True)
        if done.returncode != 0:
            sys.exit(f"reproduce-papers: scripts/reproduce-table2 failed: {done.stderr.strip()}")
        block = done.stdout[done.stdout.index(BEGIN):done.stdout.index(END) + len(END)]
        ctx.commands.append(f"scripts/reproduce-table2 --print   ({time.monotonic() - t0:.0f} s)")
        how = "measured by this run"
    else:
        block = old[old.index(BEGIN):old.index(END) + len(END)]
        how = ("carried forward from the last measurement (the benchmark alone takes 1.5–3 minutes on the "
               "shared 2-core machine, beyond this page's default budget: `scripts/reproduce-papers --full` or "
               "`scripts/reproduce-table2` measures it again)")
    ours = {}  # lights -> (paper's low, paper's high, ours for the paper preset, our range low, high)
    for m in re.finditer(r"^\| (\d) \| \d+ \| [\d–]+ \| ([\d.]+)–([\d.]+) \| ([\d.]+) \|.*\| ([\d.]+)–([\d.]+) \|$",
                         block, re.M):
        ours[int(m[1])] = tuple(float(x) for x in m.groups()[1:])
    inside = all(lo <= mine <= hi for lo, hi, mine, _, _ in ours.values())
    faster = [k for k, (_, _, mine, _, _) in ours.items() if mine > 1]
    summary = "; ".join(f"{k} light{'s' if k > 1 else ''}: the paper's settings at {mine:.2f} of the standard "
                        f"map's rate (the paper: {lo:.2f}–{hi:.2f}; all three techniques {rlo:.2f}–{rhi:.2f})"
                        for k, (lo, hi, mine, rlo, rhi) in sorted(ours.items()))
    ctx.entry(
        "Table 2", "frame-time ratios, one and two lights",
        "On a GeForce 8800 GTS, 800×600, 2048² maps, a close-up with about 20 % of the 250k-triangle "
        "platform visible and the lights circling it: the standard map ran at 45 fps (1 light) and 25 fps "
        "(2 lights), the recommended techniques at 29–59 and 18–30 fps, i.e. 0.64–1.31 and 0.72–1.20 of the "
        "standard map's rate, sometimes faster thanks to per-partition culling.",
        "The 2007 GPU is gone, so what compares is each technique's rate relative to the standard map's in the "
        "same run. `scripts/reproduce-table2` runs `frame_benchmark --benchmark_filter=^Table2/`: the "
        "platform's `deck` view, directional lights circling in 45° steps at 40° elevation (two lights "
        "opposite each other), ssm against the paper, lispsm and pssm3 presets, frame pairs alternating so "
        f"that the machine's drift cancels. The table is {how}:\n\n{block}\n\n"
        "`scripts/reproduce-table2` alone rewrites only the table between its markers; the verdict quotes it as "
        "of the last `scripts/reproduce-papers` run. No check case: frame times on a shared CPU renderer are "
        "too noisy to bound in the test command.",
        "agrees in shape" if inside and ours else "disagrees",
        f"{summary}. "
        + ("Inside the paper's ranges, " if inside else "Outside the paper's ranges, ")
        + ("and above 1 as in the paper's best views." if faster else
           "but at their low end: the paper's settings never beat the standard map here, where the paper's ran "
           "up to 1.31× as fast. On llvmpipe (rasterization on the CPU) the second map and the 5×5 PCF cost more "
           "than per-split culling saves; whether the ratio passes 1 on a GPU is still open. The ratios vary by "
           "about ±0.1 from run to run on the shared machine."))
