"""Scenes in the time domain: simulate, spectra, peaks, swings and fft-check (docs/python.md,
"Scenes and simulation"), against `railmodal simulate` and `railmodal fft-check`.

Tolerances: the binding and the command line run the same library call on the same files, so
their numbers agree to the digits the JSON writer prints; rtol=1e-12 holds any writer that
prints 13 significant digits or more (the "outputs" work may shorten them, not below that).
"""
import threading

import numpy as np
import pandas
import pytest

import railmodal
from railmodal_paths import cli, cli_json, data

FREE = data("scenes", "resort_car_free_response.toml")  # linear: a release from displaced positions
DROP = data("scenes", "leaf_spring_drop_test.toml")  # nonlinear: leaf friction, with events
REL = 1e-12
SAME = dict(rtol=REL, atol=0)


def test_simulate_equals_the_command_lines_history():
    scene = railmodal.load_scene(FREE)
    history = railmodal.simulate(scene)
    expected = cli_json("simulate", FREE)
    np.testing.assert_allclose(history.time, expected["time_s"], **SAME)
    assert list(expected["displacement"]) == history.labels  # the scene outputs every DOF
    for j, label in enumerate(history.labels):
        np.testing.assert_allclose(history.displacement[:, j], expected["displacement"][label], **SAME)
    assert history.velocity.shape == history.displacement.shape


def test_histories_are_read_only_views_of_the_result():
    history = railmodal.simulate(railmodal.load_scene(FREE))
    d = history.displacement
    assert d.base is not None and not d.flags.writeable and d.flags.f_contiguous
    column = history.column("body.pitch")
    assert column.base is not None and not column.flags.writeable
    np.testing.assert_array_equal(column, d[:, history.labels.index("body.pitch")])
    frame = pandas.DataFrame(history.columns())
    assert list(frame.columns) == ["time_s"] + history.labels and len(frame) == len(history.time)
    with pytest.raises(KeyError, match="no DOF 'body.yaw'"):
        history.column("body.yaw")


def test_outputs_only_keeps_what_the_command_line_writes():
    scene = railmodal.load_scene(DROP)
    full = railmodal.simulate(scene)
    outputs = railmodal.simulate(scene, outputs_only=True)
    expected = cli_json("simulate", DROP)
    assert outputs.labels == list(expected["displacement"])
    assert outputs.velocity.size == 0  # the record keeps no velocities
    for j, label in enumerate(outputs.labels):
        np.testing.assert_allclose(outputs.displacement[:, j], expected["displacement"][label], **SAME)
        np.testing.assert_array_equal(outputs.displacement[:, j], full.column(label))
    # The nonlinear path's events: the same times and kinds; the binding gives the element's index.
    vehicle = railmodal.load_vehicle(scene.vehicle_file)
    assert len(outputs.events) == len(expected["events"]) > 0
    for got, want in zip(outputs.events, expected["events"]):
        assert got["kind"] == want["kind"] and vehicle.elements[got["element"]].name == want["element"]
        assert got["time_s"] == pytest.approx(want["time_s"], rel=1e-12)
    assert outputs.steps_taken == expected["integration_steps"]


def test_a_vehicle_given_replaces_the_scenes():
    scene = railmodal.load_scene(FREE)
    by_file = railmodal.simulate(scene, scene.vehicle_file)
    by_object = railmodal.simulate(scene, railmodal.load_vehicle(scene.vehicle_file))
    np.testing.assert_array_equal(by_file.displacement, by_object.displacement)
    with pytest.raises(TypeError):
        railmodal.simulate(scene, 42)


def test_simulation_spec_reads_the_scenes_table():
    spec = railmodal.simulation_spec(railmodal.load_scene(FREE))
    assert spec["duration_s"] == 80.0 and spec["time_step_s"] == 0.005
    assert spec["initial"][0] == {"dof": "body.bounce", "displacement": 0.02, "velocity": 0.0}
    assert railmodal.simulation_spec(railmodal.load_scene(data("scenes", "resort_car_10m_rails.toml"))) is None


def test_a_scene_without_simulation_is_the_command_lines_input_error():
    path = data("scenes", "two_axle_freight_wagon_joints.toml")
    code, _, stderr = cli("simulate", path, check=False)
    assert code == 3
    with pytest.raises(railmodal.InputError) as error:
        railmodal.simulate(railmodal.load_scene(path))
    assert error.value.file == path and "the scene has no [simulation] table" in str(error.value)
    assert "the scene has no [simulation] table" in stderr


def test_fft_check_equals_the_command_line():
    scene = railmodal.load_scene(FREE)
    result = railmodal.fft_check(scene)
    expected = cli_json("fft-check", FREE)
    assert result.passed and result.failed == 0 and result.checked == len(result.checks)
    assert len(result.checks) == len(expected["checks"])
    for got, want in zip(result.checks, expected["checks"]):
        assert (got["mode_name"], got["dof"], got["outcome"]) == (want["mode_name"], want["dof"], want["outcome"])
        assert got["undamped_frequency_hz"] == pytest.approx(want["undamped_frequency_hz"], rel=1e-12)
        assert got["peak_frequency_hz"] == pytest.approx(want["peak_frequency_hz"], rel=1e-12)
    frame = pandas.DataFrame(result.records())
    assert frame.to_dict("records") == result.checks
    assert frame["excited"].all() and result.summary.passed
    # The command line's verdict in words, and a repr that says it (user audit 2026-11-28b, F9 f).
    assert result.verdict == expected["verdict_text"] and result.verdict.startswith("passed: ")
    assert repr(result) == "FftCheckResult(" + result.verdict + ")"
    # Spectra of the DOFs the checks looked at (each mode's most energetic one).
    assert set(result.spectra) == {c["dof"] for c in result.checks} <= set(result.history.labels)


