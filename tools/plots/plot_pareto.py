#!/usr/bin/python3
"""Draws one `pyro chart` as a PNG: time per frame (x) against error (y, log scale), one point
per setting, coloured by group, the Pareto front (computed by pyro: the `pareto` column) joined
by a line and ringed.

Usage: /usr/bin/python3 tools/plots/plot_pareto.py DIR/NAME.csv DIR/NAME.png

Run by `pyro chart NAME --out DIR` (tools/pyro/command_chart.cpp), which measures every value
and writes the CSV: comment lines "# title: ", "# x: ", "# y: " (and others this script passes
over), then the header label,group,time,error,...,pareto,usable,front. The script only draws; settings that
failed (usable 0, e.g. a blown-up integrator) are crosses. Errors of 0 (a
setting that is its own ground truth) or not finite (a blown-up method) cannot sit on a log axis:
they are drawn as triangles on the bottom or top edge. The PNG is written to a temporary name and
renamed when complete.

Needs Debian's matplotlib (python3-matplotlib, tools/install-deps.sh): exit status 3 when it
cannot be imported, 1 on any other failure.
"""
import math
import sys

from plot_setup import fail, load_matplotlib, label_and_save, read_commented_csv, run_main

plt = load_matplotlib()


def read_chart(path):
    return read_commented_csv(path, ("label", "group", "time", "error", "pareto"))


def main():
    if len(sys.argv) != 3:
        fail("usage: plot_pareto.py CHART.csv CHART.png")
    csv_path, png_path = sys.argv[1], sys.argv[2]
    meta, rows = read_chart(csv_path)
    if not rows:
        fail("%s: no points" % csv_path)
    for r in rows:
        r["time"] = float(r["time"])
        r["error"] = float(r["error"])
        r["pareto"] = r["pareto"] == "1"
        r["usable"] = r.get("usable", "1") == "1"
    plottable = [r["error"] for r in rows if math.isfinite(r["error"]) and r["error"] > 0]
    low = min(plottable) / 3 if plottable else 1e-3
    high = max(plottable) * 3 if plottable else 1.0

    fig, ax = plt.subplots(figsize=(9, 6), dpi=110)
    groups = []
    for r in rows:
        if r["group"] not in groups:
            groups.append(r["group"])
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for i, g in enumerate(groups):
        colour = colours[i % len(colours)]
        inside = [r for r in rows if r["group"] == g and math.isfinite(r["error"]) and r["error"] > 0]
        good = [r for r in inside if r["usable"]]
        failed = [r for r in inside if not r["usable"]]
        ax.scatter([r["time"] for r in good], [r["error"] for r in good], color=colour,
                   label=g, s=28, zorder=3)
        if failed:
            ax.scatter([r["time"] for r in failed], [r["error"] for r in failed], color=colour,
                       marker="x", s=40, zorder=3, label=g + " (failed: never on the front)")
        zero = [r for r in rows if r["group"] == g and r["error"] == 0]
        ax.scatter([r["time"] for r in zero], [low] * len(zero), color=colour, marker="v", s=40,
                   zorder=3)
        blown = [r for r in rows if r["group"] == g and not math.isfinite(r["error"])]
        ax.scatter([r["time"] for r in blown], [high] * len(blown), color=colour, marker="^",
                   s=40, zorder=3)
    # One front per `front` key (one per scene or volume where those are not alternatives).
    front = sorted((r for r in rows if r["pareto"]), key=lambda r: r["time"])
    keys = []
    for r in front:
        if r.get("front", "") not in keys:
            keys.append(r.get("front", ""))
    for i, key in enumerate(keys):
        line = [r for r in front if r.get("front", "") == key]
        ax.plot([r["time"] for r in line], [max(r["error"], low) for r in line], color="black",
                linewidth=1, linestyle="--", zorder=2,
                label=("Pareto front" + (" (one per %d inputs)" % len(keys) if len(keys) > 1 else ""))
                if i == 0 else None)
        ax.scatter([r["time"] for r in line], [max(r["error"], low) for r in line],
                   facecolors="none", edgecolors="black", s=110, zorder=4)
    # Label every point when there are few; else the front only.
    labelled = rows if len(rows) <= 24 else front
    for r in labelled:
        y = r["error"]
        y = low if y == 0 else high if not math.isfinite(y) else y
        ax.annotate(r["label"], (r["time"], y), textcoords="offset points", xytext=(4, 3),
                    fontsize=6.5)
    ax.set_yscale("log")
    ax.set_ylim(low / 1.5, high * 1.5)
    times = [r["time"] for r in rows if r["time"] > 0]
    if times and max(times) / min(times) > 30:
        ax.set_xscale("log")
    label_and_save(fig, ax, meta, csv_path, png_path, "time", "error", 10)

if __name__ == "__main__":
    run_main(main)
