#!/usr/bin/env python3
"""`arksph run` with scheme isph decomposed over MPI ranks (label mpi): the projection after each
step (Cummins & Rudman 1999) with its pressure Poisson equation solved over the ranks (by the
default CG with the distributed AMG V-cycle, and in one case by hypre's BoomerAMG-PCG), against the one-process run, whose KLU solves each PPE exactly (to round-off):

  - the spin-down (cases/spin_down/defaults.toml: walls as ghosts, particle shifting, adaptive
    steps) to t = 0.2 on 2 and 3 ranks, and with migrations every 5 steps, and the periodic
    Taylor-Green vortex (25 x 25) to t = 0.05: the same steps, the last frame's velocities matched
    by particle id within POISSON of the largest speed, summary.json "ppe" with the solves of one
    process; the spin-down also with the projection after each stage (projection_points = stages);
  - the hydrostatic tank (cases/hydrostatic_tank, gravity and walls: the projection's body-force
    split, method.body_force_pressure = "split") to t = 0.02: velocities within POISSON of g t (the tank stays at rest up to spurious
    currents of 6e-6: g t is the speed the pressure holds back) and pressures within POISSON of the
    largest;
  - the comparison can fail: with the ranks' Poisson tolerance loosened to 1e-5 the spin-down
    differs by more than POISSON;
  - a checkpoint at t = 0.1 of a 2-rank run (migrations every 5 steps) restarted on 2 ranks ends
    with every array of the last frame bit for bit that of the uninterrupted 2-rank run (both pin
    the same particle and start the solver cold at the checkpoint);
  - with output.pieces = true (2 ranks, migrations every 5 steps) each rank's pieces carry the
    projection's pressure: the last frame's, by particle id, bit for bit that of the gathered frame
    of the same run without pieces;
  - a run that blows up inside the projection on one rank's particles (a body force of 1e30 in one
    corner, fixed steps: the step's end positions overflow the neighbour grid of the projection's
    field refresh) ends every rank with exit 3 and the one-process run's message, within the timeout;
  - the spin-down with the Pozorski-Wawrenczuk correction (threshold 1e-5, so that it runs at every
    step) on 2 and 3 ranks, with the Newton solver, and with Szewc's fixed point (two solves a step,
    migrations every 5 steps: the warm start dropped): as above, and the last frame's positions
    within POISSON of the spacing, summary.json density_correction with the applications and
    iterations of one process;
  - isph-gpps (the grid projection: each rank's deposit summed over the ranks, the grid solved on
    every rank) on the spin-down with migrations, the vortex and the tank, against one process as
    above;
  - the constrained projection (pressure inside f) on the periodic vortex, the spin-down with
    migrations (also with the P-W correction as a velocity inside f) and the tank, against one
    process as above, with a solve in every f;
  - what the ranks do not run exits 2 on every rank with one message naming the key: the
    orthogonal projection, the density correction's KINSOL solver, the exact operator.

usage: check_distributed_isph.py ARKSPH SOURCE_DIR WORK_DIR MPIEXEC [MPIEXEC FLAGS ...]
"""
import glob
import json
import os
import shutil
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from run_checks import check, finish, launch  # noqa: E402
from vtp_arrays import read_arrays  # noqa: E402

arksph, source, work, mpiexec = sys.argv[1:5]
flags = sys.argv[5:]

# The Poisson tolerance of these runs (method.ppe_tolerance: |b - A p| <= TOL |b| per solve).
TOL = 1e-10
# The bound of the comparison. Each step the ranks' pressure is the solver's, within its tolerance of
# the exact solution KLU gives one process: measured |p - p_KLU| / |p_KLU| = 0.1-0.3 TOL
# (arksph_mpi_tests "rank poisson"; the worst case is cond(A) TOL). The velocity correction
# dt grad P is a fraction of u, so a step adds about TOL of the largest speed, and the runs' 20-30
# steps about 20-30 TOL (measured: 2e-11 at t = 1, 103 steps). 100 TOL leaves room for the flow's
# amplification of these differences, which on the vortex grows fast after t = 0.05 (one process
# at tolerances 1e-10 and 1e-12 differs by 3e-13 at t = 0.05, 3e-6 at t = 0.1), hence its short run.
POISSON = 100 * TOL


def run(name, ranks, args):
    out = os.path.join(work, name)
    shutil.rmtree(out, ignore_errors=True)
    code, err = launch(arksph, mpiexec, flags, ranks, args, out)
    return out, code, err


def velocities(out):
    frame = sorted(glob.glob(os.path.join(out, "particles_*.vtp")))[-1]
    a = read_arrays(frame)
    v = a["velocity"]
    return {i: (v[3 * k], v[3 * k + 1]) for k, i in enumerate(a["id"])}


