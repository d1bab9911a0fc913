"""A solver's mesh file in, picked by boundary name, deformed, and the same format back out
(issue 16), through dgmf-deform and through ParaView (pvpython).

gmsh makes the meshes in the test: a unit box around a sphere of radius 0.2 (physical groups
"wing" on the sphere, "farfield" on the box, "fluid" the volume) and a 2D square around a circle.
gmsh writes them as .msh 4.1 ASCII, 4.1 binary, 2.2 ASCII, 2.2 binary, and as .su2 (gmsh's SU2
export names the markers after the physical groups); dgmf-test-convert-mesh writes them as Exodus
II (side sets) and CGNS (BCWall boundary conditions with families) with those formats' own
libraries. Every round trip asserts: the same node count
and order, the names present, the static boundary unmoved to the bit, the moving boundary at its
rigid position to 1e-12, and the quality summary of the .vtu route (the same mesh with a
BoundaryMarker array instead of names).

  pvpython test_formats.py --deform DGMF_DEFORM --convert CONVERTER --plugin PLUGIN --work DIR
"""
import argparse
import math
import os
import re
import shutil
import subprocess
import sys
import unittest

import gmsh
import numpy as np

ARGS = None
CENTER = (0.5, 0.5, 0.0)
ANGLES_3D = (10.0, 20.0, 30.0)
ANGLE_2D = 25.0


def make_meshes(work):
    """The test meshes in every format; returns {label: path}."""
    files = {}
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    for dimension in (3, 2):
        gmsh.model.add("box%d" % dimension)
        occ = gmsh.model.occ
        if dimension == 3:
            outer, hole = occ.addBox(0, 0, 0, 1, 1, 1), occ.addSphere(0.5, 0.5, 0.5, 0.2)
        else:
            outer, hole = occ.addRectangle(0, 0, 0, 1, 1), occ.addDisk(0.5, 0.5, 0, 0.2, 0.2)
        cut, _ = occ.cut([(dimension, outer)], [(dimension, hole)])
        occ.synchronize()
        boundary = [t for _, t in gmsh.model.getBoundary(cut, oriented=False)]
        wing = [t for t in boundary
                if max(abs(c - 0.5) for c in occ.getCenterOfMass(dimension - 1, t)[:dimension])
                < 1e-6]
        farfield = [t for t in boundary if t not in wing]
        for tag, (dim, entities, name) in enumerate(
                [(dimension, [cut[0][1]], "fluid"), (dimension - 1, wing, "wing"),
                 (dimension - 1, farfield, "farfield")], start=1):
            gmsh.model.addPhysicalGroup(dim, entities, tag)
            gmsh.model.setPhysicalName(dim, tag, name)
        gmsh.option.setNumber("Mesh.MeshSizeMax", 0.12 if dimension == 3 else 0.05)
        gmsh.model.mesh.generate(dimension)
        for version, binary in ((4.1, 0), (4.1, 1), (2.2, 0), (2.2, 1)):
            label = "%dd_msh%s%s" % (dimension, version, "_binary" if binary else "")
            gmsh.option.setNumber("Mesh.MshFileVersion", version)
            gmsh.option.setNumber("Mesh.Binary", binary)
            files[label] = os.path.join(work, label + ".msh")
            gmsh.write(files[label])
        gmsh.option.setNumber("Mesh.Binary", 0)
        files["%dd_su2" % dimension] = os.path.join(work, "%dd.su2" % dimension)
        gmsh.write(files["%dd_su2" % dimension])
        gmsh.model.remove()
    gmsh.finalize()
    for dimension in (3, 2):
        for extension in ("exo", "cgns"):
            label = "%dd_%s" % (dimension, extension)
            files[label] = os.path.join(work, "%dd.%s" % (dimension, extension))
            subprocess.run([ARGS.convert, files["%dd_msh4.1" % dimension], files[label]],
                           check=True)
    return files


