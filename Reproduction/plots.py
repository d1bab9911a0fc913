"""Plots of the reproduction CSV files (matplotlib; run with pvpython or Debian's /usr/bin/python3).

Reads fig4_rectangle.csv, fig8_circle.csv, fig12_twisted_bar_<form>.csv and
table2_twisted_bar_<form>.csv from the results folder and writes, beside them,
fig4_rectangle.png, fig8_circle.png, fig12_twisted_bar_<form>.png and
table2_twisted_bar_<form>.png: mean and minimum SizeSkew side by side; a cross marks a result
with inverted cells. Usage: plots.py [--results DIR]
"""
import argparse
import csv
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

MARKERS, LINES = "os^vDP*", ("-", "--", "-.", ":")
RESULTS = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))),
                       "Documentation", "results")
plt.rcParams.update({"svg.hashsalt": "dgmf", "font.size": 9})


def read_rows(path):
    """The rows of a CSV file as dicts."""
    with open(path, newline="") as stream:
        return list(csv.DictReader(stream))


def series(rows, key, name, x):
    """(x values, means, minima, inverted flags) of the rows where row[key] == name."""
    chosen = sorted((r for r in rows if r[key] == name), key=lambda r: float(r[x]))
    return ([float(r[x]) for r in chosen], [float(r["mean"]) for r in chosen],
            [float(r["minimum"]) for r in chosen], [int(r["inverted"]) > 0 for r in chosen])


def plot(rows, key, names, x, xlabel, title, path, styles=None, log2=False):
    """Two panels (mean, minimum) with one line per name; crosses where cells are inverted."""
    figure, axes = plt.subplots(1, 2, figsize=(9, 3.6))
    for index, name in enumerate(names):
        xs, means, minima, inverted = series(
            [r for r in rows if not log2 or float(r[x]) > 0], key, name, x)
        style = {"marker": MARKERS[index % len(MARKERS)], "markersize": 4,
                 "linestyle": LINES[index % len(LINES)], **(styles or {}).get(name, {})}
        for axis, values in zip(axes, (means, minima)):
            line, = axis.plot(xs, values, label=name, **style)
            bad = [(a, v) for a, v, i in zip(xs, values, inverted) if i]
            if bad:
                axis.plot(*zip(*bad), "x", color=line.get_color(), markersize=8)
    reference = [r for r in rows if r[key] == "undeformed"]
    for axis, what in zip(axes, ("mean", "minimum")):
        if reference:
            axis.axhline(float(reference[0][what]), color="grey", linestyle=":", linewidth=1,
                         label="undeformed mesh")
    for axis, what in zip(axes, ("mean SizeSkew", "minimum SizeSkew")):
        axis.set_xlabel(xlabel)
        axis.set_ylabel(what)
        axis.set_ylim(0.0, 1.0)
        axis.grid(True, alpha=0.3)
        if log2:
            axis.set_xscale("log", base=2)
            axis.set_xticks([4, 8, 16, 32], ["4", "8", "16", "32"])
    axes[1].legend(fontsize=7, loc="upper right")
    figure.suptitle(title + "   (x: inverted cells)")
    figure.tight_layout()
    figure.savefig(path, dpi=90, metadata={"Software": None})
    plt.close(figure)
    print(f"wrote {path}")


def main():
    """Make every plot whose CSV exists."""
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--results", default=RESULTS, help="folder of the CSV files")
    results = parser.parse_args().results
    csv_path = lambda name: os.path.join(results, name + ".csv")  # noqa: E731
    png_path = lambda name: os.path.join(results, name + ".png")  # noqa: E731
    if os.path.exists(csv_path("fig4_rectangle")):
        names = [f"DGMF-u{u}" for u in range(1, 7)] + ["DGM"]
        plot(read_rows(csv_path("fig4_rectangle")), "case", names, "angle", "rotation (degrees)",
             "Fig. 4: rotating rectangle", png_path("fig4_rectangle"),
             styles={"DGM": {"color": "black", "linewidth": 2}})
    if os.path.exists(csv_path("fig8_circle")):
        extra = {"linestyle": "--", "linewidth": 0.8}
        plot(read_rows(csv_path("fig8_circle")), "method", ["DGMF", "DGM", "RBF", "DGRBF", "IDW"],
             "angle", "rotation (degrees)", "Fig. 8: rotating circle (dashed: not in the paper)",
             png_path("fig8_circle"), styles={"DGRBF": extra, "IDW": extra})
    methods = ["RBF", "DGM", "DGRBF", "DGMF1", "DGMF2"]
    for form in ("paper", "method"):
        for name, title in (("fig12_twisted_bar", "Fig. 12: twisted bar"),
                            ("table2_twisted_bar", "Table 2 against A: twisted bar, 45 degrees")):
            stem = f"{name}_{form}"
            if os.path.exists(csv_path(stem)):
                plot(read_rows(csv_path(stem)), "method", methods, "A", "A",
                     f"{title}, bump form '{form}'", png_path(stem), log2=True)


if __name__ == "__main__":
    main()
