"""Writes Documentation/benchmark/README.md from the benchmark CSV, beside the paper's Table 3,
and, when given, the node-numbering CSV (the same mesh numbered layer by layer, along a Hilbert
curve, at random), the composite-input CSV (the mesh as one grid and as a reader's multiblock) and
the whole-command CSV (dgmf-deform's wall time).

    /usr/bin/python3 Benchmarks/write_benchmark_page.py benchmark.csv machine.txt OUTPUT.md \
        [numbering.csv [numbering-machine.txt [composite.csv [command.csv [motion.csv
        [wing_body.csv]]]]]]
"""
import csv
import os
import sys

# The paper's Table 3 (CPU seconds, one 2.7 GHz core): nodes -> method -> seconds.
PAPER = {
    201920: {"dgm": 0.099, "dgmf": 0.099, "dgrbf": 0.160, "idw": 485.105},
    403840: {"dgm": 0.172, "dgmf": 0.188, "dgrbf": 0.297, "idw": 955.096},
    826080: {"dgm": 0.359, "dgmf": 0.359, "dgrbf": 0.578, "idw": 8295.252},
    8260800: {"dgm": 3.419, "dgmf": 3.254, "dgrbf": 3.482},
}


def read_rows(path):
    """The benchmark rows, numbers converted."""
    with open(path) as handle:
        rows = list(csv.DictReader(handle))
    for row in rows:
        for key, value in row.items():
            if key not in ("method", "numbering", "input", "mesh"):
                row[key] = float(value) if value not in ("", None) else None
    return rows


def fmt(value, digits=3):
    return ("%%.%df" % digits) % value


def main():
    csv_path, machine_path, output_path = sys.argv[1:4]
    rows = read_rows(csv_path)
    machine = open(machine_path).read().strip()
    lines = [
        "# Benchmark: the paper's Table 3 on this machine",
        "",
        "Produced by `bash scripts/run-benchmark.sh` (Release build); the raw figures are in",
        "[benchmark.csv](benchmark.csv). Do not edit by hand.",
        "",
        "## Machine",
        "",
        "```",
        machine,
        "```",
        "",
        "## Meshes",
        "",
        "Procedural layered hexahedral meshes (`Benchmarks/LayeredMesh.h`): a unit sphere (moving) in",
        "the box [-10, 10]^3 (static), joined by layers of hexahedra along rays; a box-surface grid of",
        "30^3 (5,048 nodes per layer) or 60 x 60 x 59 (20,652 nodes per layer) nodes mapped onto both",
        "surfaces, 40, 80, 40 and 400 layers: exactly the paper's node and boundary-node counts. The",
        "sphere's nodes are cospherical, the box's coplanar grids, and every node lies on a segment",
        "between a sphere node and a box node: the degenerate input of real structured O-grids.",
        "Nodes are numbered layer by layer, so the filter's hint stride (the index difference of",
        "neighbours across layers, found from the cells: see ../speed.md) is the layer size.",
        "Motion: rotation of (5, 10, 15) degrees about x, y, z (three angles, the most expensive case)",
        "and a translation. Times exclude mesh generation, file I/O and (except the quality column) the",
        "quality metric. Medians of 3 runs (IDW: 1 run).",
        "",
        "Columns: *first* = a deformation from an empty cache (graph + location + mapping, and the",
        "filter's own overhead); *repeated* = the same mesh with a new motion (graph and locations",
        "cached); *paper* = the paper's Table 3 time (one 2.7 GHz core, first deformation);",
        "*quality* = the SizeSkew metric as the filter computes it for a new motion of the same mesh",
        "(its `GetLastQualitySeconds()`, the hexahedra's original half kept from the first run with",
        "the quality on; a new `vtkSizeSkewQualityFilter`, nothing kept, is in benchmark.csv's",
        "quality_first_s); *cache* = memory the filter keeps between executions, per node, with the",
        "quality on (its default).",
        "",
        "*peak RSS* is the benchmark process's largest resident memory so far (the mesh, the filter's",
        "input and output, and its caches); per node, it is meaningful for the largest mesh.",
        "",
        "| nodes | boundary nodes | method | threads | graph s | location s | mapping s | first s | paper s | first / paper | repeated s | quality s | cache B/node | peak RSS MB | peak RSS B/node |",
        "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|",
    ]
    for row in rows:
        nodes = int(row["nodes"])
        paper = PAPER.get(nodes, {}).get(row["method"])
        lines.append("| %s | %s | %s | %d | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
            format(nodes, ","), format(int(row["boundary_nodes"]), ","), row["method"].upper(),
            int(row["threads"]), fmt(row["graph_s"]), fmt(row["location_s"]), fmt(row["mapping_s"]),
            fmt(row["first_s"]), fmt(paper) if paper else "-",
            fmt(row["first_s"] / paper, 2) if paper else "-", fmt(row["repeated_s"]),
            fmt(row["quality_s"]), fmt(row["cache_bytes_per_node"], 1), fmt(row["peak_rss_mb"], 0),
            fmt(row["peak_rss_mb"] * 1048576.0 / nodes, 0)))
    lines.append("")
    if len(sys.argv) > 4 and os.path.exists(sys.argv[4]):
        machine = open(sys.argv[5]).read().strip() if len(sys.argv) > 5 else None
        if machine:
            lines += ["The sections of issue 18 below were measured on:", "", "```", machine,
                      "```", ""]
        lines += numbering_section(read_rows(sys.argv[4]))
    if len(sys.argv) > 6 and os.path.exists(sys.argv[6]):
        lines += composite_section(read_rows(sys.argv[6]))
    if len(sys.argv) > 7 and os.path.exists(sys.argv[7]):
        lines += command_section(read_rows(sys.argv[7]))
    if len(sys.argv) > 8 and os.path.exists(sys.argv[8]):
        lines += motion_section(read_rows(sys.argv[8]))
    if len(sys.argv) > 9 and os.path.exists(sys.argv[9]):
        lines += mesh_section(read_rows(sys.argv[9]))
    optional = [read_rows(sys.argv[k]) if len(sys.argv) > k and os.path.exists(sys.argv[k])
                else [] for k in (4, 6, 7, 9)]
    lines += targets_section(rows, *optional)
    with open(output_path, "w") as handle:
        handle.write("\n".join(lines))


