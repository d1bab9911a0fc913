"""Twisted bar (paper Fig. 10): a bar 10 long and 1 thick (x in [-5, 5], y in [-0.5, 0.5]) in the
outer rectangle x in [-45, 45], y in [-30, 60], triangles.

The outer domain keeps the bar at least 21 units (two bar lengths) away from it after the bump
y1 = y + A exp(1 - 1/(1 - (x/4)^2)) with A = 32 combined with a rotation of up to 45 degrees (either
sense, either order) about the origin: the bar then stays in x in [-23.1, 23.1], y in [-3.9, 32.5].

Usage: pvpython twisted_bar.py OUTPUT.vtu [--size-min 0.1] [--size-max 4] [--dist-max 16]
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.dont_write_bytecode = True  # keep Data/generators free of __pycache__
import gmsh  # noqa: E402
import meshgen  # noqa: E402

LENGTH, THICKNESS = 10.0, 1.0
OUTER_X, OUTER_Y = (-45.0, 45.0), (-30.0, 60.0)


def build_geometry():
    """The outer rectangle minus the bar."""
    occ = gmsh.model.occ
    outer = occ.addRectangle(OUTER_X[0], OUTER_Y[0], 0,
                             OUTER_X[1] - OUTER_X[0], OUTER_Y[1] - OUTER_Y[0])
    bar = occ.addRectangle(-LENGTH / 2, -THICKNESS / 2, 0, LENGTH, THICKNESS)
    occ.cut([(2, outer)], [(2, bar)])


if __name__ == "__main__":
    args = meshgen.parse_args(__doc__, size_min=0.1, size_max=4.0, dist_max=16.0)
    x, y = 0.55 * LENGTH, 0.55 * THICKNESS
    meshgen.generate(args, 2, build_geometry, (-x, -y, -1, x, y, 1))
