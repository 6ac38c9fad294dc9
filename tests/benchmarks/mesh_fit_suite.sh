#!/usr/bin/env bash
# Meshes against a hand-made capsule model: the shipped meshed arm, 4 copies around the mesh table
# (demos/benchmarks/meshes), planned with the link meshes' fitted capsules and with the hand-made capsule model of the
# same arm, one configuration after the other in one run. Prints one Markdown row per planner: median planning time
# of each and their ratio, and median makespan and sum of costs over the bound of each.
# Usage: tests/benchmarks/mesh_fit_suite.sh [BIN_DIR]     (run on a quiet machine)
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
bin=${1:-$root/build/bin}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for cell in meshed_cell meshed_cell_capsules; do
    sed "s|^output = .*|output = $tmp|; s|^file = \.\./|file = $root/demos/benchmarks/|" \
        "$root/demos/benchmarks/meshes/$cell.cfg" >"$tmp/$cell.cfg"
    "$bin/ompl_parc_benchmark" "$tmp/$cell.cfg" >/dev/null
done
python3 - "$tmp/meshed_cell.csv" "$tmp/meshed_cell_capsules.csv" <<'PY'
import csv, statistics, sys
def load(path):
    rows = {}
    for r in csv.DictReader(open(path)):
        rows.setdefault(r["method"], []).append(r)
    return rows
mesh, hand = load(sys.argv[1]), load(sys.argv[2])
def med(rows, key):
    return statistics.median(float(r[key]) for r in rows if r["success"] == "1")
print("| planner | solved (mesh / hand-made) | median time, mesh fit (s) | median time, hand-made capsules (s) | mesh / hand-made | makespan / bound (mesh, hand-made) | sum of costs / bound (mesh, hand-made) |")
print("|---|---|---|---|---|---|---|")
for planner in mesh:
    m, h = mesh[planner], hand[planner]
    solved = lambda rows: "%d/%d" % (sum(r["success"] == "1" for r in rows), len(rows))
    tm, th = med(m, "planning_time_seconds"), med(h, "planning_time_seconds")
    print("| %s | %s / %s | %.4f | %.4f | %.2f | %.2f, %.2f | %.2f, %.2f |" % (
        planner, solved(m), solved(h), tm, th, tm / th, med(m, "makespan_ratio"), med(h, "makespan_ratio"),
        med(m, "sum_of_costs_ratio"), med(h, "sum_of_costs_ratio")))
PY
