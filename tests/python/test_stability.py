"""Hunting stability, the nonlinear critical speed and the static lateral stability
(docs/python.md, "Hunting stability"), against `railmodal stability` and `railmodal compare`.

Tolerances: the binding and the command line run the same library call on the same file, so
they agree to the digits the JSON writer prints; rtol=1e-12 holds any writer that prints 13
significant digits or more.
"""
import json

import numpy as np
import pandas
import pytest

import railmodal
from railmodal_paths import cli_json, data

WHEELSET = data("vehicles", "wheelset_on_springs.toml")
REL = 1e-12
SAME = dict(rtol=REL, atol=0)


@pytest.fixture(scope="module")
def locus():
    return railmodal.hunting_stability(WHEELSET, speed_count=20, conicities=[0.1, 0.2], threads=1)


def test_every_branch_interval_and_the_rigid_bogie_frequency_on_the_coach():
    # Two branches of the coach go unstable, overlapping (docs/stability.md, "Reading the
    # output"): each is listed with its number, as the command line lists them.
    coach = data("vehicles", "manchester_benchmark_coach_wheelsets.toml")
    got = railmodal.hunting_stability(coach, threads=1)
    expected = cli_json("stability", coach, "--threads", "1")
    assert len(got.unstable_intervals) == len(expected["unstable_intervals"]) >= 2
    for g, e in zip(got.unstable_intervals, expected["unstable_intervals"]):
        assert (g["branch"], g["branch_number"]) == (e["branch"], e["branch_number"])
        assert got.branches[g["branch_number"] - 1] == g["branch"]
        assert g["from_m_s"] == pytest.approx(e["from_m_s"], rel=REL)
    assert got.critical["bogie_frequency_hz"] == pytest.approx(expected["critical"]["bogie_frequency_hz"], rel=REL)


def test_root_locus_equals_the_command_line(locus):
    expected = cli_json("stability", WHEELSET, "--speed-count", "20", "--conicity", "0.1,0.2", "--threads", "1")
    assert locus.verdict == expected["verdict"] == "critical_speed_in_range"
    np.testing.assert_allclose(locus.speeds_m_s, expected["speeds_m_s"], **SAME)
    assert locus.branches == [b["name"] for b in expected["branches"]]
    assert locus.eigenvalues.shape == locus.damping_ratio.shape == (20, len(locus.branches))
    for j, branch in enumerate(expected["branches"]):
        np.testing.assert_allclose(locus.eigenvalues[:, j].real, branch["eigenvalue_re"], **SAME)
        np.testing.assert_allclose(locus.eigenvalues[:, j].imag, branch["eigenvalue_im"], **SAME)
        np.testing.assert_allclose(locus.damping_ratio[:, j], branch["damping_ratio"], **SAME)
        np.testing.assert_allclose(locus.frequency_hz[:, j], branch["frequency_hz"], **SAME)
        np.testing.assert_allclose(locus.continuity[:, j], branch["continuity"], **SAME)
        assert locus.veers[j] == branch["veers"]
    critical = locus.critical
    for key in ("speed_m_s", "frequency_hz", "klingel_frequency_hz"):
        assert critical[key] == pytest.approx(expected["critical"][key], rel=REL)
    assert (critical["branch"], critical["motion"]) == (expected["critical"]["branch"], expected["critical"]["motion"])
    assert critical["bogie_frequency_hz"] is None and expected["critical"]["bogie_frequency_hz"] is None  # no bogies
    (interval,) = locus.unstable_intervals
    assert interval["from_m_s"] == pytest.approx(critical["speed_m_s"], rel=REL) and interval["to_highest_speed"]
    assert interval["branch_number"] == expected["unstable_intervals"][0]["branch_number"]
    for got, want in zip(locus.conicity_curve, expected["conicity_curve"]):
        assert got["conicity"] == want["conicity"] and got["verdict"] == want["verdict"]
        assert got["critical_speed_m_s"] == pytest.approx(want["critical"]["speed_m_s"], rel=REL)
    (contact,) = locus.contacts
    assert contact == pytest.approx({k: v for k, v in expected["contacts"][0].items() if k != "ellipse"} | {
        "axle_load_source": contact["axle_load_source"]})
    assert locus.summary.analysis == expected["summary"]["analysis"]


