"""Ride on random track (docs/python.md, "Ride"): track spectra, the frequency-domain ride, track
realisations and the time-domain ride with its FFT checks, the comfort weightings, against
`railmodal ride` and the headers' printed examples.

Tolerances: against the command line, the same library call on the same files, so the numbers
agree to the digits the JSON writer prints; rtol=1e-12 holds any writer that prints 13
significant digits or more. Against a header's printed example, half a unit of its last digit.
"""
import pathlib

import numpy as np
import pandas
import pytest

import railmodal
from railmodal_paths import SOURCE, cli, cli_json, data

COACH = data("scenes", "manchester_coach_ore_low.toml")
COACH_TIME = data("scenes", "manchester_coach_ore_low_time_domain.toml")
# The same scene on a realisation 8 times shorter (1024 m): the binding against the command line
# on the same file, every stage of the time-domain ride, in an eighth of the time.
COACH_TIME_SHORT = str(SOURCE / "tests" / "python" / "scenes" / "coach_time_domain_short.toml")
REL = 1e-12
SAME = dict(rtol=REL, atol=0)


@pytest.fixture(scope="module")
def coach():
    return railmodal.ride_scene(railmodal.load_scene(COACH))


def test_ride_scene_equals_the_command_line(coach):
    expected = cli_json("ride", COACH)
    np.testing.assert_allclose(coach.frequencies_hz, expected["frequencies_hz"], **SAME)
    np.testing.assert_allclose(coach.speeds_m_s, [s["speed_m_s"] for s in expected["speeds"]], **SAME)
    assert coach.output_names == [o["name"] for o in expected["outputs"]]
    assert [m["name"] for m in coach.modes] == [m["name"] for m in expected["modes"]]
    assert coach.psd.shape == (len(coach.speeds_m_s), len(coach.outputs), len(coach.frequencies_hz))
    rows = iter(coach.records())
    for s, at in enumerate(expected["speeds"]):
        for i, want in enumerate(at["outputs"]):
            got = next(rows)
            assert got["output"] == want["name"] and got["unbounded"] == want["unbounded"]
            # The RMS and PSD under one key whatever the output's unit, the unit beside them.
            assert got["rms"] == pytest.approx(want["rms"], rel=REL) and got["unit"] == want["unit"]
            np.testing.assert_allclose(coach.psd[s, i], want["psd"], **SAME)
            for key in ("weighted_rms_m_s2", "p95_estimate_m_s2"):  # the JSON's keys (test_record_names.py)
                assert (got[key] is None) == (want.get(key) is None)
                if got[key] is not None:
                    assert got[key] == pytest.approx(want[key], rel=REL)
    comfort = [c for at in expected["speeds"] for c in at["comfort"]]
    assert [c["nmv_estimate"] for c in coach.comfort()] == pytest.approx([c["nmv_estimate"] for c in comfort], rel=REL)


def test_ride_rms_only(coach):
    # rms_only=True (RideOptions::rms_only, `railmodal ride --rms-only`): the RMS and weighted RMS
    # bit for bit the full solve's (the same sums in the same order), the other indices skipped
    # and shown as skipped (None, empty), never as numbers.
    assert not coach.rms_only and coach.grid_error_estimate > 0
    only = railmodal.ride_scene(railmodal.load_scene(COACH), rms_only=True)
    assert only.rms_only and only.grid_error_estimate is None
    assert any(n.startswith("rms_only:") for n in only.notes)
    every = coach.records()
    assert len(only.records()) == len(every)
    for got, want in zip(only.records(), every):
        assert got["output"] == want["output"]
        assert got["rms"] == want["rms"] and got["weighted_rms_m_s2"] == want["weighted_rms_m_s2"]
        for key in ("sperling_wz", "p95_estimate_m_s2", "cross_term_variance", "direct_variance"):
            assert got[key] is None, key
    assert any(r["sperling_wz"] is not None for r in every)
    assert only.comfort() == [] and only.contributions() == []
    assert coach.comfort() and coach.contributions()
    # ride() takes the keyword too, with the same answer.
    scene = railmodal.load_scene(COACH)
    system = railmodal.assemble(railmodal.load_vehicle(scene.vehicle_file), scene.dofs)
    speed = [coach.speeds_m_s[0]]
    a = railmodal.ride(system, scene, speeds_m_s=speed, rolling_radius_m=0.46, rms_only=True)
    b = railmodal.ride(system, scene, speeds_m_s=speed, rolling_radius_m=0.46)
    assert a.rms_only and not b.rms_only
    assert [r["rms"] for r in a.records()] == [r["rms"] for r in b.records()]
    assert "rms_only" in railmodal.ride.__doc__ and "Sperling" in railmodal.ride.__doc__


