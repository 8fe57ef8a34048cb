# The tools every script of musclesim builds and tests with, sourced by them. Chosen by path
# rather than taken from whatever comes first on PATH: a machine may carry pip's CMake and a
# pyenv python3 ahead of Debian's, and the build is made for Debian's C++ libraries, whose
# CMake package files Debian's CMake reads (pip's CMake 4 cannot configure this project with
# Debian's NLopt) and whose Python packages (python3-numpy, python3-pytest, pybind11-dev)
# belong to Debian's python3. scripts/install-deps.sh installs all three.
#   MUSCLESIM_CMAKE, MUSCLESIM_CTEST, MUSCLESIM_PYTHON   override one of them
cmake=${MUSCLESIM_CMAKE:-/usr/bin/cmake}
ctest=${MUSCLESIM_CTEST:-/usr/bin/ctest}
python=${MUSCLESIM_PYTHON:-/usr/bin/python3}
# ccache in front of the compilers, with paths taken relative to the repository, so that
# two build directories of the same flags (build/ and the wheel's build-wheel/) share objects
launcher=()
if command -v ccache >/dev/null; then
  export CCACHE_BASEDIR=${CCACHE_BASEDIR:-$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)}
  launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi
