#!/usr/bin/env bash
# One command from a fresh clone: install dependencies, build, run the whole test suite, then build
# and run it again under AddressSanitizer + UndefinedBehaviorSanitizer (build-asan/), and the tests of the
# parallel code (P-ARC, the OR race, the worker pool, the threaded validator, the MPI race) under ThreadSanitizer (build-tsan/),
# then fuzzes the scenario, solution and benchmark-config parsers (200 000 inputs, fixed seed: scripts/fuzz.sh).
# OMPL_PARC_SKIP_SANITIZERS=1 skips the sanitizer pass (for quick local iterations only; CI runs it).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh build
ctest --test-dir build --output-on-failure -j"$(nproc)"
if [ "${OMPL_PARC_SKIP_SANITIZERS:-0}" != "1" ]; then
    echo "== sanitizer pass: ASan + UBSan =="
    bash scripts/build.sh build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DOMPL_PARC_SANITIZE="address;undefined" \
        -DOMPL_PARC_BUILD_BENCHMARKS=OFF
    LSAN_OPTIONS="suppressions=$PWD/tests/lsan.supp print_suppressions=0" ctest --test-dir build-asan \
        --output-on-failure -j"$(nproc)"
    echo "== sanitizer pass: TSan on the parallel planners and runtime =="
    # Only what runs under TSan: the test binary and ompl_parc_mpi (target sanitized_checks).
    bash scripts/build.sh build-tsan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DOMPL_PARC_SANITIZE=thread \
        -DOMPL_PARC_BUILD_BENCHMARKS=OFF -- --target sanitized_checks
    TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1 suppressions=$PWD/tests/tsan.supp" ctest --test-dir build-tsan --output-on-failure \
        -j"$(nproc)" -R 'Parc|SharedStates|HugePageMemory|BatchDetection|WorkerPool|OrTaskRunner|SpaceRegistryLock|SolutionValidator|ConflictDetector.Concurrent|InnerPlannerLog|tools.mpi'
    echo "== fuzzing the file parsers: libFuzzer, 200 000 inputs from a fixed seed (build-fuzz/) =="
    bash scripts/fuzz.sh 200000 1
fi