def test_no_grid_error_estimate_when_every_output_is_unbounded():
    # Khanin's car has neither dampers nor friction: the track drives undamped modes, so every
    # output is unbounded at every speed and there is no RMS to estimate an error of. The report
    # says "no grid error estimate" (JSON null); the binding gives None, not 0.0.
    system = railmodal.assemble(railmodal.load_vehicle(data("vehicles", "khanin_car_upstroke.toml")), "vertical")
    track = {"vertical_level": railmodal.TrackSpectrum.fra_class(4, "vertical_level")}
    r = railmodal.ride(system, track, speeds_m_s=[20.0, 30.0])
    assert r.records() and all(row["unbounded"] for row in r.records())
    assert r.grid_error_estimate is None and not r.rms_only


def test_ride_tables_for_pandas(coach):
    frame = pandas.DataFrame(coach.records())
    assert len(frame) == len(coach.speeds_m_s) * len(coach.outputs)
    # The RMS is the square root of the PSD's area over the grid: the trapezoid rule on the grid
    # the result gives reproduces it within the grid's own error estimate (what halving the
    # grid changes, which bounds the difference between two rules on it).
    area = np.trapz(coach.psd[0, 0], coach.frequencies_hz)
    assert abs(np.sqrt(area) / frame["rms"][0] - 1) < coach.grid_error_estimate
    shares = pandas.DataFrame(coach.contributions())
    first = shares[(shares.speed_m_s == coach.speeds_m_s[0]) & (shares.output == coach.output_names[0])]
    # The modes' shares and the cross terms add up to the variance exactly (ride.hpp).
    variance = frame["rms"][0] ** 2
    assert first["variance"].sum() + frame["cross_term_variance"][0] == pytest.approx(variance, rel=1e-9)
    assert coach.input_psd.shape == (len(coach.speeds_m_s), 3, len(coach.frequencies_hz))
    assert coach.frequencies_hz.base is not None and not coach.frequencies_hz.flags.writeable


