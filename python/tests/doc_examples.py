"""The Python examples of the README and of the documentation site: every ```python block of
README.md and of docs/ (but the generated reports under docs/reports/), in page order.
Shared by test_readme.py (each block runs) and typecheck_examples.py (mypy --strict on each)."""
import pathlib
import re
from typing import NamedTuple

FENCE = re.compile(r"```python\n(.*?)```", re.S)


class Block(NamedTuple):
    page: pathlib.Path  # the Markdown file
    line: int  # the page's line of the block's first line of code (1-based)
    code: str


def documents(root: pathlib.Path) -> list[pathlib.Path]:
    """README.md, then docs/**/*.md in path order, the reports left out."""
    return [root / "README.md"] + sorted(
        p for p in (root / "docs").rglob("*.md") if "reports" not in p.relative_to(root).parts)


def python_blocks(root: pathlib.Path) -> list[Block]:
    blocks = []
    for page in documents(root):
        text = page.read_text()
        for match in FENCE.finditer(text):
            line = text.count("\n", 0, match.start(1)) + 1
            blocks.append(Block(page, line, match.group(1)))
    return blocks
