#!/usr/bin/python3
"""railmodal's amplitude spectrum against numpy.fft, side by side in one run.

Times numpy.fft.rfft of 2^20 samples (bare, and inside the same Hann amplitude spectrum that
railmodal computes: window-weighted mean removed, 2|X|/sum(w)), runs build/tools/benchmarks/
spectrum_timing on the same samples, checks that the two spectra agree and prints the ratios.
numpy plans inside every call; railmodal is timed both planning every call and reusing a plan.

    /usr/bin/python3 tools/benchmarks/compare_fft.py [--log2n 20] [--repeats 21] [--driver PATH]

Needs Debian's python3-numpy (for /usr/bin/python3) and a build with benchmarks.
"""
import argparse
import os
import subprocess
import sys
import tempfile
import time

try:
    import numpy as np
except ImportError:
    sys.exit("compare_fft.py: error: numpy is missing (Debian: apt-get install python3-numpy)")

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def median_seconds(f, repeats):
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        f()
        times.append(time.perf_counter() - start)
    return sorted(times)[len(times) // 2]


def numpy_amplitude_spectrum(x, w):
    """What railmodal computes: Hann (periodic), weighted mean removed, one-sided peak amplitude."""
    weight = w.sum()
    a = np.abs(np.fft.rfft((x - w @ x / weight) * w)) * (2.0 / weight)
    a[0] *= 0.5
    if len(x) % 2 == 0:
        a[-1] *= 0.5
    return a


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--log2n", type=int, default=20)
    parser.add_argument("--repeats", type=int, default=21)
    parser.add_argument("--driver", default=os.path.join(ROOT, "build", "tools", "benchmarks", "spectrum_timing"))
    args = parser.parse_args()
    if not os.access(args.driver, os.X_OK):
        sys.exit(f"compare_fft.py: error: {args.driver} not found; build with benchmarks first")

    n = 1 << args.log2n
    rng = np.random.default_rng(5)
    t = np.arange(n)
    x = 0.3 + np.sin(2 * np.pi * 0.0123 * t) + 0.1 * np.sin(2 * np.pi * 0.271 * t) + 0.01 * rng.standard_normal(n)
    w = 0.5 - 0.5 * np.cos(2 * np.pi * t / n)

    bare = median_seconds(lambda: np.fft.rfft(x), args.repeats)
    full = median_seconds(lambda: numpy_amplitude_spectrum(x, w), args.repeats)

    with tempfile.TemporaryDirectory() as tmp:
        signal, amplitude = os.path.join(tmp, "x.f64"), os.path.join(tmp, "a.f64")
        x.astype(np.float64).tofile(signal)
        out = subprocess.run([args.driver, signal, amplitude, str(args.repeats)], check=True, capture_output=True,
                             text=True).stdout
        ours = dict((k, float(v)) for k, v in (line.split() for line in out.splitlines()))
        a = np.fromfile(amplitude, dtype=np.float64)

    reference = numpy_amplitude_spectrum(x, w)
    difference = np.max(np.abs(a - reference)) / np.max(reference)

    print(f"amplitude spectrum of 2^{args.log2n} = {n} samples, Hann, median of {args.repeats} runs")
    print(f"  numpy {np.__version__} rfft alone            {bare * 1e3:8.2f} ms")
    print(f"  numpy amplitude spectrum            {full * 1e3:8.2f} ms")
    print(f"  railmodal, plan made in every call  {ours['new_plan_s'] * 1e3:8.2f} ms")
    print(f"  railmodal, plan reused              {ours['reused_plan_s'] * 1e3:8.2f} ms")
    print(f"  ratio numpy / railmodal, amplitude spectrum: {full / ours['new_plan_s']:.2f} (new plan), "
          f"{full / ours['reused_plan_s']:.2f} (reused plan)")
    print(f"  ratio numpy bare rfft / railmodal reused-plan spectrum: {bare / ours['reused_plan_s']:.2f}")
    print(f"  max |railmodal - numpy| / max amplitude: {difference:.1e}")
    if difference > 1e-12:
        sys.exit("compare_fft.py: error: the spectra disagree")


if __name__ == "__main__":
    main()
