#!/usr/bin/python3
"""Vertical ride on random track in railmodal against numpy, side by side in one run.

The Manchester benchmark coach (data/vehicles/manchester_benchmark_coach.toml, vertical motions:
6 DOFs, 8 axlebox springs on the track) on ORE B176 low-level track (vertical level,
wavelengths 3 … 100 m) at 20 speeds (10, 20, …, 200 km/h) over about 10⁴ frequencies
(0.1 … 80 Hz): the RMS and the EN 12299 Wb-weighted RMS of the vertical floor acceleration over
each bogie centre and at mid-car. build/tools/benchmarks/ride_timing times railmodal's
solve_ride and writes M, C, K, the track inputs, the output points, its grid and its figures;
this script redoes the ride with numpy alone and compares.

What railmodal is compared with, and why it is the strongest fair baseline: the whole
computation is vectorised, no Python loop over frequencies or speeds.
  * The receptances are solved ONCE for all speeds: on this vehicle H(f) does not depend on
    speed (no creep terms), only the wheels' delays x_i/V do. One np.linalg.solve over the
    stack of all 10⁴ dynamic stiffness matrices (a batched LAPACK gesv gufunc) with the 4 axle
    load vectors as right-hand sides (the two axleboxes of an axle see the same vertical level
    and are summed first: 4 columns, not 8).
  * The 20 speeds' delays are applied by broadcasting one (frequencies × axles × speeds) array
    of phase factors, built from np.cos and np.sin (numpy's complex exp is not vectorised:
    4x slower measured), by one batched matrix product; |H|² is taken in real arithmetic
    (re² + im²), and the band-limited trapezoid rule is one einsum per index over all speeds
    and outputs at once.
  * A second, faster variant replaces the 10⁴ solves by one eigen-decomposition of the
    first-order system (D(ω)⁻¹ = V (iω − Λ)⁻¹ W, O(n) per frequency instead of O(n³)): exact for
    this diagonalisable system, and what a user who knows modal methods would write. Both are
    timed and the faster is the one railmodal is held against.
The same work on both sides, two ways (both reported). railmodal's full solve_ride also gives
each output's modal shares with their cross term, Sperling's Wz, the P95 estimate (its ∫S²),
N_MV and the grid error estimate (a second integral on every other point); an RMS-only script
held against that would time unequal work. So:
  * every index: ride_full() computes all of them too, vectorised as a competent user would
    (the undamped modes by numpy's eigh through the Cholesky factor of M, the modal coordinates ΦᵀM·X of the DOF
    receptances from the same eigen-decomposition, one einsum per index over all speeds, the
    P95 by scipy.special.chdtri), against railmodal's default solve;
  * the RMS and weighted RMS only: ride() (both receptance variants) against solve_ride with
    RideOptions::rms_only, which skips the rest (and its grid error estimate) in railmodal.
Neither baseline is weakened: each is the fastest vectorised numpy we found for its outputs.
Details of the two sides: the same grid (railmodal's, read from its JSON: the log base with the
band edges of every speed inserted), the same band and the same integration rule (trapezoid
over the intervals inside each speed's band), so the figures agree to round-off; the EN 12299
Wb weighting and the ORE B176 spectrum are written here again from their published definitions
(EN 12299:2009 / ISO 2631-1 Annex A; ORE B176 via the constants cited in docs/ride.md), not read
from railmodal.

Timing, two ways (medians; wall and processor time: on a shared, loaded machine the processor
time is the fair figure):
  * in process: solve_ride inside ride_timing against the numpy computation inside this
    script, each from assembled matrices in memory to the indices; railmodal's ratios are
    those of its solves in a kept workspace (as a study's worker keeps one), and the public
    solve_ride, which allocates its arrays at every call, is printed beside them;
  * whole processes: `ride_timing --once` (read the vehicle file, assemble, solve, print)
    against `python3 compare_ride.py --baseline MODEL.json` (start Python, import numpy, read
    the model, solve, print), each started by subprocess and timed from outside.

--table prints the reference table the validation test ride_validation_test.cpp pins (100, 150,
200 km/h), computed on this script's own fine grid (2·10⁵ log-spaced points over each speed's
band ∩ 0.1 … 80 Hz, Simpson's rule), independent of railmodal's grid. --quarter-car prints the
test's quarter-car on ORE level by adaptive quadrature, the check of its exact (Lyapunov)
solution. Neither runs railmodal's solver.

    /usr/bin/python3 tools/benchmarks/compare_ride.py [--repeats 11] [--driver PATH]
    /usr/bin/python3 tools/benchmarks/compare_ride.py --table [--driver PATH]
    /usr/bin/python3 tools/benchmarks/compare_ride.py --quarter-car

Needs Debian's python3-numpy (and python3-scipy for Simpson's rule in --table) and a build with
benchmarks (the target ride_timing).
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
except ImportError:
    sys.exit("compare_ride.py: error: numpy missing (Debian: apt-get install python3-numpy python3-scipy)")

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

# ORE B176 (ERRI B176) low level, vertical level: S(Ω) = A Ω_c² / ((Ω² + Ω_r²)(Ω² + Ω_c²)),
# one-sided, m²/(rad/m). A_v = 4.032e-7 m·rad, Ω_c = 0.8246, Ω_r = 0.0206 rad/m, as printed in
# the ERRI B176 parameter sets reproduced by several independent codes (docs/ride.md, "ORE
# B176"; /work/shared/reference/ride-comfort-and-track-sources.md §4.1 lists them).
ORE_A, ORE_OC, ORE_OR = 4.032e-7, 0.8246, 0.0206
BAND = (2 * np.pi / 100.0, 2 * np.pi / 3.0)  # rad/m: wavelengths 100 … 3 m


def ore_temporal(f, V):
    """G(f) = (2π/V) S(2πf/V), m²/Hz, zero outside the band; f (…, F), V broadcastable."""
    om = 2 * np.pi * f / V
    s = ORE_A * ORE_OC**2 / ((om**2 + ORE_OR**2) * (om**2 + ORE_OC**2))
    return np.where((om >= BAND[0]) & (om <= BAND[1]), 2 * np.pi / V * s, 0.0)


def wb_squared(f):
    """|Wb(j2πf)|² of EN 12299:2009 (ISO 2631-1:1997 Annex A structure): band limits 0.4 and
    100 Hz (Q = 1/√2), a–v transition f3 = f4 = 16 Hz, Q4 = 0.63, upward step f5 = 2.5 Hz,
    Q5 = 0.8, f6 = 4 Hz, Q6 = 0.8, K = 0.4."""
    s = 2j * np.pi * f
    w = lambda fc: 2 * np.pi * fc
    q1 = 1 / np.sqrt(2)
    hh = s**2 / (s**2 + s * w(0.4) / q1 + w(0.4)**2)
    hl = w(100)**2 / (s**2 + s * w(100) / q1 + w(100)**2)
    ht = (1 + s / w(16)) / (1 + s / (0.63 * w(16)) + (s / w(16))**2)
    hs = 0.4 * (1 + s / (0.8 * w(2.5)) + (s / w(2.5))**2) / (1 + s / (0.8 * w(4)) + (s / w(4))**2)
    return np.abs(hh * hl * ht * hs)**2


class Model:
    """M, C, K; the axle load vectors (the axleboxes at one x summed); the output rows."""

    def __init__(self, j):
        self.M, self.C, self.K = (np.array(j[k]) for k in ("mass", "damping", "stiffness"))
        n = self.M.shape[0]
        xs = sorted({round(i["x"], 9) for i in j["inputs"]}, reverse=True)
        self.x = np.array(xs)
        self.Bd = np.zeros((n, len(xs)))
        self.Bv = np.zeros((n, len(xs)))
        for i in j["inputs"]:
            a = xs.index(round(i["x"], 9))
            self.Bd[:, a] += i["load_per_displacement"]
            self.Bv[:, a] += i["load_per_velocity"]
        # Vertical displacement of a body point: bounce − (x_p − x_ref)·pitch (+ (y_p − y_ref)·roll);
        # a right-handed pitch about y (y to the left, z up) lowers a point ahead of the reference.
        self.P = np.zeros((len(j["outputs"]), n))
        for o, out in enumerate(j["outputs"]):
            ref = j["reference_points"][out["body"]]
            for d, dof in enumerate(j["dofs"]):
                if dof["body"] != out["body"]:
                    continue
                motion = dof["label"].split(".")[-1]
                self.P[o, d] = {"bounce": 1.0, "pitch": -(out["point"][0] - ref[0]),
                                "roll": out["point"][1] - ref[1]}.get(motion, 0.0)
        self.names = [o["name"] for o in j["outputs"]]


def receptance_solve(m, f):
    """Acceleration receptance of every output to every axle, (F, outputs, axles): one batched
    complex solve of the dynamic stiffness over all frequencies."""
    w = 2 * np.pi * f
    D = m.K[None] - (w**2)[:, None, None] * m.M[None] + 1j * w[:, None, None] * m.C[None]
    R = m.Bd[None] + 1j * w[:, None, None] * m.Bv[None]
    X = np.linalg.solve(D, R)
    return -(w**2)[:, None, None] * (m.P[None] @ X)


def receptance_modal(m, f):
    """The same receptance from one eigen-decomposition of the first-order system
    [[0, I], [−M⁻¹K, −M⁻¹C]]: D(ω)⁻¹ = [V (iω − Λ)⁻¹ V⁻¹]_(upper right) M⁻¹."""
    n = m.M.shape[0]
    Minv = np.linalg.inv(m.M)
    A = np.block([[np.zeros((n, n)), np.eye(n)], [-Minv @ m.K, -Minv @ m.C]])
    lam, V = np.linalg.eig(A)
    W = np.linalg.inv(V)
    left = m.P @ V[:n]                       # (outputs, 2n)
    rd = W[:, n:] @ Minv @ m.Bd              # (2n, axles)
    rv = W[:, n:] @ Minv @ m.Bv
    w = 2 * np.pi * f
    # X[f,o,a] = Σ_k left[o,k] g[f,k] (rd[k,a] + iω rv[k,a]): two matrix products.
    Lg = left[None] * (1.0 / (1j * w[:, None] - lam[None]))[:, None, :]  # (F, outputs, 2n)
    X = Lg @ rd + (1j * w)[:, None, None] * (Lg @ rv)
    return -(w**2)[:, None, None] * X


def band_weights(f, V):
    """Trapezoid weights per speed over the intervals whose midpoint lies in the band:
    (speeds, F). railmodal inserts every speed's band edges into its grid, so this is exact
    at the jumps of the spectrum."""
    lo, hi = V * BAND[0] / (2 * np.pi), V * BAND[1] / (2 * np.pi)
    mid = 0.5 * (f[1:] + f[:-1])
    h = np.diff(f)[None] * ((mid[None] >= lo[:, None]) & (mid[None] <= hi[:, None]))
    wts = np.zeros((V.size, f.size))
    wts[:, :-1] += 0.5 * h
    wts[:, 1:] += 0.5 * h
    return wts


def ride(m, f, V, receptance):
    """RMS and Wb-weighted RMS, (speeds, outputs) each."""
    A = receptance(m, f)                                                   # (F, outputs, axles)
    # e^{iωx_a/V}: the axle at x_a (forward of the origin) meets a point of the track x_a/V
    # earlier. cos and sin are vectorised where numpy's complex exp is not (measured: 4x).
    th = ((2 * np.pi * f)[:, None, None] * m.x[None, :, None]) / V[None, None, :]  # (F, axles, speeds)
    phase = np.empty(th.shape, complex)
    phase.real, phase.imag = np.cos(th), np.sin(th)
    H = A @ phase                                                          # (F, outputs, speeds)
    P = H.real**2 + H.imag**2
    GW = ore_temporal(f[:, None], V[None]) * band_weights(f, V).T          # (F, speeds)
    var = np.einsum("fos,fs->so", P, GW)
    wvar = np.einsum("fos,fs->so", P, GW * wb_squared(f)[:, None])
    return np.sqrt(var), np.sqrt(wvar)


def sperling_squared(f):
    """|B(f)|², Sperling's vertical weighting (Sperling 1941, as EN 12299:2009 Annex D and
    docs/ride.md give it): B² = 0.588² (1.911 f² + (0.25 f²)²) / ((1 − 0.277 f²)² + (1.563 f − 0.0368 f³)²)."""
    f2 = f * f
    return 0.588**2 * (1.911 * f2 + (0.25 * f2)**2) / ((1 - 0.277 * f2)**2 + (1.563 * f - 0.0368 * f2 * f)**2)


def coarse_weights(f, wts):
    """The trapezoid weights of the interpolant through every other grid point (the first, the
    third, …, and the last) over the same band: each odd point's weight goes to its neighbours
    in proportion to the distance (the halved grid of the grid error estimate), (speeds, F)."""
    c = wts.copy()
    k = np.arange(1, f.size - 1, 2)
    alpha = (f[k + 1] - f[k]) / (f[k + 1] - f[k - 1])
    c[:, k - 1] += alpha * wts[:, k]
    c[:, k + 1] += (1 - alpha) * wts[:, k]
    c[:, k] = 0.0
    return c


def ride_full(m, f, V, window=5.0):
    """Everything railmodal's full solve_ride gives for these outputs, vectorised: the RMS, the
    Wb-weighted RMS, Sperling's Wz, the P95 estimate of the 5-s weighted RMS (chi-square with
    ν = 2T(∫S)²/∫S², ∫S² by the trapezoid of the square over the band's intervals), N_MV
    (each output is a floor point with its vertical axis only: 6·P95), each undamped mode's
    share ∫|(a·φ_j)(φ_jᵀM X)|²G df and the grid error estimate (the RMS with every other grid
    point). The DOF receptances X from one eigen-decomposition, as receptance_modal. Only
    scipy.special is imported (for the χ² quantile): scipy.stats and scipy.linalg would cost a
    whole process a few hundred milliseconds of import."""
    from scipy.special import chdtri
    n = m.M.shape[0]
    Minv = np.linalg.inv(m.M)
    A = np.block([[np.zeros((n, n)), np.eye(n)], [-Minv @ m.K, -Minv @ m.C]])
    lam, Vec = np.linalg.eig(A)
    W = np.linalg.inv(Vec)
    rd = W[:, n:] @ Minv @ m.Bd
    rv = W[:, n:] @ Minv @ m.Bv
    w = 2 * np.pi * f
    iw = 1j * w
    g = 1.0 / (iw[:, None] - lam[None])                                   # (F, 2n)
    X = (Vec[:n][None] * g[:, None, :]) @ (rd[None] + iw[:, None, None] * rv[None])  # (F, n, axles)
    acc = -(w**2)[:, None, None]
    Aout = acc * (m.P[None] @ X)                                          # (F, outputs, axles)
    # The undamped modes, mass-normalised, lowest first: K φ = ω² M φ through M = LLᵀ.
    L = np.linalg.cholesky(m.M)
    Linv = np.linalg.inv(L)
    _, Y = np.linalg.eigh(Linv @ m.K @ Linv.T)
    Phi = Linv.T @ Y
    Q = (Phi.T @ m.M)[None] @ X                                           # (F, modes, axles)
    seen = (w**4)[:, None, None] * (m.P @ Phi)[None]**2                   # |a·φ_j|², (F, outputs, modes)
    th = ((2 * np.pi * f)[:, None, None] * m.x[None, :, None]) / V[None, None, :]
    phase = np.empty(th.shape, complex)
    phase.real, phase.imag = np.cos(th), np.sin(th)
    # The outputs and the modal coordinates in one batched product (one call per frequency).
    HQ = np.concatenate([Aout, Q], axis=1) @ phase                        # (F, outputs + modes, speeds)
    PQ = HQ.real**2 + HQ.imag**2
    P, Pq = PQ[:, :Aout.shape[1]], PQ[:, Aout.shape[1]:]
    # G at the wavenumber clamped to the band (an edge point takes the edge value whatever the
    # round-off of 2πf/V), weighed by the band's weights.
    om = np.clip(2 * np.pi * f[:, None] / V[None], *BAND)
    G = 2 * np.pi / V[None] * ORE_A * ORE_OC**2 / ((om**2 + ORE_OR**2) * (om**2 + ORE_OC**2))  # (F, speeds)
    wts = band_weights(f, V)                                              # (speeds, F)
    GW, wb2 = G * wts.T, wb_squared(f)
    var = np.einsum("fos,fs->so", P, GW)
    wvar = np.einsum("fos,fs->so", P, GW * wb2[:, None])
    svar = np.einsum("fos,fs->so", P, GW * sperling_squared(f)[:, None])
    coarse = np.einsum("fos,fs->so", P, G * coarse_weights(f, wts).T)
    modal = np.einsum("foj,fjs,fs->soj", seen, Pq, GW)                    # (speeds, outputs, modes)
    S = P * (G * wb2[:, None])[:, None, :]                                 # weighted PSD (F, outputs, speeds)
    lo, hi = V * BAND[0] / (2 * np.pi), V * BAND[1] / (2 * np.pi)
    mid = 0.5 * (f[1:] + f[:-1])
    inside = ((mid[:, None] >= lo[None]) & (mid[:, None] <= hi[None]))[:, None, :]  # (F-1, 1, speeds)
    sq = np.einsum("f,fos->so", 0.5 * np.diff(f), np.where(inside, S[:-1]**2 + S[1:]**2, 0.0))
    nu = 2 * window * wvar**2 / sq
    p95 = np.sqrt(wvar * chdtri(nu, 0.05) / nu)                           # χ²_{ν,0.95}
    rms, wrms = np.sqrt(var), np.sqrt(wvar)
    return {"rms": rms, "weighted_rms": wrms, "sperling_wz": (100 * np.sqrt(2) * np.sqrt(svar))**0.3,
            "p95": p95, "nmv": 6 * p95, "modal_variance": modal, "cross_term_variance": var - modal.sum(axis=2),
            "grid_error": np.max(np.abs(np.sqrt(coarse) - rms) / rms)}


def reference_table(m, speeds_kmh, points=200001):
    """RMS and weighted RMS on a fine grid of this script's own: each speed's band ∩ 0.1 … 80 Hz,
    log-spaced, Simpson's rule (the integrand is smooth inside the band)."""
    from scipy.integrate import simpson
    rows = []
    for kmh in speeds_kmh:
        V = kmh / 3.6
        lo = max(0.1, V * BAND[0] / (2 * np.pi))
        hi = min(80.0, V * BAND[1] / (2 * np.pi))
        f = np.geomspace(lo, hi, points)
        A = receptance_solve(m, f)
        H = np.einsum("foa,fa->fo", A, np.exp(1j * (2 * np.pi * f)[:, None] * m.x[None] / V))
        S = (H.real**2 + H.imag**2) * ore_temporal(f, V)[:, None]
        rows.append((kmh, np.sqrt(simpson(S, x=f, axis=0)), np.sqrt(simpson(S * wb_squared(f)[:, None], x=f, axis=0))))
    return rows


