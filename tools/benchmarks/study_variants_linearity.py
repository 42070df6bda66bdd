#!/usr/bin/python3
"""Reading a study of explicit [[variant]] tables takes time linear in their number (issue 18, item 6).

Writes studies of N and 10 N [[variant]] tables (each one override of the resort car's
cradle springs), reads each with `railmodal compare STUDY --shard 999999/999999`, a shard
that lists every variant but evaluates none, and prints the CPU time (user + system of the
child, which other jobs on the machine disturb less than the wall clock) and the peak memory
of each, and their ratios. Exits 1 when 10x the variants takes more than 20x the time: a
linear reader gives about 10, and the quadratic one it replaces gave about 100 (toml11
counted the newlines from the start of the file for each variant's line: 10 000 variants
took 14 s, 20 000 took 62 s).

The two sizes are read interleaved (N, 10 N, N, 10 N, ...) REPEATS times (3 by default) and
the ratio is the median of the per-pair ratios, printed with its range: a change of load on
the shared machine between two runs must not pass for a change of complexity.

  python3 tools/benchmarks/study_variants_linearity.py build/railmodal [N] [REPEATS]   # N = 2000
"""
import os
import resource
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def write_study(path, count):
    with open(path, "w") as f:
        f.write('[study]\nvehicle = "%s"\nscene = "%s"\n' % (os.path.join(ROOT, "data/vehicles/resort_car.toml"),
                                                            os.path.join(ROOT, "data/scenes/fette_car_10m_rails.toml")))
        for i in range(count):
            f.write('\n[[variant]]\nname = "v%d"\noverrides = { "secondary.spring.stiffness" = "%.2f kgf/cm" }\n'
                    % (i, 500 + 0.01 * i))


def read_study(exe, path):
    """CPU seconds (from getrusage: microseconds, where GNU time has 10 ms steps) and peak kB of
    one child reading the study (GNU time's %M: this child's peak, where RUSAGE_CHILDREN's is
    the largest of all children so far)."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    run = subprocess.run(["/usr/bin/time", "-f", "%M", exe, "compare", path, "--shard", "999999/999999", "-q",
                          "-o", os.devnull], check=True, stderr=subprocess.PIPE, text=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return cpu, int(run.stderr.strip().splitlines()[-1])


def main():
    exe = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build/railmodal")
    small = int(sys.argv[2]) if len(sys.argv) > 2 else 2000
    repeats = int(sys.argv[3]) if len(sys.argv) > 3 else 3
    with tempfile.TemporaryDirectory() as folder:
        paths = []
        for count in (small, 10 * small):
            paths.append(os.path.join(folder, "study_%d.toml" % count))
            write_study(paths[-1], count)
        pairs = [[read_study(exe, path) for path in paths] for _ in range(repeats)]
    median = lambda xs: sorted(xs)[len(xs) // 2]
    for i, count in enumerate((small, 10 * small)):
        print("%7d variants: %.2f s CPU (median of %d), peak %d MB"
              % (count, median([p[i][0] for p in pairs]), repeats, median([p[i][1] for p in pairs]) // 1024))
    ratios = [b[0] / max(a[0], 1e-3) for a, b in pairs]
    ratio = median(ratios)
    print("10x the variants: %.1fx the time (range %.1f-%.1f; linear: about 10)" % (ratio, min(ratios), max(ratios)))
    return 0 if ratio <= 20 else 1


if __name__ == "__main__":
    sys.exit(main())
