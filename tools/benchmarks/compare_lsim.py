#!/usr/bin/python3
"""One million steps of railmodal's linear simulation against scipy, side by side in one run.

The Manchester coach (all 15 DOFs, with its primary and secondary dampers) over staggered
joints of 25 m rails at 30 m/s (6 harmonics, 1.2-7.2 Hz), released with the body 10 mm up,
1 ms steps. railmodal's build/tools/benchmarks/simulation_timing times its own
simulate_linear and writes M, C, K, the load harmonics F(t) = sum_k Re(Q_k e^{i w_k t}), the
initial state and its response (displacement and velocity of every DOF); this script computes
the same 30 state histories from the same first-order system

    d/dt [x; v] = A [x; v] + B F(t),   A = [[0, I], [-M^-1 K, -M^-1 C]],  B = [0; M^-1],

with F sampled at the same instants and taken linear between samples (first-order hold) on
both sides, so both are exact for that load and agree to round-off.

WHY THIS IS THE STRONGEST FAIR BASELINE. scipy.signal.lsim steps the state in a Python loop,
one small matrix product per step; a competent user with a linear time-invariant system
diagonalises it instead: A = U diag(mu) U^-1, so each complex mode z_r obeys z' = mu_r z + g_r(t)
and its exact first-order-hold recursion z_{k+1} = e^{mu h} z_k + b0 g_k + b1 g_{k+1} is one
scipy.signal.lfilter call (compiled, over all steps at once). Real input makes the modes of a
conjugate pair conjugate, so only one of each pair is filtered and x = 2 Re(U z) (a real mode,
if any, counts once). The load is sampled as cosines and sines of the harmonics times fixed real
vectors, folded straight into the modal input (one (steps x 2H) @ (2H x modes) product; F is
never formed), and the states Re(z (wU)ᵀ) one real (steps x 2 modes) @ (2 modes x 2n) product. This is faster than lsim by two orders of magnitude,
and is the figure the ratio is taken against. lsim itself runs too (--lsim, one run per round,
it takes seconds), given a zero 1 x 2n output matrix: the states are its xout, and an identity
output matrix would only make it multiply them once more.

AGREEMENT. Both are exact for the sampled first-order-hold load, so they differ by round-off:
of the order of the step count times eps times the modal condition number for the recursion
(1e6 x 1e-16 x cond(U) ~ 1e-9 at worst, in practice far less because errors of a damped mode
decay). The displacements are compared to 1e-8 of the largest displacement, the velocities to
1e-8 of the largest velocity (a DOF the vertical joints do not move holds only round-off, so
it is measured against its block), which a wrong step, a wrong hold or a wrong mode (errors of
1e-3 or more) cannot pass.

TIMING. Interleaved rounds (side_by_side.py): in each round railmodal (one run in a fresh
simulation_timing process, which writes no response after the first) and the lfilter baseline
(and lsim with --lsim) run back to back; ratios are formed within each round; medians and
spread are reported, for wall and CPU time.

    /usr/bin/python3 tools/benchmarks/compare_lsim.py [--rounds 5] [--steps 1000000] [--lsim]
        [--quick] [--driver PATH]

--quick: 20 000 steps, 2 rounds, lsim included (a smoke run). Needs Debian's python3-numpy and
python3-scipy (for /usr/bin/python3) and a build with benchmarks (simulation_timing).
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile
import time

for _var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS", "BLIS_NUM_THREADS"):
    os.environ[_var] = "1"  # before numpy is imported: railmodal's simulation is one thread

try:
    import numpy as np
    import scipy
    import scipy.linalg
    import scipy.signal
except ImportError:
    sys.exit("compare_lsim.py: error: numpy/scipy missing (Debian: apt-get install python3-numpy python3-scipy)")

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
from side_by_side import Rounds  # noqa: E402

TOLERANCE = 1e-8  # of the largest displacement (velocity); the docstring says why


def state_space(model):
    M, C, K = (np.array(model[k]) for k in ("mass", "damping", "stiffness"))
    n = M.shape[0]
    Minv = np.linalg.inv(M)
    A = np.block([[np.zeros((n, n)), np.eye(n)], [-Minv @ K, -Minv @ C]])
    B = np.vstack([np.zeros((n, n)), Minv])
    return A, B


def load_samples(model, t):
    """F(t_i) = sum_k Re(Q_k e^{i w_k t_i}), one row per instant, as trig @ W: the cosines and
    sines of the harmonics (steps x 2H) and [Re Q; -Im Q] (2H x n), real arithmetic only."""
    w = 2 * np.pi * np.array([h["frequency_hz"] for h in model["harmonics"]])
    trig = np.hstack([np.cos(np.outer(t, w)), np.sin(np.outer(t, w))])
    W = np.vstack([np.array([h["re"] for h in model["harmonics"]]), -np.array([h["im"] for h in model["harmonics"]])])
    return trig, W


class Diagonalised:
    """The modal decomposition, each kept mode's first-order-hold recursion and its initial
    value (set up once, as lsim discretises once; inside the timing all the same)."""

    def __init__(self, A, B, h, x0):
        mu, U = scipy.linalg.eig(A)
        Uinv = np.linalg.inv(U)
        keep = mu.imag >= 0.0  # one of each conjugate pair, and the real modes
        self.weight = np.where(mu[keep].imag > 0.0, 2.0, 1.0)
        self.mu, self.U = mu[keep], U[:, keep]
        self.LB = Uinv[keep] @ B
        self.z0 = (Uinv @ x0)[keep]  # the dropped modes' z0 are the conjugates of these
        E = np.exp(self.mu * h)
        P0 = (E - 1.0) / self.mu                  # ∫_0^h e^{mu(h-s)} ds
        P1 = (E - 1.0 - self.mu * h) / self.mu**2  # ∫_0^h e^{mu(h-s)} s ds
        self.E, self.b1, self.b0 = E, P1 / h, P0 - P1 / h

    def run(self, trig, W):
        """The state history (steps x 2n, real) for the load F = trig @ W (steps x n).

        Complex arrays are handled through their real views ([re, im] pairs side by side), so
        that both products are single real BLAS calls on contiguous arrays: numpy's matmul of
        a strided .real/.imag view falls back to a slow loop."""
        modal = W @ self.LB.T                                  # 2H x kept modes, complex
        Wm = np.empty((W.shape[0], 2 * modal.shape[1]))
        Wm[:, 0::2], Wm[:, 1::2] = modal.real, modal.imag
        g = (trig @ Wm).view(np.complex128)                    # modal input, steps x kept modes
        z = np.empty_like(g)
        for r in range(self.mu.size):
            # Direct form II transposed: y[0] = b1 g[0] + zi, so zi = z0 - b1 g[0].
            zi = [self.z0[r] - self.b1[r] * g[0, r]]
            z[:, r] = scipy.signal.lfilter([self.b1[r], self.b0[r]], [1.0, -self.E[r]], g[:, r], zi=zi)[0]
        wU = (self.U * self.weight).T                          # kept modes x 2n
        R = np.empty((2 * wU.shape[0], wU.shape[1]))
        R[0::2], R[1::2] = wU.real, -wU.imag                   # Re(z wU) = z.re wU.re - z.im wU.im
        return z.view(np.float64) @ R


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rounds", type=int, default=5)
    parser.add_argument("--steps", type=int, default=1000000)
    parser.add_argument("--lsim", action="store_true", help="also time scipy.signal.lsim (seconds per run)")
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--driver", default=os.path.join(ROOT, "build", "tools", "benchmarks", "simulation_timing"))
    args = parser.parse_args()
    if not os.access(args.driver, os.X_OK):
        sys.exit(f"compare_lsim.py: error: {args.driver} is missing; build with benchmarks (bash tools/test.sh)")
    if args.quick:
        args.rounds, args.steps, args.lsim = 2, 20000, True
    with tempfile.TemporaryDirectory() as tmp:
        model_path, response_path = os.path.join(tmp, "model.json"), os.path.join(tmp, "response.f64")
        subprocess.run([args.driver, os.path.join(ROOT, "data"), model_path, response_path, "1", str(args.steps)],
                       check=True, capture_output=True, text=True)
        with open(model_path) as f:
            model = json.load(f)
        n, steps = len(model["mass"]), model["steps"]
        ours_state = np.fromfile(response_path).reshape(2 * n, steps + 1).T  # columns: x then v

    h = model["time_step"]
    t = np.arange(steps + 1) * h
    A, B = state_space(model)
    X0 = np.concatenate([model["initial_displacement"], model["initial_velocity"]])
    results = {}

    def cpu_and_wall(f):
        start, cpu = time.perf_counter(), time.process_time()
        f()
        return time.perf_counter() - start, time.process_time() - cpu

    def baseline():
        results.pop("lfilter", None)
        results["lfilter"] = Diagonalised(A, B, h, X0).run(*load_samples(model, t))
    cpu = {}

    def timed(name, f):
        def run():
            wall, c = cpu_and_wall(f)
            cpu.setdefault(name, []).append(c)
            return wall
        return run

    def ours():
        run = subprocess.run([args.driver, os.path.join(ROOT, "data"), os.devnull, "-", "1", str(args.steps)],
                             check=True, capture_output=True, text=True)
        figures = dict(line.split() for line in run.stdout.splitlines())
        cpu.setdefault("railmodal", []).append(float(figures["simulate_cpu_s"]))
        return float(figures["simulate_s"])

    def lsim():
        results.pop("lsim", None)
        trig, W = load_samples(model, t)
        _, _, results["lsim"] = scipy.signal.lsim((A, B, np.zeros((1, 2 * n)), np.zeros((1, n))), trig @ W, t, X0=X0)
    contenders = {"railmodal": ours, "lfilter, diagonalised": timed("lfilter, diagonalised", baseline)}
    if args.lsim:
        contenders["lsim"] = timed("lsim", lsim)
    rounds = Rounds(contenders).run(args.rounds)

    def difference(a, b):
        # Per block (displacements, velocities): a lateral DOF the vertical joints do not move
        # holds round-off only, so a history is measured against its block's largest value.
        return max(float(np.max(np.abs(a[:, blk] - b[:, blk])) / np.max(np.abs(b[:, blk])))
                   for blk in (slice(0, n), slice(n, 2 * n)))
    worst = {name: difference(r, ours_state) for name, r in results.items()}
    print(f"linear simulation: {model['vehicle']}, {n} DOFs (state of {2 * n}), {steps} steps of {h * 1e3:g} ms, "
          f"{len(model['harmonics'])} load harmonics + initial displacement; {args.rounds} interleaved rounds; "
          f"load average {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores")
    from side_by_side import quantiles
    for name in rounds.names:
        c = quantiles(cpu[name])
        print(f"  {name:22s} wall {rounds.describe_time(name, 1.0, 's')}; CPU median {c[0]:.3f} s "
              f"({c[0] / steps * 1e9:.0f} ns/step)")
    for name in rounds.names[1:]:
        ratios = [a / b for a, b in zip(cpu[name], cpu["railmodal"])]
        m, q1, q3, lo, hi = quantiles(ratios)
        print(f"  ratio {name} / railmodal: wall {rounds.describe_ratio(name, 'railmodal')}; "
              f"CPU {m:.2f}x (range {lo:.2f}-{hi:.2f})")
    for name, w in worst.items():
        print(f"  max |{name} - railmodal| / max of its block (x or v): {w:.1e} (tolerance {TOLERANCE:g})")
    if not all(w <= TOLERANCE for w in worst.values()):
        sys.exit("compare_lsim.py: error: the responses disagree")


if __name__ == "__main__":
    main()
