#!/usr/bin/python3
"""A sampled design study in railmodal against numpy/scipy, side by side in one run.

The study is tools/benchmarks/resort_car_sample_study.toml: 100 000 spring sets of the
resort car (bogie wagon, vertical DOFs) over 10 m rail joints, 10-180 km/h. railmodal's
study_timing loads, evaluates (on --threads threads) and ranks it, timing each step; checks
that 1 thread and --threads threads give byte-identical results on the first 2000
variants; and writes, for the first --numpy-variants variants, the assembled M, K, C, each
source harmonic's load Q(w) = s(w)(Q_K + iwQ_C), the speed range, the outputs and its own
answers. This script then redoes the same per-variant work in numpy/scipy on one core:

  - static condensation of massless DOFs (if any) and scipy.linalg.eigh(K, M): the modes;
  - critical speeds V = Lambda f / k of every source harmonic and every oscillatory mode (a
    repeated frequency is one eigenspace) that the harmonic loads, in the speed range;
  - the speed grid (the scene's step plus every critical speed), the amplitude curve of each
    output by modal superposition vectorised over harmonics x speeds x modes (batched
    direct solves if C were not proportional), undamped resonances flagged as unbounded;
  - the peak of each curve: its largest finite grid value (no refinement);
  - the static deflections, (K - K_gravity) q = M u g.

and checks agreement: frequencies, critical speeds and static deflections to 1e-9 relative,
the grids to 1e-12, the grid curves point by point to 1e-9 relative (widened to 1e-13/g at a
point g (relative) away from a natural frequency, where the amplitude is that ill-conditioned)
with identical unbounded flags, and the peaks: numpy's grid maximum may not exceed
railmodal's peak beyond that, and railmodal's golden-section refinement may raise it above
numpy's by at most 1 % (CURVE_TOLERANCE, PEAK_TOLERANCE below say why). It prints variants
per minute for both (wall clock, and from CPU time, which other jobs on the machine disturb
less) and their ratios, and exits 1 on any disagreement or thread dependence.

NOT LIKE FOR LIKE: numpy is given the assembled matrices and loads, so its time excludes
parsing the TOML, applying the overrides, reading the vehicle and assembling it; railmodal's
end-to-end time includes all of that (load_study) and its evaluation time still includes
assembly. numpy also leaves out what railmodal computes but the comparison does not need:
mode naming, energy shares, residual checks, the metacentric height (a lateral assembly and
solve), the golden-section peak refinement and, per critical speed, a direct harmonic solve
and the friction criterion. The figures favour numpy.

    /usr/bin/python3 tools/benchmarks/compare_study.py [--variants N] [--threads 2]
        [--numpy-variants 2000] [--repeats 3] [--driver PATH] [--keep-json PATH]

--variants N runs a copy of the study with `count = N` (default: the file's 100 000).
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


def parse_args():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--variants", type=int, default=0, help="sample count (default: the study file's)")
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--numpy-variants", type=int, default=2000)
    parser.add_argument("--repeats", type=int, default=3, help="numpy passes (the median is reported)")
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


def modes_of(M, K):
    """Static condensation of massless DOFs, then eigh: lambda ascending, phi over all DOFs."""
    massless = np.flatnonzero(~np.any(M != 0.0, axis=1))
    kept = np.flatnonzero(np.any(M != 0.0, axis=1))
    Kr = K[np.ix_(kept, kept)]
    if massless.size:
        recover = -np.linalg.solve(K[np.ix_(massless, massless)], K[np.ix_(massless, kept)])
        Kr = Kr + K[np.ix_(kept, massless)] @ recover
    lam, phi_kept = scipy.linalg.eigh(Kr, M[np.ix_(kept, kept)])
    phi = np.zeros((M.shape[0], lam.size))
    phi[kept] = phi_kept
    if massless.size:
        phi[massless] = recover @ phi_kept
    return lam, phi, massless


def evaluate(p):
    """One variant's modes, critical speeds, curves, peaks and static deflections."""
    M, K, C = p["mass"], p["stiffness"], p["damping"]
    n = M.shape[0]
    lam, phi, massless = modes_of(M, K)
    zero = ZERO_TOLERANCE * np.max(np.abs(lam))
    osc = lam > zero
    freq = np.where(osc, np.sqrt(np.where(osc, lam, 0.0)) / TWO_PI, 0.0)

    # Static deflections: K_el q = M u g.
    up = p["bounce"].astype(float)
    q = np.linalg.solve(K - p["gravity_stiffness"], M @ up * p["gravity"])
    deflections = q[p["bounce"]]

    # Eigenspaces of the oscillatory modes (relative gap 1e-8 as railmodal's).
    idx = np.flatnonzero(osc)
    groups = []
    for j in idx:
        if groups and abs(lam[j] - lam[groups[-1][0]]) <= 1e-8 * lam[j]:
            groups[-1].append(j)
        else:
            groups.append([j])
    first = np.array([g[0] for g in groups], dtype=int)
    member = np.zeros((len(groups), lam.size))  # group x mode indicator
    for g, js in enumerate(groups):
        member[g, js] = 1.0
    phi_norm = np.linalg.norm(phi, axis=0)

    vmin, vmax, step = p["range"]
    critical = []  # (speed, source, harmonic)
    for s, (wavelength, k, Qk, Qc, _) in enumerate(p["sources"]):
        # All harmonics x eigenspaces at once: V = Lambda f / k, w = 2 pi f.
        V = freq[first][None, :] * wavelength / k[:, None]
        w = TWO_PI * freq[first]
        Q = Qk[:, None, :] + 1j * w[None, :, None] * Qc[:, None, :]           # H x G x n
        force = (Qk @ phi)[:, None, :] + 1j * w[None, :, None] * (Qc @ phi)[:, None, :]  # H x G x modes
        F0 = np.sqrt(np.einsum("hgj,gj->hg", np.abs(force) ** 2, member))
        driven = F0 > PARTICIPATION * phi_norm[first][None, :] * np.linalg.norm(Q, axis=2)
        ok = driven & (V >= vmin) & (V <= vmax)
        for h, g in zip(*np.nonzero(ok)):
            critical.append((V[h, g], s, int(k[h]), h, g))
    critical.sort(key=lambda c: (c[0], c[1], c[3], c[4]))  # railmodal: source, harmonic, mode order, stable by speed
    critical = [c[:3] for c in critical]

    steps = int(np.ceil((vmax - vmin) / step - 1e-9))
    grid = np.unique(np.concatenate([np.minimum(vmin + np.arange(steps + 1) * step, vmax),
                                     np.array([c[0] for c in critical])]))

    c_modal = np.einsum("ij,ik,kj->j", phi, C, phi)
    off = phi.T @ C @ phi - np.diag(c_modal)
    proportional = (np.max(np.abs(off), initial=0.0) <= 1e-12 * np.max(np.abs(c_modal), initial=0.0)
                    and not np.any(C[massless] != 0.0))
    out_dofs = sorted({d for d, _ in p["outputs"]})
    curves, peaks = [], []
    for s, (wavelength, k, Qk, Qc, scale) in enumerate(p["sources"]):
        w = TWO_PI * k[:, None] * grid[None, :] / wavelength                  # H x S
        x = {}
        unbounded = {}
        if proportional:
            A = Qk @ phi                                                      # H x modes
            B = Qc @ phi
            gap = lam[None, None, :] - w[:, :, None] ** 2                     # H x S x modes
            undamped = osc & (c_modal == 0.0)
            at_res = undamped[None, None, :] & (np.abs(gap) <= AT_RESONANCE * lam[None, None, :])
            den = np.where(at_res, 1.0, gap + 1j * w[:, :, None] * c_modal[None, None, :])
            for d in out_dofs:
                at = phi[d]
                num = (A[:, None, :] + 1j * w[:, :, None] * B[:, None, :]) * at
                terms = np.where(at_res, 0.0, num / den)
                xd = scale * terms.sum(axis=2)
                if massless.size and d in massless:
                    i = list(massless).index(d)
                    flex = np.linalg.inv(K[np.ix_(massless, massless)])[i]
                    xd = xd + scale * ((Qk[:, massless] @ flex)[:, None] + 1j * w * (Qc[:, massless] @ flex)[:, None])
                moves = np.abs(at) > 1e-9 * np.max(np.abs(phi), axis=0)
                floor = 1e-12 * np.abs(at) * phi_norm
                drive = np.abs(num) > floor * (np.linalg.norm(Qk, axis=1)[:, None, None]
                                               + w[:, :, None] * np.linalg.norm(Qc, axis=1)[:, None, None])
                unbounded[d] = np.any(at_res & moves & drive, axis=(0, 2))
                x[d] = np.abs(xd)                                             # H x S
        else:
            # Batched direct solves over harmonics x speeds (damped systems: nothing unbounded).
            D = K[None, None] - (w**2)[:, :, None, None] * M + 1j * w[:, :, None, None] * C
            Q = scale[:, :, None] * (Qk[:, None, :] + 1j * w[:, :, None] * Qc[:, None, :])
            X = np.linalg.solve(D, Q[..., None])[..., 0]
            for d in out_dofs:
                x[d] = np.abs(X[:, :, d])
                unbounded[d] = np.zeros(grid.size, dtype=bool)
        for d, quantity in p["outputs"]:
            power = {"displacement": 1.0, "velocity": w, "acceleration": w**2}[quantity]
            amp = np.where(unbounded[d], 0.0, np.sum(x[d] * power, axis=0))
            curves.append((amp, unbounded[d]))
            peaks.append((np.max(amp, initial=0.0), bool(np.any(unbounded[d]))))
    return {"lam": lam, "freq": freq, "osc": osc, "critical": critical, "grid": grid, "curves": curves,
            "peaks": peaks, "deflections": deflections}


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


