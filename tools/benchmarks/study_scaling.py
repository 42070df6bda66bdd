#!/usr/bin/env python3
"""Whole-process `railmodal compare` on the sampled benchmark study: rate, threads, memory.

Issue 19, item 2. For each size N (a copy of tools/benchmarks/resort_car_sample_study.toml with
N samples and absolute paths), runs `railmodal compare COPY --threads T -q --format F -o OUT`
for T = 1 and 2, the two interleaved over the repeats (the order alternating), under GNU time:
wall time, processor time (user + system, all threads) and peak resident memory of the whole
process (start, study read, variants read and evaluated, ranked, written). Prints the medians
with their range, the variants per minute (wall; and per core from processor time), the speed-up
from 1 to 2 threads (ratio of the medians, and the range of the per-repeat ratios), the load
average before and after (the machine may be shared: state it with the figures), and checks that
the outputs of 1 and 2 threads are the same bytes.

    /usr/bin/python3 tools/benchmarks/study_scaling.py [--build build] [--sizes 10000 100000]
        [--repeats 3] [--format csv]

The numpy side of the comparison is tools/benchmarks/compare_study.py (batched numpy over
variants); this script measures railmodal alone, as a user runs it.
"""
import argparse
import os
import re
import statistics
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
STUDY = os.path.join(ROOT, "tools", "benchmarks", "resort_car_sample_study.toml")


def study_copy(count, folder):
    """The benchmark study with `count` samples and absolute vehicle and scene paths."""
    with open(STUDY) as f:
        text = f.read()
    text = text.replace('"../../data/', '"' + os.path.join(ROOT, "data") + "/")
    text = re.sub(r"count = \d+", f"count = {count}", text)
    path = os.path.join(folder, f"study_{count}.toml")
    with open(path, "w") as f:
        f.write(text)
    return path


def run(exe, study, threads, fmt, out):
    """Wall s, CPU s, peak KiB of one whole `railmodal compare` process."""
    command = ["/usr/bin/time", "-f", "%e %U %S %M", exe, "compare", study, "--threads", str(threads), "-q",
               "--format", fmt, "-o", out]
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"study_scaling.py: error: {' '.join(command)} failed: {done.stderr.strip()}")
    wall, user, system, peak = done.stderr.strip().splitlines()[-1].split()
    return float(wall), float(user) + float(system), int(peak)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    parser.add_argument("--sizes", type=int, nargs="+", default=[10000, 100000])
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--format", default="csv")
    args = parser.parse_args()
    exe = os.path.join(args.build, "railmodal")
    print(f"load average before: {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores")
    with tempfile.TemporaryDirectory() as tmp:
        for n in args.sizes:
            study = study_copy(n, tmp)
            runs = {1: [], 2: []}
            outputs = {t: os.path.join(tmp, f"out_{t}.{args.format}") for t in runs}
            for r in range(args.repeats):
                for t in ((1, 2) if r % 2 == 0 else (2, 1)):
                    runs[t].append(run(exe, study, t, args.format, outputs[t]))
            with open(outputs[1], "rb") as a, open(outputs[2], "rb") as b:
                identical = a.read() == b.read()
            print(f"\n{n} variants, --format {args.format}, {args.repeats} repeats (medians, range):")
            for t, rs in runs.items():
                wall = [x[0] for x in rs]
                cpu = [x[1] for x in rs]
                peak = [x[2] / 1024 for x in rs]
                print(f"  {t} thread(s): wall {statistics.median(wall):7.2f} s ({min(wall):.2f}-{max(wall):.2f}), "
                      f"CPU {statistics.median(cpu):7.2f} s ({min(cpu):.2f}-{max(cpu):.2f}), "
                      f"peak {statistics.median(peak):6.0f} MiB; "
                      f"{60 * n / statistics.median(wall):9.0f} variants/min wall, "
                      f"{60 * n / statistics.median(cpu):9.0f} per core (CPU), "
                      f"{1e6 * statistics.median(cpu) / n:6.1f} us CPU a variant")
            speedups = [a[0] / b[0] for a, b in zip(runs[1], runs[2])]
            print(f"  speed-up 1 -> 2 threads (wall): {statistics.median(speedups):.2f} "
                  f"(range {min(speedups):.2f}-{max(speedups):.2f})")
            print(f"  outputs of 1 and 2 threads identical: {'yes' if identical else 'NO'}")
    print(f"\nload average after: {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores")


if __name__ == "__main__":
    main()
