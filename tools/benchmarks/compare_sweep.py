#!/usr/bin/python3
"""A speed sweep in railmodal against tuned numpy/scipy, side by side in one run.

10 000 speeds. By default every source a bogie wagon meets (rail joints with 6 harmonics, wheel
eccentricity, wheel flats with 6 harmonics, hunting) on the resort car with all its DOFs, body
bounce displacement and acceleration, summed over each source's harmonics; with --scene, a
bundled critical-speed scene's vehicle, sources and output DOFs over its speed range (--all-scenes:
every one of them). railmodal's build/tools/benchmarks/sweep_timing times its own sweep and
writes the model and each harmonic's load Q(ω) = s(ω)(Q_K + iωQ_C); this script redoes the same
computation in numpy and checks that the two agree.

WHY THIS IS THE STRONGEST FAIR BASELINE. It is what a competent numpy/scipy user would write
for this one problem, knowing its structure as railmodal does:
  - the modes are found once a sweep (scipy.linalg.eigh, and scipy.linalg.eig of the first-order
    form when the damping is not proportional) and the sweep is vectorised over all speeds at once,
    one (speeds × modes) array per harmonic, no Python loop over speeds;
  - modes that the harmonic does not load, or that do not move the output, are dropped before
    the sweep (a term below 1e-12 of |φ_d|·‖φ‖·‖Q‖: round-off of an exact zero, railmodal's
    rule), which also keeps numpy out of subnormal arithmetic on responses of 1e-300;
  - real arithmetic where the problem is real: with C = 0 the denominators λ_j − ω² are real, so
    the response is two real matrix-vector products (real and imaginary parts of the modal
    load) through one real (speeds × modes) array, no complex division;
  - proportional damping (ΦᵀCΦ diagonal): n complex terms per speed; other damping: the 2n
    complex modes of the first-order form, never a linear solve per speed;
  - the phase is one numpy.angle of the harmonic-1 response, only where asked.
Batched direct solves (numpy.linalg.solve over all speeds at once) are computed once, untimed,
as the independent check of both fast paths.

WHAT EACH SIDE TIMES: the same work, from the assembled M, C, K, the real modes and the sources'
loads to the curves. Untimed on both sides: assembly and the real modal solve (railmodal's
solve_modes before its clock starts; numpy's scipy.linalg.eigh in real_modes()). Timed on both
sides: what the damping asks for before the sweep, then the sweep and the allocation of its
curves. railmodal's amplitude_curves does the former inside each call, per source: ΦᵀCΦ and the
proportionality test, and with discrete dampers the 2n × 2n eigen-decomposition of the
first-order form, its left eigenvectors and the check against direct solves at nine speeds
(src/response/speed_sweep.cpp, sweep_curves); numpy's damping_path() does its equivalent (ΦᵀCΦ
and the test; M⁻¹, scipy.linalg.eig of the first-order form and the inverse of its eigenvectors)
inside every timed call, once for all sources, as a user would. (Until 2026-11-26 numpy's
damping_path ran once, untimed, while railmodal's time held its own: on the complex path the
ratios favoured numpy by the cost of that eigen-decomposition.) Left in numpy's favour:
railmodal derives each harmonic's load parts and load scales s(ω) inside its clock, numpy reads
them from railmodal's JSON (untimed); railmodal repeats the damping work for each source and
runs its nine-speed check, which the numpy path does not.

AGREEMENT. Amplitudes: each curve to 1e-9 of the largest value of its quantity over the source's
output DOFs (a DOF the source does not reach is 0 on one side, round-off on the other), at the
speeds railmodal does not
flag unbounded (it reports 0 there, numpy an overflow or a huge finite number). Both sides are
backward-stable sums of the same modal terms (or, for railmodal's direct fallback, an LU solve),
so they differ by round-off amplified by how close a speed sits to an undamped resonance; on a
10 000-speed grid the closest speed is ~1e-4 relative from a resonance, which turns 1e-16 into
~1e-12 of that curve's peak, and 1e-9 leaves three decades of margin while a wrong term (a
dropped mode, a wrong harmonic) shows at 1e-3 or more. Phases of harmonic 1: to 1e-6 degrees
where harmonic 1 reaches the output (elsewhere either phase is that of round-off).

TIMING. Interleaved rounds (side_by_side.py): in each round railmodal (the median of its own
--inner repeats, in a fresh sweep_timing process) and numpy (the median of --inner calls) run
back to back; the ratio is formed within the round, and the report gives the median ratio and
its spread over the rounds. Processor time by default (--clock wall for the wall clock): on
the shared development machine a process waits for a core between time slices, which the wall
clock counts, and a sweep of a millisecond is then mostly waiting.

    /usr/bin/python3 tools/benchmarks/compare_sweep.py [--rounds 7] [--inner 21]
        [--scene FILE ... | --all-scenes] [--quick] [--driver PATH]

--quick: 2 rounds of 3, the default case only (a smoke run: it checks agreement, its times mean
little). Needs Debian's python3-numpy and python3-scipy (for /usr/bin/python3) and a build with
benchmarks (sweep_timing).
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile
import time

for _var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS", "BLIS_NUM_THREADS"):
    os.environ[_var] = "1"  # before numpy is imported: railmodal's sweep is one thread too

try:
    import numpy as np
    import scipy.linalg
except ImportError:
    sys.exit("compare_sweep.py: error: numpy/scipy missing (Debian: apt-get install python3-numpy python3-scipy)")

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
from side_by_side import Rounds, median_of  # noqa: E402

AMPLITUDE_TOLERANCE = 1e-9  # of each curve's largest value; the docstring says why
PHASE_TOLERANCE_DEG = 1e-6
DROP = 1e-12                # a modal term below this fraction of the largest is round-off of 0

# Scenes a sweep applies to: periodic sources, no simulation or ride table.
SCENES = ["fette_car_10m_rails", "hunting_wavelengths", "manchester_coach_hunting", "pullman_coil_spring_15m_rails",
          "resort_car_10m_rails", "resort_car_wheel_defects", "steam_locomotive_unbalance",
          "two_axle_example2_threshold", "two_axle_freight_wagon_10m_rails", "two_axle_freight_wagon_joints"]


class Problem:
    """The model as arrays, each harmonic's load parts and scales (not timed: reading JSON)."""

    def __init__(self, model):
        self.M, self.K, self.C = (np.array(model[k], dtype=float) for k in ("mass", "stiffness", "damping"))
        self.V = np.array(model["speeds"])
        self.dofs = list(model["output_dofs"])
        self.sources = []
        for s in model["sources"]:
            harmonics = []
            for h in s["harmonics"]:
                qk = np.array(h["stiffness_part"]["re"]) + 1j * np.array(h["stiffness_part"]["im"])
                qc = np.array(h["damping_part"]["re"]) + 1j * np.array(h["damping_part"]["im"])
                w = 2 * np.pi * h["harmonic"] * self.V / s["wavelength"]
                harmonics.append((h["harmonic"], w, qk, qc, np.array(h["load_scale"])))
            ref = s["phase_reference"]
            self.sources.append((harmonics, np.arctan2(ref["im"], ref["re"])))


