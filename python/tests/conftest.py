"""What the Python tests share: where the repository's scenarios and data are, and the
musclesim program whose files they compare the module's results with. ctest sets
MUSCLESIM_SOURCE_DIR and MUSCLESIM_CLI; run by hand, the repository is two folders up and the
program is the one on PATH (an installed package's), else build/musclesim."""
import os
import pathlib
import shutil

SOURCE = pathlib.Path(os.environ.get("MUSCLESIM_SOURCE_DIR",
                                     pathlib.Path(__file__).resolve().parents[2]))
SCENARIOS = SOURCE / "scenarios"
DATA = SOURCE / "data"
CONCENTRIC = SCENARIOS / "concentric.yaml"
CLI = (os.environ.get("MUSCLESIM_CLI") or shutil.which("musclesim")
       or str(SOURCE / "build" / "musclesim"))
