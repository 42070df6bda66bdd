"""Errors arrive as Python exceptions with the command line's text (docs/python.md, "Errors")."""
import warnings

import numpy as np
import pytest

import railmodal
from railmodal_paths import SOURCE, cli, data


def test_input_error_from_a_file_carries_the_clis_text_and_its_place():
    bad = "tests/cli/bad/wrong_unit.toml"
    code, _, stderr = cli("modes", bad, check=False)
    assert code == 3
    with pytest.raises(railmodal.InputError) as caught:
        railmodal.load_vehicle(bad)  # the tests run in the source tree (ctest's working directory)
    e = caught.value
    assert str(e) == stderr.strip()
    assert (e.file, e.line, e.column, e.key) == (bad, 9, 13, "body.cg_height")
    assert e.message.startswith("key 'body.cg_height': expected a length")
    assert isinstance(e, ValueError)


def test_input_error_without_a_place_has_none():
    with pytest.raises(railmodal.InputError) as caught:
        railmodal.load_vehicle(str(SOURCE / "no_such_vehicle.toml"))
    assert caught.value.line is None and caught.value.column is None and caught.value.key is None


def test_matrix_market_error_names_the_line():
    path = "tests/corpus/bad_inputs/matrix_nan_entry.mtx"
    # The corpus file's second line: "% expect modes-mtx: <the message>".
    expected = open(SOURCE / path).read().splitlines()[1].split("modes-mtx:", 1)[1].strip()
    with pytest.raises(railmodal.InputError) as caught:
        railmodal.read_matrix_market(path)
    assert caught.value.file == path and caught.value.line is not None
    assert expected in str(caught.value)


def test_input_error_from_a_dict_carries_the_key_path():
    with pytest.raises(railmodal.InputError) as caught:
        railmodal.vehicle_from_dict({"vehicle": {"name": "x", "template": "two-axle"},
                                     "body": {"mass": "20 kgf/cm"}})
    e = caught.value
    assert e.file == "<dict>" and e.line is None and e.column is None
    assert e.key == "body.mass"
    assert str(e).startswith("<dict>: error: key 'body.mass': expected a mass")


def test_warnings_from_a_dict_name_the_dict_and_the_key_as_its_errors_do(tmp_path):
    # The dict is written to a temporary file and read by the file reader; its warnings named
    # that file, deleted by then (user audit 2026-11-28b, F9 d). Now "<dict>" and the key path,
    # with the words the same file's warning has after its place.
    wagon = {"vehicle": {"name": "dict wagon", "template": "two-axle"},
             "body": {"mass": "42.2 t", "cg_height": "1.0 m",
                      "radius_of_gyration": {"roll": "1.2 m", "pitch": "4.04 m", "yaw": "4.04 m"}},
             "suspension": {"wheelbase": 8000, "spring_spacing": "2.0 m",
                            "spring": [{"kind": "leaf", "stiffness": "1.2 MN/m", "relative_friction": 0.1}]}}
    with pytest.warns(railmodal.InputWarning) as caught:
        railmodal.vehicle_from_dict(wagon)
    texts = [str(w.message) for w in caught]
    assert texts and texts[0].startswith("<dict>: warning: key 'suspension.wheelbase': read as 8000 m")
    assert all(t.startswith("<dict>: warning: key '") and "vehicle.toml" not in t for t in texts)
    assert caught[0].filename == __file__  # at the caller's line, not inside the package
    written = tmp_path / "wagon.toml"
    written.write_text(railmodal.vehicle_dict.to_toml(wagon)[0])
    with pytest.warns(railmodal.InputWarning) as from_file:
        railmodal.load_vehicle(str(written))
    assert [t.split(": warning: ", 1)[1] for t in texts] == \
        [str(w.message).split(": warning: ", 1)[1] for w in from_file]
    with warnings.catch_warnings():
        warnings.simplefilter("error", railmodal.InputWarning)
        with pytest.raises(railmodal.InputWarning, match="^<dict>: warning: key 'suspension.wheelbase'"):
            railmodal.vehicle_from_dict(wagon)


def test_numerical_error_names_the_degree_of_freedom():
    # dof2 has neither mass nor stiffness: condensing it statically is impossible.
    system = railmodal.LinearSystem(np.diag([1.0, 0.0]), np.diag([4.0, 0.0]))
    with pytest.raises(railmodal.NumericalError) as caught:
        railmodal.modes(system)
    assert "dof2" in str(caught.value)
    assert isinstance(caught.value, RuntimeError)


