"""Markdown tables of the reproduction results beside the paper's numbers (plain Python).

Reads the CSV files of the results folder and writes tables.md there.
Usage: tables.py [--results DIR]
"""
import argparse
import csv
import os

RESULTS = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))),
                       "Documentation", "results")
PAPER_TABLE2 = {"RBF": (0.747, 0.014), "DGM": (0.793, 0.019), "DGRBF": (0.862, 0.296),
                "DGMF1": (0.873, 0.496), "DGMF2": (0.880, 0.530)}
PAPER_WING_SECONDS = {"DGM": 0.356, "DGMF1": 0.356}


def read_rows(results, name):
    """Rows of results/name.csv as dicts, or [] when the file does not exist."""
    path = os.path.join(results, name + ".csv")
    if not os.path.exists(path):
        return []
    with open(path, newline="") as stream:
        return list(csv.DictReader(stream))


def quality(row):
    """'mean / minimum' text of a row, with the number of inverted cells when there are any."""
    text = f"{float(row['mean']):.3f} / {float(row['minimum']):.3f}"
    return text + (f" ({row['inverted']} inverted)" if int(row["inverted"]) else "")


def table(header, rows):
    """A Markdown table."""
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(str(cell) for cell in row) + " |" for row in rows]
    return "\n".join(lines) + "\n"


def sweep_table(rows, key, names, x, values):
    """One line per name, one column per x value: 'mean / minimum'."""
    cells = {(r[key], r[x]): quality(r) for r in rows}
    return table([key] + [f"{x} = {v}" for v in values],
                 [[n] + [cells.get((n, str(v)), "") for v in values] for n in names])


def rotation_sections(results):
    """Fig. 4 and Fig. 8 at 30, 60 and 90 degrees."""
    out = []
    rows = read_rows(results, "fig4_rectangle")
    if rows:
        names = [f"DGMF-u{u}" for u in range(1, 7)] + ["DGM"]
        out += ["## Fig. 4: rotating rectangle (mean / minimum SizeSkew)\n",
                sweep_table(rows, "case", names, "angle", (30, 60, 90))]
    rows = read_rows(results, "fig8_circle")
    if rows:
        out += ["## Fig. 8: rotating circle (mean / minimum SizeSkew)\n",
                sweep_table(rows, "method", ["DGMF", "DGM", "RBF", "DGRBF", "IDW"], "angle",
                            (30, 60, 90))]
    return out


def bar_sections(results):
    """Fig. 12 and Table 2 for both bump forms, the RBF support radii, the finer mesh."""
    out = []
    methods = ["RBF", "DGM", "DGRBF", "DGMF1", "DGMF2"]
    for form in ("paper", "method"):
        rows = read_rows(results, f"fig12_twisted_bar_{form}")
        if rows:
            out += [f"## Fig. 12: twisted bar, bump form '{form}' (mean / minimum)\n",
                    sweep_table(rows, "method", methods, "A", (4, 8, 16, 32))]
        rows = read_rows(results, f"table2_twisted_bar_{form}")
        if rows:
            out += [f"## Table 2 against A: 45 degrees, bump form '{form}' (mean / minimum; "
                    "A = 0: the rotation alone)\n",
                    sweep_table(rows, "method", methods, "A", (0, 4, 8, 16, 32))]
    rows = read_rows(results, "table2_twisted_bar_paper")
    if rows:
        ours = {(r["method"], r["A"]): r for r in rows}
        at16 = lambda m, what: f"{float(ours[(m, '16')][what]):.3f}"  # noqa: E731
        out += ["## Table 2: twisted bar, A = 16 (paper form), 45 degrees\n",
                table(["method", "paper mean", "paper minimum", "ours mean", "ours minimum",
                       "ours inverted cells", "ours at A = 4 (mean / minimum)"],
                      [[m, *(f"{v:.3f}" for v in PAPER_TABLE2[m]), at16(m, "mean"),
                        at16(m, "minimum"), ours[(m, "16")]["inverted"],
                        quality(ours[(m, "4")])] for m in methods])]
    rows = read_rows(results, "table2_rbf_support")
    if rows:
        out += ["## Table 2's RBF against its support radius (paper form, 45 degrees)\n",
                table(["A", "support radius", "mean / minimum"],
                      [[r["A"], r["support_radius"], quality(r)] for r in rows])]
    rows = read_rows(results, "bar_fine_mesh")
    if rows:
        size = f"{rows[0]['points']} points, {rows[0]['cells']} cells"
        for rotation in ("0", "45"):
            chosen = [r for r in rows if r["rotation"] == rotation or r["method"] == "undeformed"]
            out += [f"## Finer bar mesh ({size}), paper form, rotation {rotation}\n",
                    sweep_table(chosen, "method", methods, "A", (0, 4, 8, 16, 32)
                                if rotation == "45" else (4, 8, 16, 32))]
    return out


def wing_sections(results):
    """The wing fold, half model (and full model when run): times and quality."""
    out = []
    for prefix, model in (("wing_fold", "half model"), ("wing_fold_full", "full model")):
        rows = read_rows(results, prefix + "_time")
        if rows:
            out += [f"## Wing fold, {model}: filter time, one thread, best of the repeats\n",
                    table(["method", "run", "repeats", "wall (s)", "CPU (s)", "paper (s)"],
                          [[r["method"], r["run"], r["repeats"], f"{float(r['wall']):.3f}",
                            f"{float(r['cpu']):.3f}", PAPER_WING_SECONDS.get(r["method"], "")
                            if r["run"].startswith("first") else ""] for r in rows])]
        rows = read_rows(results, prefix + "_quality")
        if rows:
            out += [f"## Wing fold, {model}: quality ({rows[0]['points']} points, "
                    f"{rows[0]['cells']} cells)\n",
                    table(["method", "mean", "minimum", "inverted cells"],
                          [[r["method"], f"{float(r['mean']):.3f}", f"{float(r['minimum']):.4f}",
                            r["inverted"]] for r in rows])]
    return out


def main():
    """Write tables.md."""
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--results", default=RESULTS, help="folder of the CSV files")
    results = parser.parse_args().results
    text = ["# Reproduction tables\n",
            "Generated by `Reproduction/tables.py` from the CSV files of this folder "
            "(`scripts/reproduce.sh`). The discussion is in [README.md](README.md).\n"]
    text += rotation_sections(results) + bar_sections(results) + wing_sections(results)
    path = os.path.join(results, "tables.md")
    with open(path, "w") as stream:
        stream.write("\n".join(text))
    print(f"wrote {path}")


if __name__ == "__main__":
    main()
