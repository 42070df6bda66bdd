#!/usr/bin/python3
"""The 20 lowest modes of a 10^5-DOF train of wagons: railmodal's ARPACK back-end against
scipy.sparse.linalg.eigsh in shift-invert mode (the same ARPACK underneath), alternately in
one run, with solve time and each process's peak memory (maximum resident set size).

    /usr/bin/python3 tools/benchmarks/compare_arpack.py [BUILD_DIR] [--wagons 20000] [--repeats 7]
    /usr/bin/python3 tools/benchmarks/compare_arpack.py build --accuracy   # tolerance/ncv table
    /usr/bin/python3 tools/benchmarks/compare_arpack.py build --split      # and scipy's time split

Both solve K x = λ M x for the same Matrix Market files with the same shift σ (railmodal's
automatic one) and ARPACK's default tolerance, machine precision (tol 0: eigsh keeps the
dlamch('EpsMach') dsaupd puts in its place, railmodal passes that value itself). railmodal
asks ARPACK for N plus a few (to see past a cluster), refines them by Rayleigh–Ritz and
checks the count by inertia; eigsh asks for N.

TIMING. Interleaved rounds (side_by_side.py): every round runs each solver once, in a process of
its own, the order alternating from round to round, and forms the ratio scipy/railmodal within
the round. The figures are the medians over the rounds with their spread (IQR and range), of the
solve's processor time (what a shared, loaded machine still measures fairly), of each process's
processor time (user + system, os.wait4: reading the files and, for scipy, starting Python
included), of the solve's wall time and of the peak resident memory; the load average is printed.
Why eigsh is the strongest fair baseline: it is scipy's sparse symmetric eigensolver, the same
ARPACK in the same shift-invert mode on a sparse LU (SuperLU) of K − σM, called once on the
CSC matrices with the same σ and tolerance, so that no Python runs inside the iteration.
"""
import json
import os
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from side_by_side import Rounds, quantiles  # noqa: E402

SCIPY_CHILD = r'''
import json, sys, time
import numpy as np, scipy.io, scipy.sparse.linalg as sla
M = scipy.io.mmread(sys.argv[1]).tocsc(); K = scipy.io.mmread(sys.argv[2]).tocsc()
n_modes, sigma = int(sys.argv[3]), float(sys.argv[4])
t, cpu = time.perf_counter(), time.process_time()
vals, vecs = sla.eigsh(K, k=n_modes, M=M, sigma=sigma, which="LM", tol=0)
solve, solve_cpu = time.perf_counter() - t, time.process_time() - cpu
print(json.dumps({"solve_s": solve, "solve_cpu_s": solve_cpu, "eigenvalues": sorted(vals.tolist())}))
'''

# eigsh again, untimed by the table, with the factorisation timed apart and the solves counted.
SCIPY_SPLIT = r'''
import json, sys, time
import numpy as np, scipy.io, scipy.sparse.linalg as sla
M = scipy.io.mmread(sys.argv[1]).tocsc(); K = scipy.io.mmread(sys.argv[2]).tocsc()
n_modes, sigma = int(sys.argv[3]), float(sys.argv[4])
t = time.perf_counter()
lu = sla.splu((K - sigma * M).tocsc())
factor = time.perf_counter() - t
count, solving = [0], [0.0]
def solve(x):
    count[0] += 1
    t0 = time.perf_counter()
    y = lu.solve(x)
    solving[0] += time.perf_counter() - t0
    return y
t = time.perf_counter()
sla.eigsh(K, k=n_modes, M=M, sigma=sigma, which="LM", tol=0,
          OPinv=sla.LinearOperator(M.shape, matvec=solve, dtype=float))
print(json.dumps({"factor_s": factor, "eigsh_s": time.perf_counter() - t, "solves": count[0], "solve_s": solving[0]}))
'''


def run_measured(cmd):
    """The child's JSON, wall time, peak memory (MiB) and processor time (user + system, s), from
    its own rusage via os.wait4 (not shared with other children)."""
    start = time.perf_counter()
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    out = proc.stdout.read()
    err = proc.stderr.read()
    _, status, usage = os.wait4(proc.pid, 0)
    wall = time.perf_counter() - start
    if status != 0:
        sys.exit(f"{' '.join(cmd[:2])} failed: {err.decode()}")
    return json.loads(out), wall, usage.ru_maxrss / 1024.0, usage.ru_utime + usage.ru_stime


