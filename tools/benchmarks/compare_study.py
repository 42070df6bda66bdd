#!/usr/bin/python3
"""A sampled design study in railmodal against numpy/scipy, side by side in one run.

The study is tools/benchmarks/resort_car_sample_study.toml: 100 000 spring sets of the
resort car (bogie wagon, vertical DOFs) over 10 m rail joints, 10-180 km/h. railmodal's
study_timing loads, evaluates (on --threads threads) and ranks it, timing each step; checks
that 1 thread and --threads threads give byte-identical results on the first 2000
variants; and writes, for the first --numpy-variants variants, the assembled M, K, C, each
source harmonic's load Q(w) = s(w)(Q_K + iwQ_C), the speed range, the outputs and its own
answers. This script then redoes the same work in numpy on one core, BATCHED OVER VARIANTS
(blocks of BATCH variants stacked into arrays; Python loops only over the 6 modes, the
harmonics, sources and outputs, never over variants or speeds):

  - the modes of every variant at once: the Cholesky factor of M, L^-1 K L^-T and numpy's
    batched eigh (LAPACK per matrix inside one C loop);
  - critical speeds V = Lambda f / k of every source harmonic and every oscillatory mode (a
    repeated frequency is one eigenspace) that the harmonic loads, in the speed range, as one
    (variants x harmonics x modes) array, sorted per variant;
  - the speed grid (the scene's step plus every critical speed; rows padded with +inf), the
    amplitude curve of each output by modal superposition in real arithmetic (C = 0: the
    denominators lambda - w^2 are real), one (variants x speeds x modes) array per harmonic,
    undamped resonances flagged as unbounded;
  - the peak of each curve: its largest finite grid value (no refinement);
  - the static deflections, (K - K_gravity) q = M u g, one batched solve.

WHY THIS IS THE STRONGEST FAIR BASELINE: a competent numpy user with 10^5 variants of one
model would not loop over variants in Python (the earlier version of this script did, and
spent most of its time in interpreter and per-call overhead: about 4x slower); numpy may use
the structure railmodal uses (the same DOFs in every variant, no damping in this study, one
eigen-solve per variant, modal superposition over the modes a harmonic loads). Anything the
batched path cannot treat exactly (damping, massless DOFs, load scales other than 1) is
refused, not approximated. numpy links whatever BLAS/LAPACK the system provides (Debian's
reference libblas3 on the development machine); with OpenBLAS its products would be faster.

and checks agreement: frequencies, critical speeds and static deflections to 1e-9 relative,
the grids to 1e-12, the grid curves point by point to 1e-9 relative (widened to 1e-13/g at a
point g (relative) away from a natural frequency, where the amplitude is that ill-conditioned)
with identical unbounded flags, and the peaks: numpy's grid maximum may not exceed
railmodal's peak beyond that, and railmodal's golden-section refinement may raise it above
numpy's by at most 1 % (CURVE_TOLERANCE, PEAK_TOLERANCE below say why). It prints variants
per minute for both (wall clock, and from CPU time, which other jobs on the machine disturb
less) and their ratios as the median and range over --rounds interleaved rounds (railmodal's
whole study_timing run and numpy's batched pass back to back, the order alternating), and
exits 1 on any disagreement or thread dependence.

NOT LIKE FOR LIKE: numpy is given the assembled matrices and loads, so its time excludes
parsing the TOML, applying the overrides, reading the vehicle and assembling it; railmodal's
end-to-end time includes all of that (load_study) and its evaluation time still includes
assembly. numpy also leaves out what railmodal computes but the comparison does not need:
mode naming, energy shares, residual checks, the metacentric height (a lateral assembly and
solve), the golden-section peak refinement and, per critical speed, a direct harmonic solve
and the friction criterion. The figures favour numpy.

    /usr/bin/python3 tools/benchmarks/compare_study.py [--variants N] [--threads 2]
        [--numpy-variants 2000] [--rounds 3] [--quick] [--driver PATH] [--keep-json PATH]

--variants N runs a copy of the study with `count = N` (default: the file's 100 000).
--quick: 2000 variants, numpy on 500, 2 rounds (a smoke run; it checks agreement).
numpy runs on one core (OMP/OPENBLAS/MKL_NUM_THREADS=1, set here before numpy loads).
Needs Debian's python3-numpy and python3-scipy (for /usr/bin/python3) and a build with
benchmarks (study_timing).
"""
import argparse
import json
import os
import re
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from side_by_side import quantiles  # noqa: E402

