#!/usr/bin/env python3
"""Writes DIR/accuracy.md from the results bench/run left in DIR/accuracy/.

    python3 bench/accuracy_page.py [--dir docs]

Every figure on the page is read from the CSV and text files of the run; nothing is typed in. Each
section needs its run record (NAME/run.txt, written by bench/run), its CSV files with at least one
data row and its plot: a section that lacks one of them, or whose benchmark failed, is marked so on the
page, and the script exits with status 3 after writing the page (0 when every section is complete).
Python 3 standard library only.
"""

import argparse
import csv
import math
import os
import statistics
import sys

SECTIONS = ["geodesic", "revolution", "groove", "groove-bake", "tam", "stroke", "paintstrokes", "resources", "startup"]


class Missing(Exception):
    """A result the section needs is absent or empty."""


# ---------------------------------------------------------------------------------------------------
# Reading


def read_record(path):
    """key=value lines; 'key<<' starts a block that runs to the end of the file."""
    record = {}
    if not os.path.isfile(path):
        return None
    with open(path, encoding="utf-8") as f:
        lines = f.read().splitlines()
    for i, line in enumerate(lines):
        if line.endswith("<<"):
            record[line[:-2]] = "\n".join(lines[i + 1:])
            break
        key, sep, value = line.partition("=")
        if sep:
            record[key] = value
    return record


def read_csv(directory, name):
    path = os.path.join(directory, name)
    if not os.path.isfile(path):
        raise Missing(f"{name} is missing")
    with open(path, newline="", encoding="utf-8") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        raise Missing(f"{name} has no data rows")
    return rows


def read_text(directory, name):
    path = os.path.join(directory, name)
    if not os.path.isfile(path) or os.path.getsize(path) == 0:
        raise Missing(f"{name} is missing or empty")
    with open(path, encoding="utf-8") as f:
        return f.read()


def num(value):
    """A float from a CSV cell; NaN when empty or not a number."""
    try:
        return float(value)
    except (TypeError, ValueError):
        return math.nan


# ---------------------------------------------------------------------------------------------------
# Formatting


def fmt(x, digits=3):
    """Significant digits, plain notation for ordinary magnitudes; '-' for NaN."""
    if x is None or (isinstance(x, float) and math.isnan(x)):
        return "-"
    if isinstance(x, float) and math.isinf(x):
        return "inf"
    if x == 0:
        return "0"
    magnitude = math.floor(math.log10(abs(x)))
    if magnitude < -3 or magnitude >= 7:
        return f"{x:.{digits - 1}e}"
    decimals = max(0, digits - 1 - magnitude)
    return f"{x:,.{decimals}f}"


def ratio(a, b):
    if a is None or b is None or math.isnan(a) or math.isnan(b) or b == 0:
        return math.nan
    return a / b


def fmt_ratio(x):
    return "-" if math.isnan(x) else f"{fmt(x)}×"


def pct(x):
    return "-" if math.isnan(x) else f"{fmt(100 * x)} %"


def table(header, rows):
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    for row in rows:
        lines.append("| " + " | ".join(str(c) for c in row) + " |")
    return "\n".join(lines)


# ---------------------------------------------------------------------------------------------------
# Sections: each returns markdown and reads the files it needs (raising Missing when one is absent)


