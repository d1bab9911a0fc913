"""Pitching airfoil (issue 19): a NACA 0012 of chord 1, leading edge at the origin, in the square
[-4.75, 5.25] x [-5, 5], triangles. The trailing edge is closed (the 0.1036 coefficient) so that the
profile is one smooth spline with a sharp edge; it pitches about its quarter chord (0.25, 0).

Usage: pvpython pitching_airfoil.py OUTPUT.vtu [--size-min 0.02] [--size-max 0.8] [--dist-max 4]
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.dont_write_bytecode = True  # keep Data/generators free of __pycache__
import gmsh  # noqa: E402
import meshgen  # noqa: E402

CHORD, THICKNESS, SIDE, POINTS = 1.0, 0.12, 10.0, 60


def half_thickness(x):
    """NACA 4-digit symmetric profile with a closed trailing edge."""
    return 5 * THICKNESS * (0.2969 * math.sqrt(x) - 0.1260 * x - 0.3516 * x ** 2
                            + 0.2843 * x ** 3 - 0.1036 * x ** 4)


def build_geometry():
    """The square minus the airfoil (cosine-spaced points, upper then lower surface)."""
    occ = gmsh.model.occ
    square = occ.addRectangle(0.25 - SIDE / 2, -SIDE / 2, 0, SIDE, SIDE)
    xs = [0.5 * (1 - math.cos(math.pi * k / POINTS)) for k in range(POINTS + 1)]
    trailing = occ.addPoint(CHORD, 0, 0)
    leading = occ.addPoint(0, 0, 0)
    upper = [occ.addPoint(x, half_thickness(x), 0) for x in reversed(xs[1:-1])]
    lower = [occ.addPoint(x, -half_thickness(x), 0) for x in xs[1:-1]]
    top = occ.addSpline([trailing] + upper + [leading])
    bottom = occ.addSpline([leading] + lower + [trailing])
    loop = occ.addCurveLoop([top, bottom])
    body = occ.addPlaneSurface([loop])
    occ.cut([(2, square)], [(2, body)])


if __name__ == "__main__":
    args = meshgen.parse_args(__doc__, size_min=0.02, size_max=0.8, dist_max=4.0)
    meshgen.generate(args, 2, build_geometry, (-0.05, -0.1, -1, 1.05, 0.1, 1))
