"""A Python record names a quantity as the command's JSON does (user audit 2026-11-27c, F6: the
critical-speed records had `speed_km_h` where the JSON has `speed_kmh`, so code written against
one failed with a KeyError on the other).

For each analysis that has both, the keys of the Python records are compared with those of the
JSON objects of the same run: a key the JSON does not have must be one of the differences below,
each with its reason (a flattened nested object, an index the JSON does not write, the radians of
the package's SI against the JSON's degrees, a rule of docs/input.md's "Names and units in
outputs"). A new key spelt otherwise than its JSON twin fails here.
"""
import pytest

import railmodal
from railmodal_paths import SOURCE, cli_json, data

# The time-domain ride of test_ride.py: the coach on 1024 m of synthesised track (23 s).
COACH_TIME_SHORT = str(SOURCE / "tests" / "python" / "scenes" / "coach_time_domain_short.toml")


def keys(rows):
    out = set()
    for row in rows:
        out.update(row.keys())
    return out


# Keys only the Python records have, and why; anything else must be the JSON's own key.
ONLY_IN_PYTHON = {
    # A source is `source_index` (its number from 1) and `source_kind` everywhere: no key
    # `source` holds an index in one place and a kind in another (2026-11-28).
    "critical speeds": set(),
    # The centre of oscillation, a nested object in JSON, flattened into three columns.
    "modes": {"centre_about", "centre_body", "centre_position_m", "eigenvalue_error"},
    # One complex eigenvalue of the pair the JSON writes as `eigenvalues` ([re, im] pairs).
    "damped modes": {"eigenvalue"},
    # A flat row names its output (`name` in the JSON's nested output).
    "ride records": {"output"},
    "time-domain ride records": {"output"},
    # The floor point's `point_m` flattened into x_m, y_m, z_m; a flat row carries its speed.
    "ride comfort": {"x_m", "y_m", "z_m", "speed_m_s"},
    "time-domain ride comfort": {"x_m", "y_m", "z_m", "speed_m_s"},
    # A study's rows carry their variant (`index`, `variant`: its `name` in compare's JSON).
    "study critical speeds": {"index", "variant"},
    "study peaks": {"index", "variant"},
    "study deflections": {"index", "variant"},
    "study modes": {"index", "variant"},
    "study ride": {"index", "variant"},
    # A wheel by its axle index and side beside `wheel`.
    "gear wheels": {"axle", "right"},
    # Angles in radians (the package's SI), where the JSON writes degrees (`*_angle_deg`).
    "balance wheels": {"axle", "right", "rotating_angle_rad", "vertical_angle_rad", "overbalance_angle_rad",
                       "total_angle_rad"},
    "trade-off": set(),
    # The record length a check needs to resolve its line (the JSON says it in the outcome's
    # words); the reasons, None where the outcome has none (the JSON writes them only where it has).
    "fft-check": {"needed_duration_s", "why_decayed", "why_not_applicable"},
}


@pytest.fixture(scope="module")
def critical():
    scene = data("scenes", "resort_car_10m_rails.toml")
    return railmodal.study_critical_speeds(railmodal.load_scene(scene)), cli_json("critical-speed", scene)


@pytest.fixture(scope="module")
def ride():
    scene = data("scenes", "manchester_coach_ore_low.toml")
    return railmodal.ride_scene(railmodal.load_scene(scene)), cli_json("ride", scene)


@pytest.fixture(scope="module")
def balance():
    su = data("locomotives", "su.toml")
    return railmodal.balance_study(railmodal.load_driving_gear(su)), cli_json("balance", su)


def only_in_python(python_rows, json_rows):
    python, written = keys(python_rows), keys(json_rows)
    assert python and written
    return python - written


def test_critical_speeds(critical):
    study, written = critical
    rows = study.critical_speeds.records()
    assert only_in_python(rows, written["critical_speeds"]) == ONLY_IN_PYTHON["critical speeds"]
    # One meaning per name: the source's number from 1 and its kind, as the JSON has them.
    for key in ("source_index", "source_kind"):
        assert [r[key] for r in rows] == [c[key] for c in written["critical_speeds"]], key
    assert "source" not in keys(written["critical_speeds"])
    assert [c.source_index for c in study.curves] == [c["source_index"] for c in written["curves"]]
    # 3.6·V on both sides, the JSON's printed to round trip: equal to the last bit, 1e-15 for the order of the product.
    assert [r["speed_kmh"] for r in rows] == pytest.approx([c["speed_kmh"] for c in written["critical_speeds"]], rel=1e-15)


def test_modes():
    vehicle = data("vehicles", "resort_car.toml")
    system = railmodal.assemble(railmodal.load_vehicle(vehicle), "all")
    assert only_in_python(railmodal.modes(system).records(), cli_json("modes", vehicle)["modes"]) == \
        ONLY_IN_PYTHON["modes"]
    damped = railmodal.damped_modes(system).records()
    assert only_in_python(damped, cli_json("modes", vehicle, "--damped")["modes"]) == ONLY_IN_PYTHON["damped modes"]


def test_ride(ride):
    result, written = ride
    outputs = [dict(o, speed_m_s=s["speed_m_s"]) for s in written["speeds"] for o in s["outputs"]]
    assert only_in_python(result.records(), outputs) == ONLY_IN_PYTHON["ride records"]
    # The indices with their unit under the JSON's keys, the same values (rel 1e-12 as test_ride.py:
    # the same library calls, the JSON printed to round trip).
    for key in ("weighted_rms_m_s2", "p95_estimate_m_s2"):
        assert [r[key] for r in result.records()] == pytest.approx([o[key] for o in outputs], rel=1e-12), key
    comfort = [c for s in written["speeds"] for c in s["comfort"]]
    assert only_in_python(result.comfort(), comfort) == ONLY_IN_PYTHON["ride comfort"]