def pressures(out):
    a = read_arrays(sorted(glob.glob(os.path.join(out, "particles_*.vtp")))[-1])
    return {i: a["pressure"][k] for k, i in enumerate(a["id"])}


def positions(out):
    a = read_arrays(sorted(glob.glob(os.path.join(out, "particles_*.vtp")))[-1])
    return {i: (a["Points"][3 * k], a["Points"][3 * k + 1]) for k, i in enumerate(a["id"])}


def summary(out):
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)


def difference(u1, up, scale=None):
    scale = scale or max(abs(c) for v in u1.values() for c in v)
    return max(abs(up[i][k] - u1[i][k]) for i in u1 for k in (0, 1)) / scale


def compare(case, args, ranks_args=(), bound=POISSON, within=True, ranks_list=(2, 3), speed=None, spacing=None,
            in_f=False):
    """speed: the velocity scale of the comparison (default: the largest speed of one process);
    spacing: compare the positions too, on this scale; in_f: the pressure is solved in every f
    (the constrained projection), so a run's solves are its f evaluations (a migration costs the
    ranks an evaluation more than one process's re-sort)."""
    one, code, _ = run(case + "-1", 1, args + ["--set", "method.ppe_solver=klu"])
    check(code == 0, case + ": one process exits 0")
    if code != 0:
        return
    s1 = summary(one)
    u1 = velocities(one)
    for ranks in ranks_list:
        out, code, _ = run("%s-%d" % (case, ranks), ranks, args + list(ranks_args))
        check(code == 0, "%s on %d ranks exits 0" % (case, ranks))
        if code != 0:
            continue
        s = summary(out)
        check(s["mpi"]["ranks"] == ranks, "%s: summary mpi.ranks = %d" % (case, ranks))
        check(s["steps"] == s1["steps"], "%s: %d ranks take the steps of one process (%d, %d)"
              % (case, ranks, s["steps"], s1["steps"]))
        ppe = s.get("ppe", {})
        hypre = "method.rank_ppe_solver=hypre" in " ".join(ranks_args)
        solver = ("grid-klu" if s1["ppe"]["solver"] == "grid-klu"
                  else "hypre-pcg-boomeramg" if hypre else "rank-pcg-amg")
        solves = s["rhs_evals"] if in_f else s1["ppe"]["solves"]
        check(ppe.get("solver") == solver and ppe.get("solves") == solves
              and ppe.get("iterations", 0) >= ppe.get("solves", 0) >= s["steps"] > 0,
              "%s: %d ranks: summary ppe %s, %s solves (%s expected), %s iterations (one process: %s solves)"
              % (case, ranks, ppe.get("solver"), ppe.get("solves"), solves, ppe.get("iterations"), s1["ppe"]["solves"]))
        if solver != "grid-klu":
            # Every solve meets the run's tolerance (a solve on a kept preconditioner that does not
            # is repeated on a new one: distributed_ppe/rank_poisson_solver.hpp); 2 x: the retry
            # threshold.
            settings = [a.split("=", 1)[1] for a in list(args) + list(ranks_args) if a.startswith("method.ppe_tolerance=")]
            tolerance = float(settings[-1]) if settings else 1e-8
            check(ppe.get("max_residual", 1.0) <= 2 * tolerance,
                  "%s: %d ranks: the largest relative residual %.2e within 2 x the tolerance %g"
                  % (case, ranks, ppe.get("max_residual", 1.0), tolerance))
        if "reorder_every=5" in " ".join(args):
            check(s["mpi"]["migrations"] > 0, "%s: %d ranks migrated %d times" % (case, ranks, s["mpi"]["migrations"]))
        if "density_correction" in s1:
            c1, c = s1["density_correction"], s.get("density_correction", {})
            check(c1["applications"] > 0 and c.get("applications") == c1["applications"]
                  and c.get("iterations") == c1["iterations"],
                  "%s: %d ranks: density correction applied %s times, %s iterations (one process: %d, %d)"
                  % (case, ranks, c.get("applications"), c.get("iterations"), c1["applications"], c1["iterations"]))
        up = velocities(out)
        check(sorted(up) == sorted(u1), "%s: %d ranks write every particle once" % (case, ranks))
        if sorted(up) != sorted(u1):
            continue
        worst = difference(u1, up, speed)
        if spacing:
            dr = difference(positions(one), positions(out), spacing)
            check(dr <= bound, "%s: %d ranks vs one process: position max |dr| / dx = %.3g <= %.0e"
                  % (case, ranks, dr, bound))
        if speed:
            p1, pp = pressures(one), pressures(out)
            dp = max(abs(pp[i] - p1[i]) for i in p1) / max(abs(p) for p in p1.values())
            check(dp <= bound, "%s: %d ranks vs one process: pressure max |dp| / max |p| = %.3g <= %.0e"
                  % (case, ranks, dp, bound))
        if within:
            check(worst <= bound, "%s: %d ranks vs one process: velocity max |du| / %s = %.3g <= %.0e"
                  % (case, ranks, "%g" % speed if speed else "max |u|", worst, bound))
        else:
            check(worst > bound, "%s: %d ranks vs one process: velocity max |du| / max |u| = %.3g > %.0e "
                  "(the comparison sees the solver's tolerance)" % (case, ranks, worst, bound))