def geodesic(d, run):
    rows = read_csv(d, "geodesic.csv")
    ok = [r for r in rows if r["status"] == "ok" and r["seconds"] != ""]
    if not ok:
        raise Missing("geodesic.csv has no completed row")
    out = []
    out.append(
        "**Measured:** per-vertex geodesic distance from one source and from eight sources (one combined "
        "min-field) on a mesh ladder: the shared real meshes (`../shared/data/meshes/real`) and an "
        "icosphere, refined by 1:4 midpoint subdivision up to the mode's largest rung. Time of one "
        "field (setup + solve; the median of repeated fields) against the error.\n\n"
        "**Reference:** exact polyhedral distances (our window propagation; CGAL's exact method where "
        "ours failed). Errors are the mean and largest |d − d_exact| over the reached vertices, divided "
        "by the field's largest exact distance.\n\n"
        "**Peers in this run:** CGAL `Surface_mesh_shortest_path` (`cgal-exact`) and CGAL "
        "`Heat_method_3` with intrinsic Delaunay (`cgal-heat`); ours: `exact`, `heat`, `fmm`.")

    def key(r):
        return (r["mesh"], r["sources"], r["method"])

    by = {key(r): r for r in ok}

    def total(r):
        return num(r["seconds"]) + num(r["setup_seconds"]) if r else math.nan

    # Per base mesh, the largest rung (one source).
    largest = {}
    for r in ok:
        if r["sources"] != "1":
            continue
        base = r["mesh"].split("/")[0]
        if base not in largest or int(r["triangles"]) > int(largest[base]["triangles"]):
            largest[base] = r
    body = []
    for base, r in sorted(largest.items(), key=lambda kv: int(kv[1]["triangles"])):
        m = r["mesh"]
        ex, cex = by.get((m, "1", "exact")), by.get((m, "1", "cgal-exact"))
        ht, cht = by.get((m, "1", "heat")), by.get((m, "1", "cgal-heat"))
        fm = by.get((m, "1", "fmm"))
        body.append([
            f"`{m}`", f"{int(r['triangles']):,}",
            fmt(total(ex)), fmt(total(cex)), fmt_ratio(ratio(total(ex), total(cex))),
            fmt(num(cex["max_rel_error"])) if cex else "-",
            fmt(total(ht)), fmt(total(cht)), fmt_ratio(ratio(total(ht), total(cht))),
            fmt(num(ht["mean_rel_error"])) if ht else "-", fmt(num(cht["mean_rel_error"])) if cht else "-",
            fmt(total(fm)), fmt(num(fm["mean_rel_error"])) if fm else "-",
        ])
    out.append("Largest rung of each base mesh, one source (seconds = setup + one field; "
               "'CGAL exact vs ours' is the largest relative difference between the two exact methods):")
    out.append(table(["rung", "triangles", "exact s", "CGAL exact s", "ours / CGAL", "CGAL exact vs ours",
                      "heat s", "CGAL heat s", "ours / CGAL", "heat mean err", "CGAL heat mean err",
                      "fmm s", "fmm mean err"], body))

    # Every method on the largest rung where the CGAL peers ran too (else the largest), both source counts.
    def ran(mesh, method):
        return (mesh, "1", method) in by

    with_peers = ([r for r in ok if ran(r["mesh"], "cgal-exact") and ran(r["mesh"], "cgal-heat")]
                  or [r for r in ok if r["method"].startswith("cgal-")] or ok)
    top = max(with_peers, key=lambda r: int(r["triangles"]))["mesh"]
    body = []
    for sources in ("1", "8"):
        for method in ("exact", "cgal-exact", "heat", "cgal-heat", "fmm"):
            r = by.get((top, sources, method))
            if not r:
                continue
            body.append([sources, method, fmt(num(r["setup_seconds"])), fmt(num(r["seconds"])),
                         fmt(num(r["mean_rel_error"])), fmt(num(r["max_rel_error"])), r["reference"], r["runs"]])
    tri = next(int(r["triangles"]) for r in ok if r["mesh"] == top)
    out.append(f"Every method on the largest rung the peers ran on, `{top}` ({tri:,} triangles):")
    out.append(table(["sources", "method", "setup s", "per field s", "mean rel. error", "max rel. error",
                      "reference", "runs"], body))
    bad = [r for r in rows if r["status"] != "ok"]
    if bad:
        # One line per mesh and reason: the methods and source counts it hit.
        groups = {}
        for r in bad:
            g = groups.setdefault((r["mesh"], r["status"]), [[], []])
            if r["method"] not in g[0]:
                g[0].append(r["method"])
            if r["sources"] not in g[1]:
                g[1].append(r["sources"])
        out.append(f"{len(bad)} of {len(rows)} rows did not complete:\n\n" + "\n".join(
            f"- `{mesh}`: {', '.join(m)} ({' and '.join(src)} sources): {status}"
            for (mesh, status), (m, src) in groups.items()))
    else:
        out.append(f"All {len(rows)} rows completed.")
    return "\n\n".join(out), ["geodesic.png"]


