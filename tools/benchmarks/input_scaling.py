#!/usr/bin/env python3
"""Linearity of the input front end (issue 18, items 3, 6 and 7): each case times the command
line on a small input and on one 10x larger, and prints both times, the peak memory and the
ratio. A ratio near 10 is linear; near 100, quadratic; near 1, refused up front.

Not a ctest (timings depend on the machine): run it by hand after changing the readers.
There is no numpy side: the comparison is railmodal with itself at two sizes. The two sizes run
interleaved (small, large, small, large, ...) --repeats times, and the ratio is the median of
the per-pair ratios with its range, so that a change of load on the shared machine between
the two runs does not pass for a change of complexity.

    python3 tools/benchmarks/input_scaling.py [--railmodal build/railmodal] [--only toml|mtx|study]
        [--repeats 3] [--quick]

--quick: one repeat of the toml cases only (a smoke run).

Cases:
  toml   item 3: TOML lines at the 8192-byte limit (the densest values, empty strings), 100 and
         1000 of them; the issue's 30 000 strings on one line, and 300 000; a 5 MB and a 50 MB
         comment line (both refused up front).
  mtx    item 7: a Matrix Market file whose third line is a hole of NULs, 10 MB and 100 MB
         (refused at the first byte); 10^5 and 10^6 valid entries before a bad one.
  study  item 6 (the study reader, another change of issue 18): a study of 1000 and 10 000
         explicit [[variant]] tables, loaded by `compare --shard 1/N`, which evaluates one.
Each process runs under a 3 GB address-space limit and a 600 s timeout.
"""
import argparse
import os
import resource
import subprocess
import sys
import tempfile
import time

DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "data")


def limit_memory():
    resource.setrlimit(resource.RLIMIT_AS, (3 << 30, 3 << 30))


def run(command):
    """Wall time (s), CPU time (s, user and system: steadier than wall time on a busy machine),
    peak resident memory (MB) and exit code of one run."""
    timed = ["/usr/bin/time", "-f", "%M %U %S"] + command
    start = time.perf_counter()
    p = subprocess.run(timed, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                       preexec_fn=limit_memory, timeout=600)
    seconds = time.perf_counter() - start  # /usr/bin/time's %e has 10 ms steps
    kilobytes, user, system = p.stderr.strip().splitlines()[-1].split()
    return seconds, float(user) + float(system), int(kilobytes) / 1024, p.returncode


def write(path, text):
    with open(path, "wb") as f:
        f.write(text if isinstance(text, bytes) else text.encode())
    return path


