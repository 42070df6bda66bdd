"""Every ```python block of docs/python.md runs, in order, in one namespace, from the source tree."""
import os
import re

from railmodal_paths import SOURCE


def test_every_snippet_of_the_guide_runs(capsys):
    text = (SOURCE / "docs" / "python.md").read_text()
    blocks = re.findall(r"^```python\n(.*?)^```", text, flags=re.S | re.M)
    assert len(blocks) >= 8  # the guide's examples (a block lost to a formatting slip fails here)
    namespace = {"__name__": "docs_python"}
    here = os.getcwd()
    os.chdir(SOURCE)
    try:
        for number, block in enumerate(blocks, 1):
            try:
                exec(compile(block, "docs/python.md block %d" % number, "exec"), namespace)
            except Exception as error:
                raise AssertionError("docs/python.md, block %d:\n%s" % (number, block)) from error
    finally:
        os.chdir(here)
    printed = capsys.readouterr().out
    assert "body.cg_height" in printed and "body.mass None" in printed  # the error examples ran their except