def test_a_higher_conicity_hunts_at_a_lower_speed(locus):
    # Klingel: the kinematic frequency grows as √λ, and the critical speed falls with λ.
    speeds = [p["critical_speed_m_s"] for p in locus.conicity_curve]
    assert speeds[0] > locus.critical["speed_m_s"] > speeds[1]


def test_the_locus_as_a_table(locus):
    frame = pandas.DataFrame(locus.as_dict())
    assert len(frame) == 20 * len(locus.branches)
    assert frame.equals(pandas.DataFrame(locus.records()))
    first = frame[frame["branch"] == locus.branches[0]]
    np.testing.assert_array_equal(first["damping_ratio"], locus.damping_ratio[:, 0])
    np.testing.assert_array_equal(first["speed_m_s"], locus.speeds_m_s)
    assert locus.speeds_m_s.base is not None and not locus.speeds_m_s.flags.writeable


def test_a_vehicle_object_and_an_assembly_give_the_same_locus(locus):
    vehicle = railmodal.load_vehicle(WHEELSET)
    by_vehicle = railmodal.hunting_stability(vehicle, speed_count=20, threads=1)
    by_system = railmodal.hunting_stability(railmodal.assemble(vehicle, "lateral"), speed_count=20, threads=1)
    np.testing.assert_array_equal(by_vehicle.eigenvalues, by_system.eigenvalues)
    np.testing.assert_array_equal(by_vehicle.eigenvalues, locus.eigenvalues)


def test_the_damping_threshold_speed_equals_the_command_line():
    result = railmodal.hunting_stability(WHEELSET, damping_threshold=0.05, threads=1)
    expected = cli_json("stability", WHEELSET, "--threshold", "5%", "--threads", "1")
    assert result.damping_threshold == 0.05
    assert result.threshold_speed_m_s == pytest.approx(expected["threshold_speed_m_s"], rel=REL)
    assert result.threshold_branch == expected["threshold_branch"]
    assert result.below_threshold_at_lowest_speed == expected["below_threshold_at_lowest_speed"]


def test_stability_errors():
    with pytest.raises(ValueError, match="wheelset"):  # the resort car has none
        railmodal.hunting_stability(data("vehicles", "resort_car.toml"))
    with pytest.raises(ValueError, match="speed"):
        railmodal.hunting_stability(WHEELSET, min_speed_m_s=50.0, max_speed_m_s=10.0)
    with pytest.raises(TypeError):
        railmodal.hunting_stability(WHEELSET, speeds=3)
    with pytest.raises(railmodal.InputError):
        railmodal.hunting_stability(data("vehicles", "no_such_vehicle.toml"))


@pytest.fixture(scope="module")
def nonlinear():
    # A short ramp from 80 to 20 m/s at the wheel load the creep coefficients were sized for
    # (nonlinear_hunting.hpp's example).
    return railmodal.nonlinear_hunting(WHEELSET, wheel_load_n=50e3, start_speed_m_s=80.0, end_speed_m_s=20.0)


