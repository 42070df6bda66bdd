"""The driving gear's forces and its balancing (docs/python.md, "Balancing"), against
`railmodal balance` and Zhdanov's exact crank-pin force.

Tolerances: `railmodal balance --format json` writes every number with its unit in the key and
enough digits to read the double back (the shortest round trip); the binding runs the same
library calls, so the values agree to the last bit. rel=1e-12 (and an absolute 1e-6 N, kg for
values that are round-off around zero, ~1e-11 N here) leaves room only for a writer that prints
15 significant digits instead of 17, never for a different computation.
"""
import numpy as np
import pandas
import pytest

import railmodal
from railmodal_paths import cli, cli_json, data

SU = data("locomotives", "su.toml")
REL, ABS = 1e-12, 1e-6


@pytest.fixture(scope="module")
def report():
    return cli_json("balance", SU)


@pytest.fixture(scope="module")
def gear():
    return railmodal.load_driving_gear(SU)


def close(got, expected):
    np.testing.assert_allclose(got, expected, rtol=REL, atol=ABS)


def test_forces_every_15_degrees_equal_the_command_line(gear, report):
    forces = railmodal.driving_gear_forces(gear, gear.design_speed_m_s)
    assert forces.speed_m_s == pytest.approx(report["speed_m_s"], rel=REL) and forces.summary.passed
    states = report["gear"]["states_every_15_deg"]
    assert [s["crank_angle_deg"] for s in states] == list(range(0, 360, 15))
    for state in states:
        i = state["crank_angle_deg"]  # 360 steps a revolution: 1° apart
        assert np.degrees(forces.crank_angle_rad[i]) == pytest.approx(i, abs=1e-9)
        for c, cylinder in enumerate(state["cylinders"]):
            assert cylinder["cylinder"] == gear.cylinders[c]["name"]
            close([forces.horizontal_n[i, c], forces.vertical_n[i, c], forces.guide_n[i, c]],
                  [cylinder["X_n"], cylinder["Y_n"], cylinder["Z_n"]])
        close(forces.wheel_loads_n[i], [w["dP_n"] for w in state["wheel_loads"]])
        close([forces.surging_n[i], forces.nosing_n_m[i]], [state["surging_n"], state["nosing_n_m"]])
    close([forces.max_surging_n, forces.max_nosing_n_m], [report["gear"]["max_surging_n"], report["gear"]["max_nosing_n_m"]])
    wheels = pandas.DataFrame(forces.wheels)
    close(wheels["alpha"], [w["alpha"] for w in report["gear"]["wheels"]])
    assert list(wheels["wheel_lift"]) == [w["wheel_lift"] for w in report["gear"]["wheels"]]


def test_the_crank_pin_force_is_zhdanovs_exact_solution(gear):
    # driving_gear.hpp: the Су's right rod at 100 km/h, crank at 90°: Y = 4402 kgf (Zhdanov's
    # exact solution, Table 4, printed to the kgf, with g = 9.81). su.toml gives the rod's J in
    # kgf·m·s², which the reader converts with the standard 9.80665 m/s²: J is 0.035 % smaller
    # than the book's, and Y with it by up to that much (1.5 kgf); 4e-4 holds both and no more.
    forces = railmodal.driving_gear_forces(gear, 100 / 3.6)
    assert gear.cylinders[0]["name"] == "right"
    assert forces.vertical_n[90, 0] / 9.81 == pytest.approx(4402, rel=4e-4)


def test_harmonics_rebuild_the_forces(gear):
    forces = railmodal.driving_gear_forces(gear, gear.design_speed_m_s, harmonics=20)
    h = pandas.DataFrame(forces.harmonics())
    surging = h[h.quantity == "surging"]
    phi = forces.crank_angle_rad
    rebuilt = sum(r.cosine * np.cos(r.order * phi) + r.sine * np.sin(r.order * phi) for r in surging.itertuples())
    # Twenty harmonics of an analytic function of φ whose k-th harmonic falls as λᵏ (λ = r/L =
    # 0.15): what is left is below 0.15²¹ of the force, far under 1e-9 of it.
    np.testing.assert_allclose(rebuilt, forces.surging_n, rtol=0, atol=1e-9 * forces.max_surging_n)
    assert set(h.quantity) == {"horizontal", "vertical", "guide", "wheel_load", "surging", "nosing"}


