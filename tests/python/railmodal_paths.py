"""Where the tests find the source tree's data and the command-line program they compare with."""
import json
import os
import pathlib
import subprocess

import railmodal

SOURCE = pathlib.Path(os.environ.get("RAILMODAL_SOURCE_DIR", pathlib.Path(__file__).parents[2]))
# build/python/railmodal/__init__.py: the program is build/railmodal.
CLI = pathlib.Path(railmodal.__file__).resolve().parents[2] / "railmodal"


def data(*parts):
    return str(SOURCE.joinpath("data", *parts))


def cli(*arguments, check=True):
    """Runs the command-line program from the source tree; (exit code, stdout, stderr)."""
    run = subprocess.run([str(CLI), *arguments], cwd=SOURCE, capture_output=True, text=True)
    if check and run.returncode != 0:
        raise AssertionError("railmodal %s: %d\n%s" % (" ".join(arguments), run.returncode, run.stderr))
    return run.returncode, run.stdout, run.stderr


def cli_json(*arguments):
    return json.loads(cli(*arguments, "--format", "json")[1])
