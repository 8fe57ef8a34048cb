"""The README's and the documentation site's Python examples run as written: every ```python
block of README.md and of docs/ (but the generated reports) is executed in a fresh directory
holding links to scenarios/ and data/, with matplotlib drawing off-screen."""
import os
import re
import subprocess
import sys

import pytest
from conftest import SOURCE
from doc_examples import python_blocks

ROOT = SOURCE
BLOCKS = [block.code for block in python_blocks(ROOT)]


def test_the_readme_and_the_site_have_python_examples():
    assert re.search(r"```python\n", (ROOT / "README.md").read_text()), "README.md: no ```python"
    assert len(BLOCKS) > 1


@pytest.mark.parametrize("code", BLOCKS, ids=[f"block{i}" for i in range(len(BLOCKS))])
def test_a_readme_python_block_runs(code, tmp_path):
    (tmp_path / "scenarios").symlink_to(ROOT / "scenarios")
    (tmp_path / "data").symlink_to(ROOT / "data")
    # the package as this test imports it, whatever the directory
    paths = [os.path.abspath(p) for p in os.environ.get("PYTHONPATH", "").split(os.pathsep) if p]
    env = dict(os.environ, MPLBACKEND="Agg", PYTHONPATH=os.pathsep.join(paths))
    done = subprocess.run([sys.executable, "-c", code], cwd=tmp_path, env=env,
                          capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