def targets_section(rows, numbering, composite, command, mesh):
    """Issue 18's targets, each with the figure above that decides it."""
    def one(table, **match):
        found = [r for r in table if all(r.get(k) == v for k, v in match.items())]
        return found[-1] if found else None

    checks = []
    big, threads = 8260800.0, 2.0
    layered = one(numbering, nodes=big, threads=threads, numbering="layered", method="dgmf")
    for order in ("hilbert", "random"):
        row = one(numbering, nodes=big, threads=threads, numbering=order, method="dgmf")
        if layered and row:
            ratio = row["first_s"] / layered["first_s"]
            checks.append(("numbering %s: first deformation <= 1.3 x layered" % order,
                           "%.2f x" % ratio, ratio <= 1.3, "--numberings"))
    grid = one(rows, nodes=big, threads=threads, method="dgmf")
    if grid:
        checks.append(("8.26M nodes: first deformation <= 0.5 s", "%.3f s" % grid["first_s"],
                       grid["first_s"] <= 0.5, "--sizes 3"))
        checks.append(("8.26M nodes: repeated deformation <= 0.05 s",
                       "%.3f s" % grid["repeated_s"], grid["repeated_s"] <= 0.05, "--sizes 3"))
        checks.append(("quality <= 2 repeated deformations",
                       "%.3f s against %.3f s" % (grid["quality_s"], 2 * grid["repeated_s"]),
                       grid["quality_s"] <= 2 * grid["repeated_s"], "--sizes 3"))
        checks.append(("cache <= 64 B/node", "%.1f B/node" % grid["cache_bytes_per_node"],
                       grid["cache_bytes_per_node"] <= 64, "--sizes 3"))
    for nodes in sorted({r["nodes"] for r in composite}):
        g = one(composite, nodes=nodes, threads=threads, input="grid")
        m = one(composite, nodes=nodes, threads=threads, input="multiblock")
        if g and m:
            ratio = m["repeated_s"] / g["repeated_s"]
            checks.append(("%s nodes: multiblock repeated <= 1.5 x grid" % format(int(nodes), ","),
                           "%.2f x" % ratio, ratio <= 1.5, "--inputs grid,multiblock"))
            extra = m["first_s"] - g["first_s"]
            checks.append(("%s nodes: merge (multiblock first - grid first) <= location"
                           % format(int(nodes), ","), "%.3f s against %.3f s" % (
                               extra, m["location_s"]), extra <= m["location_s"],
                           "--inputs grid,multiblock"))
            if nodes == big:
                checks.append(("8,260,800 nodes: multiblock cache <= 64 B/node (quality off)",
                               "%.1f B/node" % m["cache_bytes_per_node"],
                               m["cache_bytes_per_node"] <= 64, "--inputs grid,multiblock"))
    row = one(command, nodes=big, threads=threads)
    if row and row["first_s"]:
        ratio = row["wall_s"] / row["first_s"]
        checks.append(("8.26M nodes: the whole command <= 4 x the deformation", "%.1f x" % ratio,
                       ratio <= 4, "--command"))
    row = one(mesh, threads=threads)
    if row:
        # The issue accepts, instead, an explanation of what bounds it: speed.md gives one.
        checks.append(("wing-body: first run <= 0.356 s (the paper), or what bounds it explained",
                       "%.3f s" % row["first_s"], row["first_s"] <= 0.356 or
                       "**no**; what bounds it is explained: CGAL's sequential insertion "
                       "(../speed.md, \"A real mesh: the wing-body\")", "--mesh"))
    if not checks:
        return []
    lines = [
        "## Issue 18's targets on this page (2 threads)",
        "",
        "Each decided by the tables above (`dgmf-benchmark` with the option given); the large",
        "rotations' target is in [large_motion.md](large_motion.md) and ../speed.md; the whole",
        "command on gmsh, SU2, Exodus II and CGNS files in [solver_formats.md](solver_formats.md).",
        "",
        "| target | measured | met | option |",
        "|---|---|---|---|",
    ]
    for label, value, met, option in checks:
        verdict = met if isinstance(met, str) else ("yes" if met else "**no**")
        lines.append("| %s | %s | %s | `%s` |" % (label, value, verdict, option))
    lines.append("")
    return lines