def main():
    args = sys.argv[1:]
    build = args[0] if args and not args[0].startswith("--") else "build"
    wagons = int(args[args.index("--wagons") + 1]) if "--wagons" in args else 20000
    repeats = int(args[args.index("--repeats") + 1]) if "--repeats" in args else 7
    n_modes = 20
    timing = os.path.join(build, "tools/benchmarks/arpack_timing")
    generator = os.path.join(build, "tools/matrix_market/railmodal_train_matrices")
    with tempfile.TemporaryDirectory() as tmp:
        prefix = os.path.join(tmp, "train")
        subprocess.run([generator, str(wagons), prefix], check=True)
        m_path, k_path = prefix + "_M.mtx", prefix + "_K.mtx"
        if "--accuracy" in args:
            accuracy_table(timing, m_path, k_path, n_modes, wagons)
            return
        # railmodal's automatic σ, which eigsh is given too (an untimed first run).
        ours, _, _, _ = run_measured([timing, m_path, k_path, str(n_modes)])
        sigma, reference = ours["shift"], ours["eigenvalues"][:n_modes]
        commands = {"railmodal": [timing, m_path, k_path, str(n_modes)],
                    "scipy": ["/usr/bin/python3", "-c", SCIPY_CHILD, m_path, k_path, str(n_modes), repr(sigma)]}
        measures = ("solve_cpu", "process_cpu", "solve_wall", "memory")
        table = {m: Rounds({name: None for name in commands}) for m in measures}
        last = {}
        load_before = os.getloadavg()[0]
        for r in range(repeats):
            for name in (commands if r % 2 == 0 else list(reversed(list(commands)))):
                result, _, rss, cpu = run_measured(commands[name])
                for measure, value in zip(measures, (result["solve_cpu_s"], cpu, result["solve_s"], rss)):
                    table[measure].times[name].append(value)
                last[name] = result
        dofs = 5 * wagons
        print(f"{n_modes} lowest modes of a {dofs}-DOF train (railmodal::wagon_train({wagons})), σ = {sigma:.3g} 1/s²; "
              f"{repeats} interleaved rounds, load average {load_before:.1f} before and {os.getloadavg()[0]:.1f} "
              f"after, on {os.cpu_count()} cores; medians (range)\n")
        print("| solver | solve, CPU [s] | process, CPU [s] | solve, wall [s] | peak memory [MiB] |")
        print("|---|---:|---:|---:|---:|")
        for name, label in (("railmodal", "railmodal ARPACK (LDLᵀ, Eigen)"),
                            ("scipy", "scipy eigsh shift-invert (SuperLU)")):
            cells = []
            for measure, digits in zip(measures, (2, 2, 2, 0)):
                m, _, _, lo, hi = quantiles(table[measure].times[name])
                cells.append(f"{m:.{digits}f} ({lo:.{digits}f}–{hi:.{digits}f})")
            print(f"| {label} | " + " | ".join(cells) + " |")
        print(f"\nratio scipy/railmodal, solve CPU   {table['solve_cpu'].describe_ratio('scipy', 'railmodal')}")
        print(f"ratio scipy/railmodal, process CPU {table['process_cpu'].describe_ratio('scipy', 'railmodal')}")
        other = last["scipy"]["eigenvalues"]
        worst = max(abs(a - b) / max(abs(b), 1e-300) for a, b in zip(reference[1:], other[1:]))
        print(f"largest relative difference in λ (modes 2–{n_modes}; mode 1 is rigid-body): {worst:.1e}")
        print(f"railmodal: {last['railmodal']['operator_applications']} solves with K − σM")
        if "--split" in args:
            split, _, _, _ = run_measured(["/usr/bin/python3", "-c", SCIPY_SPLIT, m_path, k_path, str(n_modes), repr(sigma)])
            print(f"scipy split: splu {split['factor_s']:.3f} s; eigsh on the factor {split['eigsh_s']:.2f} s with "
                  f"{split['solves']} solves ({split['solve_s']:.3f} s in SuperLU's solve)")


def accuracy_table(timing, m_path, k_path, n_modes, wagons):
    """ARPACK tolerance and subspace size against frequency error and solve time."""
    exact, _, _, _ = run_measured([timing, m_path, k_path, str(n_modes), "--tolerance", "0", "--ncv", "120"])
    ref = exact["eigenvalues"]
    print(f"| tol | ncv | solve time [s] | solves with K − σM | max relative frequency error (modes 2–{n_modes}) |")
    print("|---:|---:|---:|---:|---:|")
    for tol in ("0", "1e-12", "1e-8", "1e-4"):
        for ncv in ("30", "45", "51", "80"):
            res, _, _, _ = run_measured([timing, m_path, k_path, str(n_modes), "--tolerance", tol, "--ncv", ncv])
            vals = res["eigenvalues"]
            err = max(abs((max(a, 0) ** 0.5 - b ** 0.5) / b ** 0.5) for a, b in zip(vals[1:n_modes], ref[1:n_modes]))
            print(f"| {tol} | {ncv} | {res['solve_s']:.2f} | {res['operator_applications']} | {err:.1e} |")
    print(f"\n(reference: tol 0, ncv 120; {5 * wagons} DOFs; default ncv is 45 for the 22 Ritz values asked)")


if __name__ == "__main__":
    main()
