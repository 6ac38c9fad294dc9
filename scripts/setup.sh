#!/usr/bin/env bash
# Installs every Debian package ompl_parc needs to build, test and run its demos.
# Idempotent: when all packages are present it only checks (well under a second).
# Usage: scripts/setup.sh [--demo]   (--demo: only what building the library and the demo tools needs)
set -euo pipefail
case "${1:-}" in
    "" | --demo) ;;
    *) echo "setup: unknown argument '$1' (usage: scripts/setup.sh [--demo])" >&2; exit 2 ;;
esac

# What the library and the demo tools need (scripts/demo.sh: `setup.sh --demo`) ...
PACKAGES=(
    build-essential cmake pkg-config
    libompl-dev libfcl-dev libccd-dev liburdfdom-dev libtinyxml-dev libeigen3-dev libxsimd-dev libassimp-dev
    libboost-dev libboost-program-options-dev libboost-serialization-dev
    libboost-filesystem-dev libboost-system-dev
    nlohmann-json3-dev libjs-three
)
# ... and what the tests, benchmarks, Python module, MPI tool, sanitizers and API docs add.
if [ "${1:-}" != "--demo" ]; then
    PACKAGES+=(
        libgtest-dev libgmock-dev libbenchmark-dev
        ompl-demos python3 python3-matplotlib doxygen
        pybind11-dev python3-dev python3-numpy python3-pytest
        libopenmpi-dev openmpi-bin
        clang libclang-rt-dev
        chromium python3-pil
    )
fi

missing=()
for p in "${PACKAGES[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
        missing+=("$p")
    fi
done

if [ ${#missing[@]} -eq 0 ]; then
    echo "setup: all ${#PACKAGES[@]} packages present"
    exit 0
fi

echo "setup: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then
    command -v sudo >/dev/null || { echo "setup: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
    SUDO="sudo"
fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
echo "setup: done"
