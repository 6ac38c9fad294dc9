#!/usr/bin/env bash
# One command from a fresh clone: install dependencies, build into build/, run the main demo.
# Extra arguments go to ompl_parc_demo (e.g. scripts/demo.sh --robots 8).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh build
./build/bin/ompl_parc_demo --scenario mobile_cross --robots 4 --out build/demo_solution.json "$@"
./build/bin/ompl_parc_validate --scenario mobile_cross --robots 4 build/demo_solution.json
