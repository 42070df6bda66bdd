#!/usr/bin/python3
"""The 20 lowest modes of a 10^5-DOF train of wagons: railmodal's ARPACK back-end against
scipy.sparse.linalg.eigsh in shift-invert mode (the same ARPACK underneath), alternately in
one run, with solve time and each process's peak memory (maximum resident set size).

    /usr/bin/python3 tools/benchmarks/compare_arpack.py [BUILD_DIR] [--wagons 20000] [--repeats 3]
    /usr/bin/python3 tools/benchmarks/compare_arpack.py build --accuracy   # tolerance/ncv table
    /usr/bin/python3 tools/benchmarks/compare_arpack.py build --split      # and scipy's time split

Both solve K x = λ M x for the same Matrix Market files with the same shift σ (railmodal's
automatic one) and ARPACK's default tolerance, machine precision (tol 0: eigsh keeps the
dlamch('EpsMach') dsaupd puts in its place, railmodal passes that value itself). railmodal
asks ARPACK for N plus a few (to see past a cluster), refines them by Rayleigh–Ritz and
checks the count by inertia; eigsh asks for N.
"""
import json
import os
import subprocess
import sys
import tempfile
import time

SCIPY_CHILD = r'''
import json, sys, time
import numpy as np, scipy.io, scipy.sparse.linalg as sla
M = scipy.io.mmread(sys.argv[1]).tocsc(); K = scipy.io.mmread(sys.argv[2]).tocsc()
n_modes, sigma = int(sys.argv[3]), float(sys.argv[4])
t = time.perf_counter()
vals, vecs = sla.eigsh(K, k=n_modes, M=M, sigma=sigma, which="LM", tol=0)
solve = time.perf_counter() - t
print(json.dumps({"solve_s": solve, "eigenvalues": sorted(vals.tolist())}))
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
    """Like run, with the child's own ru_maxrss via os.wait4 (not shared with other children)."""
    start = time.perf_counter()
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    out = proc.stdout.read()
    err = proc.stderr.read()
    _, status, usage = os.wait4(proc.pid, 0)
    wall = time.perf_counter() - start
    if status != 0:
        sys.exit(f"{' '.join(cmd[:2])} failed: {err.decode()}")
    return json.loads(out), wall, usage.ru_maxrss / 1024.0


def main():
    args = sys.argv[1:]
    build = args[0] if args and not args[0].startswith("--") else "build"
    wagons = int(args[args.index("--wagons") + 1]) if "--wagons" in args else 20000
    repeats = int(args[args.index("--repeats") + 1]) if "--repeats" in args else 3
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
        rows = {"railmodal": [], "scipy": []}
        reference = None
        for _ in range(repeats):  # alternately, so that both see the same machine state
            ours, wall, rss = run_measured([timing, m_path, k_path, str(n_modes)])
            rows["railmodal"].append((ours["solve_s"], wall, rss))
            sigma = ours["shift"]
            reference = ours["eigenvalues"][:n_modes]
            theirs, wall, rss = run_measured(["/usr/bin/python3", "-c", SCIPY_CHILD, m_path, k_path, str(n_modes), repr(sigma)])
            rows["scipy"].append((theirs["solve_s"], wall, rss))
            other = theirs["eigenvalues"]
        dofs = 5 * wagons
        print(f"{n_modes} lowest modes of a {dofs}-DOF train (railmodal::wagon_train({wagons})), σ = {sigma:.3g} 1/s², "
              f"median of {repeats} alternating runs\n")
        print("| solver | solve time [s] | process time [s] | peak memory [MiB] |")
        print("|---|---:|---:|---:|")
        med = lambda xs: sorted(xs)[len(xs) // 2]
        for name, label in (("railmodal", "railmodal ARPACK (LDLᵀ, Eigen)"),
                            ("scipy", "scipy eigsh shift-invert (SuperLU)")):
            r = rows[name]
            print(f"| {label} | {med([x[0] for x in r]):.2f} | {med([x[1] for x in r]):.2f} | {med([x[2] for x in r]):.0f} |")
        ratio = med([x[0] for x in rows["scipy"]]) / med([x[0] for x in rows["railmodal"]])
        print(f"\nsolve time ratio scipy/railmodal: {ratio:.2f}")
        worst = max(abs(a - b) / max(abs(b), 1e-300) for a, b in zip(reference[1:], other[1:]))
        print(f"largest relative difference in λ (modes 2–{n_modes}; mode 1 is rigid-body): {worst:.1e}")
        print(f"railmodal: {ours['operator_applications']} solves with K − σM")
        if "--split" in args:
            split, _, _ = run_measured(["/usr/bin/python3", "-c", SCIPY_SPLIT, m_path, k_path, str(n_modes), repr(sigma)])
            print(f"scipy split: splu {split['factor_s']:.3f} s; eigsh on the factor {split['eigsh_s']:.2f} s with "
                  f"{split['solves']} solves ({split['solve_s']:.3f} s in SuperLU's solve)")


def accuracy_table(timing, m_path, k_path, n_modes, wagons):
    """ARPACK tolerance and subspace size against frequency error and solve time."""
    exact, _, _ = run_measured([timing, m_path, k_path, str(n_modes), "--tolerance", "0", "--ncv", "120"])
    ref = exact["eigenvalues"]
    print(f"| tol | ncv | solve time [s] | solves with K − σM | max relative frequency error (modes 2–{n_modes}) |")
    print("|---:|---:|---:|---:|---:|")
    for tol in ("0", "1e-12", "1e-8", "1e-4"):
        for ncv in ("30", "45", "51", "80"):
            res, _, _ = run_measured([timing, m_path, k_path, str(n_modes), "--tolerance", tol, "--ncv", ncv])
            vals = res["eigenvalues"]
            err = max(abs((max(a, 0) ** 0.5 - b ** 0.5) / b ** 0.5) for a, b in zip(vals[1:n_modes], ref[1:n_modes]))
            print(f"| {tol} | {ncv} | {res['solve_s']:.2f} | {res['operator_applications']} | {err:.1e} |")
    print(f"\n(reference: tol 0, ncv 120; {5 * wagons} DOFs; default ncv is 45 for the 22 Ritz values asked)")


if __name__ == "__main__":
    main()
