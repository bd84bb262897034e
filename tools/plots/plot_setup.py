"""What every plotting script under tools/plots starts with: an error exit that names the script,
and matplotlib (Debian's python3-matplotlib) loaded for drawing to files, or exit status 3 with
how to install it. pyro's plot runner (tools/charts/plot_script.cpp) reads status 3 as "no
matplotlib" and says so. Also what the chart scripts share: reading a chart CSV with its comment
lines, saving a figure atomically, and reporting any failure with exit status 1."""
import csv
import os
import sys

EXIT_NO_MATPLOTLIB = 3


def fail(message, status=1):
    sys.stderr.write(os.path.basename(sys.argv[0]) + ": " + message + "\n")
    sys.exit(status)


def load_matplotlib():
    """Returns matplotlib.pyplot on the file-only Agg backend."""
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError as e:
        fail(
            "matplotlib cannot be imported by %s (%s); install the Debian package "
            "python3-matplotlib (./tools/install-deps.sh) and run this with /usr/bin/python3"
            % (sys.executable, e),
            EXIT_NO_MATPLOTLIB,
        )
    return plt


def read_commented_csv(path, columns):
    """A chart CSV: its comment lines ("# key: value", the first of each key kept) as a dict,
    and its rows as dicts of strings; fails unless the header has every name in `columns`."""
    meta, lines = {}, []
    with open(path, newline="") as f:
        for line in f:
            if line.startswith("#"):
                key, _, value = line[1:].strip().partition(": ")
                meta.setdefault(key, value)
            else:
                lines.append(line)
    rows = list(csv.DictReader(lines))
    for column in columns:
        if rows and column not in rows[0]:
            fail("%s: no column %r" % (path, column))
    return meta, rows


def label_and_save(fig, ax, meta, csv_path, png_path, x_label, y_label, title_size):
    """Axis labels and title from the CSV's comment lines (these defaults otherwise), a grid, the
    legend, then the figure saved atomically."""
    ax.set_xlabel(meta.get("x", x_label))
    ax.set_ylabel(meta.get("y", y_label))
    ax.set_title(meta.get("title", os.path.basename(csv_path)), fontsize=title_size)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    save_figure(fig, png_path)


def save_figure(fig, png_path):
    """Writes the figure to a temporary name, then renames it: no half-written PNG is left."""
    tmp = png_path + ".tmp-%d.png" % os.getpid()
    try:
        fig.savefig(tmp)
        os.replace(tmp, png_path)
    finally:
        if os.path.exists(tmp):
            os.remove(tmp)


def run_main(main):
    """Runs a script's main(); any failure but an exit is reported with status 1."""
    try:
        main()
    except SystemExit:
        raise
    except Exception as e:  # noqa: BLE001 - any failure is reported, exit 1
        fail("%s: %s" % (type(e).__name__, e))
