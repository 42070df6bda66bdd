"""Undamped and damped modes, against the command line's JSON of the same vehicle."""
import threading

import numpy as np
import pandas
import pytest

import railmodal
from railmodal_paths import SOURCE, cli_json, data

RESORT = data("vehicles", "resort_car.toml")
COACH = data("vehicles", "manchester_benchmark_coach.toml")


def test_resort_car_modes_equal_the_clis():
    expected = cli_json("modes", RESORT)
    result = railmodal.modes(railmodal.assemble(railmodal.load_vehicle(RESORT)))
    rows = expected["modes"]
    assert result.names == [m["name"] for m in rows]
    assert result.kinds == [m["kind"] for m in rows]
    # The same library call in both; the JSON holds round-trip digits, so only the last
    # digit's rounding may differ.
    np.testing.assert_allclose(result.frequencies_hz, [m["frequency_hz"] for m in rows], rtol=1e-14)
    np.testing.assert_allclose(result.periods_s, [m["period_s"] for m in rows], rtol=1e-14)
    np.testing.assert_allclose(result.eigenvalues, [m["eigenvalue"] for m in rows], rtol=1e-14)
    shapes = np.array([[m["shape"][label] for m in rows] for label in result.dof_labels])
    np.testing.assert_allclose(result.shapes, shapes, rtol=0, atol=1e-15 * np.abs(shapes).max())


def test_shapes_are_mass_normalised_columns():
    system = railmodal.assemble(railmodal.load_vehicle(RESORT))
    result = railmodal.modes(system)
    phi = result.shapes
    assert phi.shape == (len(system), len(result))
    # φᵀMφ = I to the orthonormality the solver checks (ModalResult::orthonormality_error ≤ 1e-10 here).
    np.testing.assert_allclose(phi.T @ system.M @ phi, np.eye(len(result)), atol=1e-10)
    np.testing.assert_array_equal(phi[:, 0], result[0].shape)
    assert result[0].shape.base is not None and not result[0].shape.flags.writeable


def test_records_make_a_dataframe_in_one_call():
    result = railmodal.modes(railmodal.assemble(railmodal.load_vehicle(RESORT)))
    frame = pandas.DataFrame(result.records())
    assert list(frame["name"]) == result.names
    np.testing.assert_array_equal(frame["frequency_hz"].to_numpy(), result.frequencies_hz)
    assert frame.loc[0, "centre_about"] == "roll" and frame["centre_about"].isna().any()


def test_arpack_options_give_the_lowest_dense_modes():
    train = railmodal.wagon_train(40)  # 200 DOFs
    dense = railmodal.modes(train, solver="dense")
    lowest = railmodal.modes(train, solver="arpack", mode_count=6, arpack={"tolerance": 0.0})
    assert lowest.solver.solver == "arpack" and len(lowest) >= 6
    k = len(lowest)
    # Both are checked to a relative residual of 1e-8 (ModalOptions::max_residual): the
    # eigenvalues then agree to about that, far better in practice.
    np.testing.assert_allclose(lowest.eigenvalues[1:], dense.eigenvalues[1:k], rtol=1e-8)
    assert lowest.kinds[0] == "rigid-body"


def test_sparse_and_dense_systems_give_the_same_modes():
    train = railmodal.wagon_train(5)
    np.testing.assert_allclose(railmodal.modes(train).eigenvalues[1:],
                               railmodal.modes(train.to_dense()).eigenvalues[1:], rtol=1e-12)


def test_modes_of_numpy_matrices():
    # Two unit masses, each on a unit spring, joined by a unit spring: λ = 1 (in phase) and 3.
    system = railmodal.LinearSystem(np.eye(2), np.array([[2.0, -1.0], [-1.0, 2.0]]))
    np.testing.assert_allclose(railmodal.modes(system).eigenvalues, [1.0, 3.0], rtol=1e-14)


def test_modes_batch_equals_a_loop_of_modes():
    system = railmodal.assemble(railmodal.load_vehicle(RESORT))
    scales = np.array([0.5, 1.0, 2.0, 4.0])
    M = np.repeat(system.M[None], len(scales), axis=0)
    K = scales[:, None, None] * system.K
    batch = railmodal.modes_batch(M, K)
    single = railmodal.modes(system)
    for scale, result in zip(scales, batch):
        # K scaled by s scales every ω² by s: frequencies by √s, to rounding.
        np.testing.assert_allclose(result.frequencies_hz, np.sqrt(scale) * single.frequencies_hz, rtol=1e-12)
    np.testing.assert_array_equal(batch[1].frequencies_hz,
                                  railmodal.modes(railmodal.LinearSystem(system.M, system.K)).frequencies_hz)
    with pytest.raises(ValueError, match="stacks of the same shape"):
        railmodal.modes_batch(M, K[:2])