def main():
    args = parse_args()
    if not os.access(args.driver, os.X_OK):
        sys.exit(f"compare_study.py: error: {args.driver} is missing; build with benchmarks "
                 "(cmake --build BUILD --target study_timing) or give --driver")
    with tempfile.TemporaryDirectory() as tmp:
        study = study_copy(args.study, args.variants, tmp) if args.variants else args.study
        path = args.keep_json or os.path.join(tmp, "study.json")
        command = [args.driver, study, str(args.threads), path, str(args.numpy_variants)]
        print("$ " + " ".join(command), flush=True)
        start = time.perf_counter()
        run = subprocess.run(command, capture_output=True, text=True)
        wall = time.perf_counter() - start
        sys.stdout.write(run.stdout)
        if run.returncode not in (0, 1):
            sys.exit(f"compare_study.py: error: study_timing failed ({run.returncode}): {run.stderr.strip()}")
        ours = dict(line.split(" ", 1) for line in run.stdout.splitlines() if " " in line)
        with open(path) as f:
            data = json.load(f)
    variants = [v for v in data["variants"] if not v["failure"]]
    prepared = [prepare(v) for v in variants]

    # numpy on one core: the median of --repeats passes over the variants (wall and CPU time).
    passes = []
    for _ in range(max(1, args.repeats)):
        start, cpu = time.perf_counter(), time.process_time()
        results = [evaluate(p) for p in prepared]
        passes.append((time.perf_counter() - start, time.process_time() - cpu))
    numpy_s, numpy_cpu_s = sorted(passes)[len(passes) // 2]

    agreement = Agreement()
    for v, p, r in zip(variants, prepared, results):
        agreement.check(v, p, r)
    ok, bad = agreement.passed()

    f = {k: float(x) for k, x in ours.items() if re.fullmatch(r"[-+0-9.e]+", x)}
    n, threads, m = int(f["variants"]), int(f["threads"]), int(f["subset_variants"])
    total_s = f["load_s"] + f["evaluate_s"] + f["rank_s"]
    rate = lambda count, s: 60.0 * count / s
    rm_rate = rate(n, total_s)
    # One thread: the subset's evaluation per variant, plus the (single-threaded) load and
    # rank per variant of the full run.
    per_variant_1 = f["subset_1_thread_s"] / m + (f["load_s"] + f["rank_s"]) / n
    per_variant_1_cpu = f["subset_1_thread_cpu_s"] / m + (f["load_cpu_s"] + f["rank_s"]) / n
    np_rate, np_cpu_rate = rate(len(prepared), numpy_s), rate(len(prepared), numpy_cpu_s)
    v0 = variants[0] if variants else {"dofs": [], "speeds": [], "sources": [], "outputs": []}
    print()
    print(f"study: {n} variants ({int(f['failed'])} failed), {len(v0['dofs'])} DOFs, {len(v0['speeds'])} grid "
          f"speeds, {sum(len(s['harmonics']) for s in v0['sources'])} source harmonic(s), {len(v0['outputs'])} "
          f"outputs; study_timing wall {wall:.1f} s; load average {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores")
    print(f"railmodal, {threads} threads: load_study {f['load_s']:.2f} s (one thread), evaluate_study "
          f"{f['evaluate_s']:.2f} s (CPU {f['evaluate_cpu_s']:.2f} s), rank_variants {f['rank_s']:.2f} s")
    print("                                          variants/min   per core   per core from CPU time")
    print(f"railmodal, {threads} threads, end to end     {rm_rate:14.0f} {rm_rate / threads:10.0f}   "
          f"{rate(n, f['load_cpu_s'] + f['evaluate_cpu_s'] + f['rank_s']):10.0f}   "
          f"target 100000/min: {'MET' if rm_rate >= 1e5 else 'NOT MET'}")
    print(f"railmodal, {threads} threads, evaluate only  {rate(n, f['evaluate_s']):14.0f} "
          f"{rate(n, f['evaluate_s']) / threads:10.0f}   {rate(n, f['evaluate_cpu_s']):10.0f}")
    print(f"railmodal, 1 thread, evaluate only      {rate(m, f['subset_1_thread_s']):14.0f} "
          f"{rate(m, f['subset_1_thread_s']):10.0f}   {rate(m, f['subset_1_thread_cpu_s']):10.0f}   "
          f"(first {m} variants; includes assembly)")
    print(f"railmodal, 1 thread, end to end (est.)  {60.0 / per_variant_1:14.0f} {60.0 / per_variant_1:10.0f}   "
          f"{60.0 / per_variant_1_cpu:10.0f}   (that, plus load and rank per variant)")
    print(f"numpy/scipy, 1 core                     {np_rate:14.0f} {np_rate:10.0f}   {np_cpu_rate:10.0f}   "
          f"({len(prepared)} variants, median of {len(passes)}; matrices given: no parsing, no assembly)")
    print(f"ratio railmodal/numpy per core: 1 thread evaluate only {rate(m, f['subset_1_thread_s']) / np_rate:.1f}x, "
          f"1 thread end to end {60.0 / per_variant_1 / np_rate:.1f}x, {threads} threads end to end "
          f"{rm_rate / threads / np_rate:.1f}x")
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