for _var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS", "BLIS_NUM_THREADS"):
    os.environ[_var] = "1"  # before numpy is imported: a per-core figure

try:
    import numpy as np
    import scipy.linalg
except ImportError:
    sys.exit("compare_study.py: error: numpy/scipy missing (Debian: apt-get install python3-numpy python3-scipy)")

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
STUDY = os.path.join(HERE, "resort_car_sample_study.toml")

TWO_PI = 2.0 * np.pi
AT_RESONANCE = 1e-9     # |lambda - w^2| <= 1e-9 lambda: at the natural frequency (as railmodal)
ZERO_TOLERANCE = 1e-13  # |lambda| below this fraction of the largest: rigid-body mode
PARTICIPATION = 1e-9    # modal force below this fraction of |phi||Q|: the harmonic does not load the mode
# Grid curves: 1e-9 of the value, widened beside a resonance. A grid point at relative
# distance g = min_j |lambda_j - w^2| / lambda_j from a natural frequency has an amplitude
# ~ 1/(lambda_j - w^2), so the eigenvalues' own difference between two solvers (~1e-14
# relative: Eigen's and LAPACK's, see "frequencies") moves it by ~1e-14/g relative. A random
# sample puts a few critical speeds within 1e-7 of a scene grid point (g ~ 1e-7: a true
# disagreement of ~1e-8 that says nothing about either code), hence per point
#   |numpy - railmodal| <= (1e-9 + 1e-13/g) |railmodal|.
CURVE_TOLERANCE = 1e-9
EIGENVALUE_AGREEMENT = 1e-13
# Peaks: railmodal's peak is the larger of its grid maximum and of golden-section refined
# local maxima between grid neighbours; numpy's is the grid maximum. So numpy's must not
# exceed railmodal's by more than the grid curves may differ (the tolerance above, at that
# point), and railmodal's may exceed numpy's only by what a curve gains between two grid
# points 0.5 km/h apart around a local maximum. Near the maximum the curve is a parabola: a
# peak at distance d <= h from the grid point exceeds it by at most A''/2 d^2. A local maximum
# of these undamped curves away from a resonance is broad (its width is of the order of the
# spacing of the modes' critical speeds, tens of km/h), so the gain is of order
# (h/width)^2 ~ (0.5/20)^2 ~ 1e-3; a damped resonance peak as narrow as a few grid steps
# would gain more. 1e-2 relative leaves a margin and still catches a wrong curve or a missed
# peak; the script prints the largest gain seen and how many peaks the refinement raised.
PEAK_TOLERANCE = 1e-2
BATCH = 1000  # variants per numpy block: its (variants x speeds x modes) arrays stay near 20 MB