os.makedirs(work, exist_ok=True)
tol = ["--set", "method.ppe_tolerance=%g" % TOL]
spin = [os.path.join(source, "cases/spin_down/defaults.toml"), "--set", "time.end=0.2",
        "--set", "output.every=0.1"] + tol
vortex = [os.path.join(source, "tests/scenes/taylor_green_vortex_25.toml"), "--set", "method.scheme=isph",
          "--set", "time.end=0.05"] + tol
compare("spin_down", spin)
compare("spin_down_migrating", spin + ["--set", "method.reorder_every=5"])
# The other solver over the ranks, hypre's BoomerAMG-PCG (method.rank_ppe_solver).
compare("spin_down_hypre", spin + ["--set", "method.reorder_every=5"],
        ranks_args=["--set", "method.rank_ppe_solver=hypre"], ranks_list=(2,))
compare("spin_down_stages", spin + ["--set", "method.projection_points=stages"])
compare("vortex", vortex)
pw = ["--set", "method.density_correction=pozorski_wawrenczuk", "--set", "method.correction_threshold=1e-5"]
compare("spin_down_pw", spin + pw, spacing=0.02)
compare("spin_down_pw_fixed_point", spin + pw + ["--set", "method.correction_solver=fixed_point",
                                                 "--set", "method.correction_max_iterations=2",
                                                 "--set", "method.reorder_every=5"], spacing=0.02)
# The tank with gravity in the momentum equation (method.body_force_pressure = "split"): the
# modified pressure, the default, leaves nothing to solve at rest (a zero source, no iterations).
split = ["--set", "method.body_force_pressure=split"]
compare("tank", [os.path.join(source, "cases/hydrostatic_tank/scene.toml"), "--set", "time.end=0.02",
                "--set", "output.every=0.02"] + tol + split, speed=0.02)  # g t = 1 x 0.02
# isph-gpps: the grid deposit summed over the ranks, the same grid solve on every rank (KLU, as one
# process). Only the order of the deposit's sums differs from one process (round-off, measured
# 2e-15 to 5e-15 of the largest speed), so the bound is the 1e-12 relative agreement asked of
# WCSPH, not the Poisson tolerance. With walls and migrations, periodic (the grid wraps), and under
# gravity (the wall faces' flux of g). Without the sum over the ranks (each rank's grid sees only
# its own particles) the spin-down on 2 ranks differs by 0.11 of the largest speed.
GRID = 1e-12
gpps = ["--set", "method.scheme=isph-gpps"]
compare("spin_down_gpps", spin + gpps + ["--set", "method.reorder_every=5"], bound=GRID)
compare("vortex_gpps", vortex + gpps, bound=GRID)
compare("tank_gpps", [os.path.join(source, "cases/hydrostatic_tank/scene.toml"), "--set", "time.end=0.02",
                     "--set", "output.every=0.02"] + gpps + split, speed=0.02, bound=GRID)
# The constrained projection (the pressure inside f, at every stage): the rows and hypre as above,
# the accelerations a* + alpha u handed to the halo copies by their owners. Periodic (the vortex of
# cases/isph_order), with walls and migrations, and under gravity (the body-force split: at 1e-10
# the tank's velocities agree within 4e-12 of g t, and within 0.015 when the wall images wrongly
# carry the step's increment of g, as the projection after each step has them).
constrained = ["--set", "method.projection=constrained"]
compare("vortex_constrained", [os.path.join(source, "cases/isph_order/taylor_green_re100.toml"), "--set", "time.end=0.1",
                               "--set", "output.every=0.1"] + tol, in_f=True)
compare("spin_down_constrained", spin + constrained + ["--set", "method.reorder_every=5"], in_f=True)
# The P-W correction as a velocity inside f (the Newton direction over the ranks), with migrations:
# positions within POISSON of the spacing too.
compare("spin_down_constrained_pw", spin + constrained + ["--set", "method.density_correction=pozorski_wawrenczuk",
                                                          "--set", "method.reorder_every=5"], in_f=True, spacing=0.02)
compare("tank_constrained", [os.path.join(source, "cases/hydrostatic_tank/scene.toml"), "--set", "time.end=0.02",
                            "--set", "output.every=0.02"] + tol + constrained + split, speed=0.02, in_f=True)
