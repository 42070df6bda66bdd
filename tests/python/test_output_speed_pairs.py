"""Every speed in the JSON outputs of compare, hunting, stability, critical-speed and ride is
written in m/s and in km/h side by side (docs/input.md, "Names and units in outputs"): a key
NAME_m_s has NAME_kmh beside it and the other way round, and the two say the same speed.

Read from the golden outputs (tests/golden/expected), which the golden tests hold to what the
commands write byte for byte. Tolerance: km/h = 3.6 × m/s to 1e-12 relative, the round-off of the
product and of the 15-digit km/h some writers keep (ride's kmh_value).
"""
import glob
import json

import pytest

from railmodal_paths import SOURCE

# Speed differences and tolerances, not speeds the vehicle runs at: m/s alone (docs/input.md,
# "Changes to outputs, 2026-11-27, afternoon").
NOT_SPEEDS = {"tolerance_m_s", "hold_margin_m_s", "convergence_difference_m_s"}
COMMANDS = ["compare", "hunting", "stability", "critical-speed", "ride"]


def pairs(node, path, found):
    if isinstance(node, dict):
        for key, value in node.items():
            if key in NOT_SPEEDS:
                continue
            for own, other in (("_m_s", "_kmh"), ("_kmh", "_m_s")):
                if key.endswith(own):
                    partner = key[: -len(own)] + other
                    found.append((path + "." + key, key, partner, node))
            pairs(value, path + "." + key, found)
    elif isinstance(node, list):
        for i, value in enumerate(node):
            pairs(value, "%s[%d]" % (path, i), found)


def as_m_s(kmh):
    return [as_m_s(v) for v in kmh] if isinstance(kmh, list) else (kmh / 3.6 if isinstance(kmh, float) else kmh)


@pytest.mark.parametrize("command", COMMANDS)
def test_every_speed_has_its_partner(command):
    files = sorted(glob.glob(str(SOURCE / "tests" / "golden" / "expected" / command / "*.json")))
    assert files
    checked = 0
    for name in files:
        with open(name, encoding="utf-8") as f:
            text = f.read()
        if text.startswith("exit code"):
            continue  # a failed case's record, not a JSON file
        found = []
        pairs(json.loads(text), "", found)
        for path, key, partner, node in found:
            assert partner in node, "%s: %s without %s" % (name, path, partner)
            if key.endswith("_kmh"):
                got, want = as_m_s(node[key]), node[partner]
                if isinstance(want, float):
                    assert got == pytest.approx(want, rel=1e-12), "%s: %s" % (name, path)
                elif isinstance(want, list):
                    assert got == pytest.approx(want, rel=1e-12), "%s: %s" % (name, path)
                else:
                    assert got == want, "%s: %s" % (name, path)  # null, "none"
                checked += 1
    assert checked > 0