def real_modes(p):
    """The real modes, as railmodal's solve_modes finds them before its clock starts (untimed)."""
    return scipy.linalg.eigh(p.K, p.M)


def damping_path(p, modes):
    """The path the damping allows and what it needs besides the real modes: the work railmodal's
    amplitude_curves does inside its clock before it sweeps, so timed with the numpy sweep."""
    n = p.M.shape[0]
    lam, phi = modes
    if not np.any(p.C):
        return "real modal (C = 0)", (lam, phi)
    c = phi.T @ p.C @ phi
    if np.max(np.abs(c - np.diag(np.diag(c)))) <= 1e-12 * np.max(np.abs(c)):
        return "complex modal (proportional C)", (lam, phi, np.diag(c).copy())
    Minv = np.linalg.inv(p.M)
    A = np.block([[np.zeros((n, n)), np.eye(n)], [-Minv @ p.K, -Minv @ p.C]])
    mu, U = scipy.linalg.eig(A)
    L = np.linalg.inv(U)
    return "first-order complex modes", (mu, U[:n], L[:, n:] @ Minv)


def sweep(p, prepared, phases):
    """Per source and output DOF, the displacement and acceleration curves (Σ_k |x_k|,
    Σ_k ω_k²|x_k|) and, with `phases`, the phase of harmonic 1 in degrees."""
    path, modes = prepared
    out = []
    for harmonics, reference in p.sources:
        # A modal term at round-off of the source's whole load drives nothing (railmodal's rule,
        # response::kLoadRoundOff): below DROP·|φ_d|·‖φ‖·(‖Q_K‖ + ‖Q_C‖ over all harmonics) it
        # is left out, so that a response that is exactly 0 comes out 0 rather than as sums of
        # 1e-300 noise (subnormal arithmetic, 100 times slower, and meaningless phases).
        q_norm = np.sqrt(sum(np.sum(np.abs(qk)**2) for _, _, qk, _, _ in harmonics)) + \
            np.sqrt(sum(np.sum(np.abs(qc)**2) for _, _, _, qc, _ in harmonics))
        x1 = {}
        disp = {d: np.zeros(p.V.size) for d in p.dofs}
        acc = {d: np.zeros(p.V.size) for d in p.dofs}
        for k, w, qk, qc, scale in harmonics:
            if path.startswith("real"):
                lam, phi = modes
                a, b = phi.T @ qk, phi.T @ qc          # modal load a + iωb (complex parts)
                for d in p.dofs:
                    ar, ai, br, bi = (phi[d] * t for t in (a.real, a.imag, b.real, b.imag))
                    keep = np.maximum(np.maximum(abs(ar), abs(ai)), np.maximum(abs(br), abs(bi)))
                    keep = keep > DROP * np.abs(phi[d]) * np.linalg.norm(phi, axis=0) * q_norm
                    R = 1.0 / (lam[keep][None, :] - (w**2)[:, None])   # real (speeds × modes)
                    re = R @ ar[keep] - w * (R @ bi[keep])
                    im = R @ ai[keep] + w * (R @ br[keep])
                    amp = scale * np.hypot(re, im)
                    disp[d] += amp
                    acc[d] += amp * w**2
                    if phases and k == 1:
                        x1[d] = np.sign(scale) * (re + 1j * im)
            else:
                if path.startswith("complex"):
                    lam, phi, c = modes
                    a, b = phi.T @ qk, phi.T @ qc
                    rows = phi
                    load_gain = np.linalg.norm(phi, axis=0)
                    den = lambda keep: lam[keep][None, :] - (w**2)[:, None] + 1j * w[:, None] * c[keep][None, :]
                else:
                    mu, rows, LB = modes
                    a, b = LB @ qk, LB @ qc
                    load_gain = np.linalg.norm(LB, axis=1)  # |participation| per unit load
                    den = lambda keep: 1j * w[:, None] - mu[keep][None, :]
                for d in p.dofs:
                    ta, tb = rows[d] * a, rows[d] * b
                    keep = np.maximum(abs(ta), abs(tb))
                    keep = keep > DROP * np.abs(rows[d]) * load_gain * q_norm
                    x = ((ta[keep][None, :] + 1j * w[:, None] * tb[keep][None, :]) / den(keep)).sum(axis=1)
                    amp = scale * np.abs(x)
                    disp[d] += amp
                    acc[d] += amp * w**2
                    if phases and k == 1:
                        x1[d] = np.sign(scale) * x
        for d in p.dofs:
            if phases:
                # angle in (-180, 180], less the reference in (-180, 180]: one add wraps it back
                # into (-180, 180] (numpy.mod would cost more than the sweep); 0 where x is 0.
                ph = np.degrees(np.angle(x1[d])) - np.degrees(reference)
                ph = np.where(ph <= -180.0, ph + 360.0, ph)
                ph = np.where(ph > 180.0, ph - 360.0, ph)
                zero = x1[d] == 0
                pa = ph + 180.0
                pa = np.where(pa > 180.0, pa - 360.0, pa)
                out += [(disp[d], np.where(zero, 0.0, ph)), (acc[d], np.where(zero, 0.0, pa))]
            else:
                out += [(disp[d], None), (acc[d], None)]
    return out


