"""Harmonic response, FRFs, critical speeds and amplitude curves (docs/python.md)."""
import numpy as np
import pandas
import pytest

import railmodal
from railmodal_paths import cli_json, data

SCENE = data("scenes", "resort_car_10m_rails.toml")


def two_dof(damping=0.02):
    M = np.diag([2.0, 1.0])
    K = np.array([[3000.0, -1000.0], [-1000.0, 1000.0]])
    return railmodal.LinearSystem(M, K, damping * K)


def test_harmonic_response_solves_the_dynamic_stiffness_at_every_frequency():
    system = two_dof()
    modes = railmodal.modes(system)
    f = np.linspace(0.0, 12.0, 97)
    load = np.array([1.0, 0.5j])
    sweep = railmodal.harmonic_response(system, modes, load, f)
    assert sweep.values.shape == (len(f), 2) and sweep.outputs == ["dof1", "dof2"]
    w = 2 * np.pi * f
    expected = np.array([np.linalg.solve(system.K - wi**2 * system.M + 1j * wi * system.C, load) for wi in w])
    # Both LU-solve a 2 x 2 system of condition number below 1e3: agreement to ~1e-13.
    np.testing.assert_allclose(sweep.values, expected, rtol=1e-11)
    assert not sweep.unbounded.any()
    assert sweep.values.base is not None and not sweep.values.flags.writeable


def test_frf_quantities_and_modal_method():
    system = two_dof()
    modes = railmodal.modes(system)
    f = np.array([0.5, 3.0, 7.0])
    receptance = railmodal.frf(system, modes, "dof1", f, outputs=["dof2"])
    mobility = railmodal.frf(system, modes, 0, f, outputs=[1], quantity="velocity")
    accelerance = railmodal.frf(system, modes, 0, f, outputs=[-1], quantity="acceleration")
    iw = 2j * np.pi * f[:, None]
    np.testing.assert_allclose(mobility.values, iw * receptance.values, rtol=1e-14)
    np.testing.assert_allclose(accelerance.values, iw**2 * receptance.values, rtol=1e-14)
    # C = 0.02·K is proportional: modal superposition is exact, to rounding of the two paths.
    modal = railmodal.frf(system, modes, "dof1", f, outputs=["dof2"], method="modal")
    np.testing.assert_allclose(modal.values, receptance.values, rtol=1e-10)
    frame = pandas.DataFrame(receptance.as_dict())
    assert list(frame.columns) == ["frequency_hz", "dof2 amplitude", "dof2 phase_deg", "dof2 unbounded"]
    np.testing.assert_allclose(frame["dof2 amplitude"], np.abs(receptance.values[:, 0]), rtol=1e-15)


def test_undamped_resonance_is_unbounded_not_infinite():
    system = railmodal.LinearSystem(np.eye(1), np.array([[4.0 * np.pi**2]]))  # f = 1 Hz
    modes = railmodal.modes(system)
    response = railmodal.frf(system, modes, 0, [0.5, 1.0, 2.0])
    assert list(response.unbounded[:, 0]) == [False, True, False]
    assert response.values[1, 0] == 0 and np.all(np.isfinite(response.values))
    # Away from resonance: 1/(k − ω²m) exactly as a closed form.
    np.testing.assert_allclose(response.values[0, 0].real, 1 / (4 * np.pi**2 * (1 - 0.25)), rtol=1e-14)


def test_critical_speed_study_equals_the_clis():
    expected = cli_json("critical-speed", SCENE)
    study = railmodal.study_critical_speeds(railmodal.load_scene(SCENE))
    rows = study.critical_speeds.records()
    assert [r["mode_name"] for r in rows] == [c["mode_name"] for c in expected["critical_speeds"]]
    # One library computation written with round-trip digits.
    np.testing.assert_allclose([r["speed_kmh"] for r in rows], [c["speed_kmh"] for c in expected["critical_speeds"]],
                               rtol=1e-14)
    assert len(study.curves) == len(expected["curves"])
    # The JSON writes null where the curve is unbounded; the arrays hold 0 there and flag it.
    written = np.array([np.nan if a is None else a for a in expected["curves"][0]["amplitudes"]])
    np.testing.assert_array_equal(study.curves[0].unbounded, np.isnan(written))
    np.testing.assert_allclose(study.curves[0].amplitudes, np.nan_to_num(written, nan=0.0), rtol=1e-14)
    frame = pandas.DataFrame(rows)
    assert frame.shape == (len(rows), 15)


