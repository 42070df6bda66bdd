"""Design studies from a file and variants built in Python (docs/python.md, "Studies"), against
`railmodal compare`.

Tolerances: the binding and the command line run the same library calls on the same files, so
they agree to the digits the JSON writer prints; rtol=1e-12 holds any writer that prints 13
significant digits or more. Variants evaluated by evaluate_study and by evaluate_variants go
through the same evaluate_variant: their results are equal, bit for bit.
"""
import numpy as np
import pandas
import pytest

import railmodal
from railmodal_paths import cli, cli_json, data

STUDY = data("studies", "resort_against_fette.toml")
REL = 1e-12


@pytest.fixture(scope="module")
def study():
    return railmodal.load_study(STUDY)


@pytest.fixture(scope="module")
def expected():
    return cli_json("compare", STUDY, "-q")


def test_compare_equals_the_command_line(study, expected):
    comparison = railmodal.compare(study)
    frame = pandas.DataFrame(comparison.records())
    assert list(frame["name"]) == [v["name"] for v in expected["variants"]]
    assert list(frame["rank"]) == [v["rank"] for v in expected["variants"]]
    assert list(frame["feasible"]) == [v["feasible"] for v in expected["variants"]]
    assert list(frame["objective"]) == pytest.approx([v["objective"] for v in expected["variants"]], rel=REL)
    # The objective's criterion is a column named by its metric.
    assert list(frame["period:body bounce"]) == pytest.approx([v["criteria"][0] for v in expected["variants"]], rel=REL)
    assert list(frame["metacentric_height_m"]) == pytest.approx(
        [v["metacentric_height_m"] for v in expected["variants"]], rel=REL)
    # The JSON writes an unbounded resonance's ratio as "unbounded"; the binding keeps +inf.
    ratios = [np.inf if v["dynamic_deflection_ratio"] == "unbounded" else v["dynamic_deflection_ratio"]
              for v in expected["variants"]]
    assert list(frame["dynamic_deflection_ratio"]) == pytest.approx(ratios, rel=REL)
    lowest = [min(v["critical_speeds_kmh"]) / 3.6 for v in expected["variants"]]
    assert list(frame["lowest_critical_speed_m_s"]) == pytest.approx(lowest, rel=REL)
    assert comparison.ranking["objective"][0]["maximise"]


def test_evaluate_study_tables(study, expected):
    results = railmodal.evaluate_study(study, threads=2)
    assert len(results) == 4 and results.summary.analysis.startswith("design study")
    modes = pandas.DataFrame(results.modes())
    by_name = {v["name"]: v for v in expected["variants"]}
    for name, group in modes.groupby("variant", sort=False):
        assert list(group["period_s"]) == pytest.approx(by_name[name]["periods_s"], rel=REL)
    speeds = pandas.DataFrame(results.critical_speeds())
    base = speeds[speeds.variant == "base"]
    assert list(base["speed_m_s"]) == pytest.approx(
        [c["speed_m_s"] for c in by_name["base"]["critical_speeds"]], rel=REL)
    deflections = pandas.DataFrame(results.deflections())
    kept = deflections.groupby("variant")["kept"].all()
    assert {name: bool(k) for name, k in kept.items()} == {
        name: v["keeps_permissible_deflections"] for name, v in by_name.items()}
    np.testing.assert_array_equal(results.metric("bounce_period"),
                                  [by_name[n]["periods_s"][0] for n in ("base", "Fette car",
                                   "resort car, softer cradle springs", "resort car, stiffer cradle springs")])
    assert len(pandas.DataFrame(results.static_deflections())) == 4 * 3  # body and two bogies
    assert railmodal.metric_unit("lowest_critical_speed") == "m/s"


def test_the_thread_count_does_not_change_the_results(study):
    one = pandas.DataFrame(railmodal.evaluate_study(study, threads=1).records())
    two = pandas.DataFrame(railmodal.evaluate_study(study, threads=2).records())
    assert one.equals(two)


def test_variants_built_in_python_equal_the_studys(study):
    scene = railmodal.load_scene(data("scenes", "fette_car_10m_rails.toml"))
    resort = railmodal.load_vehicle(data("vehicles", "resort_car.toml"))
    fette = railmodal.load_vehicle(data("vehicles", "fette_car.toml"))
    batch = railmodal.evaluate_variants(scene, [resort, fette], names=["base", "Fette car"],
                                        deflection_rule="lehner", service="passenger")
    from_file = pandas.DataFrame(railmodal.evaluate_study(study).records()).iloc[:2]
    mine = pandas.DataFrame(batch.records())
    for column in ("name", "lowest_critical_speed_m_s", "metacentric_height_m", "dynamic_deflection_ratio", "mode_count"):
        assert list(mine[column]) == list(from_file[column]), column


