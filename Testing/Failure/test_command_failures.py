"""dgmf-deform under failure (issue 17): honest exit codes, no half-written file at the output
path, the filter's own messages on stderr once, out of memory without a crash.

Run with pvpython (VTK's Python modules make and read the meshes):
  pvpython test_command_failures.py --deform DGMF_DEFORM --data DATA_DIR --work WORK_DIR [-k NAME]
"""
import argparse
import glob
import hashlib
import math
import os
import re
import shutil
import signal
import subprocess
import sys
import time
import unittest
from xml.etree import ElementTree

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import failure_meshes as meshes  # noqa: E402

ARGS = None
CIRCLE_POINTS = 822


def run(*arguments, limit=None, fsize=None, timeout=600):
    """Runs dgmf-deform; returns (exit code, stdout, stderr). Negative codes are signals."""
    command = [ARGS.deform] + [str(a) for a in arguments]
    if limit is not None or fsize is not None:
        prefix = ["prlimit"]
        if limit is not None:
            prefix.append("--as=%d" % limit)
        if fsize is not None:
            prefix.append("--fsize=%d" % fsize)
        command = prefix + ["--"] + command
    done = subprocess.run(command, capture_output=True, text=True, timeout=timeout)
    return done.returncode, done.stdout, done.stderr


def digest(path):
    with open(path, "rb") as f:
        return hashlib.sha256(f.read()).hexdigest()


def leftovers(folder):
    """Temporary files dgmf-deform left behind."""
    return glob.glob(os.path.join(folder, ".*.dgmf-*.tmp"))


