#!/usr/bin/env bash
# One command from a fresh clone: install what the demo needs, build the library and the demo tools into build/,
# run the main demo.
# Extra arguments go to ompl_parc_demo (e.g. scripts/demo.sh --time-limit 60).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh --demo
# Only the library and the two tools run here: the tests, benchmarks and the rest are scripts/test.sh's.
bash scripts/build.sh build -- --target ompl_parc_demo ompl_parc_validate
./build/bin/ompl_parc_demo --scenario mobile_cross --robots 8 --planner parc --workers 2 \
    --out build/demo_solution.json --picture build/demo.svg "$@"
./build/bin/ompl_parc_validate --scenario mobile_cross --robots 8 build/demo_solution.json
echo "picture: build/demo.svg (open it in a browser to watch the robots move)"