def revolution(d, run):
    march = read_csv(d, "march.csv")
    bake = read_csv(d, "bake.csv")
    edt = read_csv(d, "edt.csv")
    out = []
    out.append(
        "**Measured:** the runtime shader's sphere-tracing ray march, run on the CPU against the baked "
        "shape map (unorm16, revolbake's grid) for iteration budgets 10…256: silhouette mismatch "
        "against the single-threaded march time per ray; the shape-map bake cost per resolution and "
        "encoding; the binary-image EDT.\n\n"
        "**Reference:** the analytic ray / surface-of-revolution intersection (6 views × 128² rays); "
        "the mismatch is the share of rays whose hit/miss differs, over the rays either hits. Stored "
        "distances: against the exact signed distance at every texel centre.\n\n"
        "**Peers in this run:** the same march without the stacked proxy bands (the plain bounding "
        "box start); OpenCV `cv::distanceTransform(DIST_L2, DIST_MASK_PRECISE)` for the EDT.")
    target = 0.005
    profiles = list(dict.fromkeys(r["profile"] for r in march))
    body = []
    for p in profiles:
        def series(proxy):
            s = [r for r in march if r["profile"] == p and r["proxy"] == proxy and abs(num(r["omega"]) - 1.6) < 1e-9]
            return sorted(s, key=lambda r: int(r["iterations"]))

        def at(s, it):
            return next((r for r in s if int(r["iterations"]) == it), None)

        def reach(s):
            return next((r for r in s if num(r["silhouette_mismatch"]) <= target), None)

        yes, no = series("1"), series("0")
        y35, n35 = at(yes, 35), at(no, 35)
        ry, rn = reach(yes), reach(no)
        body.append([
            p,
            pct(num(y35["silhouette_mismatch"])) if y35 else "-", pct(num(n35["silhouette_mismatch"])) if n35 else "-",
            fmt(num(y35["ns_per_ray"])) if y35 else "-", fmt(num(n35["ns_per_ray"])) if n35 else "-",
            fmt_ratio(ratio(num(y35["ns_per_ray"]), num(n35["ns_per_ray"]))) if y35 and n35 else "-",
            ry["iterations"] if ry else "not within the budgets", rn["iterations"] if rn else "not within the budgets",
            fmt(num(ry["ns_per_ray"])) if ry else "-", fmt(num(rn["ns_per_ray"])) if rn else "-",
            fmt_ratio(ratio(num(ry["ns_per_ray"]), num(rn["ns_per_ray"]))) if ry and rn else "-",
        ])
    out.append("The march at over-relaxation 1.6 (revolbake's default), with the proxy bands (ours) "
               "and without (peer); target mismatch 0.5 %:")
    out.append(table(["profile", "mismatch @35 it", "no proxy @35 it", "ns/ray @35", "no proxy ns/ray @35",
                      "ours / peer", "budget to 0.5 %", "no proxy: budget", "ns/ray there",
                      "no proxy: ns/ray there", "ours / peer"], body))
    res = max(int(r["resolution"]) for r in bake)
    body = []
    for r in bake:
        if int(r["resolution"]) != res:
            continue
        body.append([r["profile"], r["encoding"], f"{r['width']} × {r['height']}", fmt(num(r["distance_s"])),
                     fmt(num(r["encode_margin_s"])), fmt(num(r["margin_texels"])),
                     fmt(num(r["stored_max_error_texels"]))])
    out.append(f"Shape-map bake at the largest resolution, {res} texels (seconds: exact distance field, then "
               "encode + decode + safety margin; errors in texels):")
    out.append(table(["profile", "encoding", "texels", "distance s", "encode/margin s", "margin",
                      "stored max error"], body))
    body = [[f"{r['size']}²", fmt(num(r["ours_ms"])), fmt(num(r["opencv_ms"])),
             fmt_ratio(num(r["ours_over_opencv"])), fmt(num(r["max_abs_diff_opencv"])),
             f"{r['wrong']} of {r['checked']}", r["threads"]]
            for r in edt]
    out.append("Exact binary EDT (24 random discs), ours against OpenCV (milliseconds, medians; OpenCV 4.6 "
               "is wrong beyond 4096², so exactness is checked apart: ours against brute force in 64-bit "
               "integers at 4,100 texels per size; a size without OpenCV figures is only checked):")
    out.append(table(["size", "ours ms", "OpenCV ms", "ours / OpenCV", "max abs. diff. from OpenCV (texels)",
                      "ours wrong", "threads"], body))
    return "\n\n".join(out), ["revolution.png"]


def spp_of(run):
    words = (run or {}).get("command", "").split()
    for i, w in enumerate(words):
        if w == "--spp" and i + 1 < len(words):
            return words[i + 1]
        if w.startswith("--spp="):
            return w.split("=", 1)[1]
    return None


