"""arksph.readers against VTK's own readers on real run folders.

  - a one-process run of the 25 x 25 Taylor-Green vortex (WCSPH, to t = 0.05, a frame every 0.01):
    every array of every frame read by read_run equals vtkXMLPolyDataReader's bit for bit; the
    times are particles.pvd's; timeseries.csv has one row per frame at the frames' times; the
    summary is summary.json;
  - the same run on 2 MPI ranks with output.pieces = true: read_frame of each .pvtp equals
    vtkXMLPPolyDataReader's bit for bit, and sorted by id agrees with the one-process run within
    ROUND_OFF (docs/parallel.md: the ranks sum in other orders, round-off of ~1e-15 at t = 0.05);
  - a frame rewritten by VTK uncompressed with UInt32 headers reads the same;
  - a missing folder, a folder without particles.pvd, a missing piece of a .pvtp, a truncated or
    corrupt .vtp raise one-line FileNotFoundError / ValueError naming the file.

Environment: ARKSPH_BINARY (default /work/main/build/arksph), PYTHONPATH holding python/ (or the
build's python/). The VTK comparisons need VTK's Python module (python3-vtk9), the 2-rank run mpirun.

    PYTHONPATH=python python3 -m unittest -v tests/python/test_readers.py
"""
import json
import os
import re
import shutil
import subprocess
import tempfile
import unittest
from pathlib import Path

import numpy as np

from arksph.readers import frames, read_frame, read_run

ROOT = Path(__file__).resolve().parents[2]
SCENE = ROOT / "tests" / "scenes" / "taylor_green_vortex_25.toml"
DEFAULT_BINARY = "/work/main/build/arksph"
# Short WCSPH run; re-sorting every 5 steps changes the particles' memory order (and on ranks the
# pieces' rows) between frames.
RUN_ARGS = ["--set", "method.scheme=wcsph", "--set", "time.end=0.05", "--set", "output.every=0.01",
            "--set", "method.reorder_every=5", "--quiet"]
FRAMES = 6  # t = 0, 0.01, ..., 0.05
# 2 ranks against one process, relative to the largest magnitude of each float field:
# docs/parallel.md measures 4.2e-15 for this vortex at t = 0.05; 1e-12 leaves room for round-off
# and still catches a wrong row, piece or field (differences of order 1 of the scale).
ROUND_OFF = 1e-12
# timeseries.csv writes 10 significant digits.
CSV_DIGITS = 1e-9
RUN_TIMEOUT = 120  # seconds

try:
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkIOXML import (vtkXMLPolyDataReader, vtkXMLPolyDataWriter,
                                     vtkXMLPPolyDataReader)
    VTK = None
except ImportError as e:  # the readers need no VTK; only these comparisons do
    VTK = "no VTK Python module (python3-vtk9): %s" % e


def binary():
    path = os.environ.get("ARKSPH_BINARY", DEFAULT_BINARY)
    if not os.access(path, os.X_OK):
        if "ARKSPH_BINARY" in os.environ:
            raise AssertionError("ARKSPH_BINARY=%s is not an executable" % path)
        raise unittest.SkipTest("no arksph binary at %s (set ARKSPH_BINARY)" % path)
    return path


def run_arksph(out, launcher=(), extra=()):
    cmd = list(launcher) + [binary(), "run", str(SCENE), "--out", str(out)] + RUN_ARGS + list(extra)
    p = subprocess.run(cmd, capture_output=True, text=True, timeout=RUN_TIMEOUT)
    if p.returncode != 0:
        raise AssertionError("%s exited %d: %s" % (" ".join(cmd), p.returncode, p.stderr[-500:]))


def vtk_arrays(path, reader):
    """{name: array} of a frame as VTK reads it: the point-data arrays and "Points"."""
    reader.SetFileName(str(path))
    reader.Update()
    data = reader.GetOutput()
    pd = data.GetPointData()
    arrays = {pd.GetArrayName(k): vtk_to_numpy(pd.GetArray(k)) for k in range(pd.GetNumberOfArrays())}
    arrays["Points"] = vtk_to_numpy(data.GetPoints().GetData())
    return arrays


def pvd_entries(run_dir):
    text = (Path(run_dir) / "particles.pvd").read_text()
    return [(float(t), f) for t, f in re.findall(r'timestep="([^"]+)"[^>]*file="([^"]+)"', text)]


