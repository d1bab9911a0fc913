"""Thin slab in a box (3D), the large-rotation case of the sub-step option (issue 10).

A flat plate of chord 1 (x), thickness 0.12 (y) and span 2 (z), centred at the origin and tilted
by 20 degrees about the x axis (so that a rotation about z is not a 2D extrusion), in the cube
[-6, 6]^3 (side 12), tetrahedra. The users' case it stands for: a flap or a thin blade rotated
about an axis through it by up to 90 degrees.

With the defaults: 10,401 nodes and 53,583 tetrahedra (the mesh of the issue). The committed
Data/thin_slab.vtu is a coarser version (--size-min 0.08 --size-max 2 --dist-max 5), quick enough
for ctest.

Usage: pvpython thin_slab.py OUTPUT.vtu [--size-min 0.05] [--size-max 0.9] [--dist-max 3.5]
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.dont_write_bytecode = True  # keep Data/generators free of __pycache__
import gmsh  # noqa: E402
import meshgen  # noqa: E402

CHORD, THICKNESS, SPAN, SIDE = 1.0, 0.12, 2.0, 12.0
TILT_DEG = 20.0


def build_geometry():
    """The cube minus the tilted slab."""
    occ = gmsh.model.occ
    cube = occ.addBox(-SIDE / 2, -SIDE / 2, -SIDE / 2, SIDE, SIDE, SIDE)
    slab = occ.addBox(-CHORD / 2, -THICKNESS / 2, -SPAN / 2, CHORD, THICKNESS, SPAN)
    occ.rotate([(3, slab)], 0, 0, 0, 1, 0, 0, math.radians(TILT_DEG))
    occ.cut([(3, cube)], [(3, slab)])


if __name__ == "__main__":
    args = meshgen.parse_args(__doc__, size_min=0.05, size_max=0.9, dist_max=3.5)
    box = 1.3  # encloses the tilted slab (half-diagonal 1.13), far from the cube's faces
    meshgen.generate(args, 3, build_geometry, (-box, -box, -box, box, box, box))
