"""tools/benchmarks/python_overhead.py keeps working (its figures are read, not asserted: speed is
shown by the benchmark, never by a test)."""
import subprocess
import sys

import railmodal
from railmodal_paths import CLI, SOURCE


def test_the_overhead_benchmark_runs_and_reports_every_call():
    build = CLI.parent
    run = subprocess.run([sys.executable, str(SOURCE / "tools" / "benchmarks" / "python_overhead.py"), str(build), "1", "1"],
                         capture_output=True, text=True, cwd=SOURCE,
                         env={"PYTHONPATH": str(build / "python"), "PATH": "/usr/bin:/bin"})
    assert run.returncode == 0, run.stderr
    rows = {line.split()[0]: line.split()[1:5] for line in run.stdout.splitlines()[1:-1]}
    assert set(rows) == {"modes_1dof", "assemble", "modes", "frf_1000", "amplitude_curve_10000",
                         "study_critical_speeds"}
    for name, (cpp, python, _, _) in rows.items():
        assert float(cpp) > 0 and float(python) > 0, name
    assert "as a view" in run.stdout.splitlines()[-1]
    assert railmodal.__version__  # the package the script imported is this build's
