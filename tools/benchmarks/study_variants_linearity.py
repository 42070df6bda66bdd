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

  python3 tools/benchmarks/study_variants_linearity.py build/railmodal [N]   # N = 2000 by default
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
    """CPU seconds and peak kB of one child reading the study."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run([exe, "compare", path, "--shard", "999999/999999", "-q", "-o", os.devnull], check=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return cpu, after.ru_maxrss


def main():
    exe = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build/railmodal")
    small = int(sys.argv[2]) if len(sys.argv) > 2 else 2000
    results = []
    with tempfile.TemporaryDirectory() as folder:
        for count in (small, 10 * small):
            path = os.path.join(folder, "study_%d.toml" % count)
            write_study(path, count)
            cpu, peak = read_study(exe, path)
            results.append((count, cpu, peak))
            print("%7d variants: %.2f s CPU, peak %d MB" % (count, cpu, peak // 1024))
    ratio = results[1][1] / max(results[0][1], 1e-3)
    print("10x the variants: %.1fx the time (linear: about 10)" % ratio)
    return 0 if ratio <= 20 else 1


if __name__ == "__main__":
    sys.exit(main())
