#!/usr/bin/python3
"""Output writers, whole process (issue 19 item 3: writing a result never costs more than
computing it). Two cases, each run alternately REPEATS times so that every side sees the same
machine state, with wall time, CPU time (user + system: steadier than wall time on a shared
machine) and peak memory (maximum resident set size) per run; medians with min–max spread.

  modes   the 20 lowest modes of a 10^5-DOF train (railmodal::wagon_train(20000), Matrix
          Market) written as CSV, JSON and the table, against scipy: eigsh in shift-invert mode
          (the same ARPACK) on the same files and shift, then the same CSV (frequencies and
          mass-normalised shapes, one row per mode) by numpy.savetxt.
  speeds  critical-speed of the resort car over 10 m rails with 10^4 speeds (the bundled
          scene with a step of 0.017 km/h), in every format.

    /usr/bin/python3 tools/benchmarks/compare_output_writers.py [BUILD_DIR] [--before OLD_RAILMODAL]
                     [--repeats 5] [--only modes|speeds]

--before runs a second railmodal (say, one built from main before this change) beside the first.

Why the scipy side is the strongest fair baseline for `modes --format csv`: eigsh in shift-invert
mode with the shift railmodal chooses runs the same ARPACK on a SuperLU factor (what a competent
user writes; sigma=None would run ARPACK in regular mode on M⁻¹K, far slower); numpy.savetxt
with '%.17g' writes every digit a double needs, as railmodal's shortest round-trip text does
(the fewer digits of a shorter format would be a different file); the rows are written as one
(modes × DOFs) array, not in a Python loop. scipy.io.mmread reads the files (its C reader since
scipy 1.12; Debian's may be older). Both sides pay their start-up (Python and the imports; the
railmodal binary's loading).
"""
import os
import re
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, "..", "..", "data")

SCIPY_MODES = r'''
import sys
import numpy as np, scipy.io, scipy.sparse.linalg as sla
M = scipy.io.mmread(sys.argv[1]).tocsc(); K = scipy.io.mmread(sys.argv[2]).tocsc()
n_modes, sigma, out = int(sys.argv[3]), float(sys.argv[4]), sys.argv[5]
vals, vecs = sla.eigsh(K, k=n_modes, M=M, sigma=sigma, which="LM", tol=0)
order = np.argsort(vals); vals = vals[order]; vecs = vecs[:, order]
f = np.sqrt(np.maximum(vals, 0.0)) / (2 * np.pi)
table = np.column_stack([np.arange(1, n_modes + 1), f, vecs.T])
np.savetxt(out, table, fmt="%.17g", delimiter=",", header="index,frequency [Hz]," +
           ",".join("dof%d" % i for i in range(M.shape[0])), comments="")
'''