def parse_args():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--variants", type=int, default=0, help="sample count (default: the study file's)")
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--numpy-variants", type=int, default=2000)
    parser.add_argument("--rounds", type=int, default=3, help="interleaved rounds (medians and range reported)")
    parser.add_argument("--quick", action="store_true", help="2000 variants, numpy 500, 2 rounds: a smoke run")
    parser.add_argument("--driver", default=os.path.join(ROOT, "build", "tools", "benchmarks", "study_timing"))
    parser.add_argument("--study", default=STUDY)
    parser.add_argument("--keep-json", default="", help="keep study_timing's JSON here")
    return parser.parse_args()


def study_copy(path, count, folder):
    """The study with `count` samples and absolute vehicle/scene paths, in `folder`."""
    with open(path) as f:
        text = f.read()
    base = os.path.dirname(os.path.abspath(path))
    text, n = re.subn(r"count\s*=\s*\d+", f"count = {count}", text, count=1)
    if n != 1:
        sys.exit(f"compare_study.py: error: no `count = ...` in {path}")
    for key in ("vehicle", "scene"):
        text = re.sub(rf'^{key}\s*=\s*"([^"]+)"', lambda m: f'{key} = "{os.path.normpath(os.path.join(base, m.group(1)))}"',
                      text, count=1, flags=re.M)
    out = os.path.join(folder, f"study_{count}.toml")
    with open(out, "w") as f:
        f.write(text)
    return out


def complex_array(v):
    return np.array(v["re"]) + 1j * np.array(v["im"])


def prepare(v):
    """JSON lists to numpy arrays (not timed: the counterpart of reading the JSON)."""
    p = {k: np.array(v[k], dtype=float) for k in ("mass", "stiffness", "damping", "gravity_stiffness")}
    p["gravity"] = v["gravity"]
    p["bounce"] = np.array([d["motion"] == "bounce" for d in v["dofs"]])
    p["range"] = (v["min_speed"], v["max_speed"], v["speed_step"])
    p["sources"] = []
    for s in v["sources"]:
        hs = s["harmonics"]
        p["sources"].append((s["wavelength"], np.array([h["harmonic"] for h in hs], dtype=float),
                             np.array([complex_array(h["stiffness_part"]) for h in hs]),
                             np.array([complex_array(h["damping_part"]) for h in hs]),
                             np.array([h["load_scale"] for h in hs])))
    p["outputs"] = [(o["dof"], o["quantity"]) for o in v["outputs"]]
    return p


class Batch:
    """A block of variants stacked into arrays (not timed: the counterpart of reading the JSON).
    The batched evaluation needs what this study has: the same DOFs in every variant, no
    massless DOF, no damping (the resort car's suspension is springs only) and load scales
    s(ω) = 1 (rail joints on rigid track); anything else is refused rather than half-handled."""

    def __init__(self, variants, prepared):
        p0 = prepared[0]
        self.M = np.stack([p["mass"] for p in prepared])
        self.K = np.stack([p["stiffness"] for p in prepared])
        self.Kg = np.stack([p["gravity_stiffness"] for p in prepared])
        self.gravity = p0["gravity"]
        self.bounce = p0["bounce"]
        self.range = p0["range"]
        self.outputs = p0["outputs"]
        self.sources = []  # (wavelength, k (H), Qk (B x H x n), Qc (B x H x n))
        for s, (wavelength, k, _, _, _) in enumerate(p0["sources"]):
            self.sources.append((wavelength, k, np.stack([p["sources"][s][2] for p in prepared]),
                                 np.stack([p["sources"][s][3] for p in prepared])))
        problems = []
        if any(p["mass"].shape != p0["mass"].shape or not np.array_equal(p["bounce"], p0["bounce"]) for p in prepared):
            problems.append("variants with different DOFs")
        if np.any(np.all(self.M == 0.0, axis=2)):
            problems.append("a massless DOF")
        if any(np.any(p["damping"]) for p in prepared):
            problems.append("damping")
        if any(np.any(np.array(h["load_scale"]) != 1.0) for v in variants for s in v["sources"] for h in s["harmonics"]):
            problems.append("a load scale other than 1")
        if problems:
            sys.exit("compare_study.py: error: the batched numpy baseline covers undamped variants of one DOF set "
                     "without massless DOFs and with unit load scales; this study has " + ", ".join(problems))


def evaluate_batch(b):
    """Every variant's modes, critical speeds, grid curves, peaks and static deflections at
    once: arrays with the variants along the first axis, no Python loop over variants (only
    over the few modes, harmonics, sources and outputs)."""
    B, n = b.M.shape[0], b.M.shape[1]
    # Modes of K φ = λ M φ through the Cholesky factor M = L Lᵀ: the standard symmetric
    # problem L⁻¹ K L⁻ᵀ y = λ y, φ = L⁻ᵀ y, in numpy's batched eigh.
    Linv = np.linalg.inv(np.linalg.cholesky(b.M))
    lam, y = np.linalg.eigh(Linv @ b.K @ np.swapaxes(Linv, 1, 2))
    phi = np.swapaxes(Linv, 1, 2) @ y                                       # B x n x modes
    osc = lam > ZERO_TOLERANCE * np.max(np.abs(lam), axis=1, keepdims=True)
    freq = np.where(osc, np.sqrt(np.where(osc, lam, 0.0)) / TWO_PI, 0.0)

    # Static deflections: (K − K_gravity) q = M u g.
    up = b.bounce.astype(float)
    q = np.linalg.solve(b.K - b.Kg, (b.M @ up * b.gravity)[..., None])[..., 0]
    deflections = q[:, b.bounce]

    # Eigenspaces: a mode starts a new group unless within 1e-8 of its group's first (as
    # railmodal); `first[:, j]` is the first mode of mode j's group.
    first = np.zeros((B, n), dtype=int)
    for j in range(1, n):
        lead = first[:, j - 1]
        same = osc[:, j] & osc[np.arange(B), lead] & (np.abs(lam[:, j] - lam[np.arange(B), lead]) <= 1e-8 * lam[:, j])
        first[:, j] = np.where(same, lead, j)
    starts = osc & (first == np.arange(n)[None, :])
    phi_norm = np.linalg.norm(phi, axis=1)                                   # B x modes
    rows = np.arange(B)[:, None]

    vmin, vmax, step = b.range
    crit_speed, crit_key = [], []  # B x (sources·H·modes): speed (inf if none), and (source, harmonic)
    for s, (wavelength, k, Qk, Qc) in enumerate(b.sources):
        w_first = TWO_PI * freq[rows, first]                                 # B x modes: ω of the group
        A, Bc = Qk @ phi, Qc @ phi                                           # B x H x modes
        force2 = np.abs(A[:, :, :] + 1j * w_first[:, None, :] * Bc) ** 2
        F0sq = np.zeros_like(force2)
        for j in range(n):                                                   # sum over each group
            F0sq[np.arange(B), :, first[:, j]] += force2[:, :, j]
        Qnorm = np.linalg.norm(Qk[:, :, None, :] + 1j * w_first[:, None, :, None] * Qc[:, :, None, :], axis=3)
        driven = starts[:, None, :] & (np.sqrt(F0sq) > PARTICIPATION * phi_norm[:, None, :] * Qnorm)
        V = freq[:, None, :] * wavelength / k[None, :, None]                 # B x H x modes
        ok = driven & (V >= vmin) & (V <= vmax)
        crit_speed.append(np.where(ok, V, np.inf).reshape(B, -1))
        crit_key += [(s, int(kh)) for kh in k for _ in range(n)]
    crit_speed = np.concatenate(crit_speed, axis=1)
    order = np.argsort(crit_speed, axis=1, kind="stable")  # by speed; ties in (source, harmonic, mode) order
    crit_speed = np.take_along_axis(crit_speed, order, axis=1)
    count = int(np.max(np.sum(np.isfinite(crit_speed), axis=1), initial=0))
    crit_speed, order = crit_speed[:, :count], order[:, :count]

    # The grid: the scene's steps and every critical speed, sorted, exact repeats removed
    # (padding is +inf, at the end of each row).
    steps = int(np.ceil((vmax - vmin) / step - 1e-9))
    base = np.minimum(vmin + np.arange(steps + 1) * step, vmax)
    grid = np.sort(np.concatenate([np.broadcast_to(base, (B, base.size)), crit_speed], axis=1), axis=1)
    repeat = np.zeros(grid.shape, dtype=bool)
    repeat[:, 1:] = grid[:, 1:] == grid[:, :-1]
    grid = np.sort(np.where(repeat, np.inf, grid), axis=1)
    valid = np.isfinite(grid)
    grid_finite = np.where(valid, grid, 0.0)

    curves, peaks = [], []
    mode_max = np.max(np.abs(phi), axis=1)                                   # B x modes
    for wavelength, k, Qk, Qc in b.sources:
        A, Bc = Qk @ phi, Qc @ phi                                           # B x H x modes
        qk_norm, qc_norm = np.linalg.norm(Qk, axis=2), np.linalg.norm(Qc, axis=2)  # B x H
        parts = {}
        for d in sorted({d for d, _ in b.outputs}):
            at = phi[:, d, :]                                                # B x modes
            moves = np.abs(at) > 1e-9 * mode_max
            floor = 1e-12 * np.abs(at) * phi_norm
            x = np.zeros((len(k), B, grid.shape[1]))
            unbounded = np.zeros((B, grid.shape[1]), dtype=bool)
            for h in range(len(k)):
                w = TWO_PI * k[h] * grid_finite / wavelength                 # B x G
                gap = lam[:, None, :] - (w**2)[:, :, None]                   # B x G x modes (real: C = 0)
                at_res = osc[:, None, :] & (np.abs(gap) <= AT_RESONANCE * lam[:, None, :])
                R = np.where(at_res, 0.0, 1.0 / np.where(at_res, 1.0, gap))
                # x = Σ_j φ_dj (A_j + iωB_j)/(λ_j − ω²), in real and imaginary parts.
                a_re, a_im = (at * A[:, h].real)[:, :, None], (at * A[:, h].imag)[:, :, None]
                b_re, b_im = (at * Bc[:, h].real)[:, :, None], (at * Bc[:, h].imag)[:, :, None]
                re = (R @ a_re)[..., 0] - w * (R @ b_im)[..., 0]
                im = (R @ a_im)[..., 0] + w * (R @ b_re)[..., 0]
                x[h] = np.hypot(re, im)
                num = np.hypot(a_re[:, None, :, 0] - w[:, :, None] * b_im[:, None, :, 0],
                               a_im[:, None, :, 0] + w[:, :, None] * b_re[:, None, :, 0])
                drive = num > floor[:, None, :] * (qk_norm[:, h, None, None] + w[:, :, None] * qc_norm[:, h, None, None])
                unbounded |= np.any(at_res & moves[:, None, :] & drive, axis=2)
            parts[d] = (x, unbounded & valid)
        for d, quantity in b.outputs:
            x, unbounded = parts[d]
            w = TWO_PI * k[:, None, None] * grid_finite[None] / wavelength   # H x B x G
            power = {"displacement": 1.0, "velocity": w, "acceleration": w**2}[quantity]
            amp = np.where(unbounded | ~valid, 0.0, np.sum(x * power, axis=0))
            curves.append((amp, unbounded))
            peaks.append((np.max(amp, axis=1), np.any(unbounded, axis=1)))
    return {"lam": lam, "freq": freq, "osc": osc, "crit_speed": crit_speed, "crit_order": order,
            "crit_key": crit_key, "grid": grid, "valid": valid, "curves": curves, "peaks": peaks,
            "deflections": deflections}


def unpack(batch_result, i):
    """Variant i's results in the per-variant form the agreement check reads (not timed)."""
    r = batch_result
    finite = np.isfinite(r["crit_speed"][i])
    valid = r["valid"][i]
    return {"lam": r["lam"][i], "freq": r["freq"][i], "osc": r["osc"][i],
            "critical": [(v, *r["crit_key"][o]) for v, o in zip(r["crit_speed"][i][finite], r["crit_order"][i][finite])],
            "grid": r["grid"][i][valid],
            "curves": [(amp[i][valid], unb[i][valid]) for amp, unb in r["curves"]],
            "peaks": [(float(pk[i]), bool(pu[i])) for pk, pu in r["peaks"]],
            "deflections": r["deflections"][i]}


def relative(a, b):
    a, b = np.asarray(a, float), np.asarray(b, float)
    if a.size == 0 and b.size == 0:
        return 0.0
    return float(np.max(np.abs(a - b) / np.maximum(np.abs(b), 1e-300)))


class Agreement:
    def __init__(self):
        self.worst = {"frequencies": 0.0, "critical speeds": 0.0, "grid": 0.0, "curves": 0.0,
                      "peaks (railmodal below numpy)": 0.0, "static deflections": 0.0}
        self.worst_ratio = {"curves": 0.0, "peaks (railmodal below numpy)": 0.0}  # difference / allowed
        self.widened = 0  # grid points beyond 1e-9, within the resonance allowance
        self.peak_gain = 0.0
        self.peaks_raised = 0
        self.refined = 0  # golden-section refined peaks railmodal found
        self.peaks = 0
        self.unbounded_peaks = 0
        self.critical_speeds = 0
        self.problems = []

    def fail(self, name, text):
        if len(self.problems) < 20:
            self.problems.append(f"{name}: {text}")

    def check(self, v, p, r):
        name = v["name"]
        f_rm = np.array([m["frequency_hz"] for m in v["modes"]])
        kinds = ["oscillatory" if o else ("rigid-body" if abs(l) <= ZERO_TOLERANCE * np.max(np.abs(r["lam"])) else "unstable")
                 for o, l in zip(r["osc"], r["lam"])]
        if kinds != [m["kind"] for m in v["modes"]]:
            self.fail(name, "mode kinds differ")
        else:
            self.worst["frequencies"] = max(self.worst["frequencies"], relative(r["freq"][r["osc"]], f_rm[r["osc"]]))
        cs = v["critical_speeds"]
        self.critical_speeds += len(cs)
        if [(c["source"], c["harmonic"]) for c in cs] != [(c[1], c[2]) for c in r["critical"]]:
            self.fail(name, f"critical speeds differ: {len(cs)} against numpy's {len(r['critical'])}")
        else:
            self.worst["critical speeds"] = max(self.worst["critical speeds"],
                                                relative([c[0] for c in r["critical"]], [c["speed"] for c in cs]))
        grid = np.array(v["speeds"])
        if grid.size != r["grid"].size:
            self.fail(name, f"grids differ: {grid.size} against numpy's {r['grid'].size} speeds")
            return
        self.worst["grid"] = max(self.worst["grid"], relative(r["grid"], grid))
        # Relative distance of each grid point from the nearest natural frequency, per source.
        lam = r["lam"][r["osc"]]
        distance = []
        for wavelength, k, *_ in p["sources"]:
            w2 = (TWO_PI * k[:, None] * r["grid"][None, :] / wavelength) ** 2
            distance.append(np.min(np.abs(lam[None, None, :] - w2[:, :, None]) / lam, axis=(0, 2), initial=np.inf))
        for c, (amp, unb), pk, (peak, peak_unb) in zip(v["curves"], r["curves"], v["peaks"], r["peaks"]):
            a = np.array(c["amplitudes"])
            if not np.array_equal(np.array(c["unbounded"], dtype=bool), unb):
                self.fail(name, f"unbounded flags differ (source {c['source']}, {c['output']} {c['quantity']})")
                continue
            self.refined += len(c["refined_peaks"])
            with np.errstate(divide="ignore"):  # g = 0 at the critical speeds: unbounded there, 0 on both sides
                allowed = CURVE_TOLERANCE + EIGENVALUE_AGREEMENT / distance[c["source"]]
            diff = np.abs(amp - a) / np.maximum(a, 1e-300)
            self.worst["curves"] = max(self.worst["curves"], float(np.max(diff)))
            self.worst_ratio["curves"] = max(self.worst_ratio["curves"], float(np.max(diff / allowed)))
            self.widened += int(np.count_nonzero(diff > CURVE_TOLERANCE))
            self.peaks += 1
            self.unbounded_peaks += peak_unb
            if pk["unbounded"] != peak_unb:
                self.fail(name, "peak unbounded flags differ")
                continue
            rm = pk["amplitude"]
            at = int(np.argmax(amp))
            below = (peak - rm) / max(rm, 1e-300)
            self.worst["peaks (railmodal below numpy)"] = max(self.worst["peaks (railmodal below numpy)"], below)
            self.worst_ratio["peaks (railmodal below numpy)"] = max(self.worst_ratio["peaks (railmodal below numpy)"],
                                                                    below / allowed[at])
            gain = (rm - peak) / max(peak, 1e-300)
            self.peak_gain = max(self.peak_gain, gain)
            self.peaks_raised += gain > allowed[at]
        self.worst["static deflections"] = max(self.worst["static deflections"],
                                               relative(r["deflections"], [d["deflection"] for d in v["static_deflections"]]))

    def passed(self):
        limits = {"frequencies": 1e-9, "critical speeds": 1e-9, "grid": 1e-12, "static deflections": 1e-9}
        bad = [k for k, x in self.worst.items() if k in limits and not x <= limits[k]]
        bad += [k for k, x in self.worst_ratio.items() if not x <= 1.0]
        if not self.peak_gain <= PEAK_TOLERANCE:
            bad.append("peaks (refinement gain)")
        return not self.problems and not bad, bad


def run_railmodal(args, study, path):
    """One study_timing run: its figures as floats, and its raw lines."""
    command = [args.driver, study, str(args.threads), path, str(args.numpy_variants)]
    start = time.perf_counter()
    run = subprocess.run(command, capture_output=True, text=True)
    wall = time.perf_counter() - start
    if run.returncode not in (0, 1):
        sys.exit(f"compare_study.py: error: study_timing failed ({run.returncode}): {run.stderr.strip()}")
    ours = dict(line.split(" ", 1) for line in run.stdout.splitlines() if " " in line)
    f = {k: float(x) for k, x in ours.items() if re.fullmatch(r"[-+0-9.e]+", x)}
    f["wall"] = wall
    return f, ours, " ".join(command)


def main():
    args = parse_args()
    if not os.access(args.driver, os.X_OK):
        sys.exit(f"compare_study.py: error: {args.driver} is missing; build with benchmarks "
                 "(cmake --build BUILD --target study_timing) or give --driver")
    if args.quick:
        args.variants, args.numpy_variants, args.rounds = 2000, 500, 2
    with tempfile.TemporaryDirectory() as tmp:
        study = study_copy(args.study, args.variants, tmp) if args.variants else args.study
        path = args.keep_json or os.path.join(tmp, "study.json")
        first, ours, command = run_railmodal(args, study, path)
        print("$ " + command, flush=True)
        with open(path) as f:
            data = json.load(f)
        variants = [v for v in data["variants"] if not v["failure"]]
        prepared = [prepare(v) for v in variants]
        batches = [Batch(variants[i:i + BATCH], prepared[i:i + BATCH]) for i in range(0, len(prepared), BATCH)]

        # Interleaved rounds: railmodal (a whole study_timing run) and numpy (one batched pass
        # over the variants, wall and CPU time) back to back, the order alternating.
        ours_runs, numpy_runs, results = [], [], None
        for r in range(args.rounds):
            for side in (("railmodal", "numpy") if r % 2 else ("numpy", "railmodal")):
                if side == "railmodal":
                    ours_runs.append(first if r == 0 else run_railmodal(args, study, path)[0])
                else:
                    start, cpu = time.perf_counter(), time.process_time()
                    results = [evaluate_batch(b) for b in batches]
                    numpy_runs.append((time.perf_counter() - start, time.process_time() - cpu))

    agreement = Agreement()
    i = 0
    for result, b in zip(results, batches):
        for j in range(b.M.shape[0]):
            agreement.check(variants[i], prepared[i], unpack(result, j))
            i += 1
    ok, bad = agreement.passed()

    rate = lambda count, s: 60.0 * count / s
    f = first
    n, threads, m = int(f["variants"]), int(f["threads"]), int(f["subset_variants"])

    def figures(f, numpy):
        """Per round: variants/min of each configuration and the ratios to numpy's."""
        one_thread = f["subset_1_thread_s"] / m + (f["load_s"] + f["rank_s"]) / n  # s per variant
        np_rate = rate(len(prepared), numpy[0])
        out = {"railmodal, threads, end to end": rate(n, f["load_s"] + f["evaluate_s"] + f["rank_s"]),
               "railmodal, threads, evaluate only": rate(n, f["evaluate_s"]),
               "railmodal, 1 thread, evaluate only": rate(m, f["subset_1_thread_s"]),
               "railmodal, 1 thread, end to end (est.)": 60.0 / one_thread,
               "numpy batched, 1 core": np_rate,
               "numpy batched, 1 core, from CPU time": rate(len(prepared), numpy[1]),
               "railmodal 1 thread, from CPU time": rate(m, f["subset_1_thread_cpu_s"])}
        out["ratio 1 thread evaluate / numpy"] = out["railmodal, 1 thread, evaluate only"] / np_rate
        out["ratio 1 thread end to end / numpy"] = out["railmodal, 1 thread, end to end (est.)"] / np_rate
        out["ratio threads end to end per core / numpy"] = out["railmodal, threads, end to end"] / threads / np_rate
        out["ratio 1 thread evaluate / numpy, CPU time"] = (out["railmodal 1 thread, from CPU time"]
                                                           / out["numpy batched, 1 core, from CPU time"])
        return out
    per_round = [figures(o, np_) for o, np_ in zip(ours_runs, numpy_runs)]
    v0 = variants[0] if variants else {"dofs": [], "speeds": [], "sources": [], "outputs": []}
    print()
    print(f"study: {n} variants ({int(f['failed'])} failed), {len(v0['dofs'])} DOFs, {len(v0['speeds'])} grid "
          f"speeds, {sum(len(s['harmonics']) for s in v0['sources'])} source harmonic(s), {len(v0['outputs'])} "
          f"outputs; numpy batched over {len(prepared)} variants in blocks of {BATCH}; {args.rounds} interleaved "
          f"rounds; load average {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores")
    print(f"railmodal, {threads} threads, first round: load_study {f['load_s']:.2f} s (one thread), evaluate_study "
          f"{f['evaluate_s']:.2f} s (CPU {f['evaluate_cpu_s']:.2f} s), rank_variants {f['rank_s']:.2f} s")
    print("variants/min (median over rounds, range); ratios > 1: railmodal faster per core")
    for key in per_round[0]:
        med, q1, q3, lo, hi = quantiles([p[key] for p in per_round])
        unit = "x" if key.startswith("ratio") else "/min"
        print(f"  {key:44s} {med:12.2f}{unit}   (range {lo:.2f}-{hi:.2f})" if unit == "x" else
              f"  {key:44s} {med:12.0f}{unit} (range {lo:.0f}-{hi:.0f})")
    print(f"threads identical (1 and {int(f['subset_threads'])} threads, first {m} variants, shard JSON and ranked "
          f"CSV bytes, and the full run's): {ours['threads_identical']}")
    print(f"agreement over {len(variants)} variants, {agreement.critical_speeds} critical speeds, "
          f"{agreement.peaks} peaks ({agreement.unbounded_peaks} with an undamped resonance in range):")
    for k, x in agreement.worst.items():
        ratio = agreement.worst_ratio.get(k)
        print(f"  {k:32s} max rel. difference {x:.1e}" +
              (f"   ({ratio:.2f} of the allowed 1e-9 + 1e-13/g)" if ratio is not None else ""))
    print(f"  grid points beyond 1e-9 (beside a resonance, within 1e-13/g): {agreement.widened}")
    print(f"  railmodal's refined (golden-section) peaks: {agreement.refined}; peaks they raised above numpy's "
          f"grid maximum: {agreement.peaks_raised}, "
          f"largest gain {agreement.peak_gain:.1e} (tolerance {PEAK_TOLERANCE:g})")
    for problem in agreement.problems:
        print("  MISMATCH " + problem)
    print("agreement: " + ("PASS" if ok else "FAIL " + ", ".join(bad)))
    if not ok or ours["threads_identical"] != "yes":
        sys.exit(1)


if __name__ == "__main__":
    main()
