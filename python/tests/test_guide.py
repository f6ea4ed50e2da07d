"""The Python code of docs/python.md runs as written, block after block, from the repository's
root (its paths are the repository's)."""

import os
import re

from conftest import REPOSITORY


def test_guide_runs(capsys):
    text = (REPOSITORY / "docs" / "python.md").read_text()
    blocks = re.findall(r"```python\n(.*?)```", text, flags=re.S)
    assert len(blocks) >= 5
    namespace = {}
    here = os.getcwd()
    os.chdir(REPOSITORY)
    try:
        for block in blocks:
            exec(compile(block, "docs/python.md", "exec"), namespace)
    finally:
        os.chdir(here)
    assert "refused:" in capsys.readouterr().out