def test_damped_modes_equal_the_clis():
    expected = cli_json("modes", "--damped", COACH)
    result = railmodal.damped_modes(railmodal.assemble(railmodal.load_vehicle(COACH)))
    rows = expected["modes"]
    assert result.names == [m["name"] for m in rows]
    assert result.kinds == [m["kind"] for m in rows]
    ratios = np.array([np.nan if m["damping_ratio"] is None else m["damping_ratio"] for m in rows])
    np.testing.assert_allclose(result.damping_ratios, ratios, rtol=1e-13)  # round-trip digits of one computation
    first = np.array([complex(*m["eigenvalues"][0]) for m in rows])
    np.testing.assert_allclose(result.eigenvalues, first, rtol=1e-13)
    assert result.stable == expected["stable"]
    frame = pandas.DataFrame(result.records())
    assert frame.shape[0] == len(rows) and "damping_ratio" in frame
    assert result.undamped.frequencies_hz.shape == (len(result.undamped),)


def test_damped_notes_are_the_damped_modes_own():
    # A coach with yaw dampers: the damped modes carry the series dampers, the undamped solve
    # leaves them out; each result says so in its own notes, as the CLI's JSON.
    vehicle = str(SOURCE / "tests" / "corpus" / "vehicles" / "yaw_damped_coach.toml")
    result = railmodal.damped_modes(railmodal.assemble(railmodal.load_vehicle(vehicle)))
    assert result.notes == cli_json("modes", "--damped", vehicle)["notes"]
    assert any(n.startswith("series dampers: in") for n in result.notes)
    assert result.undamped.notes == cli_json("modes", vehicle)["notes"]
    assert any(n.startswith("series dampers: left out") for n in result.undamped.notes)


def test_damped_options_nest_the_undamped_ones():
    system = railmodal.assemble(railmodal.load_vehicle(COACH))
    with pytest.raises(TypeError, match="unknown option 'modes'"):
        railmodal.damped_modes(system, undamped={"modes": 3})
    with pytest.raises(ValueError, match="critical_gap"):
        railmodal.damped_modes(system, critical_gap=-1.0)


def test_modes_from_several_threads_equal_the_serial_ones():
    # The solves run without the GIL; results must not depend on other threads' calls.
    systems = [railmodal.LinearSystem(np.eye(3), s * np.diag([1.0, 2.0, 3.0])) for s in (1.0, 2.0, 3.0, 4.0)]
    serial = [railmodal.modes(s).eigenvalues for s in systems]
    parallel = [None] * len(systems)

    def solve(i):
        for _ in range(50):
            parallel[i] = railmodal.modes(systems[i]).eigenvalues

    threads = [threading.Thread(target=solve, args=(i,)) for i in range(len(systems))]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for a, b in zip(serial, parallel):
        np.testing.assert_array_equal(a, b)


def test_summary_mode_objects_and_energy_shares():
    system = railmodal.assemble(railmodal.load_vehicle(RESORT))
    result = railmodal.modes(system)
    summary = result.solver
    assert summary.passed and summary.solver == "dense" and summary.analysis == "undamped modes"
    assert [c["passed"] for c in summary.checks] == [True] * len(summary.checks)
    assert {s["stage"] for s in summary.stages} >= {"eigensolve"}
    shares = result.kinetic_energy_shares
    np.testing.assert_allclose(shares.sum(axis=0), 1.0, rtol=1e-12)  # each mode's shares sum to 1
    mode = result[2]
    assert mode.name == "body bounce" and mode.to_dict() == result.records()[2]
    assert result[-1].index == len(result)
    with pytest.raises(IndexError):
        result[len(result)]
    assert result.max_residual <= 1e-8 and result.orthonormality_error < 1e-10


def test_modes_of_vehicles_equals_assembling_and_solving_each():
    car = railmodal.load_vehicle(RESORT)
    heavier = car.copy()
    bodies = heavier.bodies
    bodies[0].mass *= 1.5
    heavier.bodies = bodies
    results = railmodal.modes_of_vehicles([car, heavier], dofs="vertical", mode_count=2)
    for vehicle, result in zip([car, heavier], results):
        # The same two library calls in the same order: the same numbers.
        expected = railmodal.modes(railmodal.assemble(vehicle, "vertical"), mode_count=2)
        np.testing.assert_array_equal(result.frequencies_hz, expected.frequencies_hz)
    assert results[1].frequencies_hz[0] < results[0].frequencies_hz[0]  # a heavier body bounces slower
    with pytest.raises(ValueError, match="expected one of vertical"):
        railmodal.modes_of_vehicles([car], dofs="up")
