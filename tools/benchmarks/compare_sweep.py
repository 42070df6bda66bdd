#!/usr/bin/python3
"""A speed sweep in railmodal against numpy/scipy, side by side in one run.

10 000 speeds, every source a bogie wagon meets (rail joints with 6 harmonics, wheel
eccentricity, wheel flats with 6 harmonics, hunting), the resort car with all its DOFs, body
bounce displacement and acceleration, summed over each source's harmonics. railmodal's
build/tools/benchmarks/sweep_timing times its own sweep and writes the model and each
harmonic's load Q(ω) = Q_K + iωQ_C; this script redoes the same computation vectorised in
numpy two ways — batched direct solves of (K − ω²M + iωC)x = Q over all speeds
(numpy.linalg.solve), and modal superposition after scipy.linalg.eigh — checks that all
three agree, and prints the times and ratios. Then both sides again with the phase of
harmonic 1 against the source's reference input (the report's FRF phase).

    /usr/bin/python3 tools/benchmarks/compare_sweep.py [--repeats 7] [--driver PATH]

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
except ImportError:
    sys.exit("compare_sweep.py: error: numpy/scipy missing (Debian: apt-get install python3-numpy python3-scipy)")

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def median_seconds(f, repeats):
    times = []
    result = None
    for _ in range(repeats):
        start = time.perf_counter()
        result = f()
        times.append(time.perf_counter() - start)
    return sorted(times)[len(times) // 2], result


def loads(model):
    for source in model["sources"]:
        parts = []
        for h in source["harmonics"]:
            qk = np.array(h["stiffness_part"]["re"]) + 1j * np.array(h["stiffness_part"]["im"])
            qc = np.array(h["damping_part"]["re"]) + 1j * np.array(h["damping_part"]["im"])
            parts.append((h["harmonic"], qk, qc))
        yield source["wavelength"], parts


def direct_sweep(model):
    """Batched direct solves: one (n × n) complex system per speed and harmonic."""
    M, K, C = (np.array(model[k]) for k in ("mass", "stiffness", "damping"))
    V = np.array(model["speeds"])
    d = model["output_dof"]
    out = []
    for wavelength, parts in loads(model):
        disp = np.zeros(V.size)
        acc = np.zeros(V.size)
        for k, qk, qc in parts:
            w = 2 * np.pi * k * V / wavelength
            D = K[None, :, :] - (w**2)[:, None, None] * M[None, :, :] + 1j * w[:, None, None] * C[None, :, :]
            Q = qk[None, :] + 1j * w[:, None] * qc[None, :]
            x = np.linalg.solve(D, Q[:, :, None])[:, d, 0]
            disp += np.abs(x)
            acc += np.abs(x) * w**2
        out += [disp, acc]
    return out


def modal_sweep(model, phases=False):
    """Modal superposition (C = 0 here), vectorised over speeds with broadcasting; with
    `phases`, also the phase of harmonic 1 against the source's reference input, in degrees
    (+180 for the acceleration), wrapped into (-180, 180]."""
    M, K, C = (np.array(model[k]) for k in ("mass", "stiffness", "damping"))
    lam, phi = scipy.linalg.eigh(K, M)
    c = np.einsum("ij,ik,kj->j", phi, C, phi)
    V = np.array(model["speeds"])
    d = model["output_dof"]
    out = []
    for (wavelength, parts), source in zip(loads(model), model["sources"]):
        disp = np.zeros(V.size)
        acc = np.zeros(V.size)
        for k, qk, qc in parts:
            w = 2 * np.pi * k * V / wavelength
            f = (phi.T @ qk)[None, :] + 1j * w[:, None] * (phi.T @ qc)[None, :]
            q = f / (lam[None, :] - (w**2)[:, None] + 1j * w[:, None] * c[None, :])
            x = q @ phi[d, :]
            disp += np.abs(x)
            acc += np.abs(x) * w**2
            if phases and k == 1:
                reference = source["phase_reference"]
                arg = np.angle(x) - np.arctan2(reference["im"], reference["re"])
                phase_disp = np.degrees(arg)
                phase_acc = phase_disp + 180.0
                phase_disp, phase_acc = (np.where(x == 0, 0.0, 180.0 - np.mod(180.0 - p, 360.0))
                                         for p in (phase_disp, phase_acc))
        out += [disp, acc] if not phases else [(disp, phase_disp), (acc, phase_acc)]
    return out


def phase_defined(model):
    """Per source, the speeds where harmonic 1 reaches the output: |x₁| above 1e-9 of
    Σ_j |q_j|·max|φ_j| (what the modal loads could give). Elsewhere the exact response is 0 or
    nearly so, and either side's phase is that of round-off (railmodal drops modal loads and
    shares at round-off, so it reports 0 where the exact response is 0). Not timed."""
    M, K = (np.array(model[k]) for k in ("mass", "stiffness"))
    lam, phi = scipy.linalg.eigh(K, M)
    V = np.array(model["speeds"])
    d = model["output_dof"]
    masks = []
    for wavelength, parts in loads(model):
        _, qk, qc = parts[0]
        w = 2 * np.pi * V / wavelength
        q = ((phi.T @ qk)[None, :] + 1j * w[:, None] * (phi.T @ qc)[None, :]) / (lam[None, :] - (w**2)[:, None])
        masks.append(np.abs(q @ phi[d, :]) > 1e-9 * (np.abs(q) @ np.abs(phi).max(axis=0)))
    return masks


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=7)
    parser.add_argument("--driver", default=os.path.join(ROOT, "build", "tools", "benchmarks", "sweep_timing"))
    args = parser.parse_args()
    if not os.access(args.driver, os.X_OK):
        sys.exit(f"compare_sweep.py: error: {args.driver} is missing; build with benchmarks (bash tools/test.sh)")
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "sweep.json")
        # The C++ sweep takes about a millisecond: at least 101 runs, so that its median is not
        # the cold first run's.
        run = subprocess.run([args.driver, os.path.join(ROOT, "data"), path, str(max(args.repeats, 101))],
                             check=True, capture_output=True, text=True)
        times = dict(line.split() for line in run.stdout.splitlines())
        ours, ours_with_phases = float(times["sweep_s"]), float(times["sweep_with_phases_s"])
        with open(path) as f:
            model = json.load(f)
    direct_s, direct = median_seconds(lambda: direct_sweep(model), args.repeats)
    modal_s, modal = median_seconds(lambda: modal_sweep(model), args.repeats)
    phases_s, with_phases = median_seconds(lambda: modal_sweep(model, phases=True), args.repeats)
    reference = [np.array(a["values"]) for a in model["amplitudes"]]
    def worst(results):
        return max(float(np.max(np.abs(r - a)) / max(np.max(np.abs(a)), 1e-300)) for r, a in zip(results, reference))
    # Phases compared as angles (179.9999 and -179.9999 are 0.0002 degrees apart), where
    # harmonic 1 reaches the output and railmodal did not flag the speed unbounded (its phase
    # is 0 there).
    defined = [m & ~np.array(a["unbounded"], dtype=bool)
               for m, a in zip((m for m in phase_defined(model) for _ in range(2)), model["amplitudes"])]
    phase_difference = max(float(np.max(np.abs(np.mod(p - np.array(a["phases_deg"]) + 180.0, 360.0) - 180.0)[m],
                                        initial=0.0))
                           for (_, p), a, m in zip(with_phases, model["amplitudes"], defined))
    n = len(model["mass"])
    harmonics = sum(len(s["harmonics"]) for s in model["sources"])
    print(f"sweep: {len(model['speeds'])} speeds x {harmonics} source harmonics, {n} DOFs, 2 outputs")
    print("amplitudes (railmodal also flags unbounded speeds; numpy does not):")
    print(f"  railmodal (C++)                    {ours * 1e3:9.2f} ms")
    print(f"  numpy batched direct solves        {direct_s * 1e3:9.2f} ms   ratio {direct_s / ours:7.1f}x   "
          f"max rel. difference {worst(direct):.1e}")
    print(f"  numpy/scipy modal, vectorised      {modal_s * 1e3:9.2f} ms   ratio {modal_s / ours:7.1f}x   "
          f"max rel. difference {worst(modal):.1e}")
    print("amplitudes and the phase of harmonic 1:")
    print(f"  railmodal (C++)                    {ours_with_phases * 1e3:9.2f} ms")
    print(f"  numpy/scipy modal, vectorised      {phases_s * 1e3:9.2f} ms   ratio {phases_s / ours_with_phases:7.1f}x   "
          f"max rel. difference {worst([a for a, _ in with_phases]):.1e}, phase {phase_difference:.1e} deg")


if __name__ == "__main__":
    main()