def groove(d, run):
    rows = read_csv(d, "groove.csv")
    read_text(d, "groove-summary.txt")
    spp = spp_of(run)
    out = []
    out.append(
        "**Measured:** the seed's groove shading as the runtime shader computes it (CPU port of "
        "`libbake/grooves/oracle/shade.h`: exact trapezoid footprint density), per view of "
        "`bench/groove/cases.json` on the scenes of `bench/groove/scenes/`: RMSE and cost per pixel "
        "(CPU time over the pixels, both renderers on one thread; small frames are rendered repeatedly per measurement; "
        "the method's measurements alternate with the reference's renders (two, more for timing alone where they "
        "take under 0.3 s together) and each side keeps its fastest).\n\n"
        f"**Reference:** the independent ray tracer of `libbake/grooves/reference/reference.h` at "
        f"{spp + ' stratified samples per pixel' if spp else 'its default samples per pixel'}, rendered "
        "twice with different seeds: the RMSE between the two is its noise floor, and errors are quoted "
        "as RMSE / floor (criterion ≤ 3) next to the cost ratio reference / method (criterion ≥ 50).\n\n"
        "**Peers in this run:** the method as the seed publishes it (uniform footprint segment), against "
        "the same reference; the reference itself for cost. Where the run drew the views with the runtime too "
        "(`--runtime`: bakeplay's grooves renderer on a headless GL context, an oblique orthographic projection "
        "whose pixels are the views' footprints), its RMSE / floor is given beside the CPU port's, and how "
        "many fragments it shaded from the far level (footprints over more primitives than the shader holds, "
        "`formats/grooves.md`).")
    has_runtime = rows and "runtime_rmse_over_floor" in rows[0] and any(num(r["runtime_rmse"]) >= 0 for r in rows)
    cases = list(dict.fromkeys(r["case"] for r in rows))
    body = []
    meets = 0
    within_floor = 0
    cheap = 0
    for c in cases:
        rs = [r for r in rows if r["case"] == c]
        worst = max(num(r["rmse_over_floor"]) for r in rs)
        seed = max(num(r["seed_rmse_over_floor"]) for r in rs)
        cost = min(num(r["cost_ratio"]) for r in rs)
        method_ns = statistics.median(num(r["method_ns_per_pixel"]) for r in rs)
        ref_ns = statistics.median(num(r["reference_ns_per_pixel"]) for r in rs)
        ok = worst <= 3 and cost >= 50
        meets += ok
        within_floor += worst <= 3
        cheap += cost >= 50
        line = [c, len(rs), fmt(worst), fmt(seed)]
        if has_runtime:
            runtime_worst = max(num(r["runtime_rmse_over_floor"]) for r in rs)
            within_floor_runtime = runtime_worst <= 3
            ok = ok and within_floor_runtime
            line += [fmt(runtime_worst), fmt(sum(num(r["runtime_far_fragments"]) for r in rs))]
        body.append(line + [fmt(method_ns), fmt(ref_ns), fmt(cost), "yes" if ok else "no"])
    note = ""
    if spp and int(spp) != 256:
        note = (f" The cost criterion is stated against the reference at 256 samples per pixel; this run's "
                f"reference took {spp}, so its cost ratios are lower than the criterion assumes, and its "
                "noise floor is higher.")
    out.append(f"Per case (worst view; {len(rows)} views in all): {within_floor} of {len(cases)} cases are "
               f"within 3× the noise floor, {cheap} of {len(cases)} at least 50× cheaper than the "
               f"reference, {meets} meet both.{note}")
    runtime_columns = ["runtime RMSE / floor", "runtime far fragments"] if has_runtime else []
    out.append(table(["case", "views", "RMSE / floor", "seed's variant RMSE / floor"] + runtime_columns +
                     ["method CPU ns/px (median)", "reference CPU ns/px (median)", "smallest cost ratio",
                      "both criteria"], body))
    return "\n\n".join(out), ["groove.png"]