def test_ride_of_a_system_with_the_scenes_track_and_outputs(coach):
    scene = railmodal.load_scene(COACH)
    system = railmodal.assemble(railmodal.load_vehicle(scene.vehicle_file), scene.dofs)
    outputs = railmodal.default_ride_outputs(system)
    assert [o.name for o in outputs] == coach.output_names
    speed = coach.speeds_m_s[0]
    # The scene's [ride] rolls the rails about the rail top, 0.46 m below the vehicle file's
    # axle plane (rolling_radius); ride() takes the option as the keyword rolling_radius_m.
    r0 = 0.46
    by_scene = railmodal.ride(system, scene, speeds_m_s=[speed], rolling_radius_m=r0)
    spectra = {"vertical_level": None}
    for name in ("vertical_level", "alignment", "cross_level"):
        band = (2 * np.pi / 100, 2 * np.pi / 1)  # the scene's wavelengths 1 … 100 m
        spectra[name] = railmodal.TrackSpectrum.ore_b176("low", name, band)
    by_dict = railmodal.ride(system, spectra, outputs, speeds_m_s=[speed], rolling_radius_m=r0)
    np.testing.assert_array_equal(by_scene.psd, by_dict.psd)
    # About the axle plane instead (r0 = 0, no wheelsets here), the cross-level moves the lateral
    # outputs differently: the keyword reaches the library.
    axle_plane = railmodal.ride(system, spectra, outputs, speeds_m_s=[speed])
    lateral = [i for i, o in enumerate(outputs) if o.axis == "lateral"]
    assert lateral and all(abs(axle_plane.records()[i]["rms"] / by_dict.records()[i]["rms"] - 1) > 0.01 for i in lateral)
    assert by_dict.input_rms == pytest.approx([s.rms() for s in spectra.values()], rel=1e-12)
    assert all(r["direct_variance"] >= 0.0 for r in by_dict.records())
    # The grid is refined for the speeds asked, so one speed alone has another grid than the
    # scene's five: the RMS agree within the grids' error estimate.
    rms = [r["rms"] for r in by_dict.records()]
    assert rms == pytest.approx([r["rms"] for r in coach.records()][: len(rms)], rel=coach.grid_error_estimate)
    # One output built in Python: the same as the default output it copies.
    o = outputs[0]
    mine = railmodal.RideOutput("mine", body=o.body, point_m=o.point_m, axis=o.axis, quantity=o.quantity)
    one = railmodal.ride(system, spectra, [mine], speeds_m_s=[speed])
    np.testing.assert_array_equal(one.psd[0, 0], by_dict.psd[0, 0])
    assert mine.unit == o.unit and mine.kind == "point"
    # The frame reaches the library: a lateral point read in the track frame (inertial) differs
    # from the default floor accelerometer's reading (with g·phi: a few per cent on this coach,
    # docs/ride.md), and each output reads back its word.
    lat = outputs[lateral[0]]
    floor = railmodal.RideOutput("floor", body=lat.body, point_m=lat.point_m, axis="lateral")
    track = railmodal.RideOutput("track", body=lat.body, point_m=lat.point_m, axis="lateral", frame="track")
    both = railmodal.ride(system, spectra, [floor, track], speeds_m_s=[speed], rolling_radius_m=r0)
    assert floor.frame == "body" and track.frame == "track"
    by_floor, by_track = (r["rms"] for r in both.records())
    assert abs(by_floor / by_track - 1) > 1e-3
    with pytest.raises(ValueError, match="frame"):
        railmodal.RideOutput("x", frame="inertial")


def test_ride_errors():
    flat = railmodal.load_scene(data("scenes", "resort_car_10m_rails.toml"))
    code, _, stderr = cli("ride", data("scenes", "resort_car_10m_rails.toml"), check=False)
    with pytest.raises(railmodal.InputError) as error:
        railmodal.ride_scene(flat)
    assert code == 3 and 'kind = "irregularity"' in str(error.value) and 'kind = "irregularity"' in stderr
    scene = railmodal.load_scene(COACH)
    system = railmodal.assemble(railmodal.load_vehicle(scene.vehicle_file), scene.dofs)
    with pytest.raises(ValueError, match="track: 'level' is not one of"):
        railmodal.ride(system, {"level": None}, speeds_m_s=[30.0])
    with pytest.raises(ValueError):  # RideOptions::is_valid: no speed
        railmodal.ride(system, scene, speeds_m_s=[])
    with pytest.raises(ValueError, match="nobody"):  # an output naming no body of the system
        railmodal.ride(system, scene, [railmodal.RideOutput("x", body="nobody")], speeds_m_s=[30.0])
    with pytest.raises(ValueError, match="axis: 'up' is not one of"):
        railmodal.RideOutput("x", axis="up")
    with pytest.raises(TypeError, match="expected a dict of TrackSpectrum"):
        railmodal.ride(system, 3, speeds_m_s=[30.0])


def test_a_ride_without_speeds_is_placed_at_its_ride_table():
    # The corpus scene's [ride] gives no speeds and none are passed: the command line and the
    # binding refuse it at the [ride] table (line 12), not at the file alone.
    path = str(SOURCE / "tests" / "corpus" / "bad_inputs" / "ride_no_speeds.toml")
    code, _, stderr = cli("ride", path, check=False)
    with pytest.raises(railmodal.InputError) as error:
        railmodal.ride_scene(railmodal.load_scene(path))
    assert code == 3 and "ride_no_speeds.toml:12:" in stderr and "key 'ride.speeds': no speeds" in stderr
    assert error.value.file == path and error.value.line == 12
    assert "key 'ride.speeds': no speeds" in str(error.value)


