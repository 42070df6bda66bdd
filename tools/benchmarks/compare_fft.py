#!/usr/bin/python3
"""railmodal's amplitude spectrum against scipy.fft, side by side in one run.

The same Hann amplitude spectrum of 2^20 samples on both sides (window-weighted mean removed,
one-sided peak amplitude 2|X|/Σw, halved at 0 Hz and Nyquist): scipy.fft.rfft, bare and inside
that spectrum, against build/tools/benchmarks/spectrum_timing on the same samples.

WHY THIS IS THE STRONGEST FAIR BASELINE. scipy.fft (pocketfft in C++) is faster than numpy.fft
for real input and caches its plans between calls, so its repeated calls are compared with
railmodal's reused plan (SpectrumAnalyzer), the like-for-like figure; railmodal planning in every
call is shown too. The window and its weight are computed once outside the timing, as a user
analysing many records would; the mean removal and window are one fused expression and the
transform overwrites its input (overwrite_x), so numpy allocates no more than it must. One
worker on both sides (scipy.fft's default; railmodal's FFTW plan is single-threaded).

AGREEMENT. Both sides are FFTs of the same windowed record, each with round-off of order
ε·log2(N) ≈ 2e-15 of the largest amplitude; 1e-12 of the largest amplitude leaves a wide margin
and still catches any scaling, window or bin error (those are of order 1e-3 or more).

TIMING. Interleaved rounds (side_by_side.py): in each round railmodal (the median of its own
--inner repeats, in a fresh spectrum_timing process) and scipy (the median of --inner calls)
run back to back; the ratios are formed within each round; medians and spread are reported.

    /usr/bin/python3 tools/benchmarks/compare_fft.py [--log2n 20] [--rounds 7] [--inner 11]
        [--quick] [--driver PATH]

--quick: 2^16 samples, 2 rounds of 3 (a smoke run). Needs Debian's python3-numpy and
python3-scipy (for /usr/bin/python3) and a build with benchmarks (spectrum_timing).
"""
import argparse
import os
import subprocess
import sys
import tempfile

try:
    import numpy as np
    import scipy
    import scipy.fft
except ImportError:
    sys.exit("compare_fft.py: error: numpy/scipy missing (Debian: apt-get install python3-numpy python3-scipy)")

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
from side_by_side import Rounds, median_of  # noqa: E402

TOLERANCE = 1e-12  # of the largest amplitude; the docstring says why


def amplitude_spectrum(x, w, weight):
    """What railmodal computes: Hann (periodic), weighted mean removed, one-sided peak amplitude."""
    a = np.abs(scipy.fft.rfft((x - (w @ x) / weight) * w, overwrite_x=True))
    a *= 2.0 / weight
    a[0] *= 0.5
    if len(x) % 2 == 0:
        a[-1] *= 0.5
    return a


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--log2n", type=int, default=20)
    parser.add_argument("--rounds", type=int, default=7)
    parser.add_argument("--inner", type=int, default=11)
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--driver", default=os.path.join(ROOT, "build", "tools", "benchmarks", "spectrum_timing"))
    args = parser.parse_args()
    if not os.access(args.driver, os.X_OK):
        sys.exit(f"compare_fft.py: error: {args.driver} not found; build with benchmarks first")
    if args.quick:
        args.log2n, args.rounds, args.inner = 16, 2, 3

    n = 1 << args.log2n
    rng = np.random.default_rng(5)
    t = np.arange(n)
    x = 0.3 + np.sin(2 * np.pi * 0.0123 * t) + 0.1 * np.sin(2 * np.pi * 0.271 * t) + 0.01 * rng.standard_normal(n)
    w = 0.5 - 0.5 * np.cos(2 * np.pi * t / n)
    weight = w.sum()

    with tempfile.TemporaryDirectory() as tmp:
        signal, amplitude = os.path.join(tmp, "x.f64"), os.path.join(tmp, "a.f64")
        x.astype(np.float64).tofile(signal)
        last = {}

        def ours():
            out = subprocess.run([args.driver, signal, amplitude, str(args.inner)], check=True, capture_output=True,
                                 text=True).stdout
            last.update((k, float(v)) for k, v in (line.split() for line in out.splitlines()))
            return last["reused_plan_s"]
        rounds = Rounds({
            "railmodal, plan reused": ours,
            "railmodal, new plan": lambda: last["new_plan_s"],  # same process as the line above
            "scipy.fft spectrum": lambda: median_of(lambda: amplitude_spectrum(x, w, weight), args.inner)[0],
            "scipy.fft rfft alone": lambda: median_of(lambda: scipy.fft.rfft(x), args.inner)[0],
        })
        for r in range(args.rounds):
            groups = [["railmodal, plan reused", "railmodal, new plan"], ["scipy.fft spectrum", "scipy.fft rfft alone"]]
            for group in (groups if r % 2 == 0 else groups[::-1]):
                for name in group:
                    rounds.times[name].append(rounds.contenders[name]())
        a = np.fromfile(amplitude, dtype=np.float64)

    reference = amplitude_spectrum(x, w, weight)
    difference = np.max(np.abs(a - reference)) / np.max(reference)

    print(f"amplitude spectrum of 2^{args.log2n} = {n} samples, Hann; {args.rounds} interleaved rounds, each the "
          f"median of {args.inner} runs per side; load average {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores")
    for name in rounds.names:
        print(f"  {name:24s} {rounds.describe_time(name)}")
    print(f"  scipy {scipy.__version__} spectrum / railmodal reused plan {rounds.describe_ratio('scipy.fft spectrum', 'railmodal, plan reused')}")
    print(f"  scipy spectrum / railmodal new plan      {rounds.describe_ratio('scipy.fft spectrum', 'railmodal, new plan')}")
    print(f"  scipy bare rfft / railmodal spectrum     {rounds.describe_ratio('scipy.fft rfft alone', 'railmodal, plan reused')}")
    print(f"  max |railmodal - scipy| / max amplitude: {difference:.1e} (tolerance {TOLERANCE:g})")
    if not difference <= TOLERANCE:
        sys.exit("compare_fft.py: error: the spectra disagree")


if __name__ == "__main__":
    main()