def groove_bake(d, run):
    sizes = read_csv(d, "groove-bake.csv")
    sweep = read_csv(d, "cell-size.csv")
    out = []
    out.append(
        "**Measured:** `groovebake` end to end (`/usr/bin/time`, wall and CPU = user + system of all "
        "threads) on deterministic random patterns of 10³–10⁵ grooves (`bench-groove-scene`), and a sweep "
        "of `--cell-size` on the largest: bake time against references per cell (the runtime's lookup "
        "cost) and the stored geometry's error.\n\n"
        "**Reference:** the input scene's double-precision geometry; the error is the largest distance "
        "between a stored (cell-local fp32) position and the input's.\n\n"
        "**Peers in this run:** none (no other groove-grid baker exists to run); the ratios are against "
        "the automatic cell size of the same run.")
    body = []
    for r in sizes:
        body.append([f"{int(r['grooves']):,}", f"{fmt(num(r['domain']))} mm", fmt(num(r["wall_s"])),
                     fmt(num(r["cpu_s"])), f"{r['columns']}²", f"{fmt(num(r['mean_refs']))}, {r['max_refs']}",
                     f"{int(num(r['intersections'])):,}", fmt(num(r["file_bytes"]) / 1e6) + " MB",
                     fmt(num(r["max_position_error"]))])
    out.append("Bake time against the groove count (medians of the runs; stage times in `groove-bake.csv`):")
    out.append(table(["grooves", "domain", "wall s", "CPU s", "grid", "refs/cell mean, max", "intersections",
                      "package", "max position error (mm)"], body))
    auto = next((r for r in sweep if num(r["factor"]) == 1), None)
    body = []
    for r in sweep:
        body.append([f"× {r['factor']}", f"{fmt(num(r['cell_size']))} mm", fmt(num(r["wall_s"])),
                     fmt_ratio(ratio(num(r["wall_s"]), num(auto["wall_s"]))) if auto else "-",
                     fmt(num(r["cpu_s"])), f"{fmt(num(r['mean_refs']))}, {r['max_refs']}",
                     fmt(num(r["file_bytes"]) / 1e6) + " MB", fmt(num(r["max_position_error"]))])
    out.append(f"Cell size sweep on the largest scene ({int(sizes[-1]['grooves']):,} grooves):")
    out.append(table(["× automatic", "cell size", "wall s", "wall / automatic", "CPU s", "refs/cell mean, max",
                      "package", "max position error (mm)"], body))
    return "\n\n".join(out), ["groove-bake.png"]


def tam(d, run):
    rows = read_csv(d, "tam.csv")
    out = []
    out.append(
        "**Measured:** tonal art map construction (`libbake/hatching`, the default hatching style: 6 tones, 4 "
        "stroke levels) over the candidate count K and the finest resolution: median construction time "
        "against the tone error and the uniformity of the ink.\n\n"
        "**Reference:** the style's target tones (exact values): the largest |tone − target| over all "
        "images, over its tolerance max(0.25 %, 0.8 / N); uniformity by the largest window coefficient of "
        "variation (CV) and low-frequency power over the images in scope (`libbake/hatching/bake/quality.h`).\n\n"
        "**Peers in this run:** no outside implementation; K = 1 (the first random candidate, no "
        "selection) is the baseline the time ratios refer to.")
    base = {r["resolution"]: num(r["seconds"]) for r in rows if r["candidates"] == "1"}
    body = []
    for r in rows:
        cv = num(r["max_cv"])
        lfp = num(r["max_low_frequency_power"])
        body.append([f"{r['resolution']}²", r["candidates"], fmt(num(r["seconds"])),
                     fmt_ratio(ratio(num(r["seconds"]), base.get(r["resolution"], math.nan))),
                     fmt(num(r["max_tone_error_over_tolerance"])), fmt(cv) if cv > 0 else "-",
                     pct(lfp) if lfp > 0 else "-", r["nesting_violations"], f"{int(num(r['strokes'])):,}"])
    out.append("Per resolution and K ('-': no image of that size is in the uniformity scope):")
    out.append(table(["resolution", "K", "seconds", "time / K=1", "tone error / tolerance", "CV (scope)",
                      "low-freq. power (scope)", "nesting violations", "strokes"], body))
    return "\n\n".join(out), ["tam.png"]