def test_counterweights_equal_the_command_line(gear, report):
    study = railmodal.balance_study(gear)
    assert [r["rule"] for r in report["by_rule"]] == ["least_squares", "minimax", "book"]
    for expected in report["by_rule"]:
        result = study.by_rule[expected["rule"]]
        assert result.rule == expected["rule"]
        got = pandas.DataFrame(result.records())
        want = pandas.DataFrame(expected["wheels"])
        assert len(got) == len(want)
        for mine, theirs in (("rotating_mass_kg", "rotating_mass_kg"), ("vertical_mass_kg", "vertical_mass_kg"),
                             ("overbalance_mass_kg", "overbalance_mass_kg"), ("total_mass_kg", "total_mass_kg"),
                             ("max_hammer_blow_n", "max_hammer_blow_n"), ("alpha", "alpha"), ("alpha_89a", "alpha_89a")):
            close(got[mine], want[theirs])
        # Angles: the report's degrees are the binding's radians, within a turn (a mass of zero
        # has angle 0 in both).
        close(np.degrees(got["total_angle_rad"]), want["total_angle_deg"])
        close([result.percent_unbalanced_surging, result.percent_unbalanced_nosing],
              [expected["unbalanced_surging_percent"], expected["unbalanced_nosing_percent"]])
    trade = pandas.DataFrame(study.by_rule["book"].trade_off())
    expected = pandas.DataFrame(report["by_rule"][2]["trade_off"])
    close(trade["balanced_fraction"], expected["balanced_fraction"])
    close(trade["max_alpha"], expected["max_alpha"])
    close(trade["max_surging_n"], expected["max_surging_n"])
    close(trade["max_nosing_n_m"], expected["max_nosing_n_m"])
    assert study.by_rule["minimax"].trade_off() == []  # only the rule asked for has one
    assert study.axle_names == gear.axle_names


def test_balancing_removes_the_rotating_unbalance(gear):
    result = railmodal.balance(gear, rule="minimax", allowed_alpha=0.3)
    # The wheels' rotating masses are balanced exactly (the summary checks it); a coupled wheel
    # is overbalanced up to α = 0.3 by eq. (89a).
    assert result.summary.passed
    after = pandas.DataFrame(result.after.wheels)
    assert after["alpha_89a"].max() == pytest.approx(0.3, abs=1e-9) or after["alpha_89a"].max() < 0.3
    counterweights = pandas.DataFrame(result.balanced.masses)
    assert {"counterweight", "overbalance"} <= set(counterweights["name"])
    assert result.before.max_surging_n > 0 and result.percent_unbalanced_surging > 0


def test_balance_errors(gear):
    with pytest.raises(ValueError, match="rule: 'median' is not one of"):
        railmodal.balance(gear, rule="median")
    with pytest.raises(ValueError, match="BalanceOptions"):
        railmodal.balance(gear, allowed_alpha=1.5)
    with pytest.raises(ValueError):
        railmodal.driving_gear_forces(gear, 20.0, steps=4)
    bad = data("vehicles", "resort_car.toml")  # no [driving_gear] table
    code, _, stderr = cli("balance", bad, check=False)
    with pytest.raises(railmodal.InputError) as error:
        railmodal.load_driving_gear(bad)
    assert code == 3 and error.value.file == bad and str(error.value) in stderr


def test_speed_at_alpha_scales_as_the_square():
    assert railmodal.speed_at_alpha(0.2, 20.0, 0.8) == pytest.approx(40.0, rel=1e-15)


def test_the_gear_as_an_excitation_is_the_scenes_source(gear):
    # data/scenes/su_driving_gear.toml names the gear, the frame, the axles' places and bodies:
    # the same GearExcitation made in Python drives the engine exactly as the scene's source.
    scene = railmodal.load_scene(data("scenes", "su_driving_gear.toml"))
    study = railmodal.study_critical_speeds(scene)
    mine = railmodal.gear_excitation(gear, body="frame", axles=[(2.05, "axle1"), (0.0, "axle2"), (-2.05, "axle3")],
                                     crank_angle_rad=0.0, harmonics=3)
    v = np.linspace(5 / 3.6, 110 / 3.6, 50)
    outputs = ["frame.yaw", "frame.roll", "axle2.roll"]
    want = railmodal.amplitude_curves(study.system, study.modes, scene.sources[0], outputs, v)
    got = railmodal.amplitude_curves(study.system, study.modes, mine, outputs, v)
    for g, w in zip(got, want):
        np.testing.assert_array_equal(g.amplitudes, w.amplitudes)
        assert np.nanmax(g.amplitudes) > 0.0
    # One harmonic only: a different excitation (the second harmonic is what counterweights leave).
    first = railmodal.amplitude_curves(study.system, study.modes,
                                       railmodal.gear_excitation(gear, body="frame", harmonics=1), outputs, v)
    assert not np.array_equal(first[0].amplitudes, want[0].amplitudes)
    with pytest.raises(ValueError):
        railmodal.gear_excitation(gear, body="frame", harmonics=0)
    # Without `harmonics`, the binding takes GearExcitation's default, three, as a scene does.
    assert railmodal.gear_excitation(gear, body="frame").harmonic_count == 3