def test_find_critical_speeds_and_curves_on_a_numpy_speed_array():
    scene = railmodal.load_scene(SCENE)
    study = railmodal.study_critical_speeds(scene)
    system, modes = study.system, study.modes
    found = railmodal.find_critical_speeds(system, modes, scene.sources, scene.min_speed_m_s, scene.max_speed_m_s,
                                           outputs=[("body.bounce", "acceleration")])
    np.testing.assert_array_equal(found.speeds_m_s, study.critical_speeds.speeds_m_s)
    assert len(found.output_records()) == len(found)
    speeds = study.curves[0].speeds_m_s.copy()
    curves = railmodal.amplitude_curves(system, modes, scene.sources[0], ["body.bounce"], speeds)
    # The study computes its curves by this same call on this grid.
    np.testing.assert_array_equal(curves[0].amplitudes, study.curves[0].amplitudes)
    c = curves[0]
    assert c.amplitudes.base is not None and np.shares_memory(c.speeds_m_s, c.speeds_m_s)
    assert pandas.DataFrame(c.as_dict()).shape == (len(speeds), 4)


def test_amplitude_curves_flag_an_undamped_resonance_whatever_the_grid():
    # User audit 2026-11-28b, F7: over a grid that misses an undamped resonance the curve had a
    # finite peak whose height depended on the grid (6.35 m on 2001 speeds, 9.96 m on 2000) and
    # flagged nothing. The sweep now takes the grid as railmodal critical-speed does: the given
    # speeds with the source's critical speeds in their places, each resonance a point flagged
    # unbounded. Example 3's undamped wagon (friction only in the criterion) on 12.5 m rails.
    system = railmodal.assemble(railmodal.load_vehicle(data("vehicles", "two_axle_freight_wagon.toml")), "vertical")
    modes = railmodal.modes(system)
    joints = railmodal.rail_joints(rail_length=12.5, dip_depth=0.005)
    low, high = 50 / 3.6, 120 / 3.6
    critical = railmodal.find_critical_speeds(system, modes, joints, low, high)
    bounce = [r["speed_m_s"] for r in critical.records() if r["output"] == "body.bounce" and r["unbounded"]]
    assert len(bounce) == 1  # V = 12.5 m × 2.0843 Hz = 93.8 km/h
    flagged = {}
    for n in (2001, 2000):
        v = np.linspace(low, high, n)
        assert not np.isin(critical.speeds_m_s, v).any()  # the resonances fall between grid speeds
        c = railmodal.amplitude_curves(system, modes, joints, ["body.bounce"], v)[0]
        np.testing.assert_array_equal(c.speeds_m_s, np.union1d(v, critical.speeds_m_s))
        flagged[n] = c.speeds_m_s[c.unbounded]
        assert set(bounce) <= set(flagged[n]) <= set(critical.speeds_m_s)  # at critical speeds, nowhere else
        assert np.all(c.amplitudes[c.unbounded] == 0) and np.all(np.isfinite(c.amplitudes))
        # As given, the grid is swept exactly, and the resonance between two speeds is not flagged.
        given = railmodal.amplitude_curves(system, modes, joints, ["body.bounce"], v, with_critical_speeds=False)[0]
        np.testing.assert_array_equal(given.speeds_m_s, v)
        assert not given.unbounded.any()
        # Away from the inserted speeds the two sweeps are the same computation.
        np.testing.assert_array_equal(c.amplitudes[np.isin(c.speeds_m_s, v)], given.amplitudes)
    np.testing.assert_array_equal(flagged[2001], flagged[2000])


