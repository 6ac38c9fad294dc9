#!/usr/bin/env bash
# Installs the built tree into a temporary prefix and builds a tiny consumer project against it with
# find_package(ompl_parc) + target_link_libraries(app ompl_parc::ompl_parc), then runs it. The consumer names
# only the prefix, yet must find the OMPL the library was built with (OMPL_VERSION, e.g. one outside the system's
# paths), and compile and run against it.
# Usage: install_test.sh BUILD_DIR CONSUMER_SOURCE_DIR OMPL_VERSION
set -eu
build=$1
consumer=$2
ompl_version=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cmake --install "$build" --prefix "$tmp/prefix" >/dev/null
cmake -S "$consumer" -B "$tmp/build" -DCMAKE_PREFIX_PATH="$tmp/prefix" -DCMAKE_BUILD_TYPE=Release >"$tmp/configure.log"
if ! grep -qx -- "-- consumer: OMPL $ompl_version" "$tmp/configure.log"; then
    echo "the consumer did not find OMPL $ompl_version:"
    cat "$tmp/configure.log"
    exit 1
fi
cmake --build "$tmp/build" -j2 >/dev/null
"$tmp/build/consumer"