def run(*arguments):
    done = subprocess.run([ARGS.deform] + [str(a) for a in arguments], capture_output=True,
                          text=True, timeout=600)
    return done.returncode, done.stdout, done.stderr


def summary(text):
    """(mean, minimum, inverted) of dgmf-deform's summary line."""
    match = re.search(r"SizeSkew mean ([^,]+), minimum ([^,]+), inverted cells (\d+)", text)
    assert match, text
    return float(match.group(1)), float(match.group(2)), int(match.group(3))


def sizes(text):
    """(points, cells) of dgmf-deform's summary line."""
    match = re.search(r"dgmf-deform: (\d+) points, (\d+) cells", text)
    assert match, text
    return int(match.group(1)), int(match.group(2))


def motion(dimension):
    if dimension == 3:
        return ["--rotate"] + list(ANGLES_3D) + ["--center", 0.5, 0.5, 0.5]
    return ["--rotate", 0, 0, ANGLE_2D, "--center", 0.5, 0.5, 0]


def rotation(dimension):
    """The rotation matrix of the motion (x, then y, then z, as the filter composes them)."""
    angles = ANGLES_3D if dimension == 3 else (0.0, 0.0, ANGLE_2D)
    ax, ay, az = (math.radians(a) for a in angles)
    rx = np.array([[1, 0, 0], [0, math.cos(ax), -math.sin(ax)], [0, math.sin(ax), math.cos(ax)]])
    ry = np.array([[math.cos(ay), 0, math.sin(ay)], [0, 1, 0], [-math.sin(ay), 0, math.cos(ay)]])
    rz = np.array([[math.cos(az), -math.sin(az), 0], [math.sin(az), math.cos(az), 0], [0, 0, 1]])
    return rz @ ry @ rx