# Item 3 ------------------------------------------------------------------------------------
def toml_full_lines(directory, lines):
    """A vehicle file whose unknown key holds `lines` lines of 8192 bytes of empty strings:
    the slowest lines toml11 3.7.1 is given (it scans a value's line once per value)."""
    body = "".join("a%d = [%s]\n" % (i, '"",' * ((8192 - 12) // 3)) for i in range(lines))
    return write(os.path.join(directory, "lines%d.toml" % lines), "[vehicle]\n" + body)


def toml_one_line(directory, strings):
    return write(os.path.join(directory, "line%d.toml" % strings),
                 "[vehicle]\nnames = [" + ", ".join(['"x"'] * strings) + "]\n")


def toml_comment(directory, megabytes):
    return write(os.path.join(directory, "comment%d.toml" % megabytes),
                 "[vehicle]\n#" + "c" * (megabytes * 1000000) + "\n")


# Item 7 ------------------------------------------------------------------------------------
BANNER = b"%%MatrixMarket matrix coordinate real general\n"


def mtx_hole(directory, megabytes):
    path = os.path.join(directory, "hole%d.mtx" % megabytes)
    with open(path, "wb") as f:
        f.write(BANNER + b"2 2 2\n")
        chunk = b"\0" * 1000000
        for _ in range(megabytes):
            f.write(chunk)
    return path


def mtx_entries(directory, entries):
    """`entries` valid diagonal entries, then a bad byte on the last line."""
    path = os.path.join(directory, "entries%d.mtx" % entries)
    with open(path, "wb") as f:
        f.write(BANNER + b"%d %d %d\n" % (entries, entries, entries + 1))
        f.write(b"".join(b"%d %d 1.5\n" % (i, i) for i in range(1, entries + 1)))
        f.write(b"1 1 \x01\n")
    return path


# Item 6 (hook) -----------------------------------------------------------------------------
def study_variants(directory, variants):
    """A study of `variants` explicit [[variant]] tables, each overriding a spring."""
    lines = ['[study]', 'name = "scaling"',
             'vehicle = "%s"' % os.path.join(DATA, "vehicles", "resort_car.toml"),
             'scene = "%s"' % os.path.join(DATA, "scenes", "fette_car_10m_rails.toml")]
    for i in range(variants):
        lines += ["[[variant]]", 'name = "v%d"' % i,
                  'overrides = { "secondary.spring.stiffness" = "%d kgf/cm" }' % (500 + i % 300)]
    return write(os.path.join(directory, "study%d.toml" % variants), "\n".join(lines) + "\n")


def cases(railmodal, directory):
    mtx = lambda path: [railmodal, "modes", "--mass", path, "--stiffness", path, "-o", os.devnull]
    toml = lambda path: [railmodal, "modes", path, "-o", os.devnull]
    return {
        "toml": [
            ("8192-byte lines of empty strings, 20 vs 200 lines", toml_full_lines, (20, 200), toml),
            ("one line of N strings (refused), 30 000 vs 300 000", toml_one_line, (30000, 300000), toml),
            ("one comment line (refused), 5 MB vs 50 MB", toml_comment, (5, 50), toml),
        ],
        "mtx": [
            ("NUL hole on line 3 (refused), 10 MB vs 100 MB", mtx_hole, (10, 100), mtx),
            ("valid entries before a bad byte, 1e5 vs 1e6", mtx_entries, (100000, 1000000), mtx),
        ],
        "study": [
            ("explicit [[variant]] tables, 1000 vs 10 000", study_variants, (1000, 10000),
             lambda path: [railmodal, "compare", path, "--shard", "1/%s" % path.split("study")[-1][:-5],
                           "-q", "-o", os.devnull]),
        ],
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--railmodal", default="build/railmodal")
    parser.add_argument("--only", choices=["toml", "mtx", "study"])
    parser.add_argument("--repeats", type=int, default=3, help="interleaved small/large pairs (median reported)")
    parser.add_argument("--quick", action="store_true")
    args = parser.parse_args()
    if args.quick:
        args.only, args.repeats = "toml", 1
    railmodal = os.path.abspath(args.railmodal)
    with tempfile.TemporaryDirectory(prefix="railmodal_scaling_") as directory:
        for group, group_cases in cases(railmodal, directory).items():
            if args.only and group != args.only:
                continue
            for title, make, (small, large), command in group_cases:
                paths = [make(directory, size) for size in (small, large)]
                pairs = [[run(command(path)) for path in paths] for _ in range(args.repeats)]
                for path in paths:
                    os.remove(path)
                median = lambda xs: sorted(xs)[len(xs) // 2]
                (t1, u1, m1, c1), (t2, u2, m2, c2) = ([median([p[i][k] for p in pairs]) for k in range(4)]
                                                      for i in range(2))
                wall = [b[0] / a[0] for a, b in pairs]
                cpu = [b[1] / a[1] for a, b in pairs if a[1] >= 0.05]
                print("%-6s %-52s %7.3f s (cpu %6.2f s) %5.0f MB exit %d | %7.3f s (cpu %6.2f s) %5.0f MB exit %d"
                      " | ratio %5.1f [%.1f-%.1f] (cpu %s)"
                      % (group, title, t1, u1, m1, c1, t2, u2, m2, c2, median(wall), min(wall), max(wall),
                         "%.1f [%.1f-%.1f]" % (median(cpu), min(cpu), max(cpu)) if cpu else "-"))
                sys.stdout.flush()


if __name__ == "__main__":
    main()