def test_track_spectrum_prints_its_headers_example():
    band = (2 * np.pi / 70, 2 * np.pi / 3)
    s = railmodal.TrackSpectrum.ore_b176("low", "vertical-level", band)
    # track_spectrum.hpp prints: RMS 1.92189 mm; S(0.1 rad/m) = 3.8118e-05; at 50 m/s, 2 Hz: 7.29062e-07.
    assert 1000 * s.rms() == pytest.approx(1.92189, abs=5e-6)
    assert s.density(0.1) == pytest.approx(3.8118e-05, abs=5e-10)
    assert s.temporal_density(2.0, 50.0) == pytest.approx(7.29062e-07, abs=5e-12)
    assert s.name == "ORE B176 low, vertical level" and s.band_rad_m == band
    omega = np.array([[0.05, 0.1], [0.5, 5.0]])
    assert s.density(omega).shape == (2, 2) and s.density(omega)[1, 1] == 0.0  # outside the band
    assert s.variance() == pytest.approx(s.rms() ** 2, rel=1e-15)
    table = railmodal.TrackSpectrum.table("alignment", "wavenumber", [0.1, 1.0], [1e-5, 1e-7])
    assert table.band_rad_m == (0.1, 1.0) and table.density(np.sqrt(0.1)) == pytest.approx(1e-6, rel=1e-12)
    with pytest.raises(ValueError, match="level: 'medium' is not one of"):
        railmodal.TrackSpectrum.ore_b176("medium", "alignment", band)
    with pytest.raises(ValueError):  # FRA classes are 1 … 6
        railmodal.TrackSpectrum.fra_class(7, "alignment")


def test_synthesised_track_equals_the_bundled_realisation():
    # data/track/ore_low_synthesised.csv was written by synthesise_track: ORE B176 low level,
    # 1 … 100 m, 1200 m every 0.25 m, seed 11, in mm to 3 decimals.
    band = (2 * np.pi / 100, 2 * np.pi / 1)
    spectra = {name: railmodal.TrackSpectrum.ore_b176("low", name.replace("_", "-"), band)
               for name in ("vertical_level", "alignment", "cross_level")}
    g = railmodal.synthesise_track(spectra, length_m=1200, step_m=0.25, seed=11)
    measured = railmodal.load_track_geometry(SOURCE / "data" / "track" / "ore_low_synthesised.csv")
    assert g.periodic and not measured.periodic and g.step_m == measured.step_m == 0.25
    for name in ("vertical_level", "alignment", "cross_level"):
        np.testing.assert_allclose(getattr(g, name), getattr(measured, name), rtol=0, atol=0.5e-6)  # 0.0005 mm
    again = railmodal.synthesise_track(spectra, length_m=1200, step_m=0.25, seed=11)
    np.testing.assert_array_equal(again.vertical_level, g.vertical_level)
    assert g.distance_m[-1] == pytest.approx(1200 - 0.25) and g.length_m == pytest.approx(1200)


def test_time_domain_ride_equals_the_command_line():
    simulated, checks = railmodal.ride_scene_simulation(railmodal.load_scene(COACH_TIME_SHORT))
    expected = cli_json("ride", COACH_TIME_SHORT)["time_domain"]
    assert len(expected["comfort"]) > 0 and simulated.time_s[-1] > 20.0  # 23 s: four 5 s windows and more
    assert [c["nmv"] for c in simulated.comfort()] == pytest.approx([c["nmv"] for c in expected["comfort"]], rel=REL)
    assert checks.exact_bin_error == pytest.approx(expected["fft_checks"]["exact_bin_error"], rel=REL)
    assert checks.rms_difference == pytest.approx(expected["fft_checks"]["rms_difference"], rel=REL)
    assert checks.fraction_outside_band == pytest.approx(expected["fft_checks"]["fraction_outside_band"], rel=REL)
    first = simulated.outputs[0].name
    h = simulated.history(first)
    assert h["values"].shape == simulated.time_s.shape and h["values"].base is not None
    # The weighted RMS of the record is the RMS of its weighted samples.
    record = pandas.DataFrame(simulated.records()).set_index("output")
    assert np.sqrt(np.mean(h["weighted"] ** 2)) == pytest.approx(record.loc[first, "weighted_rms_m_s2"], rel=1e-9)


