#!/usr/bin/python3
"""tools/update_accuracy.sh is safe to run on the committed docs/accuracy.md: it replaces only
what the generator writes, between the markers, and keeps the hand-written sections after them.

    python3 tests/accuracy/splice_test.py SOURCE_DIR
"""
import os
import re
import sys

SOURCE = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "..")
sys.path.insert(0, os.path.join(SOURCE, "tools", "accuracy"))
from splice_generated import BEGIN, END, MarkerError, parts, splice  # noqa: E402

with open(os.path.join(SOURCE, "docs", "accuracy.md"), encoding="utf-8") as f:
    document = f.read()
with open(os.path.join(SOURCE, "tools", "accuracy", "accuracy_report.cpp"), encoding="utf-8") as f:
    generator = f.read()

before, generated, after = parts(document)
# The generator's output is the whole top of the file: nothing stands before the begin marker.
assert before == BEGIN, "docs/accuracy.md must open with the begin marker"
# Every section heading the generator prints lies between the markers, and no hand-written
# section after them has one of its headings (else a run would write that section twice).
generator_headings = set(re.findall(r'"(#{1,2} [^"\\]+)\\n', generator))
assert generator_headings, "no headings found in accuracy_report.cpp"
inside = set(re.findall(r"^(#{1,2} .+)$", generated, re.M))
outside = set(re.findall(r"^(#{1,2} .+)$", after, re.M))
assert generator_headings <= inside, f"generated headings outside the markers: {generator_headings - inside}"
assert not generator_headings & outside, f"generated headings after the end marker: {generator_headings & outside}"
assert outside, "no hand-written section after the end marker"
# Splicing the committed region back changes nothing; splicing another keeps the rest byte for byte.
assert splice(document, generated) == document
other = splice(document, "# Accuracy against time\n\nnew figures\n")
assert other.startswith(BEGIN + "# Accuracy against time\n\nnew figures\n") and other.endswith(after)
# A file without its markers is refused rather than overwritten.
for broken in (document.replace(END, ""), document.replace(BEGIN, ""), END + BEGIN, document + BEGIN):
    try:
        splice(broken, "x\n")
    except MarkerError:
        continue
    raise AssertionError("a document without one ordered pair of markers was accepted")
print(f"splice_test: {len(generator_headings)} generated headings inside the markers, "
      f"{len(outside)} hand-written headings after them")
