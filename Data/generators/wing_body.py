"""Wing-body half model (paper Section 3.4, Fig. 15), tetrahedra, at the paper's scale.

Geometry (units of the paper's fold formula; x downstream, y spanwise, z up):
- fuselage: a body of revolution about the x axis, radius 70: an ellipsoidal nose (semi-axis 250,
  x in [-600, -350]), a cylinder (x in [-350, 450]) and an ellipsoidal tail (semi-axis 350,
  x in [450, 800]); length 1400;
- wing: NACA 0012 (closed trailing edge), ruled loft from the root section at y = 0 (chord 300,
  leading edge at x = -100, inside the fuselage) to the flat tip at y = 700 (chord 120, leading
  edge at x = 226: 25 degrees of leading-edge sweep), no twist, no dihedral, chord plane z = 0;
- half model: the far-field box x in [-3400, 3600], y in [0, 3500], z in [-3500, 3500] (four
  semi-spans or more from the body); its face y = 0 is the symmetry plane.
Boundary markers: wing and fuselage surface nodes 2 (moving; this includes the nodes where the
fuselage meets the symmetry plane), the six faces of the box (symmetry plane included) 1 (static).

With the defaults: 257,625 nodes and 1,487,189 tetrahedra (the paper's: 257,909 and 1,507,462),
25,282 moving and 15,546 static boundary nodes; about 3 minutes and 3 GB with gmsh 4.8. --full
makes the full model instead (both wings, box y in [-3500, 3500], no symmetry plane: 497,597 nodes,
2,953,694 tetrahedra, about 9 minutes and 4.5 GB).

The mesh is too large to commit: it is generated on demand into a cache folder outside the source
tree and reused while the parameters match (a JSON file beside it records them, the counts and the
generation time).

Usage: pvpython wing_body.py [OUTPUT.vtu] [--force] [--full] [--size-min 5] [--size-max 300]
                             [--dist-max 4000]
  OUTPUT defaults to ${XDG_CACHE_HOME:-$HOME/.cache}/dgmf/wing_body.vtu
"""
import argparse
import json
import math
import os
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.dont_write_bytecode = True  # keep Data/generators free of __pycache__
import gmsh  # noqa: E402
import numpy as np  # noqa: E402
import meshgen  # noqa: E402

RADIUS = 70.0
NOSE, CYLINDER, TAIL = (-600.0, -350.0), (-350.0, 450.0), (450.0, 800.0)
ROOT_CHORD, ROOT_LE = 300.0, -100.0
TIP_CHORD, SEMI_SPAN, SWEEP_DEG = 120.0, 700.0, 25.0
THICKNESS = 0.12
BOX_MIN, BOX_MAX = (-3400.0, 0.0, -3500.0), (3600.0, 3500.0, 3500.0)
AIRFOIL_POINTS = 41  # per side, cosine spacing
DEFAULTS = {"size_min": 5.0, "size_max": 300.0, "dist_max": 4000.0}


def default_output():
    """The cache path: ${XDG_CACHE_HOME:-$HOME/.cache}/dgmf/wing_body.vtu."""
    cache = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return os.path.join(cache, "dgmf", "wing_body.vtu")


def parse_args():
    """Command line: optional output path, --force, and the grading parameters."""
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("output", nargs="?", default=default_output(),
                        help="path of the .vtu file (default: %(default)s)")
    parser.add_argument("--force", action="store_true",
                        help="generate even when a matching cached file exists")
    parser.add_argument("--full", action="store_true",
                        help="full model (both wings, no symmetry plane) instead of the half model")
    for name, value in DEFAULTS.items():
        parser.add_argument("--" + name.replace("_", "-"), type=float, default=value,
                            help="default %(default)s (see meshgen.py)")
    return parser.parse_args()


def naca_half_thickness(x):
    """NACA 00xx half thickness at chord fraction x, closed trailing edge (-0.1036)."""
    return 5.0 * THICKNESS * (0.2969 * np.sqrt(x) - 0.1260 * x - 0.3516 * x ** 2
                              + 0.2843 * x ** 3 - 0.1036 * x ** 4)