def run_measured(cmd):
    """Wall time (s), CPU time (s) and peak memory (MiB) of one process. The peak is GNU time's
    %M (the ru_maxrss of os.wait4 showed one figure for every child on the development machine);
    the CPU time is os.wait4's (microseconds, where %U and %S count hundredths: a critical-speed
    run takes a few ms), which for GNU time includes the command it waited for."""
    start = time.perf_counter()
    proc = subprocess.Popen(["/usr/bin/time", "-f", "%M"] + cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    err = proc.stderr.read().decode()
    _, status, usage = os.wait4(proc.pid, 0)
    wall = time.perf_counter() - start
    if status != 0:
        sys.exit(f"{' '.join(cmd[:3])} failed: {err}")
    return wall, usage.ru_utime + usage.ru_stime, int(err.strip().splitlines()[-1]) / 1024.0


def median(xs):
    s = sorted(xs)
    return s[len(s) // 2] if len(s) % 2 else 0.5 * (s[len(s) // 2 - 1] + s[len(s) // 2])


def figure(xs, scale, digits):
    return f"{median(xs) * scale:.{digits}f} ({min(xs) * scale:.{digits}f}–{max(xs) * scale:.{digits}f})"


def table(title, rows, scale, unit, digits):
    print(f"\n{title}\n")
    print(f"| what | wall [{unit}] | CPU [{unit}] | peak memory [MiB] |")
    print("|---|---:|---:|---:|")
    for name, runs in rows.items():
        print(f"| {name} | {figure([r[0] for r in runs], scale, digits)} | {figure([r[1] for r in runs], scale, digits)} "
              f"| {median([r[2] for r in runs]):.0f} |")


def shift_of(railmodal, m_path, k_path, directory):
    """The shift railmodal chooses, from its JSON (so that eigsh factorises the same K − σM)."""
    out = os.path.join(directory, "shift.json")
    subprocess.run([railmodal, "modes", "--mass", m_path, "--stiffness", k_path, "--solver", "arpack", "--modes", "20",
                    "--format", "json", "-o", out], check=True)
    with open(out) as f:
        return float(re.search(r'"shift": ([^,\n]+)', f.read()).group(1))


def modes_case(build, binaries, repeats, directory):
    prefix = os.path.join(directory, "train")
    subprocess.run([os.path.join(build, "tools/matrix_market/railmodal_train_matrices"), "20000", prefix], check=True)
    m_path, k_path = prefix + "_M.mtx", prefix + "_K.mtx"
    sigma = shift_of(binaries[0][1], m_path, k_path, directory)
    rows = {}
    for _ in range(repeats):
        for label, exe in binaries:
            for fmt in ("csv", "json", "table"):
                out = os.path.join(directory, "modes." + fmt)
                rows.setdefault(f"{label} modes --format {fmt}", []).append(run_measured(
                    [exe, "modes", "--mass", m_path, "--stiffness", k_path, "--solver", "arpack", "--modes", "20",
                     "--format", fmt, "-o", out]))
        rows.setdefault("scipy eigsh + numpy.savetxt (CSV)", []).append(run_measured(
            ["/usr/bin/python3", "-c", SCIPY_MODES, m_path, k_path, "20", repr(sigma),
             os.path.join(directory, "scipy.csv")]))
    table(f"20 lowest modes of a 10^5-DOF train, whole process, median (min–max) of {repeats} alternating runs",
          rows, 1.0, "s", 2)


def speeds_case(binaries, repeats, directory):
    with open(os.path.join(DATA, "scenes", "resort_car_10m_rails.toml")) as f:
        scene = f.read()
    scene = scene.replace('step = "0.5 km/h"', 'step = "0.017 km/h"')  # (180 − 10) / 0.017: 10^4 speeds
    scene = scene.replace('"../vehicles/resort_car.toml"', '"%s"' % os.path.abspath(
        os.path.join(DATA, "vehicles", "resort_car.toml")))
    path = os.path.join(directory, "speeds.toml")
    with open(path, "w") as f:
        f.write(scene)
    rows = {}
    for _ in range(repeats):
        for label, exe in binaries:
            for fmt in ("markdown", "html", "csv", "json"):
                rows.setdefault(f"{label} critical-speed --format {fmt}", []).append(run_measured(
                    [exe, "critical-speed", path, "--format", fmt, "-q", "-o", os.path.join(directory, "cs." + fmt)]))
    table(f"critical-speed, resort car, 10^4 speeds, whole process, median (min–max) of {repeats} alternating runs",
          rows, 1e3, "ms", 1)


def main():
    args = sys.argv[1:]
    build = args[0] if args and not args[0].startswith("--") else "build"
    repeats = int(args[args.index("--repeats") + 1]) if "--repeats" in args else 5
    only = args[args.index("--only") + 1] if "--only" in args else None
    binaries = [("railmodal", os.path.abspath(os.path.join(build, "railmodal")))]
    if "--before" in args:
        binaries.insert(0, ("before", os.path.abspath(args[args.index("--before") + 1])))
    with tempfile.TemporaryDirectory(prefix="railmodal_writers_") as directory:
        if only in (None, "speeds"):
            speeds_case(binaries, repeats, directory)
        if only in (None, "modes"):
            modes_case(build, binaries, repeats, directory)


if __name__ == "__main__":
    main()