compare("spin_down_loose", spin, ranks_args=["--set", "method.ppe_tolerance=1e-5"], within=False, ranks_list=(2,))

# output.pieces: the projection's pressure in each rank's piece, against the gathered frame of the
# same run (spin_down_migrating on 2 ranks, above).
pieces, code, _ = run("pieces-2", 2, spin + ["--set", "method.reorder_every=5", "--set", "output.pieces=true"])
check(code == 0, "pieces: 2 ranks with output.pieces exit 0")
gathered = os.path.join(work, "spin_down_migrating-2")
if code == 0 and os.path.isdir(gathered):
    whole = pressures(gathered)
    last = os.path.basename(sorted(glob.glob(os.path.join(gathered, "particles_*.vtp")))[-1])[:-4]
    pieced = {}
    for f in sorted(glob.glob(os.path.join(pieces, last + "_r*.vtp"))):
        a = read_arrays(f)
        pieced.update({i: a["pressure"][k] for k, i in enumerate(a["id"])})
    check(sorted(pieced) == sorted(whole) and all(pieced[i] == whole[i] for i in whole)
          and max(abs(p) for p in whole.values()) > 0,
          "pieces: the pressure of %s's pieces equals the gathered frame's by id (%d particles)"
          % (last, len(pieced)))

# Restart on the same rank count: bit for bit (docs/parallel.md, "Checkpoints and restart").
every = ["--set", "output.checkpoint_every=0.1", "--set", "method.reorder_every=5"]
whole, code_w, _ = run("restart-whole", 2, spin + every)
part, code_p, _ = run("restart-part", 2, spin + every + ["--set", "time.end=0.1"])
check(code_w == 0 and code_p == 0, "restart: the 2-rank runs to t = 0.2 and t = 0.1 exit 0")
if code_w == 0 and code_p == 0:
    resumed = os.path.join(work, "restart-resumed")
    shutil.rmtree(resumed, ignore_errors=True)
    shutil.copytree(part, resumed)
    code, _ = launch(arksph, mpiexec, flags, 2, ["--restart", os.path.join(resumed, "checkpoint.h5"),
                                                 "--set", "time.end=0.2"], resumed)
    check(code == 0, "restart: the checkpoint at t = 0.1 restarted on 2 ranks exits 0")
    if code == 0:
        last = os.path.basename(sorted(glob.glob(os.path.join(whole, "particles_*.vtp")))[-1])
        a = read_arrays(os.path.join(whole, last))
        b = read_arrays(os.path.join(resumed, last))
        same = sorted(a) == sorted(b) and all(list(a[k]) == list(b[k]) for k in a)
        check(same and summary(whole)["steps"] == summary(resumed)["steps"],
              "restart: %s of the restarted run equals the uninterrupted run's bit for bit (arrays %s), "
              "%d steps" % (last, sorted(k for k in a if k in b and list(a[k]) == list(b[k])), summary(resumed)["steps"]))

# A blow-up seen first by the projection's field refresh, on the ranks that own the corner.
corner = ["--set", 'fluid.body_force=["t > 0.01 ? (x > 0.8 ? (y > 0.8 ? 1e30 : 0) : 0) : 0", "0"]',
          "--set", "time.dt=0.001", "--set", "time.end=0.05"]
for ranks in (1, 2, 3):
    out, code, err = run("blow-up-%d" % ranks, ranks, spin + corner)
    msg = [l for l in err.splitlines() if l.startswith("arksph:")]
    check(code == 3 and any("neighbour cells" in l and "blown up" in l for l in msg),
          "a blow-up in the projection on %d rank(s): exit %s, %s" % (ranks, code, msg[-1][:100] if msg else ""))

refused = [("method.projection = orthogonal", ["--set", "method.projection=orthogonal"], "method.projection"),
           ("method.correction_solver = kinsol", ["--set", "method.density_correction=pozorski_wawrenczuk",
                                                  "--set", "method.correction_solver=kinsol"],
            "method.correction_solver"),
           ("method.ppe_operator = exact", ["--set", "method.ppe_operator=exact", "--set", "method.ppe_solver=klu"],
            "method.ppe_operator")]
for what, extra, key in refused:
    # mpirun's output forwarding can lose the one line when all ranks end at once, so the message is
    # looked for in up to three attempts (as check_distributed_run.py).
    for attempt in range(3):
        _, code, err = run("refused", 2, spin + extra)
        lines = [l for l in err.splitlines() if l.startswith("arksph:")]
        if code != 2 or lines:
            break
    check(code == 2 and len(lines) == 1 and "several MPI ranks" in lines[0] and key in lines[0],
          "%s on 2 ranks: exit %s, one message naming %s: %s" % (what, code, key, lines))

finish("check_distributed_isph")