def direct(p):
    """Batched direct solves of (K − ω²M + iωC)x = Q over all speeds: the independent check."""
    out = []
    for harmonics, _ in p.sources:
        disp = {d: np.zeros(p.V.size) for d in p.dofs}
        acc = {d: np.zeros(p.V.size) for d in p.dofs}
        for k, w, qk, qc, scale in harmonics:
            D = p.K[None] - (w**2)[:, None, None] * p.M[None] + 1j * w[:, None, None] * p.C[None]
            Q = scale[:, None] * (qk[None, :] + 1j * w[:, None] * qc[None, :])
            with np.errstate(all="ignore"):
                try:
                    X = np.linalg.solve(D, Q[:, :, None])[:, :, 0]
                except np.linalg.LinAlgError:  # a speed exactly at an undamped resonance
                    X = np.stack([np.linalg.lstsq(Di, Qi, rcond=None)[0] for Di, Qi in zip(D, Q)])
            for d in p.dofs:
                disp[d] += np.abs(X[:, d])
                acc[d] += np.abs(X[:, d]) * w**2
        for d in p.dofs:
            out += [disp[d], acc[d]]
    return out


def phase_defined(p, prepared, curves_rm):
    """Per curve, the speeds where harmonic 1's response exceeds 1e-9 of the largest the modal
    loads could give (elsewhere the exact response is 0 or nearly, and either side's phase is
    that of round-off), and railmodal did not flag the speed unbounded."""
    masks = []
    i = 0
    for harmonics, _ in p.sources:
        k, w, qk, qc, scale = harmonics[0]
        D = p.K[None] - (w**2)[:, None, None] * p.M[None] + 1j * w[:, None, None] * p.C[None]
        with np.errstate(all="ignore"):
            X = np.linalg.solve(D + 1e-300, (qk[None, :] + 1j * w[:, None] * qc[None, :])[:, :, None])[:, :, 0]
        for d in p.dofs:
            size = np.abs(X).max(axis=1)
            for _ in range(2):
                masks.append((np.abs(X[:, d]) > 1e-9 * size) & ~np.array(curves_rm[i]["unbounded"], dtype=bool))
                i += 1
    return masks


