#!/usr/bin/python3
"""Makes the realistic SU2 test meshes with gmsh (Debian 12's python3-gmsh, 4.8) and writes the
.su2 files itself (meshio 7's SU2 writer crashes):

  circle_in_square.su2  2D: triangles between a circle of radius 1 and a square of side 10,
                        markers "farfield" (the square) and "circle"
  box.su2               3D: tetrahedra in the box [0,2]x[0,1]x[0,1], markers "inlet" (x = 0),
                        "outlet" (x = 2) and "walls" (the four other sides)

Run from this folder: /usr/bin/python3 make_gmsh_meshes.py
"""
import gmsh

VTK_TYPE = {1: 3, 2: 5, 3: 9, 4: 10, 5: 12, 6: 13, 7: 14}  # gmsh element type -> VTK


def elements(dim, tag):
    """The (VTK type, 0-based node list) of the elements of entity (dim, tag)."""
    result = []
    types, _, nodes = gmsh.model.mesh.getElements(dim, tag)
    for gmsh_type, flat in zip(types, nodes):
        count = gmsh.model.mesh.getElementProperties(gmsh_type)[3]
        for k in range(0, len(flat), count):
            result.append((VTK_TYPE[gmsh_type], [int(n) - 1 for n in flat[k:k + count]]))
    return result


def write_su2(path, dim, comment):
    gmsh.model.mesh.renumberNodes()
    tags, xyz, _ = gmsh.model.mesh.getNodes()
    order = sorted(range(len(tags)), key=lambda k: tags[k])
    assert [int(tags[k]) for k in order] == list(range(1, len(tags) + 1))
    volume = []
    for _, tag in gmsh.model.getEntities(dim):
        volume += elements(dim, tag)
    with open(path, "w") as out:
        out.write("%% %s\n%% made by make_gmsh_meshes.py (gmsh %s)\n" % (comment, gmsh.__version__))
        out.write("NDIME= %d\n" % dim)
        out.write("NELEM= %d\n" % len(volume))
        for index, (vtk, nodes) in enumerate(volume):
            out.write("%d\t%s\t%d\n" % (vtk, "\t".join(map(str, nodes)), index))
        out.write("NPOIN= %d\n" % len(tags))
        for index, k in enumerate(order):
            coordinates = ["%.17g" % xyz[3 * k + c] for c in range(dim)]
            out.write("%s\t%d\n" % ("\t".join(coordinates), index))
        groups = gmsh.model.getPhysicalGroups(dim - 1)
        out.write("NMARK= %d\n" % len(groups))
        for group_dim, group in groups:
            faces = []
            for tag in gmsh.model.getEntitiesForPhysicalGroup(group_dim, group):
                faces += elements(group_dim, tag)
            out.write("MARKER_TAG= %s\n" % gmsh.model.getPhysicalName(group_dim, group))
            out.write("MARKER_ELEMS= %d\n" % len(faces))
            for vtk, nodes in faces:
                out.write("%d\t%s\n" % (vtk, "\t".join(map(str, nodes))))


def circle_in_square():
    gmsh.model.add("circle_in_square")
    occ = gmsh.model.occ
    square = occ.addRectangle(-5, -5, 0, 10, 10)
    disk = occ.addDisk(0, 0, 0, 1, 1)
    occ.cut([(2, square)], [(2, disk)])
    occ.synchronize()
    circle, farfield = [], []
    for _, tag in gmsh.model.getEntities(1):
        x, y, _ = gmsh.model.occ.getCenterOfMass(1, tag)
        (circle if abs(x) < 1.5 and abs(y) < 1.5 else farfield).append(tag)
    gmsh.model.setPhysicalName(1, gmsh.model.addPhysicalGroup(1, farfield), "farfield")
    gmsh.model.setPhysicalName(1, gmsh.model.addPhysicalGroup(1, circle), "circle")
    gmsh.model.addPhysicalGroup(2, [t for _, t in gmsh.model.getEntities(2)])
    gmsh.model.mesh.setSize(gmsh.model.getEntities(0), 1.0)
    gmsh.option.setNumber("Mesh.MeshSizeFromCurvature", 24)  # 24 edges around the circle
    gmsh.model.mesh.generate(2)
    write_su2("circle_in_square.su2", 2, "a circle of radius 1 in a square of side 10")


def box():
    gmsh.model.add("box")
    occ = gmsh.model.occ
    occ.addBox(0, 0, 0, 2, 1, 1)
    occ.synchronize()
    names = {}
    for _, tag in gmsh.model.getEntities(2):
        x, _, _ = gmsh.model.occ.getCenterOfMass(2, tag)
        name = "inlet" if abs(x) < 1e-9 else "outlet" if abs(x - 2) < 1e-9 else "walls"
        names.setdefault(name, []).append(tag)
    for name in ("inlet", "outlet", "walls"):
        gmsh.model.setPhysicalName(2, gmsh.model.addPhysicalGroup(2, names[name]), name)
    gmsh.model.addPhysicalGroup(3, [t for _, t in gmsh.model.getEntities(3)])
    gmsh.option.setNumber("Mesh.MeshSizeFromCurvature", 0)
    gmsh.model.mesh.setSize(gmsh.model.getEntities(0), 0.4)
    gmsh.model.mesh.generate(3)
    write_su2("box.su2", 3, "tetrahedra in the box [0,2]x[0,1]x[0,1]")


gmsh.initialize()
gmsh.option.setNumber("General.Terminal", 0)
gmsh.option.setNumber("Mesh.RandomSeed", 1)
circle_in_square()
box()
gmsh.finalize()
