"""Sphere in a box (3D): sphere of radius 1 at the origin in a cube of side 10 centred at the
origin, tetrahedra.

Usage: pvpython sphere_in_box.py OUTPUT.vtu [--size-min 0.15] [--size-max 1.2] [--dist-max 4]
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.dont_write_bytecode = True  # keep Data/generators free of __pycache__
import gmsh  # noqa: E402
import meshgen  # noqa: E402

RADIUS, SIDE = 1.0, 10.0


def build_geometry():
    """The cube minus the ball."""
    occ = gmsh.model.occ
    cube = occ.addBox(-SIDE / 2, -SIDE / 2, -SIDE / 2, SIDE, SIDE, SIDE)
    ball = occ.addSphere(0, 0, 0, RADIUS)
    occ.cut([(3, cube)], [(3, ball)])


if __name__ == "__main__":
    args = meshgen.parse_args(__doc__, size_min=0.15, size_max=1.2, dist_max=4.0)
    box = 1.1 * RADIUS
    meshgen.generate(args, 3, build_geometry, (-box, -box, -box, box, box, box))