def numbering_section(rows):
    """The first deformation of one mesh in three node numberings, against the layered one."""
    layered = {(r["nodes"], r["method"], r["threads"]): r for r in rows
               if r["numbering"] == "layered"}
    lines = [
        "## Node numbering (issue 18)",
        "",
        "The same meshes with their nodes renumbered (`dgmf-benchmark --numberings",
        "layered,hilbert,random`, `Benchmarks/Renumbering.h`): *hilbert* is CGAL's Hilbert sort of",
        "the coordinates (a renumbered unstructured mesh), *random* a seeded random permutation (a",
        "mesh reassembled from many pieces). Without a usable numbering each node's walk starts from",
        "a start grid's element near it (../speed.md). Target: the first deformation within 1.3 times",
        "the layered figure.",
        "",
    ]
    lines += [
        "| nodes | method | threads | numbering | location s | first s | first / layered | repeated s |",
        "|---|---|---|---|---|---|---|---|",
    ]
    for row in rows:
        base = layered.get((row["nodes"], row["method"], row["threads"]))
        lines.append("| %s | %s | %d | %s | %s | %s | %s | %s |" % (
            format(int(row["nodes"]), ","), row["method"].upper(), int(row["threads"]),
            row["numbering"], fmt(row["location_s"]), fmt(row["first_s"]),
            fmt(row["first_s"] / base["first_s"], 2) if base else "-", fmt(row["repeated_s"])))
    lines.append("")
    return lines


def composite_section(rows):
    """The same mesh as one grid with a marker and as a CFD reader's multiblock (named patches)."""
    grids = {(r["nodes"], r["threads"]): r for r in rows if r.get("input") == "grid"}
    lines = [
        "## Composite input (issue 18)",
        "",
        "The same mesh as one grid with its marker, and as ParaView's OpenFOAM reader gives a case",
        "(`dgmf-benchmark --inputs grid,multiblock`, `Benchmarks/NamedBlocks.h`: block",
        "*internalMesh* and the patches *body* and *farfield*, the body moving by name). The first",
        "run merges the blocks at their shared nodes and finds the mesh's own boundary; a new motion",
        "reuses both. Targets: a repeated deformation at most 1.5 times the grid's; the merge at most",
        "the location (*first - grid first* below is the merge, the boundary and the scatter).",
        "*Cache*: memory the filter keeps between executions, per node, quality off (the multiblock's",
        "keeps no copy of the volume's cells, which the merged grid shares; only the patches'",
        "polygons and node maps are its own).",
        "",
        "| nodes | threads | grid first s | multiblock first s | first - grid first s | location s | grid repeated s | multiblock repeated s | repeated ratio | grid cache B/node | multiblock cache B/node |",
        "|---|---|---|---|---|---|---|---|---|---|---|",
    ]
    for row in rows:
        grid = grids.get((row["nodes"], row["threads"]))
        if row.get("input") != "multiblock" or not grid:
            continue
        lines.append("| %s | %d | %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
            format(int(row["nodes"]), ","), int(row["threads"]), fmt(grid["first_s"]),
            fmt(row["first_s"]), fmt(row["first_s"] - grid["first_s"]), fmt(row["location_s"]),
            fmt(grid["repeated_s"]), fmt(row["repeated_s"]),
            fmt(row["repeated_s"] / grid["repeated_s"], 2),
            fmt(grid["cache_bytes_per_node"], 1), fmt(row["cache_bytes_per_node"], 1)))
    lines.append("")
    return lines