def airfoil_wire(leading_edge_x, chord, y):
    """A closed wire of two splines (upper and lower surface) for the section at span y."""
    occ = gmsh.model.occ
    beta = np.linspace(0.0, math.pi, AIRFOIL_POINTS)
    xc = 0.5 * (1.0 - np.cos(beta))  # 0 at the leading edge, 1 at the trailing edge
    t = naca_half_thickness(xc)
    le = occ.addPoint(leading_edge_x, y, 0.0)
    te = occ.addPoint(leading_edge_x + chord, y, 0.0)
    sides = []
    for sign in (1.0, -1.0):
        inner = [occ.addPoint(leading_edge_x + chord * xi, y, sign * chord * ti)
                 for xi, ti in zip(xc[1:-1], t[1:-1])]
        sides.append([le] + inner + [te])
    upper = occ.addSpline(sides[0])
    lower = occ.addSpline(sides[1][::-1])
    return occ.addWire([upper, lower], checkClosed=True)


def fuselage():
    """The body of revolution: nose and tail ellipse arcs and a straight side, revolved about x."""
    occ = gmsh.model.occ
    nose_tip, nose_c = occ.addPoint(NOSE[0], 0, 0), occ.addPoint(NOSE[1], 0, 0)
    tail_tip, tail_c = occ.addPoint(TAIL[1], 0, 0), occ.addPoint(TAIL[0], 0, 0)
    nose_top, tail_top = occ.addPoint(CYLINDER[0], RADIUS, 0), occ.addPoint(CYLINDER[1], RADIUS, 0)
    nose = occ.addEllipseArc(nose_top, nose_c, nose_tip, nose_tip)
    side = occ.addLine(nose_top, tail_top)
    tail = occ.addEllipseArc(tail_tip, tail_c, tail_tip, tail_top)
    axis = occ.addLine(tail_tip, nose_tip)
    profile = occ.addPlaneSurface([occ.addCurveLoop([nose, side, tail, axis])])
    revolved = occ.revolve([(2, profile)], 0, 0, 0, 1, 0, 0, 2 * math.pi)
    return [dt for dt in revolved if dt[0] == 3]


def wing():
    """The NACA 0012 wing, a ruled loft from the root (y = 0) to the tip (y = SEMI_SPAN)."""
    tip_le = ROOT_LE + SEMI_SPAN * math.tan(math.radians(SWEEP_DEG))
    root = airfoil_wire(ROOT_LE, ROOT_CHORD, 0.0)
    tip = airfoil_wire(tip_le, TIP_CHORD, SEMI_SPAN)
    return gmsh.model.occ.addThruSections([root, tip], makeSolid=True, makeRuled=True)


def build_geometry(full=False):
    """The far-field box minus the fused wing and fuselage: the half model (y >= 0), or with
    ``full`` the box mirrored to y in [-3500, 3500] around both wings."""
    occ = gmsh.model.occ
    wings = [dt for dt in wing() if dt[0] == 3]
    if full:
        mirrored = occ.copy(wings)
        occ.mirror(mirrored, 0, 1, 0, 0)
        wings += mirrored
    body, _ = occ.fuse(fuselage(), wings)
    low = (BOX_MIN[0], -BOX_MAX[1] if full else BOX_MIN[1], BOX_MIN[2])
    size = [hi - lo for lo, hi in zip(low, BOX_MAX)]
    box = occ.addBox(*low, *size)
    occ.cut([(3, box)], body)


def cached(args):
    """True when args.output exists and its sidecar records the same parameters."""
    sidecar = args.output + ".json"
    if args.force or not (os.path.exists(args.output) and os.path.exists(sidecar)):
        return False
    with open(sidecar) as stream:
        return json.load(stream).get("parameters") == parameters(args)


def parameters(args):
    """The generator parameters that determine the mesh."""
    return {"size_min": args.size_min, "size_max": args.size_max, "dist_max": args.dist_max,
            "full": args.full, "gmsh": gmsh.__version__}


def main():
    """Generate (or reuse) the wing-body mesh and record its parameters and counts."""
    args = parse_args()
    args.output = os.path.abspath(args.output)
    if cached(args):
        print(f"{args.output}: cached (use --force to regenerate)")
        return
    os.makedirs(os.path.dirname(args.output), exist_ok=True)
    start = time.perf_counter()
    box = (NOSE[0] - 10, -SEMI_SPAN - 10, -RADIUS - 10, TAIL[1] + 10, SEMI_SPAN + 10, RADIUS + 10)
    grid = meshgen.generate(args, 3, lambda: build_geometry(args.full), box,
                            shared_nodes_moving=not args.full)
    seconds = time.perf_counter() - start
    record = {"parameters": parameters(args), "points": grid.GetNumberOfPoints(),
              "cells": grid.GetNumberOfCells(), "seconds": round(seconds, 1)}
    with open(args.output + ".json", "w") as stream:
        json.dump(record, stream, indent=1, sort_keys=True)
    print(f"generated in {seconds:.1f} s")


if __name__ == "__main__":
    main()
