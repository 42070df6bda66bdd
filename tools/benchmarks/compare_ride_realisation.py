#!/usr/bin/python3
"""Ride in the time domain in railmodal against numpy/scipy, side by side in one run.

Issue 21, item 9: "a realisation of 2²⁰ samples plus simulation and weighting at least 5×
faster". The case (tools/benchmarks/ride_realisation_timing.cpp): ORE B176 low-level vertical
track, wavelengths 1 … 100 m, 2²⁰ samples every 0.05 m (52.4 km); the vertical Manchester
benchmark coach (6 DOFs, 8 axlebox springs on 4 axles) over it at 180 km/h, one 1 ms step a
track sample (2²⁰ steps, 17.5 minutes of running), from the periodic steady state; the vertical
floor acceleration over each bogie centre and at mid-car, weighted by EN 12299 Wb and by
Sperling's B, the RMS of each 5 s window, their 95th percentile and the running RMS Cc(t).

The baseline, written as a competent numpy/scipy user would, and why it is the strongest fair
one:
  * Synthesis: one scipy.fft.irfft of complex Gaussian coefficients (variance S(Ω_k)ΔΩ each
    part, the same law railmodal draws from), numpy's PCG64 generator: no loop.
  * Simulation: the exact discretisation of each mode, run by scipy.signal.lfilter (a C loop),
    not scipy.signal.lsim (whose time loop is Python: about 100× slower for 2²⁰ steps) nor an
    ODE solver (approximate, and slower). The first-order system without ẇ
    (q̇ = v + M⁻¹Bv w, v̇ = −M⁻¹Kq − M⁻¹Cv + M⁻¹(Bd − CM⁻¹Bv)w) is diagonalised once; each
    mode ζ̇ = λζ + βw is stepped exactly for the linearly interpolated track, whose kinks fall
    inside a step at a phase δ of each axle (first-order holds chained over [0, δ] and [δ, h]):
    per axle a three-tap stencil on the track samples, all axles' stencils for all modes in ONE
    matrix product (modes × 12 shifted copies of the track), one complex lfilter a mode (one of
    each conjugate pair), started on its periodic orbit exactly (ζ₀ = ζ_N/(1 − λ_d^N) from a
    first pass's final state: lfilter's zi). This is the same mathematics as railmodal's march,
    so the two agree to round-off on the same track, and it does O(modes) work a step instead of
    railmodal's dense state transition.
  * Weighting: the analog Wb and Sperling B, scipy.signal.bilinear_zpk at the sampling rate,
    as second-order sections (zpk2sos + sosfilt: the 8th-order Wb as one transfer-function
    polynomial, bilinear + lfilter, loses digits at 1 kHz with poles at 0.4 Hz), run over a
    period's tail and then the period (the periodic steady state, as railmodal does). Windows,
    percentile (numpy's linear, Hyndman–Fan 7, as railmodal) and Cc(t) by cumulative sums.
The ORE spectrum and the weightings are written here from their published definitions
(docs/ride.md), not read from railmodal. Plain bilinear without prewarping differs from
railmodal's per-section prewarped filters by about (f/f_s)²: the weighted figures agree to a
few 1e-3, the unweighted ones to round-off.

Agreement: the simulation runs on railmodal's own realisation (written by ride_realisation_timing
as OUT_DIR/track.f64), so the histories are compared sample by sample; the script's own
realisation (same spectrum, its own random numbers) is compared statistically: its RMS against
the spectrum's.

Timing (medians; wall and processor time): in process, synthesise_track + simulate_ride in
ride_realisation_timing against the same three stages here, each from assembled matrices in
memory to the indices.

    cmake --build build --target ride_realisation_timing
    /usr/bin/python3 tools/benchmarks/compare_ride_realisation.py [--repeats 5] [--driver PATH]

Needs Debian's python3-numpy and python3-scipy.
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
    import scipy.fft
    import scipy.signal
except ImportError:
    sys.exit("compare_ride_realisation.py: error: numpy/scipy missing (Debian: apt-get install python3-numpy python3-scipy)")

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

# ORE B176 low level, vertical level (docs/ride.md, "ORE B176"): S(Ω) = A Ω_c²/((Ω² + Ω_r²)(Ω² + Ω_c²)),
# one-sided, m²/(rad/m); A = 4.032e-7 m·rad, Ω_c = 0.8246, Ω_r = 0.0206 rad/m.
ORE_A, ORE_OC, ORE_OR = 4.032e-7, 0.8246, 0.0206


def ore(om):
    return ORE_A * ORE_OC**2 / ((om**2 + ORE_OR**2) * (om**2 + ORE_OC**2))


def synthesise(n, dx, band, seed):
    """z(x) = Σ Re(c_k e^{iΩ_k x}), c_k complex Gaussian, variance S(Ω_k)ΔΩ each part."""
    dom = 2 * np.pi / (n * dx)
    om = dom * np.arange(n // 2 + 1)
    inside = (om >= band[0]) & (om <= band[1])
    inside[0] = inside[-1] = False
    sd = np.sqrt(np.where(inside, ore(om) * dom, 0.0))
    rng = np.random.default_rng(seed)
    c = sd * (rng.standard_normal(om.size) + 1j * rng.standard_normal(om.size))
    return scipy.fft.irfft(c / 2, n=n, norm="forward"), np.sum(np.where(inside, ore(om) * dom, 0.0))


def w(f):
    return 2 * np.pi * f


def wb_zpk():
    """EN 12299 Wb (ISO 2631-1 Annex A): high pass 0.4 Hz and low pass 100 Hz (Q 1/√2), a–v
    transition f3 = f4 = 16 Hz, Q4 = 0.63, upward step f5 = 2.5 Hz, Q5 = 0.8, f6 = 4 Hz,
    Q6 = 0.8, gain 0.4: the product of the four factors as zeros, poles and gain."""
    z, p, k = [], [], 1.0

    def add(num, den):
        nonlocal k
        z.extend(np.roots(num)), p.extend(np.roots(den))
        k *= num[0] / den[0]

    q1 = 1 / np.sqrt(2)
    add([1.0, 0.0, 0.0], [1.0, w(0.4) / q1, w(0.4)**2])
    add([w(100)**2], [1.0, w(100) / q1, w(100)**2])
    add([1 / w(16), 1.0], [1 / w(16)**2, 1 / (0.63 * w(16)), 1.0])
    add([0.4 / w(2.5)**2, 0.4 / (0.8 * w(2.5)), 0.4], [1 / w(4)**2, 1 / (0.8 * w(4)), 1.0])
    return np.array(z), np.array(p), k


def sperling_zpk():
    """Sperling's B, vertical: 0.588 (√1.911 p + 0.25 p²)/(1 + 1.563 p + 0.277 p² + 0.0368 p³),
    p = s/2π (docs/ride.md, "Digital weightings")."""
    c = 1 / (2 * np.pi)
    num = [0.25 * c**2, np.sqrt(1.911) * c, 0.0]
    den = [0.0368 * c**3, 0.277 * c**2, 1.563 * c, 1.0]
    return np.roots(num), np.roots(den), 0.588 * num[0] / den[0]


def digital_sos(zpk, fs):
    return scipy.signal.zpk2sos(*scipy.signal.bilinear_zpk(*zpk, fs))


class Model:
    """M, C, K; the axle load vectors (the two axleboxes of an axle summed); the output rows."""

    def __init__(self, j):
        self.M, self.C, self.K = (np.array(j[k]) for k in ("mass", "damping", "stiffness"))
        n = self.M.shape[0]
        xs = sorted({round(i["x"], 9) for i in j["inputs"]}, reverse=True)
        self.lags = xs[0] - np.array(xs)
        self.Bd, self.Bv = np.zeros((n, len(xs))), np.zeros((n, len(xs)))
        for i in j["inputs"]:
            a = xs.index(round(i["x"], 9))
            self.Bd[:, a] += i["load_per_displacement"]
            self.Bv[:, a] += i["load_per_velocity"]
        self.P = np.zeros((len(j["outputs"]), n))  # vertical displacement of a body point
        for o, out in enumerate(j["outputs"]):
            ref = j["reference_points"][out["body"]]
            for d, dof in enumerate(j["dofs"]):
                if dof["body"] == out["body"]:
                    motion = dof["label"].split(".")[-1]
                    self.P[o, d] = {"bounce": 1.0, "pitch": -(out["point"][0] - ref[0]),
                                    "roll": out["point"][1] - ref[1]}.get(motion, 0.0)


def g0(lam, T):
    """∫_0^T e^{λ(T−τ)} dτ."""
    return (np.exp(lam * T) - 1) / lam


def g1(lam, T):
    """∫_0^T e^{λ(T−τ)} τ/T dτ (0 at T = 0)."""
    if T <= 0:
        return np.zeros_like(lam)
    return (np.exp(lam * T) - 1 - lam * T) / (lam**2 * T)


def simulate(m, z, dx, V):
    """The floor accelerations over one period of the periodic track z, exact for the linearly
    interpolated track, one step h = dx/V a sample, the leading axle at `span` at t = 0."""
    n = m.M.shape[0]
    N = z.size
    h = dx / V
    Mi = np.linalg.inv(m.M)
    A = np.block([[np.zeros((n, n)), np.eye(n)], [-Mi @ m.K, -Mi @ m.C]])
    B = np.vstack([Mi @ m.Bv, Mi @ (m.Bd - m.C @ Mi @ m.Bv)])
    lam_all, V_all = np.linalg.eig(A)
    sel = lam_all.imag >= 0  # one of each conjugate pair (its twin adds the conjugate), and the real modes
    lam, Vec = lam_all[sel], V_all[:, sel]
    weight = np.where(lam.imag > 0, 2.0, 1.0)
    beta = np.linalg.solve(V_all, B)[sel]  # modes × axles
    span = m.lags.max()
    # Per axle: its position at step k is span − lag + k·dx = (n0 + φ + k)·dx; it passes a
    # sample δ = (1 − φ)h into each step. Stencil on z[k + n0], z[k + n0 + 1], z[k + n0 + 2].
    shifted, coef = [], []
    w_rows, dw_rows = [], []
    for a, lag in enumerate(m.lags):
        s = (span - lag) / dx
        n0 = int(np.floor(s + 1e-9))
        phi = s - n0
        if phi < 1e-9:
            phi = 0.0
        d = (1 - phi) * h
        e = np.exp(lam * (h - d))
        Pc = e * (g0(lam, d) - g1(lam, d))
        Qc = e * g1(lam, d) + g0(lam, h - d) - g1(lam, h - d)
        Rc = g1(lam, h - d)
        for t, c in enumerate((Pc * (1 - phi), Pc * phi + Qc + Rc * (1 - phi), Rc * phi)):
            shifted.append(np.roll(z, -(n0 + t)))
            coef.append(beta[:, a] * c)
        # the track and its rate under the axle at each step (on a sample: the mean slope)
        z0, z1 = shifted[-3], shifted[-2]
        w_rows.append((1 - phi) * z0 + phi * z1)
        dw_rows.append(V * ((z1 - z0) / dx if phi > 0 else (z1 - np.roll(z, -(n0 - 1))) / (2 * dx)))
    # modes × N, the complex coefficients on the real samples as two real products
    C, S = np.array(coef).T, np.array(shifted)
    forcing = C.real @ S + 1j * (C.imag @ S)
    a_d = np.exp(lam * h)
    zeta = np.empty_like(forcing)
    for j in range(lam.size):
        b, a = [0.0, 1.0], [1.0, -a_d[j]]
        _, zf = scipy.signal.lfilter(b, a, forcing[j], zi=[0.0])
        zeta[j], _ = scipy.signal.lfilter(b, a, forcing[j], zi=zf / (1 - a_d[j]**N))
    # y = P M⁻¹(−K q − C q̇ + Bd w + Bv ẇ), q̇ = v + M⁻¹Bv w
    Ls = m.P @ Mi @ np.hstack([-m.K, -m.C])
    Lw = m.P @ Mi @ (m.Bd - m.C @ Mi @ m.Bv)
    Ld = m.P @ Mi @ m.Bv
    return (((Ls @ Vec) * weight) @ zeta).real + Lw @ np.array(w_rows) + Ld @ np.array(dw_rows)


def indices(y, fs, sos_wb, sos_b, window=5.0, tail=60.0):
    """Wb- and B-weighted histories in their periodic steady state (run over a tail of the
    period first), 5 s window RMS, P95, Cc(t), Wz."""
    k = int(round(tail * fs))
    ext = np.concatenate([y[:, -k:], y], axis=1)
    aw = scipy.signal.sosfilt(sos_wb, ext, axis=1)[:, k:]
    ab = scipy.signal.sosfilt(sos_b, ext, axis=1)[:, k:]
    L = int(round(window * fs))
    nw = aw.shape[1] // L
    win = np.sqrt(np.mean(aw[:, :nw * L].reshape(aw.shape[0], nw, L)**2, axis=2))
    c = np.cumsum(aw**2, axis=1)
    cc = np.sqrt(np.concatenate([c[:, :L] / np.arange(1, L + 1), (c[:, L:] - c[:, :-L]) / L], axis=1))
    zone = min(nw, 60)  # P95 per zone of 60 windows, the largest
    p95 = np.max([np.percentile(win[:, s:s + zone], 95, axis=1) for s in range(0, nw - zone + 1, zone)], axis=0)
    wz = (100 * np.sqrt(2) * np.sqrt(np.mean(ab**2, axis=1)))**0.3
    return {"rms": np.sqrt(np.mean(y**2, axis=1)), "weighted_rms": np.sqrt(np.mean(aw**2, axis=1)),
            "p95": p95, "sperling_wz": wz, "cc_last": cc[:, -1]}


def run_driver(driver, out, repeats):
    r = subprocess.run([driver, out, str(repeats)], capture_output=True, text=True, check=True)
    sys.stderr.write(r.stderr)
    return {k: float(v) for k, v in (line.split() for line in r.stdout.split("\n") if line)}


def timed(fn, repeats):
    wall, cpu, result = [], [], None
    for _ in range(repeats):
        t0, c0 = time.perf_counter(), time.process_time()
        result = fn()
        wall.append(time.perf_counter() - t0)
        cpu.append(time.process_time() - c0)
    return float(np.median(wall)), float(np.median(cpu)), result


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--repeats", type=int, default=5)
    ap.add_argument("--driver", default=os.path.join(ROOT, "build", "tools", "benchmarks", "ride_realisation_timing"))
    args = ap.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        cpp = run_driver(args.driver, tmp, args.repeats)
        j = json.load(open(os.path.join(tmp, "model.json")))
        track = np.fromfile(os.path.join(tmp, "track.f64"), dtype="<f8")
    m = Model(j)
    N, dx, V, band = j["samples"], j["step"], j["speed"], j["band"]
    fs = 1.0 / j["time_step"]
    sos_wb, sos_b = digital_sos(wb_zpk(), fs), digital_sos(sperling_zpk(), fs)

    ts = timed(lambda: synthesise(N, dx, band, 2021), args.repeats)
    tm = timed(lambda: simulate(m, track, dx, V), args.repeats)
    y = tm[2]
    ti = timed(lambda: indices(y, fs, sos_wb, sos_b), args.repeats)
    idx = ti[2]

    own, variance = ts[2]
    print(f"case: {m.M.shape[0]} DOFs, {m.lags.size} axles, {N} samples every {dx} m, {V * 3.6:.0f} km/h, "
          f"{N} steps of {1e3 / fs:.3f} ms, {y.shape[0]} outputs")
    print("\nagreement on railmodal's track (script / railmodal − 1):")
    first = np.array(j["first_values"])
    print(f"  first 2000 samples of each history, largest |Δ| over max|y|: "
          f"{np.max(np.abs(y[:, :2000] - first)) / np.max(np.abs(first)):.1e}")
    for key in ("rms", "weighted_rms", "p95", "sperling_wz"):
        ratio = idx[key] / np.array(j[key]) - 1
        print(f"  {key:13s} " + "  ".join(f"{r:+.1e}" for r in ratio))
    print(f"the script's own realisation: RMS {np.std(own):.4e} m against the spectrum's {np.sqrt(variance):.4e} m "
          f"(railmodal's track: {np.sqrt(np.mean(track**2)):.4e} m)")
    print("\n| | wall (ms) | CPU (ms) |\n|---|---|---|")
    rows = [("railmodal `synthesise_track`", cpp["realisation_s"], cpp["realisation_cpu_s"]),
            ("railmodal `simulate_ride` (march, weightings, windows, P95, Cc, N_MV)", cpp["simulation_s"],
             cpp["simulation_cpu_s"]),
            ("railmodal, both", cpp["realisation_s"] + cpp["simulation_s"],
             cpp["realisation_cpu_s"] + cpp["simulation_cpu_s"]),
            ("numpy/scipy synthesis (`scipy.fft.irfft`)", ts[0], ts[1]),
            ("numpy/scipy simulation (modal, `lfilter`)", tm[0], tm[1]),
            ("numpy/scipy weighting and indices (`sosfilt`)", ti[0], ti[1]),
            ("numpy/scipy, all three", ts[0] + tm[0] + ti[0], ts[1] + tm[1] + ti[1])]
    for name, wall, cpu in rows:
        print(f"| {name} | {1e3 * wall:.0f} | {1e3 * cpu:.0f} |")
    ours = cpp["realisation_cpu_s"] + cpp["simulation_cpu_s"]
    theirs = ts[1] + tm[1] + ti[1]
    print(f"\nrailmodal / numpy-scipy, CPU: {ours / theirs:.2f} (railmodal is {theirs / ours:.2f}x as fast; target 5x)")


if __name__ == "__main__":
    main()
