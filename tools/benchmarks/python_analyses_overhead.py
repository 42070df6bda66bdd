#!/usr/bin/env python3
"""What the analysis bindings (simulation, studies, stability, ride, balance) cost on top of the
library's own work, call by call (issue 23, item 4).

Each result carries an AnalysisSummary whose stage times the library measures inside the call
(StageClock); the wall time of the same call measured around it in Python, minus those stage
times, is what the binding adds: converting the arguments, releasing and taking back the GIL,
wrapping the result (arrays are made only when a property is read, not here), and any library
work outside the timed stages (so this is an upper bound of the binding's cost). Both come from
the same call, so the machine's noise (shared, 2 cores) falls on both alike. Figures: medians
over REPEATS calls, with the spread (min to max) of the overhead. python_overhead.py (the
model, modes and response bindings) times the C++ calls separately instead.

  PYTHONPATH=build/python python3 tools/benchmarks/python_analyses_overhead.py [REPEATS]
"""
import pathlib
import statistics
import sys
import time

import numpy as np

import railmodal

DATA = pathlib.Path(__file__).resolve().parents[2] / "data"


def calls():
    """(name, call returning the object whose .summary times the library's stages)."""
    free = railmodal.load_scene(str(DATA / "scenes" / "resort_car_free_response.toml"))
    car = railmodal.load_vehicle(free.vehicle_file)  # given, so that no call reads the file again
    wheelset = railmodal.assemble(railmodal.load_vehicle(str(DATA / "vehicles" / "wheelset_on_springs.toml")), "lateral")
    coach_scene = railmodal.load_scene(str(DATA / "scenes" / "manchester_coach_ore_low.toml"))
    coach = railmodal.assemble(railmodal.load_vehicle(coach_scene.vehicle_file), coach_scene.dofs)
    su = railmodal.load_driving_gear(str(DATA / "locomotives" / "su.toml"))
    study = railmodal.load_study(str(DATA / "studies" / "resort_against_fette.toml"))
    signal = np.random.default_rng(1).standard_normal(4096)
    return [
        # One-off: FFTW plans at every call, outside the timed stages (amplitude_spectra plans once).
        ("amplitude_spectrum, 4096 samples", lambda: railmodal.amplitude_spectrum(signal, 100.0)),
        ("driving_gear_forces, Su, 360 steps", lambda: railmodal.driving_gear_forces(su, 100 / 3.6)),
        ("balance, Su, book rule", lambda: railmodal.balance(su)),
        ("hunting_stability, wheelset, 50 speeds", lambda: railmodal.hunting_stability(wheelset, speed_count=50, threads=1)),
        ("ride, coach, 1 speed", lambda: railmodal.ride(coach, coach_scene, speeds_m_s=[40.0])),
        ("simulate, resort car, 16001 samples", lambda: railmodal.simulate(free, car)),
        ("evaluate_study, 4 variants, 1 thread", lambda: railmodal.evaluate_study(study, threads=1)),
    ]


def measure(call, repeats):
    walls, library = [], []
    for _ in range(repeats):
        start = time.perf_counter()
        result = call()
        walls.append(time.perf_counter() - start)
        library.append(result.summary.total_seconds)
    overheads = [w - c for w, c in zip(walls, library)]
    return statistics.median(walls), statistics.median(overheads), min(overheads), max(overheads)


def main():
    repeats = int(sys.argv[1]) if len(sys.argv) > 1 else 21
    print("%-42s %12s %14s %22s %9s" % ("call", "wall, ms", "overhead, us", "spread, us", "share"))
    for name, call in calls():
        call()  # once before timing: plans, caches, pages
        wall, overhead, low, high = measure(call, repeats)
        print("%-42s %12.3f %14.1f %10.1f ... %8.1f %8.2f%%" % (name, 1e3 * wall, 1e6 * overhead, 1e6 * low, 1e6 * high,
                                                                 100 * overhead / wall))


if __name__ == "__main__":
    main()
