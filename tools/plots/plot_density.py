#!/usr/bin/python3
"""Draws `pyro chart shadows --density` as a PNG: for each shadow setting, its error against the
reference (left, log scale) and its time per frame (right) against the optical depth through
one particle's centre, tau0 = -ln(1 - rho); the target is a dashed line, and each setting's first
point past it is ringed (where the method leaves the target).

Usage: /usr/bin/python3 tools/plots/plot_density.py DIR/shadows.csv DIR/shadows.png

The CSV (tools/charts/chart_shadow_density.cpp): comment lines "# title: ", "# x: ", "# y: ",
"# note: ... target: T; ...", then the header label,group,time,error,density,tau0,... The script
only draws. The PNG is written to a temporary name and renamed when complete. Exit status 3
without matplotlib, 1 on any other failure.
"""
import re
import sys

from plot_setup import fail, load_matplotlib, read_commented_csv, run_main, save_figure

plt = load_matplotlib()


def target_of(meta):
    for value in meta.values():
        found = re.search(r"target: ([0-9.eE+-]+)", str(value))
        if found:
            return float(found.group(1))
    return None


def main():
    if len(sys.argv) != 3:
        fail("usage: plot_density.py CHART.csv CHART.png")
    csv_path, png_path = sys.argv[1], sys.argv[2]
    meta, rows = read_commented_csv(csv_path, ("group", "time", "error", "tau0"))
    if not rows:
        fail("%s: no points" % csv_path)
    for r in rows:
        r["time"], r["error"], r["tau0"] = float(r["time"]), float(r["error"]), float(r["tau0"])
    target = target_of(meta)
    groups = []
    for r in rows:
        if r["group"] not in groups:
            groups.append(r["group"])
    fig, (left, right) = plt.subplots(1, 2, figsize=(12, 5), dpi=110)
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for i, g in enumerate(groups):
        colour = colours[i % len(colours)]
        points = sorted((r for r in rows if r["group"] == g), key=lambda r: r["tau0"])
        taus = [r["tau0"] for r in points]
        left.plot(taus, [max(r["error"], 1e-6) for r in points], marker="o", color=colour, label=g)
        right.plot(taus, [r["time"] for r in points], marker="o", color=colour, label=g)
        past = [r for r in points if target is not None and not r["error"] <= target]
        if past:
            left.scatter([past[0]["tau0"]], [past[0]["error"]], s=160, facecolors="none",
                         edgecolors=colour, linewidths=1.5, zorder=4)
    if target is not None:
        left.axhline(target, color="black", linestyle="--", linewidth=1, label="target %g" % target)
    for ax in (left, right):
        ax.set_xscale("log")
        ax.set_xlabel(meta.get("x", "tau0"))
        ax.grid(True, which="both", alpha=0.3)
    left.set_yscale("log")
    left.set_ylabel(meta.get("y", "RMSE"))
    left.set_title("error (ringed: first point past the target)", fontsize=9)
    right.set_yscale("log")
    right.set_ylabel("ms per frame")
    right.set_title("time", fontsize=9)
    left.legend(fontsize=8)
    fig.suptitle(meta.get("title", ""), fontsize=10)
    fig.tight_layout()
    save_figure(fig, png_path)


if __name__ == "__main__":
    run_main(main)
