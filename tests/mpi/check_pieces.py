#!/usr/bin/env python3
"""output.pieces (label mpi): a 2-rank run of the periodic Taylor-Green vortex (25 x 25 particles,
migrations every 5 steps, to t = 0.05) writes each frame as one VTP piece per rank and an index
particles_NNNNNN.pvtp, listed in particles.pvd. Read back with VTK (vtkXMLPPolyDataReader):

  - every frame has both pieces, and the index reads as one data set of every particle once;
  - against the gathered frames of the same run without pieces, matched by id: velocity, density,
    pressure, mass and phase bit for bit (the same state: writing pieces changes nothing in the
    run, and timeseries.csv is identical); summation_density and the positions within ROUND_OFF
    (each rank sums its particles' neighbours over its halo, rank 0 over the whole model);
  - with ranks that own no particles (empty pieces) the index still reads as every particle once;
  - one process ignores the key: particles.pvd lists whole .vtp frames.

Exit 77 (skipped) when this Python has no VTK module (Debian: python3-vtk9).

usage: check_pieces.py ARKSPH SOURCE_DIR WORK_DIR MPIEXEC [MPIEXEC FLAGS ...]
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import run_checks  # noqa: E402
from run_checks import check, finish  # noqa: E402

try:
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy
except ImportError as e:
    print("check_pieces: skipped: %s" % e)
    sys.exit(77)

arksph, source, work, mpiexec = sys.argv[1:5]
flags = sys.argv[5:]
# Sums over the neighbours in another order (the rank's evaluator against rank 0's whole model):
# round-off of a few ulp of the values.
ROUND_OFF = 1e-12


def fresh(name, ranks, args):
    return run_checks.fresh(arksph, mpiexec, flags, work, name, ranks, args)


def listed(out):
    with open(os.path.join(out, "particles.pvd")) as f:
        return re.findall(r'file="([^"]+)"', f.read())


def read(path, reader):
    reader.SetFileName(path)
    reader.Update()
    data = reader.GetOutput()
    pd = data.GetPointData()
    arrays = {pd.GetArrayName(k): vtk_to_numpy(pd.GetArray(k)) for k in range(pd.GetNumberOfArrays())}
    arrays["Points"] = vtk_to_numpy(data.GetPoints().GetData())
    ids = list(arrays["id"])
    return {name: {i: tuple(a[k].ravel()) if a.ndim > 1 else a[k] for k, i in enumerate(ids)}
            for name, a in arrays.items()}, ids


os.makedirs(work, exist_ok=True)
vortex = os.path.join(source, "tests/scenes/taylor_green_vortex_25.toml")
scene = [vortex, "--set", "method.reorder_every=5", "--set", "time.end=0.05", "--set", "output.every=0.01"]
whole = fresh("whole-2", 2, scene)
pieces = fresh("pieces-2", 2, scene + ["--set", "output.pieces=true"])
if whole and pieces:
    files = listed(pieces)
    check(len(files) == len(listed(whole)) and all(f.endswith(".pvtp") for f in files),
          "particles.pvd lists one .pvtp per frame (%d)" % len(files))
    with open(os.path.join(pieces, "timeseries.csv")) as a, open(os.path.join(whole, "timeseries.csv")) as b:
        check(a.read() == b.read(), "timeseries.csv identical with and without pieces")
    worst = {"summation_density": 0.0, "Points": 0.0}
    for k, (pvtp, vtp) in enumerate(zip(files, listed(whole))):
        frame = pvtp[:-len(".pvtp")]
        check(all(os.path.exists(os.path.join(pieces, "%s_r%d.vtp" % (frame, r))) for r in (0, 1)),
              "%s: a piece per rank" % frame)
        got, ids = read(os.path.join(pieces, pvtp), vtk.vtkXMLPPolyDataReader())
        ref, ref_ids = read(os.path.join(whole, vtp), vtk.vtkXMLPolyDataReader())
        check(sorted(ids) == sorted(ref_ids) and len(set(ids)) == len(ids),
              "%s: the index reads as every particle once (%d points)" % (pvtp, len(ids)))
        if sorted(ids) != sorted(ref_ids):
            continue
        exact = [n for n in ("velocity", "density", "pressure", "mass", "phase") if got[n] != ref[n]]
        check(not exact and set(got) == set(ref), "%s: velocity, density, pressure, mass, phase bit for bit "
              "(differ: %s; arrays %s)" % (pvtp, exact, sorted(got)))
        for n in worst:
            scale = max(max(abs(c) for c in (v if isinstance(v, tuple) else (v,))) for v in ref[n].values())
            for i in ids:
                a, b = got[n][i], ref[n][i]
                a, b = (a, b) if isinstance(a, tuple) else ((a,), (b,))
                worst[n] = max(worst[n], max(abs(x - y) for x, y in zip(a, b)) / scale)
    for n, w in worst.items():
        check(w <= ROUND_OFF, "%s of the pieces against the whole frames: max relative difference %.3g" % (n, w))

# Empty pieces: 10 x 10 particles squeezed into x < 0.4 on 4 ranks of one cell each (two ranks own
# no particles, as in check_distributed_restart.py): the index still reads as every particle once.
squeezed = fresh("pieces-empty-4", 4, [vortex, "--set", "fluid.spacing=0.1", "--set", 'initial.offset=["-0.6*x", "0"]',
                                       "--set", "time.end=0.02", "--set", "output.pieces=true"])
if squeezed:
    for pvtp in listed(squeezed):
        _, ids = read(os.path.join(squeezed, pvtp), vtk.vtkXMLPPolyDataReader())
        check(sorted(ids) == list(range(100)), "%s with empty pieces: every particle once (%d points)"
              % (pvtp, len(ids)))

one = fresh("pieces-1", 1, scene + ["--set", "output.pieces=true"])
if one:
    check(all(f.endswith(".vtp") for f in listed(one)), "one process ignores output.pieces: whole .vtp frames")

finish("check_pieces")