def test_simulate_ride_over_a_realisation():
    scene = railmodal.load_scene(COACH_TIME)
    system = railmodal.assemble(railmodal.load_vehicle(scene.vehicle_file), scene.dofs)
    outputs = railmodal.default_ride_outputs(system)[:1]
    g = railmodal.synthesise_track(scene, length_m=2000, step_m=0.25, seed=3)
    run = railmodal.simulate_ride(system, g, outputs, speed_m_s=40.0)
    checks = railmodal.check_ride_realisation(system, scene, g, run, speed_m_s=40.0)
    # A periodic realisation through a linear system: the simulated bins are H·X_track (the
    # check's own limit is 1e-6; the exact path reaches round-off).
    assert checks.exact_bin_error < 1e-6
    with pytest.raises(ValueError):  # RideSimulationOptions::is_valid: the speed must be positive
        railmodal.simulate_ride(system, g, outputs, speed_m_s=-40.0)


def test_comfort_weightings_print_their_headers_example():
    w = railmodal.comfort_weighting("wb", np.array([5.0]))[0]
    # comfort_weighting.hpp prints: |W| = 0.957033, phase 0.373371 rad; Wz 2.60698; N_MV 1.62904.
    assert abs(w) == pytest.approx(0.957033, abs=5e-7) and np.angle(w) == pytest.approx(0.373371, abs=5e-7)
    aw = abs(w) * 0.3 / np.sqrt(2)
    assert railmodal.en12299_nmv(0.1, 0.15, aw) == pytest.approx(1.62904, abs=5e-6)
    # Sperling's Wz of one sine, by its weighted RMS: (b·B(f))^0.3 with b in cm/s².
    b = railmodal.sperling_weighting(np.array([5.0]))[0]
    assert railmodal.sperling_wz_from_weighted_rms(b * 0.3 / np.sqrt(2)) == pytest.approx(2.60698, abs=5e-6)
    assert railmodal.sperling_weighting(np.array([5.0]), "lateral")[0] == pytest.approx(1.25 * b, rel=1e-15)
    with pytest.raises(ValueError, match="weighting: 'wk' is not one of"):
        railmodal.comfort_weighting("wk", np.array([1.0]))


def test_spectrum_forms_and_the_fra_classes():
    s = railmodal.TrackSpectrum.fra_class(4, "vertical-level")
    # The FRA range of wavelengths 1.524 … 304.8 m (5 … 1000 ft) by default.
    assert s.band_rad_m == pytest.approx((2 * np.pi / 304.8, 2 * np.pi / 1.524), rel=1e-12)
    n = np.array([0.01, 0.1])
    np.testing.assert_allclose(s.density_per_cycle(n), 2 * np.pi * s.density(2 * np.pi * n), rtol=1e-15)
    # A better class is a smoother track.
    assert railmodal.TrackSpectrum.fra_class(6, "vertical-level").rms() < s.rms()


def test_floor_height_places_the_default_points_and_its_absence_is_noted():
    """Body.floor_height (m above the axle plane) is where default_ride_outputs puts the floor
    points; without it they lie at the reference point (the coach's bolster plane, 0.3675 m) and
    the ride's notes say so once (docs/input.md, "Floor height")."""
    vehicle = railmodal.load_vehicle(data("vehicles", "manchester_benchmark_coach.toml"))
    assert vehicle.bodies[0].floor_height is None  # the benchmark's paper gives none
    assert "m, z of the floor above the plane of the axles" in type(vehicle.bodies[0]).floor_height.__doc__
    system = railmodal.assemble(vehicle, "all")
    low = railmodal.default_ride_outputs(system)
    assert [o.point_m[2] for o in low] == [0.3675] * len(low)
    spectra = {"cross_level": railmodal.TrackSpectrum.ore_b176("low", "cross_level", (2 * np.pi / 100, 2 * np.pi))}
    notes = railmodal.ride(system, spectra, low[:2], speeds_m_s=[40.0]).notes
    assert [n for n in notes if n.startswith("floor height not given")] == [
        next(n for n in notes if n.startswith("floor height not given: the default floor points lie at z = 0.3675 m"))]
    vehicle.bodies[0].floor_height = 0.84
    raised = railmodal.assemble(vehicle, "all")
    high = railmodal.default_ride_outputs(raised)
    assert [o.point_m[2] for o in high] == [0.84] * len(high)
    assert [o.name for o in high] == [o.name for o in low]
    notes = railmodal.ride(raised, spectra, high[:2], speeds_m_s=[40.0]).notes
    assert not [n for n in notes if n.startswith("floor height not given")]


