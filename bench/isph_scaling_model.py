#!/usr/bin/env python3
"""A model of an ISPH step (C&R's projection, hypre's BoomerAMG-PCG) on P MPI ranks.

    bench/isph_scaling_model.py            # the tables of docs/scaling.md, "ISPH: a model"

Not a measurement: it combines the per-particle costs measured on 2 ranks of the development machine
(the constants below, each with the run it comes from) with a latency-bandwidth model of the
messages an ISPH step sends, and prints the projected time a step and the parallel efficiency for
square subdomains of n particles a rank (weak scaling) on 2 to 32,768 ranks. Efficiency: the step's
compute over compute plus communication, the compute a rank's alone (as one process's at n).

Per step and rank (2D, a square subdomain of n particles with 8 neighbouring ranks):
  compute  n (t_eval + k t_iter + t_setup + t_assembly)
  halo     e (nb alpha + 40 B H_h / beta) + (2 nb alpha + 100 B H_h / beta)   [evaluations, one rebuild]
  PCG      k [(1 + m L) (nb alpha + 8 B H_l / beta) + 3 allreduce(P)]         [per iteration]
  set-up   (1 / R) L s (nb alpha + allreduce(P))                               [amortised BoomerAMG set-up]
with H_h and H_0 the halo of the evaluator (cut-off 2 supports + skin) and of the matrix rows (one
support), H_l = H_0 / q^(l / 2) on level l (q rows coarsened per level; a band of rows of constant
width around a box with sqrt(q) fewer rows a side), L the levels, m messages a level per V-cycle
(Chebyshev order 2 before and after: 4 products, the residual, restriction and interpolation: 7),
allreduce(P) = 2 alpha log2 P (recursive doubling), s message rounds a level in a set-up.
"""
import math

# Measured (2 ranks x 1 thread, N = 57,600 cavity, C&R projection, 52 steps; bench/RESULTS.md,
# "hypre: Chebyshev smoothing"): summary.json timing over steps and the rank's 28,800 particles.
T_EVAL = 0.67e-6      # s a particle-step: evaluations of f, integrator, halo bookkeeping
T_ITER = 0.306e-6     # s a row and PCG iteration (ppe.solve_seconds / ppe.iterations / n)
T_SETUP = 0.69e-6     # s a row and step: IJ hand-over and the amortised BoomerAMG set-ups
T_ASSEMBLY = 0.66e-6  # s a row and step: the rows with global numbers
K_ITER = 7.27         # PCG iterations a solve in that run (one solve a step)
EVALS = 2.13          # evaluations of f a step (summary.json rhs_evals / steps)
REUSE = 12            # solves a BoomerAMG set-up serves (211 solves, 18 set-ups in a 200-step run)
Q_COARSEN = 6.3       # rows per coarse row, level 0 -> 1 (hypre's level table, N = 57,600)
COARSEST = 5          # rows on the coarsest level there
M_PER_LEVEL = 7       # messages a level per V-cycle (above)
S_SETUP = 15          # message rounds a level in a set-up (coarsening, interpolation, RAP; assumed)
NEIGHBOURS = 8
C_H = 8.6             # evaluator halo cut-off in dx: 2 supports of 4 dx + skin 0.6 dx
C_P = 4.0             # matrix rows' halo: one support
# Loopback MPI on the development machine (docs/scaling.md, "Measured: latency, bandwidth,
# allreduce"): A the better end, B the loaded medians.
NETWORKS = {"A": (2e-6, 1e9), "B": (15e-6, 0.2e9)}


def halo(n, c):
    """Particles within c (in dx) outside a square box of n particles on all four sides, corners
    included (docs/scaling.md's H with P' = 4 sqrt(n) dx, k = 4)."""
    return 4 * math.sqrt(n) * c + math.pi * c * c


def levels(n_total):
    return 1 + max(1, math.ceil(math.log(n_total / COARSEST) / math.log(Q_COARSEN)))


def step(n, p, alpha, beta, k=K_ITER):
    """(compute, communication) seconds of a step on a rank of n particles, P ranks."""
    compute = n * (T_EVAL + k * T_ITER + T_SETUP + T_ASSEMBLY)
    if p == 1:
        return compute, 0.0
    allreduce = 2 * alpha * math.log2(p)
    nb = min(NEIGHBOURS, p - 1)
    h_h, h_0 = halo(n, C_H), halo(n, C_P)
    lv = levels(n * p)
    comm = EVALS * (nb * alpha + 40 * h_h / beta) + (2 * nb * alpha + 100 * h_h / beta)
    v_cycle = sum(M_PER_LEVEL * (nb * alpha + 8 * h_0 / Q_COARSEN ** (l / 2) / beta) for l in range(lv))
    comm += k * (nb * alpha + 8 * h_0 / beta + v_cycle + 3 * allreduce)
    comm += lv * S_SETUP * (nb * alpha + allreduce) / REUSE
    return compute, comm


def main():
    ranks = [2, 64, 1024, 32768]
    # 250,000: the weak-scaling size of the acceptance; 8,300 and 4,100: Guo et al.'s 10^8 particles on
    # 12,000 partitions and Trask et al.'s 134 M on 32,768 cores.
    for n in (250_000, 8_300, 4_100):
        print(f"\nn = {n:,} particles a rank")
        print("| P | N | levels | compute a step | comm a step, A | efficiency A | comm a step, B | efficiency B | efficiency A, iterations x (1 + 0.5 log P / log 32768) |")
        print("|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
        for p in ranks:
            base, _ = step(n, 1, *NETWORKS["A"])
            cells = [f"{p:,}", f"{n * p:,}", str(levels(n * p)), f"{1e3 * base:.1f} ms"]
            for net in ("A", "B"):
                c, m = step(n, p, *NETWORKS[net])
                cells += [f"{1e3 * m:.2f} ms", f"{base / (c + m):.2f}"]
            growth = 1 + 0.5 * math.log(p) / math.log(ranks[-1])  # 1.5x at the largest P
            c, m = step(n, p, *NETWORKS["A"], k=growth * K_ITER)
            cells.append(f"{base / (c + m):.2f}")
            print("| " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
