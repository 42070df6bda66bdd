"""Vehicles, assembled matrices, systems from numpy and Matrix Market (docs/python.md)."""
import tomllib

import numpy as np
import pytest
import scipy.sparse

import railmodal
from railmodal_paths import cli_json, data

RESORT = data("vehicles", "resort_car.toml")


def test_vehicle_fields_are_the_files_in_si():
    v = railmodal.load_vehicle(RESORT)
    assert v.name.startswith("Resort-type passenger car")
    assert [b.name for b in v.bodies] == ["body", "bogie1", "bogie2"]
    # weight = "34000 kgf" with gravity = "981 cm/s^2": m = 34000 · 9.80665 / 9.81 kg.
    assert v.bodies[0].mass == pytest.approx(34000 * 9.80665 / 9.81, rel=1e-14)  # a few ulp of unit arithmetic
    assert v.gravity == pytest.approx(9.81, rel=1e-15)
    assert len(v.elements) == 12
    leaf = v.elements[0].vertical_stages[0]
    assert leaf.kind == "leaf" and leaf.stiffness == pytest.approx(700 * 9.80665 * 100, rel=1e-14)  # kgf/cm → N/m


def test_assemble_gives_the_clis_dofs_and_views_without_copies():
    system = railmodal.assemble(railmodal.load_vehicle(RESORT), dofs="all")
    assert system.dof_labels == cli_json("modes", RESORT)["dofs"]
    n = len(system)
    for matrix in (system.M, system.C, system.K, system.K_gravity):
        assert matrix.shape == (n, n) and matrix.dtype == np.float64
        assert not matrix.flags.writeable  # a view of the system's memory
        assert matrix.base is not None
    assert np.shares_memory(system.M, system.M)  # two reads, one buffer: no copy was made
    assert np.array_equal(system.M, system.M.T) and np.array_equal(system.K, system.K.T)
    vertical = railmodal.assemble(railmodal.load_vehicle(RESORT), "vertical")
    assert all(label.endswith(("bounce", "pitch")) for label in vertical.dof_labels)


def test_a_view_keeps_its_system_alive():
    mass = railmodal.assemble(railmodal.load_vehicle(RESORT)).M  # the system is dropped at once
    again = railmodal.assemble(railmodal.load_vehicle(RESORT)).M
    assert np.array_equal(mass, again)


def test_vehicle_from_dict_is_the_file_read_through_the_same_reader():
    with open(RESORT, "rb") as f:
        document = tomllib.load(f)  # the file's tables as dicts, units still strings
    from_dict = railmodal.assemble(railmodal.vehicle_from_dict(document))
    from_file = railmodal.assemble(railmodal.load_vehicle(RESORT))
    # One reader, one unit conversion, one assembly: bit for bit the same matrices.
    for a, b in ((from_dict.M, from_file.M), (from_dict.C, from_file.C), (from_dict.K, from_file.K)):
        assert np.array_equal(a, b)


def test_linear_system_from_numpy():
    M = np.diag([2.0, 1.0])
    K = np.array([[6.0, -2.0], [-2.0, 4.0]])
    C = 0.01 * K
    system = railmodal.LinearSystem(M, K, C, dof_labels=["a", "b"])
    assert system.dof_labels == ["a", "b"]
    assert np.array_equal(system.M, M) and np.array_equal(system.K, K) and np.array_equal(system.C, C)
    assert np.array_equal(railmodal.LinearSystem(M, K).C, np.zeros((2, 2)))
    assert railmodal.LinearSystem(M, K).dof_labels == ["dof1", "dof2"]
    with pytest.raises(ValueError, match="K is 3 x 3; expected 2 x 2"):
        railmodal.LinearSystem(M, np.eye(3))
    with pytest.raises(ValueError, match="not a finite number"):
        railmodal.LinearSystem(M, np.full((2, 2), np.nan))