def command_section(rows):
    """dgmf-deform's wall time beside the filter's first deformation."""
    lines = [
        "## The whole command (issue 18)",
        "",
        "`dgmf-deform mesh.vtu deformed.vtu --marker BoundaryMarker --rotate 5 10 15 --translate",
        "0.1 0 0 --threads N` on the benchmark mesh written as a .vtu (appended raw, LZ4; the",
        "command writes appended raw without compression, its default since 2026-11-30), timed",
        "from outside (`dgmf-benchmark --command`), the run of median",
        "wall time of the repeats (on this virtual machine the first run after the benchmark",
        "freed its meshes pays the host's page faults: up to twice as long); *read*, *filter*",
        "(deformation and quality) and *write* are what the command prints. Target: the whole",
        "command at most 4 times the first deformation, on 2 threads.",
        "",
        "| nodes | threads | first deformation s | read s | filter s | write s | whole command s | whole / first |",
        "|---|---|---|---|---|---|---|---|",
    ]
    for row in rows:
        lines.append("| %s | %d | %s | %s | %s | %s | %s | %s |" % (
            format(int(row["nodes"]), ","), int(row["threads"]), fmt(row["first_s"]),
            fmt(row["read_s"]), fmt(row["filter_s"]), fmt(row["write_s"]), fmt(row["wall_s"]),
            fmt(row["wall_s"] / row["first_s"], 1) if row["first_s"] else "-"))
    lines.append("")
    return lines


def motion_section(rows):
    """Frames per second of a periodic motion, the graph built once."""
    lines = [
        "## Motion in time (issue 19)",
        "",
        "One period of a harmonic pitch (15 degrees about y) played frame after frame through the",
        "filter's Rotation Law and `UpdateTimeStep`, quality off (`dgmf-benchmark --frames N`,",
        "`Benchmarks/PeriodicMotion.h`). The first frame builds the graph; every other frame maps",
        "the input mesh again with it. *frames/s*: the frames after the first; *cycle frames/s*: the",
        "whole period, the graph included once.",
        "",
        "| nodes | threads | frames | first frame s | graph s | other frames s | frames/s | cycle frames/s |",
        "|---|---|---|---|---|---|---|---|",
    ]
    for row in rows:
        lines.append("| %s | %d | %d | %s | %s | %s | %s | %s |" % (
            format(int(row["nodes"]), ","), int(row["threads"]), int(row["frames"]),
            fmt(row["first_frame_s"]), fmt(row["graph_s"]), fmt(row["other_frames_s"]),
            fmt(row["frames_per_second"], 1), fmt(row["cycle_frames_per_second"], 1)))
    lines.append("")
    return lines


def mesh_section(rows):
    """The first run's phases on the paper's wing-body mesh."""
    lines = [
        "## A real mesh: the wing-body of Reproduction/ (issue 18)",
        "",
        "The paper's wing-body half model (`Data/generators/wing_body.py`, cached by",
        "`scripts/reproduce.sh`: tetrahedra, 25,282 moving and 15,546 static boundary nodes), DGMF",
        "rotating the body by (5, 10, 15) degrees, quality off (`dgmf-benchmark --mesh",
        "~/.cache/dgmf/wing_body.vtu`, `Benchmarks/MeshFileCase.h`). *The rest*: the first run minus",
        "graph, location and mapping (gathering the arrays, checks, the output). The paper: 0.356 s.",
        "",
        "| nodes | cells | threads | first s | graph s | location s | mapping s | the rest s | repeated s | quality s |",
        "|---|---|---|---|---|---|---|---|---|---|",
    ]
    for row in rows:
        lines.append("| %s | %s | %d | %s | %s | %s | %s | %s | %s | %s |" % (
            format(int(row["nodes"]), ","), format(int(row["cells"]), ","), int(row["threads"]),
            fmt(row["first_s"]), fmt(row["graph_s"]), fmt(row["location_s"]),
            fmt(row["mapping_s"]), fmt(row["overhead_s"]), fmt(row["repeated_s"]),
            fmt(row["quality_s"])))
    lines.append("")
    return lines


if __name__ == "__main__":
    main()
