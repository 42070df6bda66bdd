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

    /usr/bin/python3 tools/benchmarks/compare_stability.py [--repeats 5] [--driver PATH]

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

try:
    import numpy as np
    import scipy.linalg
    import scipy.optimize
except ImportError:
    sys.exit("compare_stability.py: error: numpy/scipy missing (Debian: apt-get install python3-numpy python3-scipy)")

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def median_seconds(f, repeats):
    """Medians of the wall time and of the processor time (all threads; what a shared, loaded
    machine still measures fairly), and the result."""
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
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--driver", default=os.path.join(ROOT, "build", "tools", "benchmarks", "stability_timing"))
    args = parser.parse_args()
    if not os.access(args.driver, os.X_OK):
        sys.exit(f"compare_stability.py: error: {args.driver} is missing; build with benchmarks (bash tools/test.sh)")
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "stability.json")
        run = subprocess.run([args.driver, path, str(max(args.repeats, 11))], check=True, capture_output=True, text=True)
        times = dict(line.split() for line in run.stdout.splitlines())
        with open(path) as f:
            j = json.load(f)
    model = Model(j)
    V = np.array(j["speeds"])
    scipy_s, zeta_scipy = median_seconds(lambda: locus_scipy(model, V), args.repeats)
    batched_s, zeta_batched = median_seconds(lambda: locus_numpy_batched(model, V), args.repeats)
    critical_s, critical = median_seconds(lambda: critical_scipy(model, j["critical_bracket"], j["relative_tolerance"]),
                                          args.repeats)
    ours = np.array(j["least_damped_zeta"])
    t = {k: float(v) for k, v in times.items()}
    print(f"root locus: {V.size} speeds, {model.n} DOFs + {model.m} series dampers = {model.size} states")
    print("                                          wall (ms)   CPU (ms)   ratio to railmodal, 2 threads (wall / CPU)")
    print(f"  railmodal, 1 thread                   {t['locus_1_thread_s'] * 1e3:9.1f}  {t['locus_1_thread_cpu_s'] * 1e3:9.1f}")
    print(f"  railmodal, 2 threads                  {t['locus_2_threads_s'] * 1e3:9.1f}  {t['locus_2_threads_cpu_s'] * 1e3:9.1f}")
    for label, (wall, cpu), zeta in (("scipy.linalg.eig per speed + tracking", scipy_s, zeta_scipy),
                                     ("numpy.linalg.eig batched + tracking  ", batched_s, zeta_batched)):
        print(f"  {label} {wall * 1e3:9.1f}  {cpu * 1e3:9.1f}   {wall / t['locus_2_threads_s']:5.1f}x / "
              f"{cpu / t['locus_2_threads_cpu_s']:5.1f}x   max |Δζ| {np.max(np.abs(zeta - ours)):.1e}")
    print(f"critical speed to a relative {j['relative_tolerance']:g} (coarse grid of 10 speeds + Brent):")
    print(f"  railmodal                             {t['critical_speed_s'] * 1e3:9.2f}  {t['critical_speed_cpu_s'] * 1e3:9.2f}"
          f"   {j['critical_speed'] * 3.6:.9f} km/h")
    print(f"  scipy brentq on eigvals               {critical_s[0] * 1e3:9.2f}  {critical_s[1] * 1e3:9.2f}"
          f"   {critical * 3.6:.9f} km/h   {critical_s[0] / t['critical_speed_s']:5.1f}x / "
          f"{critical_s[1] / t['critical_speed_cpu_s']:5.1f}x   relative difference {abs(critical / j['critical_speed'] - 1):.1e}")
    # Agreement: ζ from Eigen's and LAPACK's QR of the same matrices agrees to round-off (1e-9
    # leaves room for the condition of the least-damped root); the critical speeds to twice the
    # tolerance each side was refined to.
    if np.max(np.abs(zeta_scipy - ours)) > 1e-9 or abs(critical / j["critical_speed"] - 1) > 2e-8:
        sys.exit("compare_stability.py: error: railmodal and scipy disagree")


if __name__ == "__main__":
    main()