def stroke(d, run):
    rows = read_csv(d, "stroke.csv")
    out = []
    out.append(
        "**Measured:** one curved paint stroke (three control points, about 80 px long) rasterised into "
        "a 256² wrapping tile, the case `tambake` repeats thousands of times: CPU µs per stroke (Google "
        "Benchmark) against the largest per-pixel coverage error and the relative ink error.\n\n"
        "**Reference:** an area oracle, 32 × 32 point samples per pixel of the distance to the spline "
        "(good to about 0.003).\n\n"
        "**Peers in this run:** point supersampling (2×2, 4×4, 8×8 per pixel) of the same stroke; ours is "
        "`bake::stroke::rasterize` at piece lengths 0.5–4 px (default 2).")
    radii = list(dict.fromkeys(r["radius"] for r in rows))

    def find(method, radius, knob):
        return next((r for r in rows if r["method"] == method and r["radius"] == radius and num(r["knob"]) == knob), None)

    body = []
    for rad in radii:
        o, p = find("ours", rad, 2), find("supersample", rad, 4)
        body.append([rad,
                     fmt(num(o["cpu_us"])) if o else "-", fmt(num(o["max_pixel_error"])) if o else "-",
                     fmt(num(p["cpu_us"])) if p else "-", fmt(num(p["max_pixel_error"])) if p else "-",
                     fmt_ratio(ratio(num(o["cpu_us"]), num(p["cpu_us"]))) if o and p else "-",
                     fmt_ratio(ratio(num(o["max_pixel_error"]), num(p["max_pixel_error"]))) if o and p else "-",
                     fmt(num(o["ink_error"])) if o else "-"])
    out.append("Ours at the default 2 px pieces against 4×4 supersampling, per stroke radius (px):")
    out.append(table(["radius", "ours µs", "ours max px error", "4×4 µs", "4×4 max px error", "time ours / peer",
                      "error ours / peer", "ours ink error"], body))
    return "\n\n".join(out), ["stroke.png"]


def paintstrokes(d, run):
    rows = read_csv(d, "paintstrokes.csv")
    equal = read_csv(d, "paintstrokes-equal-error.csv")
    out = []
    out.append(
        "**Measured:** `bakeplay render` of three baked stroke sets (helical curls around a sphere, a tree, "
        "fur grown on a torus), three views each (close, mid, far): the polygons (triangles) and vertices "
        "the GPU generated for the strokes (GL primitive query), the median frame time and the image "
        "error. Paintstrokes are tessellated on the GPU for every view (seed 002) at quality levels 0, 1, 2 "
        "over the subdivision tolerance; the peer is the same strokes as fixed tubes tessellated on the "
        "CPU (sides around × steps per segment).\n\n"
        "**Reference:** the same strokes as fine fixed tubes (the finest `--stroke-tubes` setting of the "
        "run), same shading; RMSE of the 8-bit sRGB images (`idiff`), 0..1.\n\n"
        "**Peers in this run:** fixed tubes over a sweep of sides × steps; the criterion compares the "
        "polygons quality 1 needs with those the tubes need for the same RMSE (within 10 %). Paintstrokes "
        "skip strokes whose bounding sphere is outside the view; the tubes are drawn whole, as a static "
        "mesh would be, so in the close views part of the ratio is that culling. Frame times are those of "
        "the run's GL driver (in CI Mesa llvmpipe, where tessellation stages run on the CPU): the seed's "
        "claim, and the criterion, are about polygons.")
    body = []
    ratios = []
    for r in equal:
        if num(r["tolerance_px"]) != 0.5:
            continue
        ps = next((x for x in rows if x["set"] == r["set"] and x["view"] == r["view"] and x["method"] == "paintstrokes"
                   and x["quality"] == "1" and num(x["tolerance_px"]) == 0.5), None)
        tube = next((x for x in rows if x["set"] == r["set"] and x["view"] == r["view"] and x["method"] == "tubes"
                     and f"{x['sides']}x{x['steps']}" == r["tubes"]), None)
        ratio_i = num(r["ratio_interpolated"]) if r["ratio_interpolated"] else None
        ratios.append(ratio_i)
        body.append([f"{r['set']} / {r['view']}", fmt(num(r["polygons"])), fmt(num(r["rmse"])),
                     r["tubes"] or "none reached it", fmt(num(r["tube_polygons"])) if r["tube_polygons"] else "-",
                     fmt(num(r["tube_rmse"])) if r["tube_rmse"] else "-",
                     fmt_ratio(num(r["ratio"])) if r["ratio"] else "-",
                     fmt_ratio(ratio_i) if ratio_i else "-",
                     fmt(num(ps["frame_ms"])) if ps and ps["frame_ms"] else "-",
                     fmt(num(tube["frame_ms"])) if tube and tube["frame_ms"] else "-"])
    if not body:
        raise Missing("no quality-1 row at the default 0.5 px tolerance in paintstrokes-equal-error.csv")
    met = sum(1 for x in ratios if x is not None and x >= 3)
    out.append(f"Quality 1 at the default 0.5 px tolerance against the cheapest fixed tubes of the sweep within "
               f"10 % of its RMSE, and against the tube polygon count interpolated (log-log along the tubes' "
               f"Pareto front) at exactly its RMSE: {met} of {len(body)} views at least 3× fewer polygons "
               f"(interpolated figure).")
    out.append(table(["set / view", "q1 polygons", "q1 RMSE", "tubes", "tube polygons", "tube RMSE",
                      "tubes / q1", "tubes / q1 (interpolated)", "q1 ms", "tubes ms"], body))
    return "\n\n".join(out), ["paintstrokes.png"]