def test_invalid_options_are_value_errors_with_the_options_message():
    system = railmodal.LinearSystem(np.eye(1), np.eye(1))
    with pytest.raises(ValueError, match="ModalOptions: max_residual"):
        railmodal.modes(system, max_residual=-1.0)


def test_unknown_option_is_a_type_error_naming_it():
    system = railmodal.LinearSystem(np.eye(1), np.eye(1))
    with pytest.raises(TypeError, match="unknown option 'mode_cout'"):
        railmodal.modes(system, mode_cout=3)
    with pytest.raises(TypeError, match="unknown option 'shfit'"):
        railmodal.modes(system, arpack={"shfit": 1.0})


def test_unknown_enum_word_lists_the_words():
    system = railmodal.LinearSystem(np.eye(1), np.eye(1))
    with pytest.raises(ValueError, match="expected one of dense, arpack, auto"):
        railmodal.modes(system, solver="lapack")
    with pytest.raises(ValueError, match="expected one of vertical, lateral, all"):
        railmodal.assemble(railmodal.load_vehicle(data("vehicles", "resort_car.toml")), "sideways")


def test_invalid_argument_of_the_library_is_a_value_error():
    vehicle = railmodal.load_vehicle(data("vehicles", "resort_car.toml"))
    vehicle.bodies = vehicle.bodies + [vehicle.bodies[0]]  # a duplicate body name
    with pytest.raises(ValueError, match="body"):
        railmodal.assemble(vehicle)


def test_unknown_dof_label_lists_the_labels():
    system = railmodal.assemble(railmodal.load_vehicle(data("vehicles", "resort_car.toml")))
    modes = railmodal.modes(system)
    with pytest.raises(ValueError, match=r"no degree of freedom 'body.bonce' \(there are: body.lateral, "):
        railmodal.frf(system, modes, "body.bonce", [1.0])


def test_a_readings_warnings_are_input_warnings_with_the_clis_text():
    warned = "tests/cli/warnings/resort_car_hanger_bare_number.toml"
    _, _, stderr = cli("modes", warned)
    with pytest.warns(railmodal.InputWarning) as caught:
        odd = railmodal.load_vehicle(warned)  # the tests run in the source tree (ctest's working directory)
    assert [str(w.message) for w in caught] == stderr.splitlines()
    assert 'did you mean "734 mm"?' in str(caught[0].message)
    assert issubclass(railmodal.InputWarning, UserWarning)
    assert caught[0].filename == __file__  # at the caller's line, not inside the package
    # A warning changes nothing: the vehicle read as written (734 m hangers) whether or not
    # warnings are shown; the lateral stiffness holds the hangers'.
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        quiet = railmodal.load_vehicle(warned)
    assert np.array_equal(railmodal.assemble(odd, "lateral").K, railmodal.assemble(quiet, "lateral").K)


def test_input_warnings_become_errors_under_a_filter():
    with warnings.catch_warnings():
        warnings.simplefilter("error", railmodal.InputWarning)
        with pytest.raises(railmodal.InputWarning):
            railmodal.load_vehicle("tests/cli/warnings/resort_car_hanger_bare_number.toml")


def test_load_study_warns_the_base_files_warnings_once_as_compare_does():
    # The study's base vehicle (a bare-number hanger) and scene (dampers effect without dampers)
    # each draw one warning; its three variants read both, yet each is said once, in compare's
    # words (compare's stderr holds exactly these two lines: tests/cli, warning_compare_once).
    warned = "tests/cli/warnings/resort_car_hanger_study.toml"
    _, _, stderr = cli("compare", warned)
    for read_variants in (True, False):
        with pytest.warns(railmodal.InputWarning) as caught:
            railmodal.load_study(warned, read_variants=read_variants)
        assert [str(w.message) for w in caught] == stderr.splitlines()
        assert len(caught) == 2
        assert caught[0].filename == __file__  # at the caller's line, not inside the package
    with warnings.catch_warnings():
        warnings.simplefilter("error", railmodal.InputWarning)  # none: the same study written cleanly
        railmodal.load_study("tests/cli/warnings/resort_car_study_no_warnings.toml")