class CommandFailures(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.work = ARGS.work
        shutil.rmtree(cls.work, ignore_errors=True)
        os.makedirs(cls.work)
        cls.circle = os.path.join(ARGS.data, "rotating_circle.vtu")

    def path(self, name):
        return os.path.join(self.work, name)

    # 1. A failed write exits 1 and does not say it wrote.
    def test_failed_write_exits_1(self):
        # A missing folder is said before the work.
        code, out, err = run(self.circle, self.path("no/such/dir/o.vtu"), "--rotate", 0, 0, 30)
        self.assertEqual(code, 1, err)
        self.assertNotIn("wrote", out)
        self.assertIn("the output's folder", err)
        self.assertNotIn("dgmf-deform: 822 points", out)  # nothing was deformed
        # A path that cannot be written (a folder of that name): the write fails.
        blocked = self.path("blocked.vtu")
        os.makedirs(blocked, exist_ok=True)
        code, out, err = run(self.circle, blocked, "--rotate", 0, 0, 30)
        self.assertEqual(code, 1, err)
        self.assertNotIn("wrote", out)
        self.assertIn("could not write", err)

    # 2. The output may be the input: read completely, then replaced whole.
    def test_output_may_be_the_input(self):
        target = self.path("same.vtu")
        shutil.copy(self.circle, target)
        code, out, err = run(target, target, "--rotate", 0, 0, 30)
        self.assertEqual(code, 0, err)
        deformed = meshes.read(target)
        original = meshes.read(self.circle)
        self.assertEqual(deformed.GetNumberOfPoints(), CIRCLE_POINTS)
        moved = sum(
            deformed.GetPoint(i) != original.GetPoint(i) for i in range(CIRCLE_POINTS))
        self.assertGreater(moved, 100)
        self.assertEqual(leftovers(self.work), [])

    def test_a_series_never_overwrites_its_input_and_names_its_frames_safely(self):
        # Until 2026-11-30: a series started from a frame of an earlier one wrote its frame 0
        # over its input; a %d in a folder wrote frame 0, failed at frame 1 and wrote no .pvd; a
        # %064d wrote every frame into one file; a '&' in the name made a .pvd no reader parses.
        folder = self.path("series_names")
        shutil.rmtree(folder, ignore_errors=True)
        os.makedirs(folder)
        pitch = ("--center", 0.25, 0, 0, "--pitch", 0, 5, 1, 0, "--times", "0:1:2")
        source = os.path.join(folder, "p_0000.vtu")
        shutil.copy(os.path.join(ARGS.data, "pitching_airfoil.vtu"), source)
        before = digest(source)
        code, out, err = run(source, os.path.join(folder, "p.vtu"), *pitch)
        self.assertEqual(code, 2, err)
        self.assertIn("frame 0 of the series would overwrite the input", err)
        self.assertEqual(digest(source), before)
        for pattern in ("fr_%d/p.vtu", "w_%064d.vtu", "w_%99999999999999999999d.vtu",
                        "w_%4294967297d.vtu"):
            code, out, err = run(source, os.path.join(folder, pattern), *pitch)
            self.assertEqual(code, 2, pattern + err)
            self.assertIn("in the file's name, not in a folder", err)
        self.assertEqual(sorted(os.listdir(folder)), ["p_0000.vtu"])
        code, out, err = run(source, os.path.join(folder, "wing&flap.vtu"), *pitch)
        self.assertEqual(code, 0, err)
        listed = [element.get("file") for element in
                  ElementTree.parse(os.path.join(folder, "wing&flap.pvd")).iter("DataSet")]
        self.assertEqual(listed, ["wing&flap_0000.vtu", "wing&flap_0001.vtu"])
        for name in listed:
            self.assertGreater(meshes.read(os.path.join(folder, name)).GetNumberOfPoints(), 0)

    def test_a_series_whose_motion_fails_later_writes_no_frame(self):
        # An axis of length 0, or a 2D mesh turned about x: at angle 0 (frame 0) both passed, so
        # frame 0 and a .pvd were written before the run failed at time 0.5 (until 2026-11-30).
        for name, source, axis in (("zero_axis", "sphere_in_box.vtu", (0, 0, 0)),
                                   ("out_of_plane", "pitching_airfoil.vtu", (1, 0, 0))):
            with self.subTest(case=name):
                folder = self.path("series_" + name)
                shutil.rmtree(folder, ignore_errors=True)
                code, out, err = run(os.path.join(ARGS.data, source),
                                     os.path.join(folder, "p.vtu"), "--axis", *axis,
                                     "--pitch", 0, 20, 1, 0, "--times", "0:1:3")
                self.assertEqual(code, 1, err)
                self.assertIn("failed at time 0; 0 earlier frames were written", err)
                self.assertEqual(glob.glob(os.path.join(folder, "*")), [])

    def test_the_body_id_array_is_an_option(self):
        # A two-body table on two_circles.vtu needs its BodyId array, which the command could not
        # select until 2026-11-30 (the error named an array no option gave).
        table = self.path("two_bodies.csv")
        with open(table, "w") as handle:
            handle.write("Time,Body,RZ\n0,1,0\n0,2,0\n1,1,20\n1,2,-20\n")
        source = os.path.join(ARGS.data, "two_circles.vtu")
        folder = self.path("two_bodies")
        shutil.rmtree(folder, ignore_errors=True)
        code, out, err = run(source, os.path.join(folder, "t.vtu"), "--trajectory", table)
        self.assertEqual(code, 1, err)
        self.assertIn("dgmf-deform's --body-id", err)
        code, out, err = run(source, os.path.join(folder, "t.vtu"), "--trajectory", table,
                             "--body-id", "BodyId")
        self.assertEqual(code, 0, err)
        grid = meshes.read(source)
        ids = grid.GetPointData().GetArray("BodyId")
        moved = meshes.read(os.path.join(folder, "t_0001.vtu"))
        for body in (1, 2):
            largest = max(math.dist(grid.GetPoint(i), moved.GetPoint(i))
                          for i in range(grid.GetNumberOfPoints())
                          if ids.GetTuple1(i) == body)
            self.assertGreater(largest, 0.05, body)

    def test_series_times_are_printed_exactly_and_refused_times_say_why(self):
        # Until 2026-11-30 each refusal printed "bad option or value: --times" and the usage page,
        # and the frame lines showed 6 digits ("time 0.123457" for three different times).
        airfoil = os.path.join(ARGS.data, "pitching_airfoil.vtu")
        pitch = ("--pitch", 0, 5, 1, 0)
        for times, why in (("1:0:5", "END must be above START for several frames"),
                           ("0:1:0", "COUNT must be 1 to 1000000 frames"),
                           ("0:1:1000001", "COUNT must be 1 to 1000000 frames"),
                           ("0:1", "give START:END:COUNT, such as 0:1:21")):
            with self.subTest(times=times):
                code, out, err = run(airfoil, self.path("t.vtu"), *pitch, "--times", times)
                self.assertEqual(code, 2, err)
                self.assertIn("bad option or value: --times %s: %s" % (times, why), err)
                self.assertNotIn("usage", err.lower())
        # Bad law parameters are bad values too (exit 2 before any work; exit 1 at frame 0 before).
        for law in (("--rotation-law", "ramp", 0, 10, 1, 0), ("--pitch", 0, 10, -1, 0)):
            with self.subTest(law=law):
                code, out, err = run(airfoil, self.path("t.vtu"), *law, "--times", "0:1:3")
                self.assertEqual(code, 2, err)
                self.assertIn("bad option or value: %s: the rotation law" % law[0], err)
                self.assertNotIn("frame 1", out)
        code, out, err = run(airfoil, self.path("exact/t.vtu"), *pitch, "--times",
                             "0.1234567891234:0.2:2", "--no-write")
        self.assertEqual(code, 0, err)
        self.assertIn("time 0.1234567891234 (frame 1 of 2)", out)

    def test_a_mesh_without_a_marker_whose_nodes_cannot_move_is_an_error(self):
        # Without a marker array and with a zero displacement no node moves: until 2026-11-30
        # the input's points were written, exit 0, after a warning.
        unmarked = self.path("unmarked.vtu")
        mesh = meshes.read(self.circle)
        mesh.GetPointData().RemoveArray("BoundaryMarker")
        meshes.write(mesh, unmarked)
        output = self.path("unmarked_out.vtu")
        code, out, err = run(unmarked, output, "--rotate", 0, 0, 20)
        self.assertEqual(code, 1, err)
        self.assertIn("no boundary-marker array 'BoundaryMarker' and no non-zero displacement", err)
        self.assertFalse(os.path.exists(output))
        # With a displacement on the circle, its faces' nodes move and the command says how the
        # boundary was found.
        displaced = self.path("displaced.vtu")
        meshes.with_displacement(self.circle, displaced,
                                 lambda d, marker: np.outer(marker == 2, [0.1, 0.0, 0.0]))
        mesh = meshes.read(displaced)
        mesh.GetPointData().RemoveArray("BoundaryMarker")
        meshes.write(mesh, displaced)
        code, out, err = run(displaced, output)
        self.assertEqual(code, 0, err)
        self.assertIn("the boundary is the mesh's boundary faces, moving where 'Displacement'", out)

    # 2. A write cut short (here by a file-size limit, as a full disk would) leaves the file that
    #    was at the output path untouched and no temporary file.
    def test_cut_write_keeps_the_previous_output(self):
        target = self.path("kept.vtu")
        shutil.copy(self.circle, target)
        before = digest(target)
        code, out, err = run(self.circle, target, "--rotate", 0, 0, 30, fsize=8000)
        self.assertEqual(code, 1, err)
        self.assertEqual(digest(target), before)
        self.assertEqual(leftovers(self.work), [])

    # 2. Ctrl-C during a run: exit 130, nothing written, the previous output untouched.
    def test_interrupt_leaves_nothing_behind(self):
        mesh = self.path("interrupt_in.vtu")
        meshes.cube_in_box(30, mesh)
        target = self.path("interrupt_out.vtu")
        shutil.copy(self.circle, target)
        before = digest(target)
        process = subprocess.Popen(
            [ARGS.deform, mesh, target, "--rotate", "10", "20", "30", "--center", "0.5", "0.5",
             "0.5", "--sub-steps", "1000"],
            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        time.sleep(2.0)
        self.assertIsNone(process.poll(), "the run ended before it could be interrupted")
        process.send_signal(signal.SIGINT)
        out, err = process.communicate(timeout=120)
        self.assertEqual(process.returncode, 130, err)
        self.assertIn("interrupted while deforming", err)
        self.assertEqual(digest(target), before)
        self.assertEqual(leftovers(self.work), [])

    def test_interrupted_series_keeps_a_collection_of_its_whole_frames(self):
        # Until 2026-11-30 a series stopped by a signal left its frames without a .pvd, and said
        # "nothing was written".
        folder = self.path("interrupted_series")
        shutil.rmtree(folder, ignore_errors=True)
        process = subprocess.Popen(
            [ARGS.deform, os.path.join(ARGS.data, "pitching_airfoil.vtu"),
             os.path.join(folder, "pitch.vtu"), "--center", "0.25", "0", "0",
             "--pitch", "0", "10", "1", "0", "--times", "0:100:100000"],
            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        collection = os.path.join(folder, "pitch.pvd")
        deadline = time.time() + 120
        while time.time() < deadline and process.poll() is None:
            if os.path.exists(collection):
                with open(collection) as handle:
                    if handle.read().count("<DataSet") >= 3:
                        break
            time.sleep(0.05)
        self.assertIsNone(process.poll(), "the series ended before it could be interrupted")
        process.send_signal(signal.SIGINT)
        out, err = process.communicate(timeout=120)
        self.assertEqual(process.returncode, 130, err)
        with open(collection) as handle:
            listed = re.findall(r'file="([^"]+)"', handle.read())
        self.assertGreaterEqual(len(listed), 3)
        for name in listed:  # every frame listed is there, whole
            frame = os.path.join(folder, name)
            self.assertTrue(os.path.exists(frame), name)
            code, _, stderr = run(frame, self.path("reread.vtu"), "--rotate", "0", "0", "1")
            self.assertEqual(code, 0, stderr)
        self.assertRegex(err, r"interrupted while .*; \d+ frames before it were written \(and "
                              r".*pitch.pvd of them\)")
        self.assertEqual(glob.glob(os.path.join(folder, "*.dgmf-writing")), [])

    # 4. Each bad-input class: the filter's own message on stderr, once, without VTK's pipeline
    #    dump or colour codes; exit 1; no output.
    def test_filter_messages_reach_stderr_once(self):
        zero = self.path("marker_zero.vtu")
        meshes.with_marker(self.circle, zero, lambda m, p: 0 * m)
        nan = self.path("nan_point.vtu")
        meshes.with_nan_point(self.circle, nan)
        cases = [
            ((self.circle, "--marker", "Nope"),
             "The boundary-marker array 'Nope' is not a point array of the input."),
            ((zero, "--rotate", 0, 0, 10), "No node is a boundary node"),
            ((self.circle, "--rotate", 0, 0, 800), "rotation angles must be within"),
            ((nan, "--rotate", 0, 0, 10), "NaN or infinite point coordinates"),
            ((self.circle, "--rotate", 10, 0, 0), "2D mesh"),
        ]
        for (source, *options), message in cases:
            with self.subTest(message=message):
                output = self.path("bad_out.vtu")
                code, out, err = run(source, output, *options)
                self.assertEqual(code, 1, err)
                self.assertEqual(err.count(message), 1, err)
                self.assertNotIn("returned failure for request", err)
                self.assertNotIn("\x1b[", err)
                self.assertNotIn("vtkDGMFDeformFilter (0x", err)
                self.assertFalse(os.path.exists(output))

    def test_each_frame_of_a_series_says_its_own_warnings_after_its_time(self):
        # Until 2026-11-30 a warning was printed once per process: frames 2 and 3 of a series
        # said nothing when they gave frame 1's warning word for word, and frame 1's came before
        # its "time" line.
        folder = self.path("series_warnings")
        shutil.rmtree(folder, ignore_errors=True)
        done = subprocess.run(
            [ARGS.deform, os.path.join(ARGS.data, "pitching_airfoil.vtu"),
             os.path.join(folder, "p.vtu"), "--center", "0.25", "0", "0", "--pitch", "0", "5",
             "1", "0", "--times", "0:1:3", "--method", "dgm", "--repair", "0.2"],
            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        self.assertEqual(done.returncode, 0, done.stdout)
        lines = [line for line in done.stdout.splitlines()
                 if line.startswith("dgmf-deform: time") or "ignored by DGM" in line]
        self.assertEqual(len(lines), 6, done.stdout)
        for k in range(3):
            self.assertIn("(frame %d of 3)" % (k + 1), lines[2 * k])
            self.assertIn("warning: Sub Steps and Repair Threshold", lines[2 * k + 1])

    def test_an_empty_file_is_said_to_be_empty(self):
        empty = self.path("empty.vtu")
        open(empty, "w").close()
        output = self.path("empty_out.vtu")
        code, out, err = run(empty, output, "--rotate", 0, 0, 10)
        self.assertEqual(code, 1, err)
        self.assertIn("empty.vtu is empty (0 bytes)", err)
        self.assertNotIn("Error parsing XML", err)
        self.assertFalse(os.path.exists(output))

    def test_integer_options_refuse_fractions(self):
        for option in ("--threads", "--sub-steps", "--damping", "--repair-passes"):
            with self.subTest(option=option):
                code, out, err = run(self.circle, self.path("o.vtu"), option, "1.5")
                self.assertEqual(code, 2, err)
                self.assertIn("bad option or value: " + option, err)

    def test_numbers_are_written_as_numbers(self):
        # Until 2026-11-30 "0x10" was 16 degrees, " 10" was taken (not "10 ") and
        # "0:1:2:junk" was 0:1:2.
        for arguments in (("--rotate", 0, 0, "0x10"), ("--rotate", 0, 0, " 10"),
                          ("--pitch", 0, 5, 1, 0, "--times", "0:1:2:junk"),
                          ("--pitch", 0, 5, 1, 0, "--times", "0:1:3:")):
            with self.subTest(arguments=arguments):
                code, out, err = run(self.circle, self.path("o.vtu"), *arguments)
                self.assertEqual(code, 2, err)
                self.assertIn("bad option or value: " + arguments[-2 if len(arguments) > 4
                                                                      else 0], err)
        # The options may come first (until 2026-11-30: "bad option or value: 0"): the same bytes.
        first, last = self.path("first.vtu"), self.path("last.vtu")
        code, out, err = run("--rotate", 0, 0, 10, "--threads", 1, self.circle, first)
        self.assertEqual(code, 0, err)
        code, out, err = run(self.circle, last, "--rotate", 0, 0, 10, "--threads", 1)
        self.assertEqual(code, 0, err)
        self.assertEqual(digest(first), digest(last))
        # ... or between the files (until 2026-11-30 "bad option or value: 0": the output was taken to be "--rotate").
        middle = self.path("middle.vtu")
        code, out, err = run(self.circle, "--rotate", 0, 0, 10, "--threads", 1, middle)
        self.assertEqual(code, 0, err)
        self.assertEqual(digest(first), digest(middle))
        code, out, err = run(self.circle, self.path("o.vtu"), "extra.vtu", "--rotate", 0, 0, 10)
        self.assertEqual(code, 2, err)
        self.assertIn("too many files: expected INPUT and OUTPUT, got 3", err)
        code, out, err = run(self.circle, "--rotate", 0, 0, 10)
        self.assertEqual(code, 2, err)
        self.assertIn("missing files: expected INPUT and OUTPUT, got 1", err)
        # A name option followed by another option has no value (the option was taken as a name).
        for option in ("--moving", "--marker", "--trajectory"):
            code, out, err = run(self.circle, self.path("o.vtu"), option, "--no-write")
            self.assertEqual(code, 2, err)
            self.assertIn("bad option or value: " + option, err)
        # A file whose name starts with "-" after "--" (the end of the options).
        dashed = os.path.join(os.path.dirname(middle), "-dashed.vtu")
        shutil.copyfile(self.circle, dashed)
        done = subprocess.run([ARGS.deform, "--rotate", "0", "0", "10", "--threads", "1", "--",
                               "-dashed.vtu", "-out.vtu"], cwd=os.path.dirname(dashed),
                              capture_output=True, text=True, timeout=600)
        self.assertEqual(done.returncode, 0, done.stderr)
        self.assertEqual(digest(first), digest(os.path.join(os.path.dirname(dashed), "-out.vtu")))
        code, out, err = run(self.circle, self.path("o.vtu"), "--rotate", 0, 0, "720.0000001")
        self.assertEqual(code, 1, err)
        self.assertIn("(got 720.0000001)", err)

    def test_options_that_would_be_ignored_are_said(self):
        # Until 2026-11-30 all of these were ignored without a word.
        code, out, err = run(self.circle, self.path("o.vtu"), "--time", 5)
        self.assertEqual(code, 2, err)
        self.assertIn("--time names the time directory of an OpenFOAM case", err)
        code, out, err = run(self.circle, self.path("o.vtk"), "--rotate", 0, 0, 10,
                             "--compression", "zlib", "--repair-passes", 5)
        self.assertEqual(code, 0, err)
        self.assertIn("--compression and --vtu-mode are for .vtu outputs", err)
        self.assertIn("without --repair they do nothing", err)
        # Two rotation laws: the second replaced the first; a law beside a table moving the
        # one body was dropped (both without a word until 2026-11-30).
        code, out, err = run(self.circle, self.path("laws.vtu"), "--pitch", 0, 5, 1, 0,
                             "--rotation-law", "ramp", 0, 10, 0, 1, "--times", "0:1:2")
        self.assertEqual(code, 2, err)
        self.assertIn("--pitch and --rotation-law both give the rotation law: give one", err)
        table = self.path("one_body.csv")
        with open(table, "w") as handle:
            handle.write("Time,RZ\n0,0\n1,10\n")
        code, out, err = run(self.circle, self.path("laws.vtu"), "--pitch", 0, 5, 1, 0,
                             "--trajectory", table, "--no-write")
        self.assertEqual(code, 0, err)
        self.assertIn("--pitch moves only the bodies the trajectory table has no rows for", err)

    def test_a_trajectory_column_named_twice_is_refused(self):
        # VTK's table keeps one of two same-named columns: until 2026-11-30 the other was dropped.
        table = self.path("twice.csv")
        with open(table, "w") as handle:
            handle.write("Time,TX,TX\n0,0,0\n1,1,2\n")
        code, out, err = run(self.circle, self.path("twice.vtu"), "--trajectory", table)
        self.assertEqual(code, 1, err)
        self.assertIn("names the column 'TX' twice", err)

    # --fail-on-inverted: exit 3 and nothing written; without it the tangled mesh is written.
    def test_fail_on_inverted(self):
        output = self.path("tangled.vtu")
        code, out, err = run(self.circle, output, "--rotate", 0, 0, 400, "--fail-on-inverted")
        self.assertEqual(code, 3, err)
        self.assertIn("inverts", err)
        self.assertFalse(os.path.exists(output))
        code, out, err = run(self.circle, output, "--rotate", 0, 0, 400)
        self.assertEqual(code, 0, err)
        self.assertNotIn("inverted cells 0;", out)
        code, out, err = run(self.circle, output, "--no-quality", "--fail-on-inverted")
        self.assertEqual(code, 2, err)

    # A .vtk output is legacy VTK that VTK's legacy reader reads back.
    def test_vtk_output_is_legacy(self):
        output = self.path("legacy.vtk")
        code, out, err = run(self.circle, output, "--rotate", 0, 0, 30)
        self.assertEqual(code, 0, err)
        with open(output, "rb") as f:
            self.assertTrue(f.read(30).startswith(b"# vtk DataFile Version"))
        self.assertEqual(meshes.read(output).GetNumberOfPoints(), CIRCLE_POINTS)
        code, out, err = run(self.circle, self.path("o.exe"), "--rotate", 0, 0, 30)
        self.assertEqual(code, 2, err)
        # Written as version 4.2 with 64-bit ids as `long` (meshio reads it: formats test), but a
        # global-ids attribute stays vtkIdType, as VTK code asks for it.
        from vtkmodules.vtkCommonCore import vtkIdTypeArray
        grid = meshes.read(self.circle)
        ids = vtkIdTypeArray()
        ids.SetName("GlobalNodeId")
        ids.SetNumberOfTuples(grid.GetNumberOfPoints())
        for i in range(grid.GetNumberOfPoints()):
            ids.SetValue(i, 1000 + i)
        grid.GetPointData().SetGlobalIds(ids)
        with_ids = self.path("global_ids.vtu")
        meshes.write(grid, with_ids)
        code, out, err = run(with_ids, output, "--rotate", 0, 0, 30)
        self.assertEqual(code, 0, err)
        back = meshes.read(output).GetPointData().GetGlobalIds()
        self.assertEqual(back.GetClassName(), "vtkIdTypeArray")
        self.assertEqual(back.GetValue(5), 1005)
        # Other attributes of ids (the scalars of an Id filter) are written as long all the same.
        grid.GetPointData().SetGlobalIds(None)
        grid.GetPointData().SetScalars(ids)
        meshes.write(grid, with_ids)
        code, out, err = run(with_ids, output, "--rotate", 0, 0, 30)
        self.assertEqual(code, 0, err)
        with open(output, "rb") as handle:
            self.assertNotIn(b"vtkIdType", handle.read())

    # Progress through the sub-steps on stderr (shown after 2 s, or from the start with --progress);
    # none on a short run.
    def test_progress_is_shown(self):
        code, out, err = run(self.circle, self.path("o.vtu"), "--rotate", 0, 0, 90,
                             "--sub-steps", 20, "--repair", 0.2, "--progress")
        self.assertEqual(code, 0, err)
        shown = [int(line.split()[-1].rstrip("%")) for line in err.splitlines()
                 if line.startswith("dgmf-deform: deforming ")]
        self.assertGreaterEqual(len(shown), 4, err)
        self.assertEqual(shown, sorted(set(shown)), err)
        code, out, err = run(self.circle, self.path("o.vtu"), "--rotate", 0, 0, 30)
        self.assertNotIn("deforming", err)

    # .vtu encodings: appended raw without compression by default (LZ4 until 2026-11-30: the
    # slower write), inline binary (LZ4 by default) for stock ParaView on Debian 12, each
    # compression; all read back whole.
    def test_vtu_encodings(self):
        cases = [((), 'format="appended"', None),
                 (("--compression", "lz4"), 'format="appended"', "vtkLZ4DataCompressor"),
                 (("--vtu-mode", "binary"), 'format="binary"', "vtkLZ4DataCompressor"),
                 (("--compression", "zlib"), 'format="appended"', "vtkZLibDataCompressor"),
                 (("--vtu-mode", "binary", "--compression", "none"), 'format="binary"', None)]
        for options, mode, compressor in cases:
            with self.subTest(options=options):
                output = self.path("encoded.vtu")
                code, out, err = run(self.circle, output, "--rotate", 0, 0, 30, *options)
                self.assertEqual(code, 0, err)
                with open(output, "rb") as f:
                    head = f.read(4000).decode("latin-1")
                self.assertIn(mode, head)
                if compressor:
                    self.assertIn(compressor, head)
                else:
                    self.assertNotIn("compressor=", head)
                self.assertEqual(meshes.read(output).GetNumberOfPoints(), CIRCLE_POINTS)

    # Fixed sub-steps above 256 (once "too many steps").
    def test_many_fixed_sub_steps(self):
        code, out, err = run(self.circle, self.path("steps.vtu"), "--rotate", 0, 0, 30,
                             "--sub-steps", 300)
        self.assertEqual(code, 0, err)
        self.assertIn("sub-steps 300;", out)  # the guard's counts only with the guard
        # Other methods ignore sub-steps and the guard (and warn): no step or guard count.
        code, out, err = run(self.circle, self.path("idw.vtu"), "--rotate", 0, 0, 30,
                             "--method", "idw", "--sub-steps", 0, "--repair", 0.25)
        self.assertEqual(code, 0, err)
        self.assertNotIn("sub-steps", out)
        self.assertNotIn("bad cells found", out)

    # Cells the metric does not cover: "no cell evaluated", not "minimum 0"; NaN in the file.
    def test_no_cell_evaluated(self):
        polygons = self.path("quadratic.vtu")
        meshes.as_quadratic_triangles(self.circle, polygons)
        output = self.path("polygons_out.vtu")
        code, out, err = run(polygons, output, "--rotate", 0, 0, 30)
        self.assertEqual(code, 0, err)
        self.assertIn("no cell evaluated", out)
        self.assertNotIn("minimum 0", out)
        field = meshes.read(output).GetFieldData()
        self.assertTrue(math.isnan(field.GetArray("SizeSkewMinimum").GetTuple1(0)))

    # A displacement that contradicts the marker is reported.
    def test_contradicting_displacement_is_reported(self):
        code, out, err = run(self.circle, self.path("o.vtu"), "--rotate", 0, 0, 10)
        self.assertEqual(code, 0, err)
        self.assertNotIn("have a non-zero displacement", err)
        contradicting = self.path("contradicting.vtu")
        meshes.with_displacement(self.circle, contradicting,
                                 lambda d, m: d + [0.01, 0.0, 0.0] * (m == 1)[:, None])
        code, out, err = run(contradicting, self.path("o.vtu"), "--rotate", 0, 0, 10)
        self.assertEqual(code, 0, err)
        self.assertIn("nodes not marked as moving have a non-zero displacement", err)

    # 3. Out of memory at every stage (reading, deforming, writing): exit 1 with a message, never
    #    a signal; the limit raised step by step until the run succeeds.
    def test_out_of_memory_never_crashes(self):
        mesh = self.path("memory_in.vtu")
        points, cells = meshes.cube_in_box(50, mesh)
        output = self.path("memory_out.vtu")
        failures = set()
        limit = 40 << 20
        while True:
            if os.path.exists(output):
                os.remove(output)
            code, out, err = run(mesh, output, "--rotate", 10, 20, 30, "--center", 0.5, 0.5, 0.5,
                                 limit=limit)
            if code == 127 and "error while loading shared libraries" in err:
                limit += 6 << 20  # too low for the program's libraries: not a run yet
                continue
            self.assertIn(code, (0, 1), "limit %d MiB: %s" % (limit >> 20, err))
            self.assertEqual(leftovers(self.work), [])
            if code == 0:
                self.assertEqual(meshes.read(output).GetNumberOfPoints(), points)
                break
            self.assertFalse(os.path.exists(output))
            kinds = [k for k in ("Unable to allocate", "needs about", "Out of memory",
                                 "memory runs out", "Out of resources") if k in err]
            self.assertTrue(kinds, "limit %d MiB: %s" % (limit >> 20, err))
            failures.update(kinds)
            limit += 4 << 20
            self.assertLess(limit, 2 << 30, "never succeeded")
        print("out-of-memory messages seen:", sorted(failures))
        self.assertGreaterEqual(len(failures), 2)


if __name__ == "__main__":
    parser = argparse.ArgumentParser()
    parser.add_argument("--deform", required=True)
    parser.add_argument("--data", required=True)
    parser.add_argument("--work", required=True)
    ARGS, rest = parser.parse_known_args()
    unittest.main(argv=[sys.argv[0]] + rest, verbosity=2)