def test_matrix_market_model_gives_the_clis_modes():
    mass, stiffness = data("matrices", "resort_car_vertical_M.mtx"), data("matrices", "resort_car_vertical_K.mtx")
    expected = cli_json("modes", "--mass", mass, "--stiffness", stiffness)
    system = railmodal.load_matrix_model(mass, stiffness)
    result = railmodal.modes(system)
    assert system.dof_labels == expected["dofs"]
    # The JSON writes round-trip digits of the same computation: equal to rounding of the last digit.
    np.testing.assert_allclose(result.frequencies_hz, [m["frequency_hz"] for m in expected["modes"]], rtol=1e-14)
    sparse = railmodal.load_matrix_model(mass, stiffness, sparse=True)
    assert isinstance(sparse, railmodal.SparseSystem)
    assert np.array_equal(sparse.M.toarray(), system.M)


def test_matrix_market_round_trip(tmp_path):
    matrix, labels = railmodal.read_matrix_market(data("matrices", "resort_car_vertical_K.mtx"))
    assert scipy.sparse.issparse(matrix)
    path = str(tmp_path / "K.mtx")
    railmodal.write_matrix_market(path, matrix, symmetric=True, dof_labels=labels)
    again, labels_again = railmodal.read_matrix_market(path, require_symmetric=True)
    assert labels_again == labels
    assert np.array_equal(again.toarray(), matrix.toarray())  # 17 digits: exact


def test_sparse_train_as_scipy_sparse():
    train = railmodal.wagon_train(10)
    assert len(train) == 50 and train.dof_labels[0] == "wagon1.body.longitudinal"
    assert scipy.sparse.issparse(train.K) and train.K.shape == (50, 50)
    dense = train.to_dense()
    assert np.array_equal(dense.K, train.K.toarray()) and np.array_equal(dense.M, train.M.toarray())


def test_vehicle_fields_can_be_changed_for_a_variant():
    car = railmodal.load_vehicle(RESORT)
    variant = car.copy()
    variant.bodies[0].mass *= 2.0  # the list's items are the vehicle's own bodies
    assert car.bodies[0].mass * 2.0 == variant.bodies[0].mass
    body = railmodal.assemble(variant).M[1, 1]  # body.bounce
    assert body == pytest.approx(2.0 * railmodal.assemble(car).M[1, 1], rel=1e-15)
    assert variant.bodies[0].held == car.bodies[0].held
    e = car.elements[0]
    # The axlebox: a leaf spring in series with two coils (1/k = 1/k_leaf + 1/(2 k_coil)).
    k_leaf, k_coil = e.vertical_stages[0].stiffness, e.vertical_stages[1].stiffness
    assert e.vertical_stiffness == pytest.approx(1.0 / (1.0 / k_leaf + 1.0 / (2.0 * k_coil)), rel=1e-14)


def test_large_matrices_are_views_not_copies():
    big = railmodal.wagon_train(400).to_dense()  # 2000 DOFs: 32 MB per matrix
    first, second = big.M, big.K
    assert np.shares_memory(first, big.M) and np.shares_memory(second, big.K)
    assert first.nbytes == 2000 * 2000 * 8


def test_changing_an_item_of_a_vehicle_list_changes_the_vehicle():
    # The obvious notebook edit, which changed a copy (and nothing else) while the lists were
    # converted to Python lists: now items are references into the vehicle.
    car = railmodal.load_vehicle(RESORT)
    before = railmodal.modes(railmodal.assemble(car, "vertical")).frequencies_hz
    car.bodies[0].mass *= 2.0
    for stage in car.elements[0].vertical_stages:
        stage.stiffness *= 3.0
    after = railmodal.modes(railmodal.assemble(car, "vertical")).frequencies_hz
    reference = railmodal.load_vehicle(RESORT)
    assert car.bodies[0].mass == 2.0 * reference.bodies[0].mass
    assert car.elements[0].vertical_stages[1].stiffness == 3.0 * reference.elements[0].vertical_stages[1].stiffness
    assert not np.array_equal(before, after)
    # The 3-vectors are read-only copies: an in-place edit raises instead of doing nothing.
    with pytest.raises(ValueError):
        car.bodies[0].inertia[0] *= 2.0
    car.bodies[0].inertia = 2.0 * car.bodies[0].inertia
    with pytest.raises(AttributeError):  # a tuple: appending to a copy would change nothing
        car.bodies[0].held.append("roll")
    car.bodies[0].held = [*car.bodies[0].held, "roll"]
    assert "roll" in car.bodies[0].held
    assert car.bodies[0].inertia[1] == 2.0 * reference.bodies[0].inertia[1]


