#!/usr/bin/env python3
"""What a call through the Python package costs on top of the same C++ call (issue 23, item 4).

The C++ program python_call_timing times the library calls the bindings make, on the same
inputs; this script times the same calls through `railmodal` in Python. Both sides are run in
alternation, ROUNDS times, in one run of this script (the machine is shared and noisy), and
each figure is the median over the rounds of a median over 5 batches, with the spread (min to
max over the rounds), all in CPU time of the calling thread. The overhead is the difference per call; the ratio says how much of a
call that is. It also times reading M of a 2000-DOF system (a view, no copy) against copying it.

  PYTHONPATH=build/python python3 tools/benchmarks/python_overhead.py build [ROUNDS] [REPEATS]
"""
import pathlib
import statistics
import subprocess
import sys
import time

import numpy as np

import railmodal

ROOT = pathlib.Path(__file__).resolve().parents[2]
DATA = ROOT / "data"


def per_call(repeats, call):
    """Seconds per call: the median over 5 batches of `repeats` calls, as the C++ side does, in
    CPU time of the calling thread (the machine is shared: wall time would count the time other
    processes hold the core)."""
    batches = []
    for _ in range(5):
        start = time.thread_time()
        for _ in range(repeats):
            call()
        batches.append((time.thread_time() - start) / repeats)
    return statistics.median(batches)


def python_side(repeats):
    car = railmodal.load_vehicle(str(DATA / "vehicles" / "resort_car.toml"))
    system = railmodal.assemble(car)
    modes = railmodal.modes(system)
    single = railmodal.LinearSystem(np.eye(1), 4.0 * np.eye(1))
    frequencies = 0.01 * np.arange(1, 1001)
    scene = railmodal.load_scene(str(DATA / "scenes" / "resort_car_10m_rails.toml"))
    speeds = 1.0 + 0.004 * np.arange(10000)
    source = scene.sources[0]
    return {
        "modes_1dof": per_call(repeats * 20, lambda: railmodal.modes(single)),
        "assemble": per_call(repeats, lambda: railmodal.assemble(car)),
        "modes": per_call(repeats, lambda: railmodal.modes(system)),
        "frf_1000": per_call(max(1, repeats // 50), lambda: railmodal.frf(system, modes, "body.bounce", frequencies)),
        # The C++ side sweeps the grid as given: so does the call timed here (by default the
        # binding also finds the source's critical speeds and adds them to the grid).
        "amplitude_curve_10000": per_call(max(1, repeats // 20), lambda: railmodal.amplitude_curves(
            system, modes, source, ["body.bounce"], speeds, with_critical_speeds=False)),
        "study_critical_speeds": per_call(max(1, repeats // 20), lambda: railmodal.study_critical_speeds(scene, car)),
    }


def cpp_side(build, repeats):
    program = pathlib.Path(build) / "tools" / "benchmarks" / "python_call_timing"
    out = subprocess.run([str(program), str(DATA), str(repeats)], check=True, capture_output=True, text=True).stdout
    return {name: float(value) for name, value in (line.split() for line in out.splitlines())}


def views_against_copies():
    big = railmodal.wagon_train(400).to_dense()  # 2000 DOFs: M is 32 MB
    view = per_call(1000, lambda: big.M)
    copy = per_call(5, lambda: np.array(big.M))
    return big.M.nbytes, view, copy


def main():
    build = sys.argv[1] if len(sys.argv) > 1 else "build"
    rounds = int(sys.argv[2]) if len(sys.argv) > 2 else 5
    repeats = int(sys.argv[3]) if len(sys.argv) > 3 else 200
    cpp, py = {}, {}
    for _ in range(rounds):  # alternate, so that both sides see the same load on the machine
        for name, value in cpp_side(build, repeats).items():
            cpp.setdefault(name, []).append(value)
        for name, value in python_side(repeats).items():
            py.setdefault(name, []).append(value)
    print("%-22s %12s %12s %12s %10s   spread (min–max over %d rounds, Python)" %
          ("call", "C++ (us)", "Python (us)", "overhead", "ratio", rounds))
    for name in cpp:
        c, p = statistics.median(cpp[name]), statistics.median(py[name])
        print("%-22s %12.2f %12.2f %12.2f %9.2f%%   %.2f–%.2f us" % (
            name, 1e6 * c, 1e6 * p, 1e6 * (p - c), 100 * (p - c) / c, 1e6 * min(py[name]), 1e6 * max(py[name])))
    size, view, copy = views_against_copies()
    print("reading M of a 2000-DOF system (%.0f MB): %.2f us as a view, %.0f us copied" % (size / 1e6, 1e6 * view, 1e6 * copy))


if __name__ == "__main__":
    main()