class Formats(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        from paraview import simple

        cls.simple = simple
        simple.LoadPlugin(ARGS.plugin, remote=False)
        shutil.rmtree(ARGS.work, ignore_errors=True)
        os.makedirs(ARGS.work)
        cls.files = make_meshes(ARGS.work)

    def read(self, path):
        """(points, FileNodeId, boundary name -> node indices) of a .msh or .su2 file, read with
        the plugin's reader."""
        from paraview import servermanager
        from vtkmodules.util.numpy_support import vtk_to_numpy

        reader = self.simple.DGMFMeshFileReader(FileName=path)
        data = servermanager.Fetch(reader)
        self.simple.Delete(reader)
        volume = data.GetBlock(0)
        points = vtk_to_numpy(volume.GetPoints().GetData()).copy()
        ids = vtk_to_numpy(volume.GetPointData().GetArray("FileNodeId")).copy()
        index = {tuple(p): i for i, p in enumerate(points)}
        names = {}
        boundary = data.GetBlock(1)
        for b in range(boundary.GetNumberOfBlocks()):
            block = boundary.GetBlock(b)
            name = boundary.GetMetaData(b).Get(data.NAME())
            names[name] = sorted({index[tuple(p)]
                                  for p in vtk_to_numpy(block.GetPoints().GetData())})
        return points, ids, names

    def check_deformed(self, source, deformed, dimension):
        points, ids, names = self.read(source)
        moved, moved_ids, moved_names = self.read(deformed)
        self.assertEqual(len(moved), len(points))
        np.testing.assert_array_equal(moved_ids, ids)
        self.assertEqual(set(moved_names), {"wing", "farfield"})
        wing, farfield = names["wing"], names["farfield"]
        self.assertTrue(wing and farfield)
        np.testing.assert_array_equal(moved[farfield], points[farfield])
        center = np.array([0.5, 0.5, 0.5 if dimension == 3 else 0.0])
        expected = (points[wing] - center) @ rotation(dimension).T + center
        self.assertLess(np.abs(moved[wing] - expected).max(), 1e-12)
        self.assertGreater(np.abs(moved - points).max(), 0.01)  # the mesh moved

    def vtu_route(self, source, dimension):
        """The quality summary of the same mesh through a .vtu with a BoundaryMarker array."""
        from paraview import servermanager
        from vtkmodules.util.numpy_support import numpy_to_vtk
        from vtkmodules.vtkCommonDataModel import vtkUnstructuredGrid
        from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridWriter

        points, ids, names = self.read(source)
        reader = self.simple.DGMFMeshFileReader(FileName=source)
        volume = vtkUnstructuredGrid()
        volume.DeepCopy(servermanager.Fetch(reader).GetBlock(0))
        self.simple.Delete(reader)
        marker = np.zeros(len(points), dtype=np.int32)
        marker[names["farfield"]] = 1
        marker[names["wing"]] = 2
        array = numpy_to_vtk(marker, deep=1)
        array.SetName("BoundaryMarker")
        volume.GetPointData().AddArray(array)
        path = source + ".marker.vtu"
        writer = vtkXMLUnstructuredGridWriter()
        writer.SetInputData(volume)
        writer.SetFileName(path)
        writer.SetDataModeToBinary()
        writer.Write()
        code, out, err = run(path, path + ".out.vtu", *motion(dimension))
        self.assertEqual(code, 0, err)
        self.assertEqual(sizes(out), (len(points), volume.GetNumberOfCells()))
        return summary(out), sizes(out)

    def test_command_round_trip_every_format(self):
        for label, source in sorted(self.files.items()):
            with self.subTest(file=label):
                dimension = int(label[0])
                extension = os.path.splitext(source)[1]
                output = os.path.join(ARGS.work, "cli_" + label + extension)
                code, out, err = run(source, output, "--moving", "wing", *motion(dimension))
                self.assertEqual(code, 0, err)
                self.assertIn("moving wing;", out)
                self.assertIn("others (farfield)", out)
                self.check_deformed(source, output, dimension)
                # The same quality, and the same mesh size: the volume's, without the boundary
                # blocks' points and faces (counted on top until 2026-11-30).
                self.assertEqual((summary(out), sizes(out)), self.vtu_route(source, dimension))

    def test_gmsh_reopens_the_written_files(self):
        for label, source in sorted(self.files.items()):
            if not source.endswith(".msh"):
                continue
            with self.subTest(file=label):
                output = os.path.join(ARGS.work, "cli_" + label + ".msh")
                if not os.path.exists(output):
                    run(source, output, "--moving", "wing", *motion(int(label[0])))
                with open(source, "rb") as a, open(output, "rb") as b:
                    self.assertEqual(a.readline() + a.readline(), b.readline() + b.readline())
                gmsh.initialize()
                gmsh.option.setNumber("General.Terminal", 0)
                groups = {}
                for path in (source, output):
                    gmsh.open(path)
                    groups[path] = sorted(
                        (d, t, gmsh.model.getPhysicalName(d, t),
                         len(gmsh.model.mesh.getNodesForPhysicalGroup(d, t)[0]))
                        for d, t in gmsh.model.getPhysicalGroups())
                    gmsh.clear()
                gmsh.finalize()
                self.assertEqual(groups[source], groups[output])

    def test_su2_keeps_every_line_but_the_points(self):
        source = self.files["3d_su2"]
        output = os.path.join(ARGS.work, "cli_3d_su2.su2")
        if not os.path.exists(output):
            run(source, output, "--moving", "wing", *motion(3))
        with open(source) as a, open(output) as b:
            before, after = a.read().splitlines(), b.read().splitlines()
        self.assertEqual(len(before), len(after))
        start = next(k for k, line in enumerate(before) if line.startswith("NPOIN"))
        count = int(before[start].split("=")[1].split()[0])
        outside = [k for k in range(len(before)) if not start < k <= start + count]
        self.assertTrue(all(before[k] == after[k] for k in outside))

    def test_unknown_name_lists_the_file_names(self):
        code, out, err = run(self.files["3d_su2"], os.path.join(ARGS.work, "x.su2"),
                             "--moving", "wnig", "--rotate", 0, 0, 10)
        self.assertEqual(code, 1, err)
        self.assertIn("'wnig'", err)
        self.assertIn("wing", err)
        self.assertIn("farfield", err)
        code, out, err = run(self.files["3d_su2"], os.path.join(ARGS.work, "x.su2"))
        self.assertEqual(code, 2, err)
        self.assertIn("wing, farfield", err)

    def test_a_group_that_is_not_a_boundary_is_said_to_be_one(self):
        # "fluid" is the 3D mesh's volume group: named, it is said to be a group of dimension 3,
        # with the file's boundaries (until 2026-11-30: "No block of the input is named 'fluid'").
        # Both .msh readers: version 4.1 (gmsh's library) and 2.2 (read without it).
        for label in ("3d_msh4.1", "3d_msh2.2", "3d_msh2.2_binary"):
            with self.subTest(label=label):
                code, out, err = run(self.files[label], os.path.join(ARGS.work, "x.vtu"),
                                     "--moving", "fluid", "--rotate", 0, 0, 10)
                self.assertEqual(code, 1, err)
                self.assertIn("'fluid' is a physical group of dimension 3 in the mesh file, not a "
                              "boundary", err)
                self.assertIn("The input's blocks are: internalMesh, wing, farfield.", err)

    def test_upper_case_extensions(self):
        # BOX.MSH, BOX.SU2 and OUT.VTU are the files of their formats (until 2026-11-30 they were
        # read as XML, and their outputs refused).
        for label, name in (("3d_msh4.1", "BOX.MSH"), ("3d_su2", "BOX.SU2")):
            with self.subTest(name=name):
                upper = os.path.join(ARGS.work, name)
                shutil.copy(self.files[label], upper)
                for output in (os.path.join(ARGS.work, "OUT" + name[3:]),
                               os.path.join(ARGS.work, "OUT.VTU")):
                    code, out, err = run(upper, output, "--moving", "wing", *motion(3))
                    self.assertEqual(code, 0, err)
                    self.assertIn("wrote " + output, out)

    def test_other_formats_out(self):
        source = self.files["3d_msh4.1"]
        code, out, err = run(source, os.path.join(ARGS.work, "x.su2"), "--moving", "wing")
        self.assertEqual(code, 2, err)
        vtu = os.path.join(ARGS.work, "msh_to.vtu")
        code, out, err = run(source, vtu, "--moving", "wing", *motion(3))
        self.assertEqual(code, 0, err)
        from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
        reader = vtkXMLUnstructuredGridReader()
        reader.SetFileName(vtu)
        reader.Update()
        grid = reader.GetOutput()
        self.assertEqual(grid.GetNumberOfPoints(), len(self.read(source)[0]))
        # The volume carries what the filter gives one grid: every quality array, and the summary
        # it printed (the filter puts the summary on the reader's blocks, not on the volume).
        for name in ("SizeSkew", "Inverted", "InputInvalid"):
            array = grid.GetCellData().GetArray(name)
            self.assertIsNotNone(array, name)
            self.assertEqual(array.GetNumberOfTuples(), grid.GetNumberOfCells())
        field = grid.GetFieldData()
        mean, minimum, inverted = summary(out)
        self.assertIsNotNone(field.GetArray("SizeSkewMean"))
        self.assertAlmostEqual(field.GetArray("SizeSkewMean").GetValue(0), mean, places=5)
        self.assertAlmostEqual(field.GetArray("SizeSkewMinimum").GetValue(0), minimum, places=5)
        self.assertEqual(field.GetArray("InvertedCellCount").GetValue(0), inverted)
        self.assertEqual(field.GetArray("InputInvalidCellCount").GetValue(0), 0)

    def test_string_arrays_of_the_input_reach_the_output(self):
        from vtkmodules.vtkCommonCore import vtkStringArray
        from vtkmodules.vtkIOLegacy import vtkUnstructuredGridReader
        from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader, vtkXMLUnstructuredGridWriter

        # The .msh route's output, as a .vtu with a BoundaryMarker, and two string arrays.
        source = self.files["3d_msh4.1"]
        self.vtu_route(source, 3)
        reader = vtkXMLUnstructuredGridReader()
        reader.SetFileName(source + ".marker.vtu")
        reader.Update()
        grid = reader.GetOutput()
        labels = vtkStringArray()
        labels.SetName("PointLabel")
        for p in range(grid.GetNumberOfPoints()):
            labels.InsertNextValue("node %d" % p)
        grid.GetPointData().AddArray(labels)
        case = vtkStringArray()
        case.SetName("CaseName")
        case.InsertNextValue("sphere in a box")
        grid.GetFieldData().AddArray(case)
        labelled = os.path.join(ARGS.work, "labelled.vtu")
        writer = vtkXMLUnstructuredGridWriter()
        writer.SetInputData(grid)
        writer.SetFileName(labelled)
        writer.SetDataModeToBinary()
        writer.Write()
        for extension, reading in ((".vtu", vtkXMLUnstructuredGridReader),
                                   (".vtk", vtkUnstructuredGridReader)):
            with self.subTest(output=extension):
                output = os.path.join(ARGS.work, "labelled_out" + extension)
                code, out, err = run(labelled, output, *motion(3))
                self.assertEqual(code, 0, err)
                back = reading()
                back.SetFileName(output)
                if extension == ".vtk":
                    back.ReadAllScalarsOn()
                    back.ReadAllFieldsOn()
                back.Update()
                deformed = back.GetOutput()
                written = deformed.GetPointData().GetAbstractArray("PointLabel")
                self.assertIsNotNone(written)
                self.assertEqual(written.GetNumberOfValues(), grid.GetNumberOfPoints())
                self.assertEqual(written.GetValue(17), "node 17")
                self.assertEqual(
                    deformed.GetFieldData().GetAbstractArray("CaseName").GetValue(0),
                    "sphere in a box")
                # The filter's own string (Method) stays out: meshio cannot read strings.
                self.assertIsNone(deformed.GetFieldData().GetAbstractArray("Method"))

    def test_paraview_reads_deforms_and_saves_each_format(self):
        from paraview import servermanager

        for label in ("3d_msh4.1", "3d_msh2.2_binary", "3d_su2", "2d_su2"):
            with self.subTest(file=label):
                source = self.files[label]
                dimension = int(label[0])
                extension = os.path.splitext(source)[1]
                reader = self.simple.DGMFMeshFileReader(FileName=source)
                deform = self.simple.DGMFDeform(Input=reader)
                deform.MovingBoundaries = ["wing"]
                deform.RotationCenter = [0.5, 0.5, 0.5 if dimension == 3 else 0.0]
                deform.RotationAngles = list(ANGLES_3D) if dimension == 3 else [0, 0, ANGLE_2D]
                deform.UpdatePipeline()
                output = os.path.join(ARGS.work, "pv_" + label + extension)
                self.simple.SaveData(output, proxy=deform)
                self.check_deformed(source, output, dimension)
                cli = os.path.join(ARGS.work, "cli_" + label + extension)
                if os.path.exists(cli):
                    np.testing.assert_array_equal(self.read(output)[0], self.read(cli)[0])
                self.simple.Delete(deform)
                self.simple.Delete(reader)

    def test_exodus_node_sets_name_the_boundaries(self):
        """An Exodus file (written by meshio from the gmsh mesh, its physical groups as node sets)
        read by both of ParaView's Exodus readers (a multiblock from ExodusIIReader, a partitioned
        data set collection from IOSSReader), deformed by name."""
        from paraview import servermanager
        from vtkmodules.util.numpy_support import vtk_to_numpy

        exodus = os.path.join(ARGS.work, "3d_meshio.exo")
        script = (
            "import sys, gmsh, meshio, numpy as np\n"
            "gmsh.initialize(); gmsh.option.setNumber('General.Terminal', 0)\n"
            "gmsh.open(sys.argv[1])\n"
            "tags, xyz, _ = gmsh.model.mesh.getNodes()\n"
            "order = np.argsort(tags); tags = tags[order]; points = xyz.reshape(-1, 3)[order]\n"
            "index = {t: i for i, t in enumerate(tags)}\n"
            "types, _, nodes = gmsh.model.mesh.getElements(3)\n"
            "tets = np.array([index[t] for t in nodes[0]]).reshape(-1, 4)\n"
            "sets = {gmsh.model.getPhysicalName(d, t): np.array(sorted(index[n] for n in\n"
            "        gmsh.model.mesh.getNodesForPhysicalGroup(d, t)[0]))\n"
            "        for d, t in gmsh.model.getPhysicalGroups(2)}\n"
            "meshio.write(sys.argv[2], meshio.Mesh(points, [('tetra', tets)], point_sets=sets))\n")
        done = subprocess.run(["/usr/bin/python3", "-c", script, self.files["3d_msh4.1"], exodus],
                              capture_output=True, text=True)
        self.assertEqual(done.returncode, 0, done.stderr)
        points, ids, names = self.read(self.files["3d_msh4.1"])
        for reader_name in ("ExodusIIReader", "IOSSReader"):
            with self.subTest(reader=reader_name):
                reader = getattr(self.simple, reader_name)(FileName=[exodus])
                if reader_name == "ExodusIIReader":
                    reader.NodeSetArrayStatus = ["wing", "farfield"]
                else:
                    reader.NodeSets = ["wing", "farfield"]
                deform = self.simple.DGMFDeform(Input=reader)
                deform.MovingBoundaries = ["wing"]
                deform.RotationCenter = [0.5, 0.5, 0.5]
                deform.RotationAngles = list(ANGLES_3D)
                merged = self.simple.MergeBlocks(Input=deform)
                result = servermanager.Fetch(merged)
                moved = vtk_to_numpy(result.GetPoints().GetData())
                # Every node of the file, at its rigid or static position (matched by position in
                # the original mesh: the readers add the node sets' own copies of the nodes).
                before = vtk_to_numpy(
                    servermanager.Fetch(self.simple.MergeBlocks(Input=reader)).GetPoints().GetData())
                # Exodus readers may give single-precision points: matched to the nearest node.
                def nearest(p):
                    distances = np.abs(points - p).max(axis=1)
                    i = int(np.argmin(distances))
                    self.assertLess(distances[i], 1e-6)
                    return i
                rotate = rotation(3)
                center = np.array([0.5, 0.5, 0.5])
                wing, farfield = set(names["wing"]), set(names["farfield"])
                checked = 0
                for p, q in zip(before, moved):
                    i = nearest(p)
                    if i in wing:
                        self.assertLess(np.abs(q - ((p - center) @ rotate.T + center)).max(), 1e-12)
                        checked += 1
                    elif i in farfield:
                        self.assertTrue(np.array_equal(p, q))
                self.assertGreaterEqual(checked, len(wing))
                self.simple.Delete(merged)
                self.simple.Delete(deform)
                self.simple.Delete(reader)
        # The same file (node sets; coordinates in meshio's combined "coord" variable) through
        # dgmf-deform and back into Exodus.
        written = os.path.join(ARGS.work, "cli_3d_meshio.exo")
        code, out, err = run(exodus, written, "--moving", "wing", *motion(3))
        self.assertEqual(code, 0, err)
        self.check_deformed(exodus, written, 3)

    def leaves(self, data):
        """{block name: leaf} of a composite data set."""
        named = {}
        iterator = data.NewIterator()
        iterator.InitTraversal()
        while not iterator.IsDoneWithTraversal():
            named[iterator.GetCurrentMetaData().Get(data.NAME())] = \
                iterator.GetCurrentDataObject()
            iterator.GoToNextItem()
        return named

    def cell_points(self, block):
        """The points the cells of `block` use, sorted by their index in the block."""
        from vtkmodules.util.numpy_support import vtk_to_numpy

        used = sorted({block.GetCell(c).GetPointId(k) for c in range(block.GetNumberOfCells())
                       for k in range(block.GetCell(c).GetNumberOfPoints())})
        return vtk_to_numpy(block.GetPoints().GetData())[used]

    def check_paraview_reads_back(self, source, written, open_reader, tolerance=1e-12):
        """ParaView's own reader (open_reader(path) -> {name: block}) finds the wing and the
        farfield in the written file, the wing at its rigid position and the farfield unmoved."""
        before, after = open_reader(source), open_reader(written)
        for name in ("wing", "farfield"):
            self.assertIn(name, after)
            self.assertGreater(after[name].GetNumberOfCells(), 0)
            self.assertEqual(after[name].GetNumberOfCells(), before[name].GetNumberOfCells())
        center = np.array([0.5, 0.5, 0.5])
        wing = self.cell_points(before["wing"])
        expected = (wing - center) @ rotation(3).T + center
        self.assertLess(np.abs(self.cell_points(after["wing"]) - expected).max(), tolerance)
        np.testing.assert_array_equal(self.cell_points(after["farfield"]),
                                      self.cell_points(before["farfield"]))

    def deformed(self, reader):
        deform = self.simple.DGMFDeform(Input=reader)
        deform.MovingBoundaries = ["wing"]
        deform.RotationCenter = [0.5, 0.5, 0.5]
        deform.RotationAngles = list(ANGLES_3D)
        return deform

    def test_exodus_written_back_reads_in_paraviews_exodus_reader(self):
        """DGMF Mesh File Reader, DGMF Deform, SaveData(.exo) (the DGMF writer: ParaView has no
        .exo writer); the file read back by ParaView's ExodusIIReader with its side sets."""
        from paraview import servermanager

        def open_exodus(path):
            reader = self.simple.ExodusIIReader(FileName=[path])
            reader.SideSetArrayStatus = ["wing", "farfield"]
            blocks = self.leaves(servermanager.Fetch(reader))
            self.simple.Delete(reader)
            return blocks

        source = self.files["3d_exo"]
        reader = self.simple.DGMFMeshFileReader(FileName=source)
        deform = self.deformed(reader)
        written = os.path.join(ARGS.work, "pv_3d.exo")
        self.simple.SaveData(written, proxy=deform)
        self.check_deformed(source, written, 3)
        # ExodusIIReader gives the points in single precision.
        self.check_paraview_reads_back(source, written, open_exodus, tolerance=1e-6)
        self.assertEqual(open_exodus(written)["fluid"].GetNumberOfPoints(),
                         len(self.read(source)[0]))
        self.simple.Delete(deform)
        self.simple.Delete(reader)

    def test_exodus_from_paraviews_reader_saved_as_exo(self):
        """ParaView's own ExodusIIReader (side sets ticked), DGMF Deform by name, SaveData(.exo)
        with SourceFileName: the DGMF writer places the points by GlobalNodeId into a copy of
        the file."""
        source = self.files["3d_exo"]
        reader = self.simple.ExodusIIReader(FileName=[source])
        reader.SideSetArrayStatus = ["wing", "farfield"]
        deform = self.deformed(reader)
        written = os.path.join(ARGS.work, "pv_exodus_reader_3d.exo")
        # ParaView wraps its Exodus reader in a file-series reader: the source file is named.
        self.simple.SaveData(written, proxy=deform, SourceFileName=source)
        # The same file with the same names; the static nodes keep every bit of the file's
        # doubles; the wing at its rigid position to the single precision ExodusIIReader reads.
        points, ids, names = self.read(source)
        moved, moved_ids, moved_names = self.read(written)
        np.testing.assert_array_equal(moved_ids, ids)
        self.assertEqual(set(moved_names), {"wing", "farfield"})
        np.testing.assert_array_equal(moved[names["farfield"]], points[names["farfield"]])
        center = np.array([0.5, 0.5, 0.5])
        expected = (points[names["wing"]] - center) @ rotation(3).T + center
        self.assertLess(np.abs(moved[names["wing"]] - expected).max(), 1e-6)
        cli = os.path.join(ARGS.work, "cli_3d_exo.exo")
        if os.path.exists(cli):
            np.testing.assert_allclose(moved, self.read(cli)[0], atol=1e-6)
        self.simple.Delete(deform)
        self.simple.Delete(reader)

    def test_cgns_written_back_reads_in_paraviews_cgns_reader(self):
        """DGMF Mesh File Reader, DGMF Deform, the DGMF writer (SaveData(.cgns) picks ParaView's
        CGNS writer, which writes no boundary conditions); the file read back by ParaView's
        CGNSSeriesReader with its boundary conditions as patches."""
        from paraview import servermanager

        def open_cgns(path):
            reader = self.simple.CGNSSeriesReader(FileNames=[path])
            reader.LoadPatches = 1
            blocks = self.leaves(servermanager.Fetch(reader))
            self.simple.Delete(reader)
            return blocks

        for label in ("3d_cgns", "2d_cgns"):
            with self.subTest(file=label):
                source = self.files[label]
                dimension = int(label[0])
                reader = self.simple.DGMFMeshFileReader(FileName=source)
                deform = self.deformed(reader)
                if dimension == 2:
                    deform.RotationCenter = [0.5, 0.5, 0.0]
                    deform.RotationAngles = [0, 0, ANGLE_2D]
                written = os.path.join(ARGS.work, "pv_" + label + ".cgns")
                writer = servermanager.writers.DGMFMeshFileWriter(Input=deform, FileName=written)
                writer.UpdatePipeline()
                self.check_deformed(source, written, dimension)
                if dimension == 3:
                    self.check_paraview_reads_back(source, written, open_cgns)
                    self.assertEqual(open_cgns(written)["Internal"].GetNumberOfPoints(),
                                     len(self.read(source)[0]))
                del writer
                self.simple.Delete(deform)
                self.simple.Delete(reader)

    def test_vtu_and_vtk_outputs_read_in_meshio(self):
        # meshio 5 (Debian 12) reads zlib and lzma, not LZ4; its appended-raw reader finds the
        # arrays by offset, which the field data's small arrays make ambiguous (README). Legacy
        # files are written as version 4.2 with 64-bit ids as `long`: meshio's reader of 5.1
        # knows neither `unsigned_char` nor `vtkIdType`.
        outputs = {".vtu": ["--compression", "zlib"], ".vtk": []}
        read = {}
        for extension, options in outputs.items():
            with self.subTest(output=extension):
                path = os.path.join(ARGS.work, "meshio" + extension)
                code, out, err = run(self.files["3d_su2"], path, "--moving", "wing", *motion(3),
                                     *options)
                self.assertEqual(code, 0, err)
                done = subprocess.run(
                    ["/usr/bin/python3", "-c",
                     "import meshio, sys, numpy as np\n"
                     "m = meshio.read(sys.argv[1])\n"
                     "np.save(sys.argv[2], np.hstack([m.points, m.point_data['f'][:, None]]))\n"
                     "print(sum(len(c.data) for c in m.cells), len(m.cell_data['SizeSkew']))",
                     path, path + ".npy"],
                    capture_output=True, text=True)
                self.assertEqual(done.returncode, 0, done.stderr)
                read[extension] = np.load(path + ".npy")
                self.assertEqual(len(read[extension]), len(self.read(self.files["3d_su2"])[0]))
                cells, blocks = (int(word) for word in done.stdout.split())
                self.assertGreater(cells, 0)
                self.assertGreater(blocks, 0)
        # The same deformed points and damping factors through both files.
        np.testing.assert_array_equal(read[".vtu"], read[".vtk"])


if __name__ == "__main__":
    parser = argparse.ArgumentParser()
    parser.add_argument("--deform", required=True)
    parser.add_argument("--convert", required=True)
    parser.add_argument("--plugin", required=True)
    parser.add_argument("--work", required=True)
    ARGS, rest = parser.parse_known_args()
    unittest.main(argv=[sys.argv[0]] + rest, verbosity=2)