def body_bounce_hz(vehicle):
    rows = railmodal.modes(railmodal.assemble(vehicle, "vertical")).records()
    return next(r["frequency_hz"] for r in rows if r["name"] == "body bounce")


def test_a_plain_loop_edits_the_springs_of_a_copy():
    """docs/python.md's studies edit a copy's spring stages in a plain loop (user audit
    2026-11-27c, F12): an element's stages are the vehicle's own, so the loop changes the result,
    and the copy-modify-assign the guide showed before gives the same matrices: it is not needed."""
    base = railmodal.load_vehicle(data("vehicles", "manchester_benchmark_coach.toml"))
    plain = base.copy()
    for e in plain.elements:
        if e.name.endswith("cradle"):
            for s in e.vertical_stages:
                s.stiffness = 300e3
    assigned = base.copy()
    elements = assigned.elements
    for e in elements:
        if e.name.endswith("cradle"):
            stages = e.vertical_stages
            for s in stages:
                s.stiffness = 300e3
            e.vertical_stages = stages
    assigned.elements = elements
    # The audit's figures, printed to 4 decimals: 1.0739 Hz for the file's 430 kN/m air springs,
    # 0.9188 Hz with 300 kN/m.
    assert body_bounce_hz(base) == pytest.approx(1.0739, abs=5e-5)
    assert body_bounce_hz(plain) == pytest.approx(0.9188, abs=5e-5)
    np.testing.assert_array_equal(railmodal.assemble(plain).K, railmodal.assemble(assigned).K)
    # The copy is a vehicle of its own: the base keeps its springs.
    assert all(s.stiffness != 300e3 for e in base.elements if e.name.endswith("cradle") for s in e.vertical_stages)
    assert any(e.name.endswith("cradle") for e in base.elements)


def test_a_vehicle_list_changes_length_only_while_no_item_is_held():
    car = railmodal.load_vehicle(RESORT)
    n = len(car.elements)
    damper = railmodal.Element()
    damper.name, damper.lower, damper.upper = "extra damper", "", "body"
    damper.point = [0.0, 0.0, 0.0]
    damper.vertical_damping = 1e4
    car.elements.append(damper)  # no item held: the list grows
    assert len(car.elements) == n + 1 and car.elements[-1].name == "extra damper"
    assert railmodal.assemble(car).C[1, 1] == pytest.approx(railmodal.assemble(railmodal.load_vehicle(RESORT)).C[1, 1] + 1e4)
    held = car.elements[0]  # a reference into the list's storage, which a longer list would move
    with pytest.raises(RuntimeError, match="cannot change length"):
        car.elements.append(damper)
    with pytest.raises(RuntimeError, match="cannot change length"):
        car.elements = list(car.elements)[:-1]
    kept = held.copy()
    del held
    car.elements = [e.copy() for e in car.elements][:-1]  # nothing held now
    assert len(car.elements) == n and kept.name == car.elements[0].name
    # Same length: assigned in place, and an item held sees the new values.
    stage = car.elements[0].vertical_stages[0]
    stiffer = [s.copy() for s in car.elements[0].vertical_stages]
    stiffer[0].stiffness *= 2.0
    car.elements[0].vertical_stages = stiffer
    assert stage.stiffness == stiffer[0].stiffness
    with pytest.raises(RuntimeError, match="cannot change length"):
        car.elements[0].vertical_stages = stiffer[:1]
    with pytest.raises(IndexError):
        car.bodies[len(car.bodies)]


def test_assemble_takes_a_vehicle_file_as_the_other_analyses_do():
    by_file = railmodal.assemble(RESORT, "vertical")
    by_object = railmodal.assemble(railmodal.load_vehicle(RESORT), "vertical")
    assert np.array_equal(by_file.K, by_object.K) and by_file.dof_labels == by_object.dof_labels
    with pytest.raises(TypeError, match="expected a vehicle file or a Vehicle, got int"):
        railmodal.assemble(3)
