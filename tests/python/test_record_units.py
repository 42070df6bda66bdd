"""Every field of the package's records says its unit (user audit 2026-11-27: a VAMPIRE/SIMPACK
user could not tell the unit of `rms`, `amplitude` or `eigenvalue` from the records alone).

A key has a unit suffix of docs/input.md's rule ("Names and units in outputs": `speed_m_s`,
`frequency_hz`), or a row of docs/python.md's table "The records' fields and their units" gives
its unit (or says it is a word, a count or a flag). The records checked are those of every
analysis, on the bundled data; a new key without either fails here. The docstrings of the
records' methods name every key they return, each with its unit where it has one.
"""
import re

import pytest

import railmodal
from railmodal_paths import SOURCE, data

# docs/input.md's suffixes, and the compound ones the package uses (kg·m², N·m²).
SUFFIXES = ("_m", "_s", "_hz", "_deg", "_rad", "_kg", "_n", "_n_m", "_n_m2", "_kg_m2", "_m_s", "_m_s2",
            "_rad_s", "_kmh", "_per_s")


def documented_keys():
    """The keys of docs/python.md's units table (its first column), with the unit column of each."""
    text = (SOURCE / "docs" / "python.md").read_text(encoding="utf-8")
    section = text.split("## The records' fields and their units", 1)[1].split("\n## ", 1)[0]
    keys = {}
    for line in section.splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) < 2 or not line.startswith("| `"):
            continue
        for key in re.findall(r"`([a-z0-9_]+)`", cells[0]):
            keys[key] = cells[1]
    return keys


def undocumented(keys, table, exempt=()):
    return sorted(k for k in set(keys) if not k.endswith(SUFFIXES) and k not in table and k not in exempt)


def keys_of(rows):
    out = set()
    for row in rows:
        out.update(row.keys())
    return out


def test_the_table_is_there_and_gives_every_row_a_unit():
    table = documented_keys()
    assert {"rms", "amplitude", "eigenvalue", "variance", "share", "damping_ratio"} <= set(table)
    assert all(unit for unit in table.values()), table  # no row without its unit (or its kind)


@pytest.fixture(scope="module")
def table():
    return documented_keys()


@pytest.fixture(scope="module")
def modal():
    system = railmodal.assemble(railmodal.load_vehicle(data("vehicles", "resort_car.toml")), dofs="all")
    return railmodal.modes(system)


@pytest.fixture(scope="module")
def ride():
    return railmodal.ride_scene(railmodal.load_scene(data("scenes", "manchester_coach_ore_low.toml")),
                                speeds_m_s=[160 / 3.6])


@pytest.fixture(scope="module")
def critical():
    return railmodal.study_critical_speeds(railmodal.load_scene(data("scenes", "resort_car_10m_rails.toml")))


@pytest.fixture(scope="module")
def locus():
    return railmodal.hunting_stability(data("vehicles", "wheelset_on_springs.toml"), conicities=[0.1, 0.3])


def test_modes_and_summaries(table, modal):
    coach = railmodal.assemble(railmodal.load_vehicle(data("vehicles", "manchester_benchmark_coach.toml")))
    damped = railmodal.damped_modes(coach)
    for rows in (modal.records(), damped.records(), damped.summary.checks, damped.summary.stages):
        assert undocumented(keys_of(rows), table) == []


def test_critical_speeds_and_curves(table, critical):
    assert undocumented(keys_of(critical.critical_speeds.records()), table) == []
    assert undocumented(keys_of(critical.critical_speeds.output_records()), table) == []
    assert undocumented(critical.curves[0].as_dict().keys(), table) == []


def test_ride(table, ride):
    for rows in (ride.records(), ride.comfort(), ride.contributions()):
        assert rows
        assert undocumented(keys_of(rows), table) == []


def test_stability(table, locus):
    rows = [locus.critical] + locus.conicity_curve + locus.contacts + locus.unstable_intervals + locus.records()
    assert undocumented(keys_of(r for r in rows if r), table) == []


def test_balance(table):
    su = railmodal.load_driving_gear(data("locomotives", "su.toml"))
    forces = railmodal.driving_gear_forces(su, su.design_speed_m_s)
    balanced = railmodal.balance(su, rule="minimax", allowed_alpha=0.3)
    for rows in (forces.wheels, forces.harmonics(), balanced.records()):
        assert undocumented(keys_of(rows), table) == []


def test_simulation(table):
    check = railmodal.fft_check(railmodal.load_scene(data("scenes", "resort_car_free_response.toml")))
    assert undocumented(keys_of(check.records()), table) == []
    spectrum = next(iter(check.spectra.values()))
    assert undocumented(keys_of(spectrum.peaks()), table) == []


def test_studies(table):
    study = railmodal.load_study(data("studies", "resort_against_fette.toml"))
    ranked = railmodal.compare(study)
    metrics = [c["metric"] for c in ranked.ranking["objective"]]  # a criterion's key is its metric's name
    assert undocumented(keys_of(ranked.records()), table, exempt=metrics) == []
    results = ranked.results
    for rows in (results.modes(), results.critical_speeds(), results.peaks(), results.deflections(),
                 results.static_deflections()):
        assert undocumented(keys_of(rows), table) == []


# The records' docstrings name every key their rows have (the units beside them, as written).
def docstring_names_every_key(method, rows):
    doc = method.__doc__
    missing = sorted(k for k in keys_of(rows) if not re.search(r"\b%s\b" % re.escape(k), doc))
    assert missing == [], "%s: %s" % (method.__qualname__ if hasattr(method, "__qualname__") else method, doc)


def test_docstrings_name_every_key(modal, ride, critical, locus):
    docstring_names_every_key(type(modal).records, modal.records())
    docstring_names_every_key(type(ride).records, ride.records())
    docstring_names_every_key(type(ride).comfort, ride.comfort())
    docstring_names_every_key(type(ride).contributions, ride.contributions())
    docstring_names_every_key(type(critical.critical_speeds).records, critical.critical_speeds.records())
    docstring_names_every_key(type(critical.critical_speeds).output_records, critical.critical_speeds.output_records())
    docstring_names_every_key(type(locus).as_dict, locus.records())
    docstring_names_every_key(type(locus).records, locus.records())


def test_a_docstring_without_a_key_fails():
    """The check above can fail: a docstring that leaves out one key is caught."""
    class Fake:
        def records(self):
            """One row: speed_m_s (m/s)."""

    with pytest.raises(AssertionError):
        docstring_names_every_key(Fake.records, [{"speed_m_s": 1.0, "rms": 2.0}])
