"""mypy --strict on the Python examples of the README and of the documentation site (the
blocks test_readme.py runs), against the musclesim package that `import musclesim` finds: an
installed one (its py.typed and stubs), or the one on PYTHONPATH, as mypy looks for imports
where Python does. Each block is written to a temporary directory as a module of its own and
all are checked in one mypy run; errors are printed as PAGE:LINE of the Markdown source.

    python3 python/tests/typecheck_examples.py [mypy options...]

Needs mypy (pip install mypy), and matplotlib for the examples that draw. Exits 0 when mypy
reports nothing, 1 on any error (2 when mypy itself fails)."""
import importlib.util
import os
import pathlib
import re
import sys
import tempfile

from mypy import api
from mypy.version import __version__ as mypy_version

from doc_examples import python_blocks

# the repository (as the tests find it: conftest.py)
ROOT = pathlib.Path(os.environ.get("MUSCLESIM_SOURCE_DIR",
                                   pathlib.Path(__file__).resolve().parents[2]))
# a message of mypy: FILE:LINE[:COLUMN]: error|note: TEXT
MESSAGE = re.compile(r"^(?P<file>[^:\n]+):(?P<line>\d+):(?:\d+:)? (?P<rest>(?:error|note): .*)$")


def main(options: list[str]) -> int:
    spec = importlib.util.find_spec("musclesim")
    if spec is None or spec.origin is None:
        print("typecheck_examples: no musclesim package to check against", file=sys.stderr)
        return 2
    print(f"typecheck_examples: mypy {mypy_version}, musclesim from "
          f"{pathlib.Path(spec.origin).parent}")
    blocks = python_blocks(ROOT)
    with tempfile.TemporaryDirectory() as work:
        files = {}
        for k, block in enumerate(blocks):
            module = f"example_{k}.py"
            pathlib.Path(work, module).write_text(block.code)
            files[module] = block
        # in the temporary directory, so that mypy (which looks in the working directory
        # first) finds nothing of the repository but the package as Python would
        cwd = os.getcwd()
        os.chdir(work)
        try:
            out, err, status = api.run(["--strict", "--cache-dir", os.path.join(work, ".cache"),
                                        "--no-error-summary", *options, *files])
        finally:
            os.chdir(cwd)
    if err:
        print(err, end="", file=sys.stderr)
    errors = 0
    for text in out.splitlines():
        found = MESSAGE.match(text)
        where = files.get(os.path.basename(found["file"])) if found else None
        if found is None or where is None:
            print(text)  # a message on another file (the package, a stub)
            errors += " error: " in text
            continue
        page = where.page.relative_to(ROOT) if where.page.is_relative_to(ROOT) else where.page
        print(f"{page}:{where.line + int(found['line']) - 1}: {found['rest']}")
        errors += found["rest"].startswith("error:")
    if status not in (0, 1):
        print(f"typecheck_examples: mypy failed (status {status})", file=sys.stderr)
        return 2
    errors = max(errors, status)  # status 1: mypy found errors, however they read
    print(f"typecheck_examples: {len(blocks)} blocks of {len({b.page for b in blocks})} pages, "
          + ("mypy --strict finds no error" if not errors else f"{errors} errors"))
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
