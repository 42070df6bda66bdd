#!/usr/bin/python3
"""One million steps of railmodal's linear simulation against scipy.signal.lsim, in one run.

The Manchester coach (all 15 DOFs, with its primary and secondary dampers) over staggered
joints of 25 m rails at 30 m/s (6 harmonics, 1.2-7.2 Hz), released with the body 10 mm up,
1 ms steps. railmodal's build/tools/benchmarks/simulation_timing times its own
simulate_linear and writes M, C, K, the load harmonics F(t) = sum_k Re(Q_k e^{i w_k t}), the
initial state and its response; this script builds the same first-order system

    d/dt [x; v] = [[0, I], [-M^-1 K, -M^-1 C]] [x; v] + [0; M^-1] F(t),

samples F at the same instants, and runs scipy.signal.lsim on it. Both integrate exactly for
a load linear between samples (lsim's default interp=True is the same first-order hold), so
the responses agree to round-off. Prints both times, the ratio and the largest differences.

    /usr/bin/python3 tools/benchmarks/compare_lsim.py [--repeats 3] [--steps 1000000] [--driver PATH]

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
    import scipy
    import scipy.signal
except ImportError:
    sys.exit("compare_lsim.py: error: numpy/scipy missing (Debian: apt-get install python3-numpy python3-scipy)")

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def state_space(model):
    M, C, K = (np.array(model[k]) for k in ("mass", "damping", "stiffness"))
    n = M.shape[0]
    Minv = np.linalg.inv(M)
    A = np.block([[np.zeros((n, n)), np.eye(n)], [-Minv @ K, -Minv @ C]])
    B = np.vstack([np.zeros((n, n)), Minv])
    return A, B, np.eye(2 * n), np.zeros((2 * n, n))


def load_samples(model, t):
    """F(t_i) = sum_k Re(Q_k e^{i w_k t_i}), one row per instant."""
    n = len(model["mass"])
    U = np.zeros((t.size, n))
    for h in model["harmonics"]:
        Q = np.array(h["re"]) + 1j * np.array(h["im"])
        U += np.real(np.exp(2j * np.pi * h["frequency_hz"] * t)[:, None] * Q[None, :])
    return U


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--steps", type=int, default=1000000)
    parser.add_argument("--driver", default=os.path.join(ROOT, "build", "tools", "benchmarks", "simulation_timing"))
    args = parser.parse_args()
    if not os.access(args.driver, os.X_OK):
        sys.exit(f"compare_lsim.py: error: {args.driver} is missing; build with benchmarks (bash tools/test.sh)")
    with tempfile.TemporaryDirectory() as tmp:
        model_path, response_path = os.path.join(tmp, "model.json"), os.path.join(tmp, "response.f64")
        run = subprocess.run([args.driver, os.path.join(ROOT, "data"), model_path, response_path,
                              str(args.repeats), str(args.steps)], check=True, capture_output=True, text=True)
        figures = dict(line.split() for line in run.stdout.splitlines())
        ours, ours_cpu = float(figures["simulate_s"]), float(figures["simulate_cpu_s"])
        with open(model_path) as f:
            model = json.load(f)
        n, steps = len(model["mass"]), model["steps"]
        ours_state = np.fromfile(response_path).reshape(2 * n, steps + 1).T  # columns: x then v

    t = np.arange(steps + 1) * model["time_step"]
    start = time.perf_counter()
    U = load_samples(model, t)
    load_s = time.perf_counter() - start
    system = state_space(model)
    X0 = np.concatenate([model["initial_displacement"], model["initial_velocity"]])
    times, cpu_times = [], []
    xout = None
    for _ in range(args.repeats):
        xout = None  # free the last run's output first
        start, cpu_start = time.perf_counter(), time.process_time()
        _, _, xout = scipy.signal.lsim(system, U, t, X0=X0)
        cpu_times.append(time.process_time() - cpu_start)
        times.append(time.perf_counter() - start)
    lsim_s = sorted(times)[len(times) // 2]
    lsim_cpu = sorted(cpu_times)[len(cpu_times) // 2]

    def difference(a, b):
        return float(np.max(np.abs(a - b))), float(np.max(np.abs(b)))
    dx, xmax = difference(ours_state[:, :n], xout[:, :n])
    dv, vmax = difference(ours_state[:, n:], xout[:, n:])
    print(f"linear simulation: {model['vehicle']}, {n} DOFs (state of {2 * n}), {steps} steps of "
          f"{model['time_step'] * 1e3:g} ms, {len(model['harmonics'])} load harmonics + initial displacement, "
          f"median of {args.repeats}")
    print("                                        wall        CPU    CPU/step")
    print(f"railmodal simulate_linear          {ours:9.3f} s {ours_cpu:9.3f} s {ours_cpu / steps * 1e9:7.0f} ns")
    print(f"scipy {scipy.__version__} signal.lsim (FOH)   {lsim_s:9.3f} s {lsim_cpu:9.3f} s "
          f"{lsim_cpu / steps * 1e9:7.0f} ns   (+ {load_s:.3f} s wall to sample the load)")
    print(f"ratio lsim / railmodal: {lsim_s / ours:.1f}x wall, {lsim_cpu / ours_cpu:.1f}x CPU")
    print(f"max |difference|: displacement {dx:.2e} m of max {xmax:.2e} m (rel. {dx / xmax:.1e}), "
          f"velocity {dv:.2e} m/s of max {vmax:.2e} m/s (rel. {dv / vmax:.1e})")


if __name__ == "__main__":
    main()