def test_nonlinear_hunting_returns_its_bifurcation_curve(nonlinear):
    assert nonlinear.verdict in ("limit_cycle_dies_out", "survives_to_end_speed", "no_limit_cycle_at_start",
                                 "unbounded_growth")
    curve = nonlinear.curve
    assert len(curve["speed_m_s"]) == len(curve["amplitude_m"]) > 0
    # The ramp runs downward from the start speed: every half cycle lies within the ramp.
    assert np.all(curve["speed_m_s"] <= 80.0) and np.all(curve["speed_m_s"] >= 20.0 - 1.0)
    np.testing.assert_array_equal(curve["speed_m_s"], nonlinear.stated_rate["curve"]["speed_m_s"])
    assert nonlinear.halved_rate["ramp_rate_m_s2"] == pytest.approx(nonlinear.stated_rate["ramp_rate_m_s2"] / 2)
    if nonlinear.critical_speed_m_s is not None:
        # Saturation and the flange keep a limit cycle alive below the linear critical speed
        # (a subcritical bifurcation), never above it.
        linear = railmodal.hunting_stability(WHEELSET, threads=1).critical["speed_m_s"]
        assert 20.0 <= nonlinear.critical_speed_m_s <= linear * (1 + 1e-6)
    assert nonlinear.convergence in ("converged", "not_converged", "not_applicable")
    assert nonlinear.converged == (nonlinear.convergence == "converged")
    # The flags the reports write (JSON ramp_too_fast, collapsing_at_end_speed,
    # not_converged_reason) are the result's too: a reason exactly when not converged.
    assert isinstance(nonlinear.ramp_too_fast, bool) and isinstance(nonlinear.collapsing_at_end_speed, bool)
    assert (nonlinear.not_converged_reason is None) == (nonlinear.convergence != "not_converged")


def test_a_ramp_too_fast_says_so_as_the_report_does(tmp_path):
    # The bundled scene at ten times its ramp rate (5 m/s²): the ramp drags the cycle down before
    # it settles, far above the held speed; the result's flags and reason are the JSON report's.
    text = open(data("scenes", "wheelset_on_springs_nonlinear_hunting.toml"), encoding="utf-8").read()
    text = text.replace('ramp_rate = "0.5 m/s^2"', 'ramp_rate = "5 m/s^2"')
    text = text.replace('vehicle = "../vehicles/', 'vehicle = "%s/' % data("vehicles"))
    assert '"5 m/s^2"' in text
    scene_file = tmp_path / "fast_ramp.toml"
    scene_file.write_text(text, encoding="utf-8")
    scene = railmodal.load_scene(str(scene_file))
    result = railmodal.hunting_scene(scene)
    report = json.loads(railmodal.hunting_report(scene, format="json"))
    assert result.ramp_too_fast and report["ramp_too_fast"]
    assert result.collapsing_at_end_speed == report["collapsing_at_end_speed"]
    assert result.convergence == "not_converged"
    assert result.not_converged_reason == report["not_converged_reason"]
    assert "the ramp is too fast" in result.not_converged_reason


def test_nonlinear_hunting_errors():
    with pytest.raises(ValueError, match="effects: 'creep' is not one of"):
        railmodal.nonlinear_hunting(WHEELSET, effects=["creep"])
    with pytest.raises(ValueError):  # NonlinearHuntingOptions::is_valid: end above start
        railmodal.nonlinear_hunting(WHEELSET, start_speed_m_s=10.0, end_speed_m_s=20.0)


def test_lateral_stability_equals_the_studys_metacentric_height():
    resort = data("vehicles", "resort_car.toml")
    s = railmodal.lateral_stability(resort, "body")
    # The study evaluates eq. (235b) for its base variant, the resort car.
    study = cli_json("compare", data("studies", "resort_against_fette.toml"), "-q")
    base = next(v for v in study["variants"] if v["name"] == "base")
    assert s.metacentric_height_m == pytest.approx(base["metacentric_height_m"], rel=REL)
    assert s.margin_m == pytest.approx(s.metacentric_height_m - s.cg_height_m, rel=1e-15)
    assert s.nolltein_measure(1.0) == pytest.approx(s.metacentric_height_m / s.cg_height_m, rel=1e-15)
    with pytest.raises(ValueError):
        railmodal.lateral_stability(resort, "no such body")


