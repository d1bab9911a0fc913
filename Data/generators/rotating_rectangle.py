"""Rotating rectangle (paper Fig. 3): a 2 x 0.5 rectangle centred at the origin in a square of side
10, triangles.

Usage: pvpython rotating_rectangle.py OUTPUT.vtu [--size-min 0.1] [--size-max 0.8] [--dist-max 4]
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.dont_write_bytecode = True  # keep Data/generators free of __pycache__
import gmsh  # noqa: E402
import meshgen  # noqa: E402

LENGTH, WIDTH, SIDE = 2.0, 0.5, 10.0


def build_geometry():
    """The square minus the rectangle."""
    occ = gmsh.model.occ
    square = occ.addRectangle(-SIDE / 2, -SIDE / 2, 0, SIDE, SIDE)
    body = occ.addRectangle(-LENGTH / 2, -WIDTH / 2, 0, LENGTH, WIDTH)
    occ.cut([(2, square)], [(2, body)])


if __name__ == "__main__":
    args = meshgen.parse_args(__doc__, size_min=0.1, size_max=0.8, dist_max=4.0)
    x, y = 0.55 * LENGTH, 0.55 * WIDTH
    meshgen.generate(args, 2, build_geometry, (-x, -y, -1, x, y, 1))
