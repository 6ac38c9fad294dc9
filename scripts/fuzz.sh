#!/usr/bin/env bash
# Builds the file parsers' libFuzzer target with clang, AddressSanitizer and UndefinedBehaviorSanitizer in
# build-fuzz/, and fuzzes it for RUNS inputs (default 200 000, about a minute here) from a corpus of the project's
# own files: the example scenarios, the benchmark configs, a solution file and two URDF arms (tests/fuzz/ParsersFuzzer.cpp
# says how inputs are read). The fuzzer's seed is fixed (SEED, default 1), so a run is repeatable, not a lottery in CI.
# Exits non-zero with the reproducer's path if the fuzzer finds a crash, a sanitizer error, a hang or a leak.
# Usage: scripts/fuzz.sh [RUNS [SEED]]
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-200000}
fuzz_seed=${2:-1}
CC=clang CXX=clang++ cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_UNITY_BUILD=ON -DOMPL_PARC_FUZZ=ON \
    -DOMPL_PARC_BUILD_TESTS=OFF -DOMPL_PARC_BUILD_BENCHMARKS=OFF >/dev/null
cmake --build build-fuzz -j"$(nproc)" --target ompl_parc_fuzz_parsers
corpus=build-fuzz/corpus
rm -rf "$corpus"  # the same start every time (a grown corpus from earlier runs would change the run)
mkdir -p "$corpus" build-fuzz/findings
# A seed is the parser's selector byte (0 scenario, 1 solution, 2 benchmark config, 3 URDF) followed by a file.
seed() { { printf "\\x$(printf %02x "$1")"; cat "$2"; } >"$corpus/seed_$1_$(basename "$2")"; }
for f in demos/scenarios/*.json; do seed 0 "$f"; done
seed 1 tests/fuzz/seeds/solution_two_discs.json
for f in demos/benchmarks/quick/*.cfg; do seed 2 "$f"; done
seed 3 tests/fuzz/seeds/small_arm.urdf
{ echo "panda_link0 panda_link8"; cat ompl_parc/robots/models/panda.urdf; } >build-fuzz/panda.urdf
seed 3 build-fuzz/panda.urdf
build-fuzz/bin/ompl_parc_fuzz_parsers -runs="$runs" -seed="$fuzz_seed" -timeout=10 -rss_limit_mb=2048 \
    -artifact_prefix=build-fuzz/findings/ -print_final_stats=1 "$corpus"
