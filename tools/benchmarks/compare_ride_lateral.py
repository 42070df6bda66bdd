#!/usr/bin/python3
"""Lateral ride with creep in railmodal against numpy, side by side in one run.

The Manchester benchmark coach on its four wheelsets (data/vehicles/
manchester_benchmark_coach_wheelsets.toml, all DOFs) on ORE B176 low-level alignment
(wavelengths 1 … 100 m) at 100, 125, …, 200 km/h: the RMS lateral floor acceleration over each
bogie centre and at mid-car. The wheelsets run on the linear creep contact, so the dynamic
stiffness depends on speed:

    D(ω, V) = K + K_c − ω²M + iω(C + C_c/V + V·G),

and the alignment y_t loads each wheelset through Q = [K_c·e_y + iω(ρ·C_c·e_y/V + V·G·e_y)]·ŷ_t
(docs/ride.md, "Lateral ride through the creep forces"). build/tools/benchmarks/
ride_lateral_timing times railmodal's solve_ride and writes M, C, K, K_c, C_c, G, the wheelsets'
DOFs, positions and roll shares ρ, the output points, its grid and its RMS values; this script
redoes the ride with numpy alone and compares.

Why this is the strongest fair baseline: no Python loop over frequencies, one over the 5 speeds
only (D changes with V, so a user must factor per speed, as railmodal does).
  * Variant "solve": per speed one np.linalg.solve over the stack of all grid frequencies'
    dynamic stiffness matrices (a batched LAPACK gesv gufunc), the 4 wheelsets' load vectors as
    right-hand sides at once.
  * Variant "modal": per speed one eigen-decomposition of the first-order system
    [[0, I], [−M⁻¹K_V, −M⁻¹C_V]] (52 states), then D⁻¹ = [V (iω − Λ)⁻¹ V⁻¹]_(upper right)·M⁻¹ for
    every frequency by two matrix products: O(n) per frequency instead of O(n³), exact for this
    diagonalisable system, what a user who knows modal methods writes. The faster of the two is
    the one railmodal is held against.
  * The delays e^{iωx/V} from np.cos/np.sin (numpy's complex exp is slower), |H|² in real
    arithmetic (re² + im²), the trapezoid band integral as one einsum over outputs.
The same work on both sides: railmodal's grid (read from its JSON), the same band and the same
trapezoid rule over the intervals inside each speed's band, so the RMS values agree to
round-off (checked). The ORE B176 alignment spectrum is written here from its published
constants (docs/ride.md, "ORE B176": A_a = 2.119e-7 m²·rad/m, Ω_c = 0.8246, Ω_r = 0.0206 rad/m),
not read from railmodal. Debian's numpy links the reference BLAS/LAPACK: fair to a Debian user,
slower than an OpenBLAS numpy would be (stated beside the ratio in docs/ride.md).

Timing: processor time (user + system), medians with their range, side by side and interleaved
(railmodal's driver, then numpy, repeated), on the shared machine; and whole processes
(`ride_lateral_timing --once` against `python3 compare_ride_lateral.py --baseline MODEL.json`).

    /usr/bin/python3 tools/benchmarks/compare_ride_lateral.py [--repeats 7] [--driver PATH]

Needs Debian's python3-numpy and a build with benchmarks (the target ride_lateral_timing).
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
    sys.exit("compare_ride_lateral.py: error: numpy missing (Debian: apt-get install python3-numpy)")

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
ORE_A, ORE_OC, ORE_OR = 2.119e-7, 0.8246, 0.0206  # ORE B176 low, alignment


class Model:
    def __init__(self, j):
        self.M, self.C, self.K = (np.array(j[k]) for k in ("mass", "damping", "stiffness"))
        self.Kc, self.Cc, self.G = (np.array(j[k]) for k in ("contact_stiffness", "creep_damping", "gyroscopic"))
        n = self.M.shape[0]
        ws = j["wheelsets"]
        self.x = np.array([w["x"] for w in ws])
        self.lat = [w["lateral"] for w in ws]
        self.rho = np.array([w["rho"] for w in ws])
        self.band = j["band"]
        self.grid = np.array(j["grid"])
        self.speeds = np.array(j["speeds"])
        # Lateral displacement of a body point: lateral + (x − x_ref)·yaw − (z − z_ref)·roll
        # (u = θ × r, its y component ψ·dx − φ·dz).
        self.P = np.zeros((len(j["outputs"]), n))
        # A floor accelerometer (frame "body", the default) also reads gravity along its axis
        # tilted by the roll: + g·roll on a lateral reading (docs/ride.md, "Lateral
        # acceleration's frame"); frame "track" is the inertial acceleration alone.
        self.G_roll = np.zeros((len(j["outputs"]), n))
        for o, out in enumerate(j["outputs"]):
            ref = j["reference_points"][out["body"]]
            for d, dof in enumerate(j["dofs"]):
                if dof["body"] != out["body"]:
                    continue
                motion = dof["label"].split(".")[-1]
                self.P[o, d] = {"lateral": 1.0, "yaw": out["point"][0] - ref[0],
                                "roll": -(out["point"][2] - ref[2])}.get(motion, 0.0)
                if motion == "roll" and out.get("frame", "body") == "body":
                    self.G_roll[o, d] = j["gravity"]

    def at_speed(self, V):
        """K_V, C_V and the wheelsets' loads per metre (Bd) and per m/s (Bv) of alignment."""
        Bd = self.Kc[:, self.lat]
        Bv = self.rho[None] * self.Cc[:, self.lat] / V + V * self.G[:, self.lat]
        return self.K + self.Kc, self.C + self.Cc / V + V * self.G, Bd, Bv