COACH_WHEELSETS_SHORT = str(SOURCE / "tests" / "python" / "scenes" / "coach_wheelsets_ride_short.toml")


def coach_with_yaw_dampers(folder):
    """The coach on wheelsets with the yaw dampers of data/studies/coach_hunting_yaw_dampers.toml
    (400 kN·s/m with 10 MN/m in series, 2.6 m apart), written to `folder`."""
    text = pathlib.Path(data("vehicles", "manchester_benchmark_coach_wheelsets.toml")).read_text()
    secondary = text.index("\n[secondary]")
    line_end = text.index("\n", secondary + 1)
    damper = 'yaw_damper = { damping = "400 kN*s/m", series_stiffness = "10 MN/m", spacing = "2.6 m" }\n'
    path = folder / "coach_yaw_dampers.toml"
    path.write_text(text[: line_end + 1] + damper + text[line_end + 1 :])
    return str(path)


def test_ride_of_a_coach_with_yaw_dampers_equals_the_binding(tmp_path):
    # Series dampers are the ride's (docs/input.md, "Series dampers"): `railmodal ride --vehicle`
    # with yaw dampers ran into the scene check's refusal before 2026-11-28 (user audit F2). Its
    # numbers are the binding's ride() of the same assembled system, which no scene check stands
    # before: the same solve, so to the digits the JSON prints (REL).
    vehicle = coach_with_yaw_dampers(tmp_path)
    expected = cli_json("ride", COACH_WHEELSETS_SHORT, "--vehicle", vehicle)
    scene = railmodal.load_scene(COACH_WHEELSETS_SHORT)
    damped = railmodal.assemble(railmodal.load_vehicle(vehicle), scene.dofs)
    speeds = [s["speed_m_s"] for s in expected["speeds"]]
    grid = dict(speeds_m_s=speeds, points_per_decade=20, points_per_bandwidth=2)
    got = railmodal.ride(damped, scene, **grid)
    assert got.output_names == [o["name"] for o in expected["outputs"]]
    np.testing.assert_allclose(got.frequencies_hz, expected["frequencies_hz"], **SAME)
    rows = iter(got.records())
    for at in expected["speeds"]:
        for want in at["outputs"]:
            row = next(rows)
            assert row["output"] == want["name"] and row["rms"] == pytest.approx(want["rms"], rel=REL)
            assert row["sperling_wz"] == pytest.approx(want["sperling_wz"], rel=REL)
    # The dampers are in that ride, not left out: without them (the scene's own vehicle) the
    # lateral Wz over the front bogie at 200 km/h is 9 % higher, 2.597 against 2.360 (the audit's
    # 2.595 and 2.359 on the default grid). This grid's error estimate of the RMS is below 5 %
    # (2.2 % at most here), which Wz, as RMS^0.3, takes as under 1.5 %: a drop of 5 % is the dampers'.
    plain = railmodal.ride(railmodal.assemble(railmodal.load_vehicle(scene.vehicle_file), scene.dofs), scene, **grid)
    lateral = got.output_names.index("floor over front bogie, lateral")
    wz = [next(r for r in reversed(x.records()) if r["output"] == got.output_names[lateral])["sperling_wz"]
          for x in (got, plain)]
    assert max(got.grid_error_estimate, plain.grid_error_estimate) < 0.05
    assert wz[0] < 0.95 * wz[1]