def quarter_car_quadrature():
    """The quarter-car of ride_validation_test.cpp on ORE B176 low level (band 0 … ∞), RMS of the
    sprung acceleration, its Wb-weighted RMS and the suspension deflection, by adaptive
    quadrature of |H|²G (scipy.integrate.quad, pieces split at the resonances): the check of the
    test's exact stationary-covariance solution."""
    from scipy.integrate import quad
    m1, m2, k1, k2, c2 = 1307.5, 8000.0, 2.44e6, 4.3e5, 2.0e4

    def responses(f):
        s = 2j * np.pi * f
        D = m1 * m2 * s**4 + c2 * (m1 + m2) * s**3 + (k1 * m2 + k2 * m1 + k2 * m2) * s**2 + c2 * k1 * s + k1 * k2
        z2, z1 = k1 * (c2 * s + k2) / D, k1 * (m2 * s**2 + c2 * s + k2) / D
        return s * s * z2, z2 - z1

    pieces = [0.0, 0.01, 0.1, 0.5, 1, 2, 5, 7.5, 10, 20, 100, np.inf]
    integral = lambda g: sum(quad(g, a, b, limit=500, epsabs=0, epsrel=1e-11)[0] for a, b in zip(pieces, pieces[1:]))
    for kmh in (100.0, 200.0):
        V = kmh / 3.6
        G = lambda f: ORE_A * ORE_OC**2 * 2 * np.pi / V / (((2 * np.pi * f / V)**2 + ORE_OR**2) * ((2 * np.pi * f / V)**2 + ORE_OC**2))
        a = np.sqrt(integral(lambda f: abs(responses(f)[0])**2 * G(f)))
        w = np.sqrt(integral(lambda f: abs(responses(f)[0])**2 * G(f) * wb_squared(f)))
        d = np.sqrt(integral(lambda f: abs(responses(f)[1])**2 * G(f)))
        print(f"  {kmh:5.0f} km/h  sprung acceleration RMS {a:.10g} m/s², Wb-weighted {w:.10g} m/s², "
              f"suspension deflection {d:.10g} m")


