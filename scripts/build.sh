#!/usr/bin/env bash
# Configures and builds one build tree.
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
cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=Release "${configure[@]}" >/dev/null
cmake --build "$dir" -j"$(nproc)" "$@"
