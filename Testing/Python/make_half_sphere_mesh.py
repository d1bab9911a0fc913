"""Writes a half model for the distributed slip test: the half ball of radius 1 on the plane z = 0
(moving) in the box [-5, 5]^2 x [0, 5] (static), tetrahedra from gmsh, the plane z = 0 outside the
ball marked 3 (slip) but for its outer edges (static). The slip nodes carry up to 1e-7 of noise
off the plane (as a single-precision mesh's), so that a piece fitting the plane to its own slip
nodes finds another plane than the serial run, which fits it to all of them; and the body is on
the plane, so that its slip nodes move.

usage: pvpython make_half_sphere_mesh.py TARGET.vtu
"""
import os
import sys
from types import SimpleNamespace

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "Data",
                                "generators"))
sys.dont_write_bytecode = True
import gmsh  # noqa: E402
import meshgen  # noqa: E402

HALF = 5.0


def build_geometry():
    occ = gmsh.model.occ
    box = occ.addBox(-HALF, -HALF, 0.0, 2 * HALF, 2 * HALF, HALF)
    ball = occ.addSphere(0, 0, 0, 1.0)
    occ.cut([(3, box)], [(3, ball)])


args = SimpleNamespace(output=sys.argv[1], size_min=0.2, size_max=1.5, dist_max=3.0)
mesh = meshgen.generate(args, 3, build_geometry, (-1.1, -1.1, -0.1, 1.1, 1.1, 1.1),
                        shared_nodes_moving=True)
marker = mesh.GetPointData().GetArray(meshgen.MARKER_ARRAY)
slip = 0
for i in range(mesh.GetNumberOfPoints()):
    x, y, z = mesh.GetPoint(i)
    if z == 0.0 and marker.GetTuple1(i) == meshgen.STATIC and max(abs(x), abs(y)) < HALF:
        marker.SetTuple1(i, 3)
        mesh.GetPoints().SetPoint(i, x, y, ((i * 7919) % 201 - 100) * 1e-9)
        slip += 1
moving = sum(1 for i in range(mesh.GetNumberOfPoints()) if marker.GetTuple1(i) == meshgen.MOVING)
meshgen.write_and_check(mesh, args.output)
print("half sphere mesh: %d nodes, %d slip nodes, %d moving nodes" % (
    mesh.GetNumberOfPoints(), slip, moving))
