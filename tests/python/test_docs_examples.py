"""The Python examples of README.md and docs/python.md run as printed (from the repository's root)."""
import os
import pathlib
import re
import subprocess
import sys

import pytest

from conftest import SOURCE


def python_blocks(page):
    text = (SOURCE / page).read_text()
    return re.findall(r"```python\n(.*?)```", text, re.S)


@pytest.mark.parametrize("page", ["README.md", str(pathlib.Path("docs", "python.md"))])
def test_page_examples_run(page):
    blocks = python_blocks(page)
    assert blocks, f"{page} has no Python example"
    for code in blocks:
        done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=str(SOURCE),
                              env=dict(os.environ))
        assert done.returncode == 0, f"{page}:\n{code}\n{done.stderr}"
        assert "Y/Q" in done.stdout or re.search(r"\d", done.stdout), done.stdout
