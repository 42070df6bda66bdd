#!/usr/bin/env python3
"""Checks that a change of golden outputs is one of number representation only.

Usage: tools/golden_numbers.py [--relative R] [REV] [PATH ...]
       (default REV HEAD, PATH tests/golden/expected)

For every JSON and CSV file under the paths that differs between REV and the working tree:
  - JSON: both parse; every object has the same members in the same order, every array the same
    length, every string and literal the same, every number the same double; and the text is
    the same once each number is replaced by a placeholder (the layout did not change).
  - CSV: the same rows and fields; a field that reads as a number in both is the same double, or
    the old one was rounded (written to fewer digits): the new one written with the old one's
    significant digits reads back as the old one.
Any other file that differs is listed (its change is not checked here). Exits 1 on a mismatch.

With --relative R (a change allowed to move numbers by round-off, e.g. 1e-13) a number may also
differ by at most R relative to the larger of the two (a CSV number also by one unit in its
last written digit: a round-off change that tips the rounding); the largest
relative change of a JSON number is printed, and each number beyond R is listed with its
absolute change (a value that is round-off of zero, such as a cross term, is judged from that).
"""
import csv
import io
import json
import math
import re
import subprocess
import sys

NUMBER = re.compile(r'-?\d+(?:\.\d+)?(?:[eE][-+]?\d+)?')
RELATIVE = 0.0      # --relative: the round-off a change may move a number by
LARGEST = [0.0, '']  # the largest relative change of a JSON number seen, and where


def old_text(rev, path):
    r = subprocess.run(['git', 'show', f'{rev}:{path}'], capture_output=True, text=True)
    return r.stdout if r.returncode == 0 else None


def json_same(a, b, where, problems):
    if isinstance(a, dict) and isinstance(b, dict):
        if list(a) != list(b):
            problems.append(f'{where}: members {list(a)} != {list(b)}')
            return
        for k in a:
            json_same(a[k], b[k], f'{where}.{k}', problems)
    elif isinstance(a, list) and isinstance(b, list):
        if len(a) != len(b):
            problems.append(f'{where}: {len(a)} elements != {len(b)}')
            return
        for i, (x, y) in enumerate(zip(a, b)):
            json_same(x, y, f'{where}[{i}]', problems)
    elif isinstance(a, bool) or isinstance(b, bool) or a is None or b is None or isinstance(a, str):
        if a != b or type(a) is not type(b):
            problems.append(f'{where}: {a!r} != {b!r}')
    elif float(a) != float(b):
        change = abs(float(a) - float(b)) / max(abs(float(a)), abs(float(b)))
        if change > LARGEST[0]:
            LARGEST[:] = [change, where]
        if change > RELATIVE:
            problems.append(f'{where}: {a!r} != {b!r} (relative {change:.2g}, absolute {abs(float(a) - float(b)):.2g})')


def skeleton(text):
    # Numbers outside strings become '#': the layout without the digits.
    parts = re.split(r'("(?:[^"\\]|\\.)*")', text)
    return ''.join(p if i % 2 else NUMBER.sub('#', p) for i, p in enumerate(parts))


def significant_digits(text):
    mantissa = re.split('[eE]', text.lstrip('-'))[0].replace('.', '').lstrip('0')
    return max(1, len(mantissa))


def csv_same(old, new, problems):
    a = list(csv.reader(io.StringIO(old)))
    b = list(csv.reader(io.StringIO(new)))
    if len(a) != len(b):
        problems.append(f'{len(a)} rows != {len(b)}')
        return
    for r, (x, y) in enumerate(zip(a, b), 1):
        if len(x) != len(y):
            problems.append(f'row {r}: {len(x)} fields != {len(y)}')
            continue
        for c, (u, v) in enumerate(zip(x, y), 1):
            if u == v:
                continue
            try:
                fu, fv = float(u), float(v)
            except ValueError:
                problems.append(f'row {r} field {c}: {u!r} != {v!r}')
                continue
            if fu != fv and float(f'{fv:.{significant_digits(u)}g}') != fu:
                unit = 10.0 ** (math.floor(math.log10(abs(fu))) - significant_digits(u) + 1) if fu else 0.0
                if RELATIVE > 0 and (abs(fu - fv) <= unit * (1 + 1e-9) or abs(fu - fv) <= RELATIVE * max(abs(fu), abs(fv))):
                    continue  # round-off, or the last written digit tipped by it
                problems.append(f'row {r} field {c}: {u} is not {v} rounded')


def main():
    global RELATIVE
    args = sys.argv[1:]
    if args and args[0] == '--relative':
        RELATIVE = float(args[1])
        args = args[2:]
    rev = args.pop(0) if args and not args[0].startswith('tests') else 'HEAD'
    paths = args or ['tests/golden/expected']
    changed = subprocess.run(['git', 'diff', '--name-only', rev, '--', *paths], capture_output=True, text=True,
                             check=True).stdout.split()
    bad = 0
    for path in changed:
        old = old_text(rev, path)
        try:
            new = open(path, encoding='utf-8').read()
        except FileNotFoundError:
            new = None
        if old is None or new is None:
            print(f'{path}: {"added" if old is None else "removed"}')
            continue
        problems = []
        if path.endswith('.json') and not old.startswith('exit code'):
            json_same(json.loads(old, object_pairs_hook=dict), json.loads(new, object_pairs_hook=dict), '$',
                      problems)
            if skeleton(old) != skeleton(new):
                problems.append('layout differs beyond the numbers')
        elif path.endswith('.csv') and not old.startswith('exit code'):
            csv_same(old, new, problems)
        else:
            print(f'{path}: changed (not checked)')
            continue
        print(f'{path}: {"numbers only" if not problems else "MISMATCH"}')
        for p in problems[:10]:
            print(f'  {p}')
        bad += bool(problems)
    if RELATIVE > 0:
        print(f'largest relative change of a JSON number: {LARGEST[0]:.3g} at {LARGEST[1]}')
    sys.exit(1 if bad else 0)


if __name__ == '__main__':
    main()
