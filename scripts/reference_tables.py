#!/usr/bin/env python3
"""Rewrites the reference tables in docs/guide/ from the parts' descriptions.

usage: python3 scripts/reference_tables.py [BINARY]   (BINARY: build/musclesim by default)

Each table sits between "<!-- reference: NAME -->" and "<!-- end reference -->" and is what
`musclesim reference PART` prints; tests/io/reference_table_test.cc fails while one differs.
"""
import pathlib
import re
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
# block name -> (page, part)
BLOCKS = {
    "actuator": ("docs/guide/scenarios.md", "actuator"),
    "nodes": ("docs/guide/networks.md", "nodes"),
    "element laws": ("docs/guide/networks.md", "elements"),
    "waveforms": ("docs/guide/scenarios.md", "waveforms"),
    "loads": ("docs/guide/scenarios.md", "loads"),
    "activation dynamics": ("docs/guide/scenarios.md", "activation_dynamics"),
    "model families": ("docs/guide/model.md", "models"),
    "fit": ("docs/guide/model.md", "fit"),
    "controllers": ("docs/guide/control.md", "controllers"),
    "time": ("docs/guide/scenarios.md", "time"),
    "solver": ("docs/guide/scenarios.md", "solver"),
    "output": ("docs/guide/scenarios.md", "output"),
    "sweep": ("docs/guide/sweeps.md", "sweep"),
    "problem": ("docs/guide/optimize.md", "problem"),
    "identify": ("docs/guide/identification.md", "identify"),
    "identify series": ("docs/guide/identification.md", "identify_series"),
}


def main() -> int:
    binary = sys.argv[1] if len(sys.argv) > 1 else str(ROOT / "build" / "musclesim")
    for name, (page, part) in BLOCKS.items():
        table = subprocess.run([binary, "reference", part], capture_output=True, text=True,
                               check=True).stdout
        path = ROOT / page
        text = path.read_text()
        pattern = re.compile(r"(<!-- reference: " + re.escape(name) + r" -->\n).*?(<!-- end reference -->)",
                             re.S)
        if not pattern.search(text):
            print(f"reference_tables.py: {page} has no block '{name}'", file=sys.stderr)
            return 1
        path.write_text(pattern.sub(lambda m: m.group(1) + table + m.group(2), text, count=1))
    return 0


if __name__ == "__main__":
    sys.exit(main())