def test_fft_check_says_why_not_applicable_and_checks_the_half_periods():
    # The drop test is a free release with leaf friction: a mode whose motion comes to rest is
    # not applicable (the words are the JSON's why_not_applicable) and the half periods between
    # turning points are checked instead (the JSON's half_period_check), as fft-check writes them.
    scene = railmodal.load_scene(DROP)
    result = railmodal.fft_check(scene)
    expected = cli_json("fft-check", DROP)
    assert len(result.checks) == len(expected["checks"])
    not_applicable = 0
    for got, want in zip(result.checks, expected["checks"]):
        assert got["outcome"] == want["outcome"]
        assert got["why_not_applicable"] == want.get("why_not_applicable")  # None where the JSON has none
        not_applicable += got["outcome"] == "not applicable"
    assert not_applicable > 0
    h, want = result.half_period_check, expected["half_period_check"]
    assert (h["count"], h["passed"]) == (want["count"], want["passed"]) and h["count"] > 0
    assert h["tolerance"] == pytest.approx(want["tolerance"], rel=REL)
    assert h["worst_rel_error"] == pytest.approx(want["worst_rel_error"], rel=REL)
    # A linear release is checked by its spectrum: no half-period check, nothing not applicable.
    assert result.verdict == expected["verdict_text"]
    free = railmodal.fft_check(railmodal.load_scene(FREE))
    assert free.half_period_check is None
    assert all(c["why_not_applicable"] is None for c in free.checks)


def test_output_spectra_show_the_modes_the_fft_check_found():
    scene = railmodal.load_scene(FREE)
    spectra = railmodal.output_spectra(railmodal.simulate(scene, outputs_only=True), scene)
    check = railmodal.fft_check(scene)
    bounce = next(c for c in check.checks if c["mode_name"] == "body bounce")
    peaks = spectra["body.bounce"].peaks()
    # The same record, window and padding as the fft-check's: the same peak to round-off.
    assert peaks[0]["frequency_hz"] == pytest.approx(bounce["peak_frequency_hz"], rel=1e-12)
    s = spectra["body.bounce"]
    assert s.amplitude.base is not None and s.frequencies[1] == pytest.approx(s.bin_spacing_hz)
    assert s.transform_length == 4 * s.signal_length  # zero-padded ×4


def test_amplitude_spectrum_of_a_tone():
    fs = 200.0
    n = np.arange(4000)
    x = 0.003 * np.sin(2 * np.pi * 1.37 * n / fs)
    s = railmodal.amplitude_spectrum(x, fs, padding="next-power-of-two")
    (peak,) = s.peaks()
    # The header example of spectrum.hpp prints 1.37021 Hz, 0.00300097 m, ± 0.05038 Hz (six digits).
    assert peak["frequency_hz"] == pytest.approx(1.37021, abs=5e-6)
    assert peak["amplitude"] == pytest.approx(0.00300097, abs=5e-9)
    assert peak["resolution_hz"] == pytest.approx(0.05038, abs=5e-6)
    assert s.window == "hann" and s.transform_length == 4096


def test_amplitude_spectra_plan_once_for_a_batch():
    rng = np.random.default_rng(3)
    signals = rng.standard_normal((5, 1000))
    batch = railmodal.amplitude_spectra(signals, 100.0, window="flat-top")
    assert len(batch) == 5
    for row, spectrum in zip(signals, batch):
        one = railmodal.amplitude_spectrum(row, 100.0, window="flat-top")
        # Both plans are FFTW's by estimate for the same length: the same transform, to round-off.
        np.testing.assert_allclose(spectrum.amplitude, one.amplitude, rtol=1e-12, atol=1e-15)


def test_spectrum_errors_name_the_argument():
    with pytest.raises(ValueError, match="window: 'blackman' is not one of"):
        railmodal.amplitude_spectrum(np.ones(8), 1.0, window="blackman")
    with pytest.raises(ValueError):  # the library's own check: fewer than 2 samples
        railmodal.amplitude_spectrum(np.ones(1), 1.0)
    with pytest.raises(TypeError):
        railmodal.amplitude_spectrum(np.ones(8), 1.0, windw="hann")


def test_swings_of_a_friction_decay():
    scene = railmodal.load_scene(DROP)
    history = railmodal.simulate(scene)
    dof = history.labels[0]
    s = railmodal.swings(history, dof)
    assert s["dof"] == dof and len(s["turning_times_s"]) == len(s["turning_values"]) >= 2
    np.testing.assert_allclose(s["half_periods_between_turns_s"], np.diff(s["turning_times_s"]), rtol=1e-12)
    with pytest.raises(KeyError):
        railmodal.swings(history, "nothing.here")


def test_simulations_run_at_once_on_threads():
    # The GIL is released around the run: two threads get the same answer as one.
    scene = railmodal.load_scene(FREE)
    reference = railmodal.simulate(scene).displacement
    results = [None, None]

    def run(k):
        results[k] = railmodal.simulate(scene).displacement

    threads = [threading.Thread(target=run, args=(k,)) for k in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for r in results:
        np.testing.assert_array_equal(r, reference)