def median_seconds(f, repeats):
    wall, cpu, result = [], [], None
    for _ in range(repeats):
        start, start_cpu = time.perf_counter(), time.process_time()
        result = f()
        wall.append(time.perf_counter() - start)
        cpu.append(time.process_time() - start_cpu)
    return (sorted(wall)[len(wall) // 2], sorted(cpu)[len(cpu) // 2]), result


def process_seconds(command, repeats):
    """Median wall time of a whole process, and its processor time (user + system of the child)."""
    wall, cpu = [], []
    for _ in range(repeats):
        before = os.times()
        start = time.perf_counter()
        subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
        wall.append(time.perf_counter() - start)
        after = os.times()
        cpu.append(after.children_user - before.children_user + after.children_system - before.children_system)
    return sorted(wall)[len(wall) // 2], sorted(cpu)[len(cpu) // 2]


def baseline(path, full):
    """The numpy side as a whole process: read the model, solve, print the table (with `full`
    what `ride_timing --once` prints: Wz, P95, N_MV and the grid error estimate too)."""
    with open(path) as fh:
        j = json.load(fh)
    m = Model(j)
    f, V = np.array(j["frequencies"]), np.array(j["speeds"])
    if not full:
        rms, wrms = ride(m, f, V, receptance_modal)
        for v, r, w in zip(V, rms, wrms):
            print(f"{v * 3.6:g}\t" + "\t".join(f"{a:.9g}\t{b:.9g}" for a, b in zip(r, w)))
        return
    r = ride_full(m, f, V)
    for s, v in enumerate(V):
        print(f"{v * 3.6:g}\t" + "\t".join(f"{r['rms'][s, o]:.9g}\t{r['weighted_rms'][s, o]:.9g}\t"
                                           f"{r['sperling_wz'][s, o]:.9g}\t{r['p95'][s, o]:.9g}\t{r['nmv'][s, o]:.9g}"
                                           for o in range(len(m.names))))
    print(f"grid error estimate {r['grid_error']:.9g}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=11)
    parser.add_argument("--driver", default=os.path.join(ROOT, "build", "tools", "benchmarks", "ride_timing"))
    parser.add_argument("--table", action="store_true", help="print only the reference table (no railmodal solve)")
    parser.add_argument("--quarter-car", action="store_true",
                        help="print only the quarter-car on ORE level by quadrature (no railmodal)")
    parser.add_argument("--baseline", metavar="MODEL.json", help=argparse.SUPPRESS)
    parser.add_argument("--baseline-full", metavar="MODEL.json", help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.baseline or args.baseline_full:
        return baseline(args.baseline or args.baseline_full, bool(args.baseline_full))
    if args.quarter_car:
        print("quarter-car (ride_validation_test.cpp) on ORE B176 low vertical level, 0 … ∞, by quadrature:")
        return quarter_car_quadrature()
    if not os.access(args.driver, os.X_OK):
        sys.exit(f"compare_ride.py: error: {args.driver} is missing; build the target ride_timing")
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "ride.json")
        if args.table:
            subprocess.run([args.driver, "--model", path], check=True)
            with open(path) as fh:
                m = Model(json.load(fh))
            print("reference: Manchester coach, ORE B176 low vertical level (3 … 100 m), 0.1 … 80 Hz, "
                  "vertical floor acceleration, m/s² (RMS, Wb-weighted RMS)")
            for kmh, r, w in reference_table(m, (100.0, 150.0, 200.0)):
                print(f"  {kmh:5.0f} km/h  " + "  ".join(f"{n.split(',')[0]}: {a:.7g} / {b:.7g}"
                                                        for n, a, b in zip(m.names, r, w)))
            return
        run = subprocess.run([args.driver, path, str(args.repeats)], check=True, capture_output=True, text=True)
        times = {k: float(v) for k, v in (line.split() for line in run.stdout.splitlines())}
        sys.stderr.write(run.stderr)
        with open(path) as fh:
            j = json.load(fh)
        m = Model(j)
        f, V = np.array(j["frequencies"]), np.array(j["speeds"])
        ours = {k: np.array(j[k]) for k in ("rms", "weighted_rms", "sperling_wz", "p95", "nmv", "modal_variance",
                                            "cross_term_variance", "rms_only_rms", "rms_only_weighted_rms")}
        ours_rms, ours_w = ours["rms_only_rms"], ours["rms_only_weighted_rms"]
        full_t, full = median_seconds(lambda: ride_full(m, f, V), args.repeats)
        solve_t, (rms_s, w_s) = median_seconds(lambda: ride(m, f, V, receptance_solve), args.repeats)
        modal_t, (rms_m, w_m) = median_seconds(lambda: ride(m, f, V, receptance_modal), args.repeats)
        proc_ours = process_seconds([args.driver, "--once"], args.repeats)
        proc_numpy = process_seconds([sys.executable, os.path.abspath(__file__), "--baseline-full", path], args.repeats)
        proc_ours_rms = process_seconds([args.driver, "--once", "--rms-only"], args.repeats)
        proc_numpy_rms = process_seconds([sys.executable, os.path.abspath(__file__), "--baseline", path], args.repeats)

    dev = lambda a, b: np.max(np.abs(a / b - 1))
    print(f"vertical ride, Manchester coach on ORE B176 low: {V.size} speeds × {f.size} frequencies, "
          f"{m.M.shape[0]} DOFs, {m.x.size} axles, {len(m.names)} outputs")
    # Each mode's share against the output's variance (a small share's relative error is the
    # variance's round-off over the share).
    var = ours["rms"]**2
    full_dev = {"RMS": dev(full["rms"], ours["rms"]), "weighted": dev(full["weighted_rms"], ours["weighted_rms"]),
                "Wz": dev(full["sperling_wz"], ours["sperling_wz"]), "P95": dev(full["p95"], ours["p95"]),
                "N_MV": dev(full["nmv"], ours["nmv"]),
                "shares": np.max(np.abs(full["modal_variance"] - ours["modal_variance"]) / var[:, :, None]),
                "cross term": np.max(np.abs(full["cross_term_variance"] - ours["cross_term_variance"]) / var),
                "grid error": abs(full["grid_error"] - j["grid_error_estimate"])}
    print("in process, from assembled matrices to the indices     wall (ms)   CPU (ms)   numpy / railmodal (wall / CPU)")
    print("  every index (RMS, weighted RMS, Wz, P95, N_MV, modal shares and cross term, grid error estimate)")
    print(f"    railmodal solve_ride, kept workspace            {times['ride_s'] * 1e3:9.2f}  {times['ride_cpu_s'] * 1e3:9.2f}")
    print(f"    railmodal solve_ride, public (allocates)        {times['ride_public_s'] * 1e3:9.2f}  "
          f"{times['ride_public_cpu_s'] * 1e3:9.2f}   "
          f"{full_t[0] / times['ride_public_s']:6.1f}x / {full_t[1] / times['ride_public_cpu_s']:6.1f}x (numpy against it)")
    print(f"    numpy, one eigen-decomposition (modal)          {full_t[0] * 1e3:9.2f}  {full_t[1] * 1e3:9.2f}   "
          f"{full_t[0] / times['ride_s']:6.1f}x / {full_t[1] / times['ride_cpu_s']:6.1f}x")
    print("      max rel. Δ " + ", ".join(f"{k} {v:.1e}" for k, v in full_dev.items()))
    print("  RMS and weighted RMS only")
    print(f"    railmodal solve_ride, rms_only, kept workspace  {times['ride_rms_s'] * 1e3:9.2f}  "
          f"{times['ride_rms_cpu_s'] * 1e3:9.2f}")
    for label, (wall, cpu), r, w in (("numpy, batched np.linalg.solve            ", solve_t, rms_s, w_s),
                                     ("numpy, one eigen-decomposition (modal)    ", modal_t, rms_m, w_m)):
        print(f"    {label}      {wall * 1e3:9.2f}  {cpu * 1e3:9.2f}   {wall / times['ride_rms_s']:6.1f}x / "
              f"{cpu / times['ride_rms_cpu_s']:6.1f}x   max rel. Δ RMS {dev(r, ours_rms):.1e}, weighted {dev(w, ours_w):.1e}")
    print("whole processes (start, read, solve, print)")
    for label, ours_p, numpy_p, numpy_label in (
            ("ride_timing --once                              ", proc_ours,
             proc_numpy, "python3 compare_ride.py --baseline-full (numpy) "),
            ("ride_timing --once --rms-only                   ", proc_ours_rms,
             proc_numpy_rms, "python3 compare_ride.py --baseline (numpy, modal)")):
        print(f"  {label}  {ours_p[0] * 1e3:9.2f}  {ours_p[1] * 1e3:9.2f}")
        print(f"  {numpy_label}  {numpy_p[0] * 1e3:9.2f}  {numpy_p[1] * 1e3:9.2f}"
              f"   {numpy_p[0] / ours_p[0]:6.1f}x / {numpy_p[1] / max(ours_p[1], 1e-9):6.1f}x")
    # Agreement: the same grid, band and rule on both sides, so only the solves' round-off
    # differs (condition of D(ω) ≲ 1e6 here): 1e-9 relative leaves a wide margin above it and
    # is far below any modelling difference (a wrong delay sign or weighting constant moves
    # the figures by percent). rms_only must not change the RMS at all (bit for bit).
    if max(dev(rms_s, ours_rms), dev(w_s, ours_w), dev(rms_m, ours_rms), dev(w_m, ours_w), *full_dev.values()) > 1e-9:
        sys.exit("compare_ride.py: error: railmodal and numpy disagree")
    if not (np.array_equal(ours["rms"], ours_rms) and np.array_equal(ours["weighted_rms"], ours_w)):
        sys.exit("compare_ride.py: error: rms_only changed the RMS")


if __name__ == "__main__":
    main()