class ReadersTestCase(unittest.TestCase):
    def assertSameArrays(self, mine, theirs, where):
        self.assertEqual(sorted(mine), sorted(theirs), where)
        for name, a in theirs.items():
            self.assertEqual(mine[name].dtype, a.dtype, "%s %s" % (where, name))
            np.testing.assert_array_equal(mine[name], a, "%s %s" % (where, name))


class OneProcessRun(ReadersTestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="arksph_readers_")
        cls.out = Path(cls.tmp) / "one"
        run_arksph(cls.out)

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def test_times_are_particles_pvd(self):
        run = read_run(self.out)
        listed = pvd_entries(self.out)
        self.assertEqual(len(listed), FRAMES)
        np.testing.assert_array_equal(run.times, [t for t, _ in listed])
        self.assertEqual([p.name for p in run.paths], [f for _, f in listed])
        self.assertEqual([(t, p.name) for t, p in frames(self.out)], listed)

    @unittest.skipIf(VTK, VTK)
    def test_every_frame_equals_vtk(self):
        run = read_run(self.out, sort_by_id=False)
        self.assertEqual(len(run.frames), FRAMES)
        for k, (t, path) in enumerate(frames(self.out)):
            mine = run.frames[k]
            self.assertEqual(mine.pop("time"), t)
            self.assertEqual(mine["Points"].shape, (625, 3))
            self.assertEqual(mine["velocity"].shape, (625, 3))
            self.assertSameArrays(mine, vtk_arrays(path, vtkXMLPolyDataReader()), path.name)

    def test_sorted_frames_list_each_id_once_in_order(self):
        run = read_run(self.out)
        for f in run.frames:
            np.testing.assert_array_equal(f["id"], np.arange(625))
        self.assertEqual(run.frame(-1)["time"], run.times[-1])
        self.assertEqual([f["time"] for f in run.frames[1:3]], list(run.times[1:3]))

    def test_timeseries_has_a_row_per_frame(self):
        ts = read_run(self.out).timeseries
        self.assertEqual(len(ts), FRAMES)
        np.testing.assert_allclose(np.asarray(ts["t"]), read_run(self.out).times, rtol=CSV_DIGITS, atol=0)
        self.assertEqual(int(np.asarray(ts["steps"])[0]), 0)
        self.assertGreater(int(np.asarray(ts["steps"])[-1]), 0)
        columns = list(ts.dtype.names) if isinstance(ts, np.ndarray) else list(ts.columns)  # NumPy or pandas
        self.assertEqual(columns[:5], ["t", "dt", "steps", "kinetic_energy", "max_speed"])

    def test_summary_is_summary_json(self):
        summary = read_run(self.out).summary
        self.assertEqual(summary, json.loads((self.out / "summary.json").read_text()))
        self.assertEqual(summary["frames"], FRAMES)
        self.assertEqual(summary["particles"], 625)
        self.assertEqual(summary["status"], "ok")

    @unittest.skipIf(VTK, VTK)
    def test_uncompressed_uint32_headers(self):
        path = frames(self.out)[-1][1]
        reader = vtkXMLPolyDataReader()
        reader.SetFileName(str(path))
        reader.Update()
        plain = Path(self.tmp) / "plain.vtp"
        w = vtkXMLPolyDataWriter()
        w.SetInputData(reader.GetOutput())
        w.SetFileName(str(plain))
        w.SetDataModeToAppended()
        w.EncodeAppendedDataOff()
        w.SetCompressorTypeToNone()
        w.SetHeaderTypeToUInt32()
        self.assertEqual(w.Write(), 1)
        self.assertNotIn(b"compressor", plain.read_bytes()[:400])
        self.assertSameArrays(read_frame(plain), read_frame(path), plain.name)

    def test_bad_input_raises_one_line_errors(self):
        tmp = Path(self.tmp)
        cases = []
        with self.assertRaises(FileNotFoundError) as e:
            read_run(tmp / "no_such_run")
        cases.append((e.exception, "no_such_run"))
        (tmp / "empty").mkdir(exist_ok=True)
        with self.assertRaises(FileNotFoundError) as e:
            read_run(tmp / "empty")
        cases.append((e.exception, "empty"))
        with self.assertRaises(FileNotFoundError) as e:
            read_frame(tmp / "missing.vtp")
        cases.append((e.exception, "missing.vtp"))

        whole = frames(self.out)[-1][1].read_bytes()
        data_start = whole.index(b"<AppendedData")
        flipped = bytearray(whole)
        flipped[data_start + 200] ^= 0xFF  # inside the first array's zlib stream
        huge = bytearray(whole)  # the first array's block count (UInt64 after the "_") made absurd
        first = whole.index(b"_", data_start) + 1
        huge[first:first + 8] = (2 ** 60).to_bytes(8, "little")
        for name, content in [("cut_in_data.vtp", whole[:len(whole) * 2 // 3]),
                              ("cut_in_xml.vtp", whole[:data_start // 2]),
                              ("cut_at_end.vtp", whole[:-40]),
                              # cut short but closed again: the arrays' headers point past the end
                              ("cut_and_closed.vtp", whole[:len(whole) * 2 // 3] + b"\n</AppendedData>\n</VTKFile>\n"),
                              ("hole_in_data.vtp", whole[:data_start + 3000] + whole[data_start + 5000:]),
                              ("flipped.vtp", bytes(flipped)),
                              ("huge_block_count.vtp", bytes(huge)),
                              ("empty.vtp", b"")]:
            (tmp / name).write_bytes(content)
            with self.assertRaises(ValueError) as e:
                read_frame(tmp / name)
            cases.append((e.exception, name))
        for exc, name in cases:
            self.assertIn(name, str(exc))
            self.assertNotIn("\n", str(exc))


@unittest.skipIf(shutil.which("mpirun") is None, "no mpirun on PATH: the 2-rank run is skipped")
class TwoRankPieces(ReadersTestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="arksph_readers_mpi_")
        cls.one = Path(cls.tmp) / "one"
        cls.two = Path(cls.tmp) / "two"
        run_arksph(cls.one)
        run_arksph(cls.two, launcher=[str(ROOT / "scripts" / "mpirun.sh"), "-n", "2"],
                   extra=["--set", "output.pieces=true"])

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def test_ran_on_two_ranks_in_pieces(self):
        summary = read_run(self.two).summary
        self.assertEqual(summary["mpi"]["ranks"], 2, "the binary ran as one process (built without MPI?)")
        self.assertTrue(all(p.suffix == ".pvtp" for p in read_run(self.two).paths))

    @unittest.skipIf(VTK, VTK)
    def test_pvtp_equals_vtk(self):
        for t, path in frames(self.two):
            self.assertSameArrays(read_frame(path), vtk_arrays(path, vtkXMLPPolyDataReader()), path.name)

    def test_missing_piece_raises_naming_it(self):
        index = frames(self.two)[-1][1]
        lone = Path(self.tmp) / "lone"
        lone.mkdir(exist_ok=True)
        shutil.copy(index, lone)
        piece = index.name.replace(".pvtp", "_r0.vtp")
        shutil.copy(self.two / piece, lone)
        with self.assertRaises(FileNotFoundError) as e:
            read_frame(lone / index.name)
        self.assertIn(index.name.replace(".pvtp", "_r1.vtp"), str(e.exception))

    def test_file_rows_change_order_and_sorting_matches_them_by_id(self):
        raw = read_run(self.two, sort_by_id=False)
        ids = [f["id"] for f in raw.frames]
        self.assertTrue(any(not np.array_equal(a, ids[0]) for a in ids),
                        "the pieces' rows never change order: the sort is not exercised")
        for k, f in enumerate(read_run(self.two).frames):
            np.testing.assert_array_equal(f["id"], np.arange(625))
            where = np.argsort(ids[k])
            np.testing.assert_array_equal(f["velocity"], raw.frames[k]["velocity"][where])

    def test_pieces_agree_with_one_process_by_id(self):
        one, two = read_run(self.one), read_run(self.two)
        np.testing.assert_array_equal(one.times, two.times)
        for a, b in zip(one.frames, two.frames):
            self.assertEqual(sorted(a), sorted(b))
            for name in a:
                if name == "time":
                    continue
                where = "t = %g %s" % (a["time"], name)
                if np.issubdtype(a[name].dtype, np.integer):
                    np.testing.assert_array_equal(a[name], b[name], where)
                else:
                    scale = max(np.abs(a[name]).max(), np.finfo(float).tiny)
                    self.assertLessEqual(np.abs(a[name] - b[name]).max() / scale, ROUND_OFF, where)


if __name__ == "__main__":
    unittest.main()
