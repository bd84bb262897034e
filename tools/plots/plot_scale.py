#!/usr/bin/python3
"""Draws `pyro chart scale` as a PNG: ms per frame against particles on log-log axes, the CPU
work and the whole frame, each with its least-squares line over 10^5 to 2*10^6 particles and
its slope in the legend (the slopes pyro computed, from the CSV's comment lines).

Usage: /usr/bin/python3 tools/plots/plot_scale.py DIR/scale.csv DIR/scale.png

The CSV (written by tools/pyro/command_chart.cpp): comment lines "# title: ", "# x: ", "# y: ",
"# cpu_slope: ", "# frame_slope: ", then the header particles,ms_per_frame,cpu_ms_per_frame,...
The PNG is written to a temporary name and renamed when complete. Exit status 3 without
matplotlib, 1 on any other failure.
"""
import math
import sys

from plot_setup import fail, load_matplotlib, label_and_save, read_commented_csv, run_main

plt = load_matplotlib()

SERIES = (("cpu_ms_per_frame", "CPU work", "cpu_slope"), ("ms_per_frame", "whole frame", "frame_slope"))


def read_chart(path):
    meta, rows = read_commented_csv(path, ("particles",) + tuple(s[0] for s in SERIES))
    return meta, [{k: float(v) for k, v in r.items()} for r in rows]


def fitted_line(rows, column):
    """Least squares of log y on log x over 1e5..2e6 (the same fit as pyro's slope)."""
    pts = [(math.log(r["particles"]), math.log(r[column])) for r in rows
           if 1e5 * 0.999 <= r["particles"] <= 2e6 * 1.001 and r[column] > 0]
    if len(pts) < 2:
        return None
    n = len(pts)
    sx = sum(p[0] for p in pts)
    sy = sum(p[1] for p in pts)
    sxx = sum(p[0] * p[0] for p in pts)
    sxy = sum(p[0] * p[1] for p in pts)
    d = n * sxx - sx * sx
    if abs(d) < 1e-12:
        return None
    slope = (n * sxy - sx * sy) / d
    return slope, (sy - slope * sx) / n


def main():
    if len(sys.argv) != 3:
        fail("usage: plot_scale.py scale.csv scale.png")
    csv_path, png_path = sys.argv[1], sys.argv[2]
    meta, rows = read_chart(csv_path)
    if not rows:
        fail("%s: no points" % csv_path)
    fig, ax = plt.subplots(figsize=(8, 5.5), dpi=110)
    for column, name, slope_key in SERIES:
        pts = [r for r in rows if r[column] > 0]
        line = ax.plot([r["particles"] for r in pts], [r[column] for r in pts], marker="o", label=name)[0]
        fit = fitted_line(rows, column)
        if fit:
            slope, intercept = fit
            xs = [1e5, 2e6]
            ax.plot(xs, [math.exp(intercept) * x ** slope for x in xs], linestyle="--",
                    color=line.get_color(), linewidth=1,
                    label="%s fit, slope %s" % (name, meta.get(slope_key, "%.3f" % slope)[:5]))
    ax.set_xscale("log")
    ax.set_yscale("log")
    label_and_save(fig, ax, meta, csv_path, png_path, "particles", "ms per frame", 9)

if __name__ == "__main__":
    run_main(main)
