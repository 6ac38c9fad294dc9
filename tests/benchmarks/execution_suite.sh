#!/usr/bin/env bash
# Execution under delays: for each problem, plan with ARC (seed 1, default smoothing), then ompl_parc_execute with
# RUNS random delays (each robot up to 1 s late, speed x0.7..1): time-indexed against coordinated by the temporal plan
# graph, every executed instant checked by the validator. Prints one table row per problem (Markdown).
# Usage: tests/benchmarks/execution_suite.sh [RUNS] [BIN_DIR]     (RUNS 100 by default; run on a quiet machine)
set -euo pipefail
runs=${1:-100}
bin=${2:-$(cd "$(dirname "$0")/../.." && pwd)/build/bin}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo "| problem | plan makespan (timesteps) | trajectory | sharpened corners | graph: motions, edges, synchronised pairs | time-indexed: runs colliding | coordinated: runs colliding | makespan median, time-indexed / coordinated (undelayed) |"
echo "|---|---|---|---|---|---|---|---|"
for problem in "panda_cage 8 0" "panda_cage 8 3" "panda_cage 16 0" "panda_cage 16 3" "mobile_cross 64 0" \
    "crossing 64 0" "field 64 0" "rooms 64 0"; do
    read -r scenario robots task <<<"$problem"
    args=(--scenario "$scenario" --robots "$robots" --task "$task")
    "$bin/ompl_parc_demo" "${args[@]}" --seed 1 --quiet --out "$tmp/plan.json" >"$tmp/demo.txt" || {
        echo "| $scenario $robots task $task | not solved | | | | | | |"
        continue
    }
    "$bin/ompl_parc_execute" "${args[@]}" --runs "$runs" "$tmp/plan.json" >"$tmp/exec.txt" || true
    makespan=$(sed -n 's/^makespan   \([0-9]*\) timesteps.*/\1/p' "$tmp/demo.txt")
    trajectory=$(sed -n 's/^trajectory: \([0-9.]*\) s.*/\1 s/p' "$tmp/exec.txt")
    sharp=$(sed -n 's/.*; \([0-9]*\) corners made sharp.*/\1/p' "$tmp/exec.txt")
    graph=$(sed -n 's/^temporal plan graph: \([0-9]*\) motions in [0-9]* phases, \([0-9]*\) edges .*, \([0-9]*\) synchronised.*/\1, \2, \3/p' "$tmp/exec.txt")
    undelayed=$(sed -n 's/.*undelayed makespan \([0-9.]*\) s.*/\1/p' "$tmp/exec.txt")
    indexed=$(sed -n 's/^  time-indexed: \([0-9]*\/[0-9]*\) runs collide; makespan median \([0-9.]*\) s.*/\1 \2/p' "$tmp/exec.txt")
    coordinated=$(sed -n 's/^  coordinated:  \([0-9]*\/[0-9]*\) runs collide; makespan median \([0-9.]*\) s (+\([-0-9.]*\)%.*/\1 \2 \3/p' "$tmp/exec.txt")
    read -r ic im <<<"$indexed"
    read -r cc cm cp <<<"$coordinated"
    echo "| $scenario $robots task $task | $makespan | $trajectory | $sharp | $graph | $ic | $cc | $im s / $cm s ($undelayed s; coordinated +$cp %) |"
done
