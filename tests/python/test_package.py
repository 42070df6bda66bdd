"""The package imports from the build tree and is the build's version."""
import pathlib
import re

import railmodal


def test_version_is_the_projects():
    # The top-level CMakeLists.txt's project(... VERSION x.y.z) is the one source of the version.
    cmake = (pathlib.Path(__file__).parents[2] / "CMakeLists.txt").read_text()
    expected = re.search(r"project\(railmodal VERSION ([0-9.]+)", cmake).group(1)
    assert railmodal.__version__ == expected
