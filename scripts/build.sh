#!/usr/bin/env bash
# Configures and builds one build tree, as a unity build (CMake compiles each target's sources in batches of eight:
# the OMPL, FCL, Boost and Eigen headers are parsed once per batch, not once per file; -DCMAKE_UNITY_BUILD=OFF
# among the arguments builds file by file, as an IDE's incremental build prefers).
# Usage: scripts/build.sh [BUILD_DIR [extra cmake arguments...] [-- extra build arguments, e.g. --target T]]
set -euo pipefail
cd "$(dirname "$0")/.."
dir=${1:-build}
shift || true
configure=()
while [ $# -gt 0 ] && [ "$1" != "--" ]; do
    configure+=("$1")
    shift
done
[ $# -gt 0 ] && shift  # the "--"
cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=Release -DCMAKE_UNITY_BUILD=ON "${configure[@]}" >/dev/null
cmake --build "$dir" -j"$(nproc)" "$@"
