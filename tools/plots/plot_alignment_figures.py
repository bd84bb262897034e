#!/usr/bin/python3
"""Draws the billboard alignment figures (Johnson & McAllister 2005, figures 4-13) as PNG charts.

Usage: /usr/bin/python3 tools/plots/plot_alignment_figures.py DIR/alignment_figures.json

Run by `pyro analyze projection-error --surface NAME|all --out DIR`, which computes every value
(engine/math/billboard_alignment.h) and writes one CSV per figure and the manifest this script
reads. The script only draws: surfaces as two heat maps side by side (the error from the
geometry, and the paper's equation as printed), figures 6 and 7 as top views of the two
billboards with the rays through their right edges. Each PNG is written to a temporary name and
renamed when complete.

Needs Debian's matplotlib (python3-matplotlib, tools/install-deps.sh): exit status 3 when it
cannot be imported, 1 on any other failure.
"""
import csv
import json
import os
import sys

from plot_setup import fail, load_matplotlib

plt = load_matplotlib()
try:
    from matplotlib import colors
    import numpy as np
except ImportError as e:  # numpy comes with Debian's matplotlib; say so if it does not
    fail("numpy cannot be imported (%s); install python3-matplotlib" % e, 3)


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def grid(rows, x, y, value):
    """The long table as 2D arrays X, Y, V (rows are x fastest, then y)."""
    xs = sorted({float(r[x]) for r in rows})
    ys = sorted({float(r[y]) for r in rows})
    ix = {v: i for i, v in enumerate(xs)}
    iy = {v: j for j, v in enumerate(ys)}
    v = np.full((len(ys), len(xs)), np.nan)
    for r in rows:
        v[iy[float(r[y])], ix[float(r[x])]] = float(r[value])
    gx, gy = np.meshgrid(xs, ys)
    return gx, gy, v


def save(fig, path):
    temp = path + ".partial"
    fig.savefig(temp, format="png", dpi=100)
    plt.close(fig)
    os.replace(temp, path)


def draw_surface(entry, rows, path):
    """Heat maps of the signed value, one panel per column (geometry, paper as printed).

    The colour scale is symmetric about zero and logarithmic beyond 1/1000 of the largest
    magnitude, so that both the steep rise next to the viewplane and the small far-field values
    show; black contour lines mark decades.
    """
    chart = entry["chart"]
    panels = chart["panels"]
    fig, axes = plt.subplots(1, len(panels), figsize=(6.6 * len(panels), 5.8), squeeze=False)
    fig.suptitle(entry["title"] + "\n" + chart["subtitle"], fontsize=12)
    for ax, panel in zip(axes[0], panels):
        gx, gy, v = grid(rows, chart["x"], chart["y"], panel["column"])
        top = float(np.nanmax(np.abs(v)))
        if top == 0.0:
            top = 1.0
        norm = colors.SymLogNorm(linthresh=top * 1e-3, linscale=0.5, vmin=-top, vmax=top, base=10)
        mesh = ax.pcolormesh(gx, gy, v, cmap="RdBu_r", norm=norm, shading="auto")
        levels = sorted({s * top * 10.0 ** -k for k in range(1, 4) for s in (-1.0, 1.0)})
        ax.contour(gx, gy, v, levels=levels, colors="black", linewidths=0.5)
        bar = fig.colorbar(mesh, ax=ax)
        top_decade = int(np.floor(np.log10(top)))
        decades = [10.0 ** d for d in range(top_decade - 2, top_decade + 1)]
        bar.set_ticks([-d for d in reversed(decades)] + [0.0] + decades)
        bar.set_ticklabels(["%.0e" % t if t else "0" for t in bar.get_ticks()])
        bar.set_label(chart["value_label"])
        ax.set_title(panel["label"], fontsize=10)
        ax.set_xlabel(chart["x_label"])
        ax.set_ylabel(chart["y_label"])
    fig.tight_layout(rect=(0, 0, 1, 0.92))
    save(fig, path)


def draw_diagram(entry, rows, path):
    chart = entry["chart"]
    n = chart["near"]
    points = {r["point"]: r for r in rows}

    def xz(name):
        return float(points[name]["x"]), float(points[name]["z"])

    fig, ax = plt.subplots(figsize=(7.5, 7.0))
    fig.suptitle(entry["title"] + "\n" + chart["subtitle"], fontsize=12)
    # Rays from the viewpoint through both right edges, and the viewplane.
    for name, colour in (("viewplane_facing_right_edge", "tab:blue"),
                         ("viewpoint_facing_right_edge", "tab:red")):
        ex, ez = xz(name)
        ax.plot([0.0, ex], [0.0, ez], color=colour, linewidth=0.8, linestyle="--")
        ax.plot([float(points[name]["x_star"])], [-n], marker="o", color=colour, markersize=4)
    # The two billboards.
    for prefix, colour, label in (("viewplane_facing", "tab:blue", "facing the viewplane"),
                                  ("viewpoint_facing", "tab:red", "facing the viewpoint")):
        lx, lz = xz(prefix + "_left_edge")
        rx, rz = xz(prefix + "_right_edge")
        ax.plot([lx, rx], [lz, rz], color=colour, linewidth=2.5, label="billboard " + label)
        ax.plot([rx], [rz], marker="o", color=colour)
    cx, cz = xz("centre")
    ax.plot([cx], [cz], marker="+", color="black", markersize=10, label="centre C")
    ax.plot([0.0], [0.0], marker="^", color="black", markersize=8, label="viewpoint V")
    xs = [float(r["x"]) for r in rows] + [0.0]
    ax.axhline(-n, color="grey", linewidth=1.0, label="viewplane z = -N")
    ax.set_xlim(min(xs) - 0.5, max(xs) + 0.5)
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("x (camera coordinates)")
    ax.set_ylabel("z (camera coordinates; the camera looks down -z)")
    ax.set_title("e_x = %.4g (geometry), %.4g (eq. 11 as printed)"
                 % (chart["e_x"], chart["e_x_paper"]), fontsize=10)
    ax.legend(loc="lower left", fontsize=8)
    ax.grid(True, linewidth=0.3)
    save(fig, path)


def main():
    if len(sys.argv) != 2:
        fail("usage: plot_alignment_figures.py DIR/alignment_figures.json")
    manifest_path = sys.argv[1]
    folder = os.path.dirname(os.path.abspath(manifest_path))
    try:
        with open(manifest_path) as f:
            manifest = json.load(f)
    except (OSError, ValueError) as e:
        fail("cannot read the manifest %s: %s" % (manifest_path, e))
    for entry in manifest["figures"]:
        csv_path = os.path.join(folder, entry["csv"])
        png_path = os.path.join(folder, entry["png"])
        try:
            rows = read_csv(csv_path)
        except OSError as e:
            fail("cannot read %s: %s" % (csv_path, e))
        if entry["kind"] == "surface":
            draw_surface(entry, rows, png_path)
        elif entry["kind"] == "diagram":
            draw_diagram(entry, rows, png_path)
        else:
            fail("%s: unknown figure kind %r" % (manifest_path, entry["kind"]))


if __name__ == "__main__":
    main()