def resources(d, run):
    rows = read_csv(d, "resources.csv")
    commands = read_text(d, "resources-commands.txt").strip().splitlines()
    out = []
    out.append(
        "Peak memory (largest resident set size) and wall time of one run of every tool on its largest "
        "benchmark input, measured with GNU `/usr/bin/time -f '%e %M'` (bakers with `-j 2`; bakeplay "
        "headless on EGL, llvmpipe when there is no GPU). Single runs on a shared machine: the times are "
        "indicative, the memory figures are stable.")
    body = []
    for r in rows:
        body.append([f"`{r['tool']}`", r["input"], r["size"], fmt(num(r["wall_s"])), fmt(num(r["peak_rss_mib"]))])
    out.append(table(["tool", "input", "size", "wall s", "peak RSS MiB"], body))
    failed = [r for r in rows if r["wall_s"] == ""]
    if failed:
        out.append(f"**{len(failed)} run(s) failed:** " + "; ".join(f"{r['tool']} {r['input']}: {r['size']}" for r in failed))
    out.append("The commands (`SCRATCH/` is the scratch folder under the build directory):\n\n```\n"
               + "\n".join(commands) + "\n```")
    return "\n\n".join(out), []


STARTUP_GOAL_MS = 50


def startup(d, run):
    rows = read_csv(d, "startup.csv")
    out = []
    out.append(
        "Start-up of every tool, whole process: the median wall time of repeated runs of `--version` "
        "and `--help`, of one small image job (which loads the image codec module, OpenImageIO), and of "
        "peers in the same run. What a build system pays per call before any work.")
    peers = [num(r["median_ms"]) for r in rows if r["group"] == "peer" and "oiiotool" in r["command"]]
    oiiotool = peers[0] if peers else None
    body = []
    for r in rows:
        ratio = fmt(num(r["median_ms"]) / oiiotool) if oiiotool else "-"
        body.append([f"`{r['command']}`", r["group"], r["runs"], fmt(num(r["median_ms"])), fmt(num(r["min_ms"])),
                     fmt(num(r["max_ms"])), ratio])
    out.append(table(["command", "group", "runs", "median ms", "min ms", "max ms", "/ oiiotool"], body))
    versions = [r for r in rows if r["group"] == "ours" and r["command"].endswith("--version")]
    if not versions:
        raise ValueError("startup.csv has no `--version` rows")
    slowest = max(versions, key=lambda r: num(r["median_ms"]))
    met = all(num(r["median_ms"]) <= STARTUP_GOAL_MS for r in versions)
    out.append(f"Goal: every tool's `--version` within {STARTUP_GOAL_MS} ms: **{'met' if met else 'not met'}** "
               f"(slowest `{slowest['command']}`, {fmt(num(slowest['median_ms']))} ms).")
    return "\n\n".join(out), []


TITLES = {
    "geodesic": ("`geobake`: geodesic distance, error against time", geodesic),
    "revolution": ("`revolbake`: revolution mapping, ray-march error against time; EDT", revolution),
    "groove": ("Groove shading (`groovebake` packages): the seed's method against a ray-traced reference", groove),
    "groove-bake": ("`groovebake`: bake time on large patterns, cell size against error", groove_bake),
    "tam": ("`tambake`: tonal art maps, quality against construction time", tam),
    "stroke": ("`tambake` strokes: rasterisation error against time", stroke),
    "paintstrokes": ("`strokebake` paintstrokes: polygons against image error, against fixed tubes", paintstrokes),
    "resources": ("Resources: peak memory and time of every tool", resources),
    "startup": ("Start-up: every tool's whole-process start against peers", startup),
}


