"""Rotating circle (paper Fig. 7): circle of radius 1 at the origin in a square of side 10,
triangles.

Usage: pvpython rotating_circle.py OUTPUT.vtu [--size-min 0.1] [--size-max 0.8] [--dist-max 4]
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.dont_write_bytecode = True  # keep Data/generators free of __pycache__
import gmsh  # noqa: E402
import meshgen  # noqa: E402

RADIUS, SIDE = 1.0, 10.0


def build_geometry():
    """The square minus the disk."""
    occ = gmsh.model.occ
    square = occ.addRectangle(-SIDE / 2, -SIDE / 2, 0, SIDE, SIDE)
    disk = occ.addDisk(0, 0, 0, RADIUS, RADIUS)
    occ.cut([(2, square)], [(2, disk)])


if __name__ == "__main__":
    args = meshgen.parse_args(__doc__, size_min=0.1, size_max=0.8, dist_max=4.0)
    box = 1.1 * RADIUS
    meshgen.generate(args, 2, build_geometry, (-box, -box, -1, box, box, 1))
