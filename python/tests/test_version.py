"""One version, from CMakeLists.txt's project(): the module's __version__, the command's
--version and (when installed by pip) the package metadata all say it."""
import importlib.metadata
import re
import subprocess

import musclesim
from conftest import CLI, SOURCE


def project_version():
    text = (SOURCE / "CMakeLists.txt").read_text()
    return re.search(r"project\(musclesim VERSION ([0-9.]+)", text).group(1)


def test_module_and_command_give_the_project_version():
    version = project_version()
    assert musclesim.__version__ == version
    shown = subprocess.run([CLI, "--version"], capture_output=True, text=True, check=True)
    assert shown.stdout.strip() == "musclesim " + version


def test_an_installed_package_carries_the_same_version():
    try:
        installed = importlib.metadata.version("musclesim")
    except importlib.metadata.PackageNotFoundError:
        # not installed: then the module is the build tree's, not a site-packages one
        assert "-packages" not in musclesim.__file__
        return
    assert installed == project_version()