def test_a_sweep_over_cradle_stiffness_in_one_call():
    scene = railmodal.load_scene(data("scenes", "fette_car_10m_rails.toml"))
    base = railmodal.load_vehicle(data("vehicles", "resort_car.toml"))
    factors = [0.8, 1.0, 1.25]
    vehicles = []
    for factor in factors:
        v = base.copy()
        elements = v.elements
        for e in elements:
            if e.name.endswith("cradle"):
                stages = e.vertical_stages
                for s in stages:
                    s.stiffness *= factor
                e.vertical_stages = stages
        v.elements = elements
        vehicles.append(v)
    results = railmodal.evaluate_variants(scene, vehicles, threads=2)
    period = results.metric("bounce_period")
    # Stiffer cradle springs: a shorter bounce period, monotonically.
    assert period[0] > period[1] > period[2]
    assert [r["name"] for r in results.records()] == [base.name] * 3


def test_study_errors(tmp_path):
    bad = tmp_path / "bad.toml"
    bad.write_text('[study]\nname = "x"\nvehicle = "nothing.toml"\nscene = "nothing.toml"\n')
    code, _, stderr = cli("compare", str(bad), check=False)
    with pytest.raises(railmodal.InputError) as error:
        railmodal.load_study(bad)
    assert code == 3 and str(error.value).split(": error")[0] in stderr
    scene = railmodal.load_scene(data("scenes", "fette_car_10m_rails.toml"))
    resort = railmodal.load_vehicle(data("vehicles", "resort_car.toml"))
    with pytest.raises(ValueError, match="names: 2 names for 1 vehicles"):
        railmodal.evaluate_variants(scene, [resort], names=["a", "b"])
    with pytest.raises(ValueError, match="deflection_rule: 'din' is not one of"):
        railmodal.evaluate_variants(scene, [resort], deflection_rule="din")
    with pytest.raises(ValueError, match="is not a metric"):
        railmodal.evaluate_variants(scene, [resort]).metric("comfort")


def test_the_hunting_speed_of_a_variant_is_the_hunting_stabilitys():
    # evaluate_variant runs solve_hunting_stability of the lateral assembly with HuntingOptions'
    # defaults on one thread: the same call as hunting_stability(vehicle, threads=1).
    coach = railmodal.load_vehicle(data("vehicles", "manchester_benchmark_coach_wheelsets.toml"))
    vertical = railmodal.load_scene(data("scenes", "resort_car_10m_rails.toml"))
    (row,) = railmodal.evaluate_variants(vertical, [coach], hunting_speed=True).records()
    assert row["ok"] and row["hunting_speed_m_s"] == railmodal.hunting_stability(coach, threads=1).critical["speed_m_s"]
    without = railmodal.evaluate_variants(vertical, [coach]).records()[0]
    assert without["hunting_speed_m_s"] is None  # not asked: not computed


def test_a_variant_that_cannot_be_evaluated_is_a_row_with_its_failure():
    coach = railmodal.load_vehicle(data("vehicles", "manchester_benchmark_coach_wheelsets.toml"))
    hunting = railmodal.load_scene(data("scenes", "manchester_coach_hunting.toml"))  # lateral track inputs
    (row,) = railmodal.evaluate_variants(hunting, [coach]).records()
    assert not row["ok"] and "wheel–rail contact" in row["failure"] and row["lowest_critical_speed_m_s"] is None


def test_a_ride_study_tables_its_ride():
    study = railmodal.load_study(data("studies", "two_axle_wagon_ride_springs.toml"))
    # The study file, its scene and the vehicle files it reads, each once.
    assert [f.split("/")[-1] for f in study.files] == [
        "two_axle_wagon_ride_springs.toml", "two_axle_wagon_fra_class4.toml", "two_axle_freight_wagon.toml"]
    names = [v["name"] for v in study.variants()]
    expected = cli_json("compare", data("studies", "two_axle_wagon_ride_springs.toml"), "-q")
    comparison = railmodal.compare(study)
    assert [r["name"] for r in comparison.results.records()] == [v["name"] for v in expected["variants"]]
    ride = pandas.DataFrame(railmodal.evaluate_study(study).ride())
    assert set(ride["variant"]) == set(names) and (ride["max_rms"] > 0).all()
    assert ride["max_wz"].notna().any()


def test_variants_read_in_the_workers_give_the_same_results():
    path = data("studies", "resort_against_fette.toml")
    read = railmodal.evaluate_study(railmodal.load_study(path), threads=2)
    named = railmodal.load_study(path, read_variants=False)  # names only: each read by its worker
    in_workers = railmodal.evaluate_study(named, threads=2, read_in_workers=True)
    assert pandas.DataFrame(in_workers.records()).equals(pandas.DataFrame(read.records()))
    with pytest.raises(ValueError):  # EvaluationOptions: a variant not read needs read_in_workers
        railmodal.evaluate_study(named, threads=2)