def agreement(p, model, prepared):
    """Largest differences of the tuned numpy sweep and of the direct solves from railmodal."""
    rm = model["amplitudes"]
    mine = sweep(p, prepared, phases=True)
    ref = direct(p)
    worst = {"tuned numpy": 0.0, "direct solves": 0.0}
    # Each curve against the largest value of its quantity over the source's output DOFs: a DOF
    # the source does not reach holds 0 on one side and round-off (1e-55 m) on the other.
    per_source = 2 * len(p.dofs)
    sizes = []
    for i, a in enumerate(rm):
        group = rm[i - i % per_source + i % 2:i - i % per_source + per_source:2]
        sizes.append(max(float(np.max(np.where(g["unbounded"], 0.0, g["values"]), initial=0.0)) for g in group))
    for name, curves in (("tuned numpy", [a for a, _ in mine]), ("direct solves", ref)):
        for c, a, size in zip(curves, rm, sizes):
            ok = ~np.array(a["unbounded"], dtype=bool)
            r = np.array(a["values"])
            if ok.any() and size > 0:
                worst[name] = max(worst[name], float(np.max(np.abs(c[ok] - r[ok])) / size))
    masks = phase_defined(p, prepared, rm)
    worst_phase = 0.0
    for (_, ph), a, m in zip(mine, rm, masks):
        d = np.abs(np.mod(ph - np.array(a["phases_deg"]) + 180.0, 360.0) - 180.0)
        worst_phase = max(worst_phase, float(np.max(d[m], initial=0.0)))
    return worst, worst_phase


