#!/usr/bin/python3
"""Hunting stability in railmodal against numpy/scipy, side by side in one run.

A bogie vehicle with four wheelsets over its lateral motions (17 DOFs and 4 yaw dampers with
series stiffness: 38 states), its root locus at 1000 speeds from 10 to 500 km/h, and its linear
critical speed to a relative 1e-8. build/tools/benchmarks/stability_timing times railmodal
(one and two threads) and writes the matrices; this script builds the same first-order state
matrices A(V) and does the same work as a competent numpy/scipy user would:

  * the state matrices of all speeds at once, by broadcasting (no Python loop);
  * scipy.linalg.eig per speed with right eigenvectors (LAPACK dgeev, balanced by default),
    because the tracking needs them, and the tracking by MAC between successive speeds with
    scipy.optimize.linear_sum_assignment (the Hungarian method in C);
  * numpy.linalg.eig over the whole stack of matrices in one call (a batched gufunc over
    LAPACK dgeev): the strongest fair baseline, since it removes the per-speed Python
    overhead that scipy.linalg.eig pays;
  * the critical speed by scipy.optimize.brentq on the least-damped damping ratio (eigenvalues
    only, scipy.linalg.eigvals) from the same coarse bracket railmodal refines, to the same
    relative tolerance.

It checks that both sides agree (the least-damped ζ at every speed and the critical speed) and
prints the times and ratios.

TIMING. Interleaved rounds (side_by_side.py): in each round the C++ driver runs once (reporting
the median of its own --inner repeats) and each numpy/scipy contender is timed as the median of
--inner calls, the order of the two sides alternating from round to round; the ratios are formed
within each round. Reported: the medians over the rounds with their spread (IQR and range), in
processor time (what a shared, loaded machine still measures fairly) and in wall time, with the
load average.

    /usr/bin/python3 tools/benchmarks/compare_stability.py [--rounds 7] [--inner 5] [--driver PATH]

Needs Debian's python3-numpy and python3-scipy (for /usr/bin/python3) and a build with
benchmarks.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from side_by_side import Rounds  # noqa: E402

try:
    import numpy as np
    import scipy.linalg
    import scipy.optimize
except ImportError:
    sys.exit("compare_stability.py: error: numpy/scipy missing (Debian: apt-get install python3-numpy python3-scipy)")

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def median_seconds(f, repeats):
    """Medians of the wall time and of the processor time (all threads) of `repeats` calls of f,
    and the result."""
    wall, cpu = [], []
    result = None
    for _ in range(repeats):
        start, start_cpu = time.perf_counter(), time.process_time()
        result = f()
        wall.append(time.perf_counter() - start)
        cpu.append(time.process_time() - start_cpu)
    return (sorted(wall)[len(wall) // 2], sorted(cpu)[len(cpu) // 2]), result


class Model:
    """The speed-independent parts of A(V), with M⁻¹ applied once (as railmodal does)."""

    def __init__(self, j):
        M = np.array(j["mass"])
        self.n = n = M.shape[0]
        S = np.array([s["stretch"] for s in j["series"]]).reshape(-1, n)
        k = np.array([s["stiffness"] for s in j["series"]])
        c = np.array([s["damping"] for s in j["series"]])
        self.m = m = S.shape[0]
        solve = lambda X: scipy.linalg.cho_solve(scipy.linalg.cho_factor(M), X)
        self.K = solve(np.array(j["stiffness"]) + np.array(j["contact_stiffness"]))
        self.C = solve(np.array(j["damping"]))
        self.Cc = solve(np.array(j["creep_damping"]))
        self.G = solve(np.array(j["gyroscopic"]))
        self.size = N = 2 * n + m
        base = np.zeros((N, N))
        base[:n, n:2 * n] = np.eye(n)
        base[n:2 * n, :n] = -self.K
        if m:
            base[n:2 * n, 2 * n:] = -solve(S.T)
            base[2 * n:, n:2 * n] = k[:, None] * S
            base[2 * n:, 2 * n:] = np.diag(-k / c)
        self.base = base
        self.weights = np.sqrt(np.diag(M))

    def matrices(self, V):
        """A(V) for every speed of V at once: shape (len(V), N, N)."""
        V = np.atleast_1d(V)
        A = np.broadcast_to(self.base, (V.size,) + self.base.shape).copy()
        n = self.n
        A[:, n:2 * n, n:2 * n] = -(self.C[None] + self.Cc[None] / V[:, None, None] + V[:, None, None] * self.G[None])
        return A


def least_damped(values):
    """ζ = −Re λ/|λ| of the least-damped root (rigid-body roots, |λ| ≤ 1e-9 max|λ|, left out;
    |Re λ| within 1e-11 max|λ| counts as 0), as railmodal defines it."""
    scale = np.max(np.abs(values), axis=-1, keepdims=True)
    mag = np.abs(values)
    zeta = np.where(np.abs(values.real) <= 1e-11 * scale, 0.0, -values.real / np.where(mag > 0, mag, 1.0))
    zeta = np.where(mag <= 1e-9 * scale, np.inf, zeta)
    return zeta.min(axis=-1)


def track(values, vectors, weights, n):
    """Follow every root from speed to speed: cost (1 − MAC) + relative eigenvalue distance,
    minimised by linear_sum_assignment (the same rule as railmodal)."""
    order = np.arange(values.shape[1])
    paths = [order]
    for s in range(1, values.shape[0]):
        U0 = weights[:, None] * vectors[s - 1][:n]
        U1 = weights[:, None] * vectors[s][:n]
        U0 = U0 / np.maximum(np.linalg.norm(U0, axis=0), 1e-300)
        U1 = U1 / np.maximum(np.linalg.norm(U1, axis=0), 1e-300)
        mac = np.abs(U0.conj().T @ U1) ** 2
        prev = values[s - 1][paths[-1]]
        if s >= 2:
            prev = 2 * prev - values[s - 2][paths[-2]]
        dist = np.abs(values[s][None, :] - prev[:, None]) / np.maximum(
            np.abs(values[s][None, :]) + np.abs(prev[:, None]), 1e-300)
        cost = (1 - mac[paths[-1], :]) + dist
        _, cols = scipy.optimize.linear_sum_assignment(cost)
        paths.append(cols)
    return paths


def locus_scipy(model, V):
    A = model.matrices(V)
    values = np.empty((V.size, model.size), complex)
    vectors = np.empty((V.size, model.size, model.size), complex)
    for s in range(V.size):
        values[s], vectors[s] = scipy.linalg.eig(A[s], check_finite=False)
    track(values, vectors, model.weights, model.n)
    return least_damped(values)


def locus_numpy_batched(model, V):
    values, vectors = np.linalg.eig(model.matrices(V))
    track(values, vectors, model.weights, model.n)
    return least_damped(values)


def critical_scipy(model, bracket, rtol):
    zeta = lambda v: least_damped(scipy.linalg.eigvals(model.matrices(v)[0], check_finite=False))
    # The coarse grid railmodal brackets from: 10 speeds, eigenvalues only.
    grid = np.linspace(bracket[0], bracket[1], 10)
    z = least_damped(np.linalg.eigvals(model.matrices(grid)))
    s = int(np.argmax(z < 0))
    return scipy.optimize.brentq(zeta, grid[s - 1], grid[s], xtol=1e-300, rtol=max(rtol, 4 * np.finfo(float).eps))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rounds", type=int, default=7)
    parser.add_argument("--inner", type=int, default=5, help="repeats per side within a round (median)")
    parser.add_argument("--driver", default=os.path.join(ROOT, "build", "tools", "benchmarks", "stability_timing"))
    args = parser.parse_args()
    if not os.access(args.driver, os.X_OK):
        sys.exit(f"compare_stability.py: error: {args.driver} is missing; build with benchmarks (bash tools/test.sh)")
    tmp = tempfile.TemporaryDirectory()
    path = os.path.join(tmp.name, "stability.json")
    ours = {}

    def run_driver():
        run = subprocess.run([args.driver, path, str(args.inner)], check=True, capture_output=True, text=True)
        ours.update({k: float(v) for k, v in (line.split() for line in run.stdout.splitlines())})

    run_driver()  # the matrices and railmodal's results, for the numpy side and the check
    with open(path) as f:
        j = json.load(f)
    model = Model(j)
    V = np.array(j["speeds"])
    results = {}

    def numpy_side(name, f):
        (wall, cpu), results[name] = median_seconds(f, args.inner)
        return wall, cpu

    # Each contender gives (wall, cpu) for one round; railmodal's three come from one process.
    theirs = {
        "scipy.linalg.eig per speed + tracking": lambda: numpy_side("scipy", lambda: locus_scipy(model, V)),
        "numpy.linalg.eig batched + tracking": lambda: numpy_side("batched", lambda: locus_numpy_batched(model, V)),
        "critical speed, scipy brentq on eigvals": lambda: numpy_side(
            "critical", lambda: critical_scipy(model, j["critical_bracket"], j["relative_tolerance"])),
    }
    mine = {"railmodal, 1 thread": "locus_1_thread", "railmodal, 2 threads": "locus_2_threads",
            "critical speed, railmodal": "critical_speed"}
    names = list(mine) + list(theirs)
    cpu, wall = Rounds({n: None for n in names}), Rounds({n: None for n in names})
    load_before = os.getloadavg()[0]
    for r in range(args.rounds):
        for side in (("mine", "theirs") if r % 2 == 0 else ("theirs", "mine")):
            if side == "mine":
                run_driver()
                for name, key in mine.items():
                    wall.times[name].append(ours[key + "_s"])
                    cpu.times[name].append(ours[key + "_cpu_s"])
            else:
                for name, f in theirs.items():
                    w, c = f()
                    wall.times[name].append(w)
                    cpu.times[name].append(c)
    tmp.cleanup()
    ours_zeta = np.array(j["least_damped_zeta"])
    print(f"root locus: {V.size} speeds, {model.n} DOFs + {model.m} series dampers = {model.size} states; "
          f"{args.rounds} interleaved rounds, each side the median of {args.inner} runs; load average "
          f"{load_before:.1f} before and {os.getloadavg()[0]:.1f} after, on {os.cpu_count()} cores")
    print("processor time, median (IQR, range):")
    for name in names:
        print(f"  {name:40s} {cpu.describe_time(name)}")
    print("wall time, median (IQR, range):")
    for name in names:
        print(f"  {name:40s} {wall.describe_time(name)}")
    print("ratios of processor time within each round:")
    for slower, faster in (("scipy.linalg.eig per speed + tracking", "railmodal, 2 threads"),
                           ("numpy.linalg.eig batched + tracking", "railmodal, 2 threads"),
                           ("scipy.linalg.eig per speed + tracking", "railmodal, 1 thread"),
                           ("numpy.linalg.eig batched + tracking", "railmodal, 1 thread"),
                           ("critical speed, scipy brentq on eigvals", "critical speed, railmodal")):
        print(f"  {slower} / {faster}: {cpu.describe_ratio(slower, faster)}")
    critical = results["critical"]
    print(f"agreement: max |Δζ| {np.max(np.abs(results['scipy'] - ours_zeta)):.1e} (scipy loop), "
          f"{np.max(np.abs(results['batched'] - ours_zeta)):.1e} (batched); critical speed railmodal "
          f"{j['critical_speed'] * 3.6:.9f} km/h, scipy {critical * 3.6:.9f} km/h, relative difference "
          f"{abs(critical / j['critical_speed'] - 1):.1e}")
    # Agreement: ζ from Eigen's and LAPACK's QR of the same matrices agrees to round-off (1e-9
    # leaves room for the condition of the least-damped root); the critical speeds to twice the
    # tolerance each side was refined to.
    if np.max(np.abs(results["scipy"] - ours_zeta)) > 1e-9 or abs(critical / j["critical_speed"] - 1) > 2e-8:
        sys.exit("compare_stability.py: error: railmodal and scipy disagree")


if __name__ == "__main__":
    main()