def test_a_scenes_nonlinear_hunting_equals_the_command_line():
    scene_file = data("scenes", "wheelset_on_springs_nonlinear_hunting.toml")
    scene = railmodal.load_scene(scene_file)
    expected = cli_json("hunting", scene_file)
    # hunting_report runs hunting_scene's ramp (the same function, python/src/bind_stability.cpp)
    # and writes the command's own report: every key and number equal (one run of each, ~1.3 s,
    # so hunting_scene's result is not run a third time here).
    report = json.loads(railmodal.hunting_report(scene, format="json"))
    assert report == expected and report["convergence"] == "converged"
    with pytest.raises(railmodal.InputError, match="no \\[nonlinear_hunting\\] table"):
        railmodal.hunting_scene(railmodal.load_scene(data("scenes", "resort_car_10m_rails.toml")))
    with pytest.raises(ValueError, match="format is 'pdf'"):
        railmodal.hunting_report(scene, format="pdf")


def test_the_holds_give_their_growth_rates_as_the_json_does():
    # Each hold's fitted growth rate, its error and what they decided (survives, undecided) are
    # the result's, under the JSON's names, equal to what 'railmodal hunting' writes for the
    # same scene (the same library call: equal to the JSON's printed digits, REL).
    scene_file = data("scenes", "wheelset_on_springs_nonlinear_hunting.toml")
    result = railmodal.hunting_scene(railmodal.load_scene(scene_file))
    expected = cli_json("hunting", scene_file)["hold"]["holds"]
    holds = result.hold["holds"]
    assert len(holds) == len(expected) > 0
    for got, want in zip(holds, expected):
        assert got["speed_m_s"] == pytest.approx(want["speed_m_s"], rel=REL)
        assert (got["survives"], got["undecided"]) == (want["survives"], want["undecided"])
        assert not (got["survives"] and got["undecided"])  # an undecided hold never counts as surviving
        assert got["rate_per_period"] == pytest.approx(want["rate_per_period"], rel=REL, abs=1e-300)
        # The JSON writes an infinite error (too few half cycles) as null.
        assert got["rate_error"] == (pytest.approx(want["rate_error"], rel=REL, abs=1e-300)
                                     if want["rate_error"] is not None else float("inf"))
        assert got["rate_change_per_period"] == pytest.approx(want["rate_change_per_period"], rel=REL, abs=1e-300)
        assert got["rate_change_error"] == (pytest.approx(want["rate_change_error"], rel=REL, abs=1e-300)
                                            if want["rate_change_error"] is not None else float("inf"))
    assert set(pandas.DataFrame(holds).columns) >= {"rate_per_period", "rate_error", "undecided",
                                                    "rate_change_per_period", "rate_change_error"}


def test_limit_cycles_scene_is_the_commands_continuation():
    # limit_cycles_scene runs continue_limit_cycles on the scene's model, as
    # 'railmodal hunting --continuation' does: the same branch, to the last digit the JSON keeps.
    scene_file = data("scenes", "wheelset_on_springs_nonlinear_hunting.toml")
    branch = railmodal.limit_cycles_scene(railmodal.load_scene(scene_file))
    expected = cli_json("hunting", scene_file, "--continuation")["continuation"]
    assert branch["kind"] == expected["kind"] == "subcritical"
    assert branch["fold"]["speed_m_s"] == expected["fold"]["speed_m_s"]
    assert branch["hopf_speed_m_s"] == expected["hopf_speed_m_s"]
    assert list(branch["points"]["amplitude_m"]) == [p["amplitude_m"] for p in expected["points"]]
    assert branch["points"]["stable"] == [p["stable"] for p in expected["points"]]
    # The fold lies below the Hopf point (subcritical); unstable orbits come first.
    assert branch["fold"]["speed_m_s"] < branch["hopf_speed_m_s"]
    assert not branch["points"]["stable"][0]
    with pytest.raises(ValueError, match="newton_tolerance"):
        railmodal.limit_cycles_scene(railmodal.load_scene(scene_file), newton_tolerance=0.0)
