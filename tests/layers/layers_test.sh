#!/usr/bin/env bash
# The layers of docs/architecture.md, held by the build: layer_probe_NAME compiles a header of one layer with that
# layer's include directories; layer_probe_NAME_planted adds an include of a layer above it, which must fail on that
# include ("No such file"), not on anything else.
# Usage: layers_test.sh BUILD_DIR NAME PLANTED_HEADER
set -u
build=$1 name=$2 planted=$3
if ! out=$(cmake --build "$build" --target "layer_probe_$name" 2>&1); then
    echo "layer_probe_$name (the layer's own header) does not compile:"
    echo "$out"
    exit 1
fi
if out=$(cmake --build "$build" --target "layer_probe_${name}_planted" 2>&1); then
    echo "layer_probe_${name}_planted compiled: $planted is visible from below its layer"
    exit 1
fi
if ! grep -q "$planted: No such file" <<<"$out"; then
    echo "layer_probe_${name}_planted failed, but not on the planted include $planted:"
    echo "$out"
    exit 1
fi
echo "$name: $planted is not visible"