def temporal(f, V, band):
    om = 2 * np.pi * f / V
    s = ORE_A * ORE_OC**2 / ((om**2 + ORE_OR**2) * (om**2 + ORE_OC**2))
    return np.where((om >= band[0]) & (om <= band[1]), 2 * np.pi / V * s, 0.0)


def weights(f, V, band):
    lo, hi = V * band[0] / (2 * np.pi), V * band[1] / (2 * np.pi)
    mid = 0.5 * (f[1:] + f[:-1])
    h = np.diff(f) * ((mid >= lo) & (mid <= hi))
    w = np.zeros(f.size)
    w[:-1] += 0.5 * h
    w[1:] += 0.5 * h
    return w


def receptance_solve(m, f, V):
    K, C, Bd, Bv = m.at_speed(V)
    w = 2 * np.pi * f
    D = K[None] - (w**2)[:, None, None] * m.M[None] + 1j * w[:, None, None] * C[None]
    X = np.linalg.solve(D, Bd[None] + 1j * w[:, None, None] * Bv[None])
    return -(w**2)[:, None, None] * (m.P[None] @ X) + m.G_roll[None] @ X  # (F, outputs, wheelsets)


def receptance_modal(m, f, V):
    K, C, Bd, Bv = m.at_speed(V)
    n = m.M.shape[0]
    Minv = np.linalg.inv(m.M)
    A = np.block([[np.zeros((n, n)), np.eye(n)], [-Minv @ K, -Minv @ C]])
    lam, Vec = np.linalg.eig(A)
    W = np.linalg.inv(Vec)
    left = m.P @ Vec[:n]
    rd, rv = W[:, n:] @ Minv @ Bd, W[:, n:] @ Minv @ Bv
    w = 2 * np.pi * f
    g = (1.0 / (1j * w[:, None] - lam[None]))[:, None, :]
    Lg = (-(w**2)[:, None, None] * left[None] + (m.G_roll @ Vec[:n])[None]) * g
    return Lg @ rd + (1j * w)[:, None, None] * (Lg @ rv)


def ride(m, receptance):
    f, out = m.grid, []
    for V in m.speeds:
        A = receptance(m, f, V)
        th = (2 * np.pi * f)[:, None] * m.x[None] / V
        phase = np.empty(th.shape, complex)
        phase.real, phase.imag = np.cos(th), np.sin(th)
        H = np.einsum("fow,fw->fo", A, phase)
        out.append(np.sqrt((H.real**2 + H.imag**2).T @ (temporal(f, V, m.band) * weights(f, V, m.band))))
    return np.array(out)  # (speeds, outputs)


def cpu_of(f):
    start = time.process_time()
    r = f()
    return time.process_time() - start, r


def child_cpu(command):
    before = os.times()
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
    after = os.times()
    return after.children_user - before.children_user + after.children_system - before.children_system


def spread(t):
    t = sorted(t)
    return f"{t[len(t) // 2] * 1e3:.1f} ms (range {t[0] * 1e3:.1f} … {t[-1] * 1e3:.1f})"


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--repeats", type=int, default=7)
    p.add_argument("--driver", default=os.path.join(ROOT, "build/tools/benchmarks/ride_lateral_timing"))
    p.add_argument("--baseline", help="only run the numpy ride on this model JSON (whole-process timing)")
    a = p.parse_args()
    if a.baseline:
        with open(a.baseline) as fh:
            m = Model(json.load(fh))
        for V, row in zip(m.speeds, ride(m, receptance_modal)):
            print(V * 3.6, *row, sep="\t")
        return
    if not os.path.exists(a.driver):
        sys.exit(f"compare_ride_lateral.py: error: no {a.driver} (build the target ride_lateral_timing)")
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "model.json")
        rail_cpu, solve_cpu, modal_cpu, rail_proc, numpy_proc = [], [], [], [], []
        for _ in range(a.repeats):  # interleaved: railmodal, numpy solve, numpy modal, processes
            subprocess.run([a.driver, "--repeats", "1", "--json", path], check=True, stdout=subprocess.DEVNULL)
            with open(path) as fh:
                j = json.load(fh)
            rail_cpu.append(j["cpu_seconds"][0])
            m = Model(j)
            t, by_solve = cpu_of(lambda: ride(m, receptance_solve))
            solve_cpu.append(t)
            t, by_modal = cpu_of(lambda: ride(m, receptance_modal))
            modal_cpu.append(t)
            rail_proc.append(child_cpu([a.driver, "--once"]))
            numpy_proc.append(child_cpu([sys.executable, os.path.abspath(__file__), "--baseline", path]))
        rail = np.array(j["rms"])
        for name, r in (("solve", by_solve), ("modal", by_modal)):
            err = np.max(np.abs(r / rail - 1))
            print(f"numpy {name}: largest relative RMS difference from railmodal {err:.2e}")
            if err > 1e-6:
                sys.exit("compare_ride_lateral.py: error: the two sides disagree")
    print(f"{len(m.grid)} frequencies x {len(m.speeds)} speeds, {m.M.shape[0]} DOFs; "
          f"load average {os.getloadavg()[0]:.1f}")
    print(f"in process, processor time: railmodal solve_ride {spread(rail_cpu)}")
    print(f"                            numpy batched solve   {spread(solve_cpu)}")
    print(f"                            numpy modal           {spread(modal_cpu)}")
    best = min(np.median(solve_cpu), np.median(modal_cpu))
    print(f"  ratio numpy (faster variant) / railmodal: {best / np.median(rail_cpu):.1f}x")
    print(f"whole process, processor time: railmodal {spread(rail_proc)}, numpy {spread(numpy_proc)}; "
          f"ratio {np.median(numpy_proc) / np.median(rail_proc):.1f}x")


if __name__ == "__main__":
    main()