# ---------------------------------------------------------------------------------------------------


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--dir", default="docs", help="folder with accuracy/ (the page is written here)")
    args = parser.parse_args()
    acc = os.path.join(args.dir, "accuracy")
    header = read_record(os.path.join(acc, "run.txt"))
    if header is None:
        print(f"accuracy_page: error: {acc}/run.txt is missing (run bench/run)", file=sys.stderr)
        return 3

    problems = []
    sections = []
    overview = []
    for name in SECTIONS:
        title, build = TITLES[name]
        d = os.path.join(acc, name)
        run = read_record(os.path.join(d, "run.txt"))
        text = [f"## {title}"]
        if run is None:
            problems.append(f"{name}: not run")
            text.append(f"**Not run:** no results in `accuracy/{name}/` (run `bench/run --only {name}`).")
            overview.append([f"[{name}](#{anchor(title)})", "-", "-", "-", "**not run**"])
            sections.append("\n\n".join(text))
            continue
        status = "ok" if run.get("exit") == "0" else f"**failed** (exit {run.get('exit')})"
        overview.append([f"[{name}](#{anchor(title)})", run.get("mode", "-"), run.get("date", "-"),
                         run.get("seconds", "-"), status])
        if run.get("exit") != "0":
            problems.append(f"{name}: benchmark failed (exit {run.get('exit')})")
            text.append(f"**This benchmark failed** (exit {run.get('exit')} after {run.get('seconds')} s). "
                        "The end of its log:\n\n```\n" + run.get("log_tail", "").strip() + "\n```")
        try:
            body, plots = build(d, run)
            text.append(body)
            for png in plots:
                path = os.path.join(d, png)
                if not os.path.isfile(path) or os.path.getsize(path) == 0:
                    raise Missing(f"the plot {png} is missing")
                text.append(f"![{name}: {png}](accuracy/{name}/{png})")
        except Missing as e:
            problems.append(f"{name}: {e}")
            text.append(f"**Results missing:** {e}.")
        except (KeyError, ValueError, StopIteration) as e:
            problems.append(f"{name}: unreadable results ({type(e).__name__}: {e})")
            text.append(f"**Results unreadable:** {type(e).__name__}: {e}.")
        files = sorted(f for f in os.listdir(d) if f != "run.txt") if os.path.isdir(d) else []
        mode_flag = " --quick" if run.get("mode") == "quick" else ""
        text.append(
            f"Made in {run.get('mode')} mode on {run.get('date')} in {run.get('seconds')} s. Files: "
            + ", ".join(f"[`{f}`](accuracy/{name}/{f})" for f in files) + ".\n\n"
            f"Reproduce this section alone (the page too): `bench/run{mode_flag} --only {name}`; the "
            f"benchmark by itself (results under the build directory):\n\n    {run.get('command')}")
        sections.append("\n\n".join(text))

    dirty = header.get("commit", "").endswith("+dirty")
    lines = [
        "# Accuracy record: error against run time",
        "",
        "Generated by [`bench/run`](../bench/README.md#benchrun-the-accuracy-record) with "
        "[`bench/accuracy_page.py`](../bench/accuracy_page.py); every figure below is parsed from the "
        "files of that run under [`accuracy/`](accuracy/). Do not edit by hand: run `bench/run` again.",
        "",
        f"- Date: {header.get('date')}",
        f"- Commit: `{header.get('commit')}`" + (" (the working tree had uncommitted changes)" if dirty else ""),
        f"- CPU: {header.get('cpu')}, {header.get('cores')} cores (a shared machine: load average "
        f"{header.get('load_start')} at the start, {header.get('load_end')} at the end)",
        f"- Build: {header.get('build_type')}",
        f"- Mode: **{header.get('mode')}**" + (" (short settings of every benchmark)" if header.get("mode") == "quick"
                                                else " (full settings)"),
        f"- Command: `{header.get('command')}` ({header.get('seconds')} s in all, builds included)",
        "",
        "Machines here are shared and noisy: quote the ratios ours / peer measured within this run, not "
        "absolute seconds from different runs.",
        "",
        table(["section", "mode", "made", "seconds", "status"], overview),
        "",
    ]
    if problems:
        lines += ["**Incomplete record:** " + "; ".join(problems) + ".", ""]
    page = "\n".join(lines) + "\n" + "\n\n".join(sections) + "\n"
    path = os.path.join(args.dir, "accuracy.md")
    tmp = path + ".tmp"
    with open(tmp, "w", encoding="utf-8") as f:
        f.write(page)
    os.replace(tmp, path)
    if problems:
        for p in problems:
            print(f"accuracy_page: error: {p}", file=sys.stderr)
        return 3
    print(f"accuracy_page: wrote {path}", file=sys.stderr)
    return 0


def anchor(title):
    """GitHub's heading anchor: lower case, punctuation dropped, spaces to hyphens."""
    kept = "".join(c for c in title.lower() if c.isalnum() or c in " -_")
    return kept.replace(" ", "-")


if __name__ == "__main__":
    sys.exit(main())
