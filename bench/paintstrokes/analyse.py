#!/usr/bin/env python3
"""Polygons at equal image error: for every stroke set and view of paintstrokes.csv (run.sh), the
paintstrokes at quality level 1 (each tolerance) against the cheapest fixed tubes of the sweep whose
RMSE against the fine-tube reference is at most 10 % above theirs, and the tube polygon count at
exactly that error, interpolated log-log along the tubes' Pareto front. Prints the summary and writes
paintstrokes-equal-error.csv next to the input."""
import csv
import math
import os
import sys

DEFAULT_TOLERANCE = 0.5  # px, bakeplay's default --stroke-tolerance


def pareto(points):
    """(polygons, rmse) points where no cheaper point has a lower or equal error, cheapest first."""
    front = []
    for p, e in sorted(points):
        if not front or e < front[-1][1]:
            front.append((p, e))
    return front


def polygons_at(front, error):
    """Tube polygons needed for `error`, log-log interpolation along the front (None: not reached)."""
    if not front or front[-1][1] > error:
        return None
    if front[0][1] <= error:
        return float(front[0][0])
    for (p0, e0), (p1, e1) in zip(front, front[1:]):
        if e0 > error >= e1:
            t = (math.log(error) - math.log(e0)) / (math.log(e1) - math.log(e0))
            return math.exp(math.log(p0) + t * (math.log(p1) - math.log(p0)))
    return None


def main():
    path = sys.argv[1]
    rows = list(csv.DictReader(open(path, newline="")))
    out_rows = []
    lines = ["set/view: quality 1 at tolerance (px): polygons, RMSE | cheapest tubes with RMSE <= 1.1x: "
             "SIDESxSTEPS polygons RMSE | tubes interpolated at equal RMSE | ratio tubes / paintstrokes"]
    keys = list(dict.fromkeys((r["set"], r["view"]) for r in rows))
    headline = []
    for key in keys:
        mine = [r for r in rows if (r["set"], r["view"]) == key]
        tubes = [r for r in mine if r["method"] == "tubes" and r["rmse"] and r["polygons"]]
        front = pareto([(int(r["polygons"]), float(r["rmse"])) for r in tubes])
        for r in mine:
            if r["method"] != "paintstrokes" or r["quality"] != "1" or not r["polygons"]:
                continue
            p, e = int(r["polygons"]), float(r["rmse"])
            within = [t for t in tubes if float(t["rmse"]) <= 1.1 * e]
            cheapest = min(within, key=lambda t: int(t["polygons"])) if within else None
            interpolated = polygons_at(front, e)
            ratio = int(cheapest["polygons"]) / p if cheapest and p else None
            ratio_interp = interpolated / p if interpolated and p else None
            out_rows.append({
                "set": key[0], "view": key[1], "tolerance_px": r["tolerance_px"], "polygons": p, "rmse": e,
                "tubes": f"{cheapest['sides']}x{cheapest['steps']}" if cheapest else "",
                "tube_polygons": cheapest["polygons"] if cheapest else "",
                "tube_rmse": cheapest["rmse"] if cheapest else "",
                "tube_polygons_interpolated": f"{interpolated:.0f}" if interpolated else "",
                "ratio": f"{ratio:.3f}" if ratio else "", "ratio_interpolated": f"{ratio_interp:.3f}" if ratio_interp else ""})
            tube_text = (f"{cheapest['sides']}x{cheapest['steps']} {cheapest['polygons']} polys "
                         f"RMSE {float(cheapest['rmse']):.5f}" if cheapest else "no tube of the sweep is that accurate")
            lines.append(f"  {key[0]}/{key[1]}: q1 @ {r['tolerance_px']} px: {p} polys, RMSE {e:.5f} | {tube_text} | "
                         + (f"{interpolated:.0f}" if interpolated else "-") + " | "
                         + (f"{ratio:.2f}x" if ratio else "-") + (f" (interp. {ratio_interp:.2f}x)" if ratio_interp else ""))
            if float(r["tolerance_px"]) == DEFAULT_TOLERANCE:
                headline.append((key, ratio, ratio_interp))
    lines.append("")
    lines.append(f"headline (quality 1 at the default {DEFAULT_TOLERANCE} px tolerance; criterion: tubes need >= 3x the polygons):")
    for key, ratio, ratio_interp in headline:
        lines.append(f"  {key[0]}/{key[1]}: {ratio:.2f}x" if ratio else f"  {key[0]}/{key[1]}: no tube of the sweep reaches its error")
        if ratio_interp:
            lines[-1] += f" (interpolated {ratio_interp:.2f}x)"
    print("\n".join(lines))
    target = os.path.join(os.path.dirname(path), "paintstrokes-equal-error.csv")
    with open(target, "w", newline="") as f:
        fields = ["set", "view", "tolerance_px", "polygons", "rmse", "tubes", "tube_polygons", "tube_rmse",
                  "tube_polygons_interpolated", "ratio", "ratio_interpolated"]
        w = csv.DictWriter(f, fieldnames=fields)
        w.writeheader()
        w.writerows(out_rows)


if __name__ == "__main__":
    main()