def run_case(args, scene):
    label = os.path.basename(scene) if scene else "resort car, all sources (built in)"
    extra = [scene] if scene else []
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "sweep.json")
        subprocess.run([args.driver, os.path.join(ROOT, "data"), path, "3"] + extra, check=True, capture_output=True)
        with open(path) as f:
            model = json.load(f)
    if not model["sources"]:
        print(f"{label}: no periodic source, skipped")
        return None
    p = Problem(model)
    modes = real_modes(p)
    prepared = damping_path(p, modes)
    worst, worst_phase = agreement(p, model, prepared)

    def ours():
        run = subprocess.run([args.driver, os.path.join(ROOT, "data"), "-", str(args.inner)] + extra,
                             check=True, capture_output=True, text=True)
        return dict((k, float(v)) for k, v in (line.split() for line in run.stdout.splitlines()))
    last = {}
    suffix = "_cpu_s" if args.clock == "cpu" else "_s"

    def ours_amplitudes():
        last.update(ours())
        return last["sweep" + suffix]

    def numpy_side(phases):
        f = lambda: sweep(p, damping_path(p, modes), phases)  # the docstring says why both are timed
        if args.clock == "wall":
            return median_of(f, args.inner)[0]
        times = []
        for _ in range(args.inner):
            start = time.process_time()
            f()
            times.append(time.process_time() - start)
        return sorted(times)[len(times) // 2]
    rounds = Rounds({
        "railmodal": ours_amplitudes,
        "railmodal, phases": lambda: last["sweep_with_phases" + suffix],  # from the same process
        "numpy": lambda: numpy_side(False),
        "numpy, phases": lambda: numpy_side(True),
    })
    # railmodal's two figures come from one process: keep them together in every round.
    for r in range(args.rounds):
        order = [["railmodal", "railmodal, phases"], ["numpy", "numpy, phases"]]
        for group in (order if r % 2 == 0 else order[::-1]):
            for name in group:
                rounds.times[name].append(rounds.contenders[name]())
    harmonics = sum(len(s["harmonics"]) for s in model["sources"])
    print(f"{label}: {model['scene']}")
    print(f"  {len(model['speeds'])} speeds x {harmonics} source harmonics, {len(model['mass'])} DOFs, "
          f"outputs {', '.join(model['labels'])} (displacement, acceleration); numpy path: {prepared[0]}")
    for name in rounds.names:
        print(f"  {name:18s} {rounds.describe_time(name)}")
    amp_ratio = rounds.ratios("numpy", "railmodal")
    ph_ratio = rounds.ratios("numpy, phases", "railmodal, phases")
    print(f"  ratio numpy/railmodal, amplitudes {rounds.describe_ratio('numpy', 'railmodal')}")
    print(f"  ratio numpy/railmodal, phases     {rounds.describe_ratio('numpy, phases', 'railmodal, phases')}")
    ok = (worst["tuned numpy"] <= AMPLITUDE_TOLERANCE and worst["direct solves"] <= AMPLITUDE_TOLERANCE
          and worst_phase <= PHASE_TOLERANCE_DEG)
    print(f"  agreement with railmodal: tuned numpy {worst['tuned numpy']:.1e}, direct solves "
          f"{worst['direct solves']:.1e} of each curve's max (tolerance {AMPLITUDE_TOLERANCE:g}); phase "
          f"{worst_phase:.1e} deg (tolerance {PHASE_TOLERANCE_DEG:g}): {'PASS' if ok else 'FAIL'}")
    return ok, amp_ratio, ph_ratio


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rounds", type=int, default=7)
    parser.add_argument("--inner", type=int, default=21)
    parser.add_argument("--scene", action="append", default=[])
    parser.add_argument("--all-scenes", action="store_true")
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--clock", choices=["cpu", "wall"], default="cpu",
                        help="processor time (default: steadier on a shared machine) or wall time")
    parser.add_argument("--driver", default=os.path.join(ROOT, "build", "tools", "benchmarks", "sweep_timing"))
    args = parser.parse_args()
    if not os.access(args.driver, os.X_OK):
        sys.exit(f"compare_sweep.py: error: {args.driver} is missing; build with benchmarks (bash tools/test.sh)")
    if args.quick:
        args.rounds, args.inner = 2, 3
    scenes = [None] + ([os.path.join(ROOT, "data", "scenes", s + ".toml") for s in SCENES] if args.all_scenes
                       else args.scene)
    print(f"interleaved rounds: {args.rounds}, each the median of {args.inner} runs per side, {args.clock} time; "
          f"load average {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores")
    results = [r for r in (run_case(args, s) for s in scenes) if r is not None]
    if len(results) > 1:
        from side_by_side import quantiles
        lowest = min(quantiles(r[1])[0] for r in results), min(quantiles(r[2])[0] for r in results)
        print(f"lowest median ratio over the cases: amplitudes {lowest[0]:.1f}x, phases {lowest[1]:.1f}x")
    if not all(r[0] for r in results):
        sys.exit("compare_sweep.py: error: railmodal and numpy disagree")


if __name__ == "__main__":
    main()
