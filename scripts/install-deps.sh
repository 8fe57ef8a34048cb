#!/usr/bin/env bash
# Installs the Debian packages musclesim needs, and only those that are missing.
# Idempotent: when everything is present it runs no apt command at all.
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  ccache                # compiler cache: the wheel's build (scripts/check_wheel.sh) reuses build/'s objects
  libsundials-dev       # CVODES: the stiff integrator and its forward sensitivities
  libsuitesparse-dev    # KLU, the sparse direct solver behind linear_solver: sparse
  libeigen3-dev         # linear algebra of the Gaussian fit
  libyaml-cpp-dev       # scenario files
  libtinyxml2-dev       # musclesim import: OpenSim (.osim) and MuJoCo (MJCF) model files
  libgtest-dev libgmock-dev googletest   # tests
  libnlopt-cxx-dev      # gradient-based minimiser of the Gaussian fit
  coinor-libipopt-dev   # IPOPT: the nonlinear programs of optimal control (musclesim optimize)
  libbenchmark-dev      # bench/
  libopenmpi-dev openmpi-bin   # sweeps across machines (-DMUSCLESIM_WITH_MPI=ON)
  gnuplot-nox           # musclesim plot draws its figures with gnuplot
  clang libclang-rt-14-dev   # scripts/fuzz.sh: libFuzzer, ASan and UBSan runtimes
  libomp-14-dev         # clang's OpenMP, which SUNDIALS' CMake package asks for (the fuzz build)
  clang-format-14       # scripts/format.sh: the code's layout (.clang-format), checked in CI
  doxygen               # scripts/docs.sh: the C++ API reference of the site (Doxyfile)
  python3-dev pybind11-dev python3-numpy   # the Python module (python/, MUSCLESIM_PYTHON)
  python3-pytest        # its tests
  python3-venv          # the virtual environments of scripts/docs.sh and scripts/check_wheel.sh
  python3-matplotlib    # the README's Python example plots with it
  python3-pandas        # its tests turn results into DataFrames (the module does not need it)
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed'; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
else
  echo "install-deps: installing ${missing[*]}"
  sudo_cmd=()
  [ "$(id -u)" -ne 0 ] && sudo_cmd=(sudo)
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get update -qq
  "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# What Debian lacks, from PyPI, pinned in scripts/pypi-deps.txt, in build-deps/venv of
# Debian's python3 (CMakeLists.txt looks there): made again only when the pins change
cd "$(dirname "$0")/.."
venv=build-deps/venv
if cmp -s scripts/pypi-deps.txt "$venv/pypi-deps.txt" 2>/dev/null; then
  echo "install-deps: the PyPI packages of scripts/pypi-deps.txt present"
else
  echo "install-deps: installing scripts/pypi-deps.txt into $venv"
  rm -rf "$venv"
  /usr/bin/python3 -m venv "$venv"
  "$venv/bin/python" -m pip install -q --disable-pip-version-check -r scripts/pypi-deps.txt
  cp scripts/pypi-deps.txt "$venv/pypi-deps.txt"
fi