def test_time_domain_ride():
    simulated, _ = railmodal.ride_scene_simulation(railmodal.load_scene(COACH_TIME_SHORT))
    written = cli_json("ride", COACH_TIME_SHORT)["time_domain"]
    assert only_in_python(simulated.records(), written["outputs"]) == ONLY_IN_PYTHON["time-domain ride records"]
    for key in ("weighted_rms_m_s2", "p95_m_s2"):  # rel 1e-12 as test_ride.py
        assert [r[key] for r in simulated.records()] == pytest.approx([o[key] for o in written["outputs"]], rel=1e-12), key
    assert only_in_python(simulated.comfort(), written["comfort"]) == ONLY_IN_PYTHON["time-domain ride comfort"]


def test_study():
    study = data("studies", "resort_against_fette.toml")
    results = railmodal.evaluate_study(railmodal.load_study(study))
    written = {v["name"]: v for v in cli_json("compare", study, "-q")["variants"]}
    for rows, key, name in ((results.modes(), "modes", "study modes"),
                            (results.critical_speeds(), "critical_speeds", "study critical speeds"),
                            (results.peaks(), "peaks", "study peaks"),
                            (results.deflections(), "dynamic_deflections", "study deflections")):
        objects = [o for v in written.values() for o in v[key]]
        assert only_in_python(rows, objects) == ONLY_IN_PYTHON[name]
        if key == "modes":
            continue
        # A source by its number from 1 in both (compare's JSON wrote its index from 0 as `source`).
        for variant, theirs in written.items():
            assert [r["source_index"] for r in rows if r["variant"] == variant] == \
                [o["source_index"] for o in theirs[key]], (name, variant)


def test_study_ride():
    """The largest Wz of a variant's ride is `max_wz` (the study metric's name) in Python and in
    compare's JSON alike; the JSON wrote `max_sperling_wz` before 2026-11-28."""
    study = data("studies", "two_axle_wagon_ride_springs.toml")
    results = railmodal.evaluate_study(railmodal.load_study(study))
    written = cli_json("compare", study, "-q")["variants"]
    objects = [o for v in written for o in v["ride"]]
    assert only_in_python(results.ride(), objects) == ONLY_IN_PYTHON["study ride"]
    by_variant = {(v["name"], o["output"]): o["max_wz"] for v in written for o in v["ride"]}
    # One double each side, printed by the JSON to round trip; a force output has none (None, null).
    assert {(r["variant"], r["output"]): r["max_wz"] for r in results.ride()} == by_variant
    assert any(w is not None for w in by_variant.values())


def test_balance(balance):
    study, written = balance
    assert only_in_python(study.gear.wheels, written["gear"]["wheels"]) == ONLY_IN_PYTHON["gear wheels"]
    # The gear's wheels named as the reports name them, "coupled 1 R", in the reports' order.
    assert [w["wheel"] for w in study.gear.wheels] == [w["wheel"] for w in written["gear"]["wheels"]]
    for rule in written["by_rule"]:
        result = study.by_rule[rule["rule"]]
        assert only_in_python(result.records(), rule["wheels"]) == ONLY_IN_PYTHON["balance wheels"]
        # The wheel as the reports name it, in the reports' order (user audit 2026-11-27c, F7).
        assert [r["wheel"] for r in result.records()] == [w["wheel"] for w in rule["wheels"]]
        assert [r["max_hammer_blow_n"] for r in result.records()] == [w["max_hammer_blow_n"] for w in rule["wheels"]]
    trade = study.by_rule["book"].trade_off()
    assert only_in_python(trade, written["by_rule"][2]["trade_off"]) == ONLY_IN_PYTHON["trade-off"]
    # The gear's wheels: the hammer blow and the signed extremes under the JSON's keys.
    for mine, theirs in zip(study.gear.wheels, written["gear"]["wheels"]):
        for key in ("max_hammer_blow_n", "max_dP_n", "min_dP_n", "least_load_n"):
            assert mine[key] == theirs[key], key  # one double, which the JSON prints to round trip


def test_fft_check():
    """A check's frequencies are named as `modes --damped` names them (undamped_frequency_hz,
    damped_frequency_hz) and the line's as a frequency (peak_frequency_hz), in Python and JSON alike
    (they were modal_hz, damped_hz and peak_hz before 2026-11-28)."""
    scene = data("scenes", "resort_car_free_response.toml")
    checks = railmodal.fft_check(railmodal.load_scene(scene)).checks
    written = cli_json("fft-check", scene)["checks"]
    assert only_in_python(checks, written) == ONLY_IN_PYTHON["fft-check"]
    for key in ("undamped_frequency_hz", "damped_frequency_hz", "peak_frequency_hz"):
        # rel 1e-12 as test_simulation.py: the same library run twice, the JSON printed to round trip.
        assert [c[key] for c in checks] == pytest.approx([w[key] for w in written], rel=1e-12), key
    damped = cli_json("modes", data("vehicles", "resort_car.toml"), "--damped")["modes"]
    assert {"undamped_frequency_hz", "damped_frequency_hz"} <= keys(damped)


def test_a_key_spelt_otherwise_is_caught():
    """The comparison can fail: the key the audit found (speed_km_h) is not the JSON's."""
    assert only_in_python([{"speed_km_h": 1.0, "mode": 1}], [{"speed_kmh": 1.0, "mode": 1}]) == {"speed_km_h"}