def test_a_source_made_in_python():
    system = railmodal.assemble(railmodal.load_vehicle(data("vehicles", "resort_car.toml")))
    modes = railmodal.modes(system)
    joints = railmodal.rail_joints(rail_length=12.5, dip_depth=0.005)
    assert joints.kind == "rail_joints" and joints.wavelength_m == 12.5
    rows = railmodal.find_critical_speeds(system, modes, joints, 1.0, 40.0).records()
    bounce = [r for r in rows if r["mode_name"] == "body bounce"][0]
    # V = Λ·f: the bounce mode's frequency times the rail length.
    assert bounce["speed_m_s"] == pytest.approx(12.5 * bounce["frequency_hz"], rel=1e-14)
    with pytest.raises(TypeError, match="unknown option 'length'"):
        railmodal.rail_joints(length=12.5)


def test_scene_fields_sources_and_peaks():
    scene = railmodal.load_scene(SCENE)
    assert scene.name == "Resort car, 10 m rails" and scene.dofs == "vertical"
    assert scene.outputs == [("body.bounce", "displacement"), ("body.bounce", "acceleration")]
    source = scene.sources[0]
    assert source.kind == "rail_joints" and source.wavelength_m == 10.0
    # f = k·V/Λ and its inverse.
    assert source.frequency_hz(20.0, 2) == pytest.approx(4.0, rel=1e-15)
    assert source.speed_for(4.0, 2) == pytest.approx(20.0, rel=1e-15)
    assert railmodal.study_critical_speeds(scene, railmodal.load_vehicle(data("vehicles", "resort_car.toml"))) \
        .critical_speeds.speeds_m_s.size == 5


def test_damped_peaks_are_refined_above_their_grid_points():
    study = railmodal.study_critical_speeds(railmodal.load_scene(data("scenes", "manchester_coach_hunting.toml")))
    peaks = study.peak_records()
    assert len(peaks) == 2
    for peak in peaks:
        curve = study.curves[peak["curve"]]
        assert peak["output"] == curve.output and not peak["unbounded"]
        nearest = np.argmin(np.abs(curve.speeds_m_s - peak["speed_m_s"]))
        # Golden-section search maximises within a bracket around a grid maximum: the refined
        # amplitude is not below the grid's there (1e-12: rounding of the two evaluations).
        assert peak["amplitude"] >= curve.amplitudes[nearest] * (1 - 1e-12)


def test_wheel_sources_run_at_the_wheels_turning_frequency():
    # A wheel of diameter D turns V/(πD) times a second: an oval (two lobes) excites twice that,
    # a flat once a revolution (excitation.hpp; bogie-wagons-forced digest §2.10).
    oval = railmodal.wheel_eccentricity(wheel_diameter=0.95, eccentricity=0.5e-3, lobes=2)
    flat = railmodal.wheel_flat(wheel_diameter=0.95, depth=1e-3, length=0.06, harmonics=4)
    turning = 30.0 / (np.pi * 0.95)
    assert oval.frequency_hz(30.0) == pytest.approx(2 * turning, rel=1e-14)
    assert flat.frequency_hz(30.0) == pytest.approx(turning, rel=1e-14) and flat.harmonic_count == 4
    with pytest.raises(TypeError, match="wheel_flat\\(\\): unknown option 'lenght'"):
        railmodal.wheel_flat(wheel_diameter=0.95, depth=1e-3, lenght=0.06)
    # The library's own rules (WheelEccentricity::is_valid and its twins), as the scene reader
    # and a C++ user meet them.
    with pytest.raises(ValueError, match="^wheel eccentricity: wheel_diameter must be positive and finite$"):
        railmodal.wheel_eccentricity(wheel_diameter=0.0, eccentricity=1e-3)
    with pytest.raises(ValueError, match="^wheel flat: length cannot exceed the wheel circumference πD$"):
        railmodal.wheel_flat(wheel_diameter=0.95, depth=1e-3, length=3.0)
    with pytest.raises(ValueError, match="^rail joints: half_wheelset_mass missing: the track's dynamics need both"):
        railmodal.rail_joints(rail_length=12.5, dip_depth=0.005, track_stiffness=5e7)
