#!/usr/bin/env bash
# ompl_parc_benchmark end to end: a tiny config runs every planner of the registry, its OMPL log goes through
# Debian's ompl_benchmark_statistics into SQLite (OMPL's `solved` agrees with our validated success for every
# planner, the ARC family fills the progress table, both versions are recorded), the CSV has one row per run in the
# authors' columns first, and bad input exits 2 with a one-line reason before any run.
# Usage: benchmark_test.sh BIN_DIR
set -u
bin=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
# csv_has FILE COLUMN=VALUE...: FILE has a row with every COLUMN equal to its VALUE.
csv_has() {
    python3 - "$@" <<'PY'
import csv, sys
path, wanted = sys.argv[1], dict(a.split("=", 1) for a in sys.argv[2:])
rows = list(csv.DictReader(open(path, newline="")))
sys.exit(0 if any(all(r.get(k) == v for k, v in wanted.items()) for r in rows) else 1)
PY
}
# sql DB QUERY: the first column of the first row.
sql() { python3 -c "import sqlite3, sys; print(sqlite3.connect(sys.argv[1]).execute(sys.argv[2]).fetchone()[0])" "$@"; }

cat >"$tmp/tiny.cfg" <<'CFG'
[problem]
name = tiny
scenario = mobile_cross
robots = 4

[benchmark]
time_limit = 5
mem_limit = 4096
run_count = 2
output = out
seed = 3
workers = 2

[planner]
arc =
parc =
parc.workers = 2
parc.name = P-ARC-2
orparc =
pp-st-rrt =
or-pp-st-rrt =
rrtconnect =
ep-rrt-c =
or-rrt-c =
or-ep-rrt-c =
or-ep-rrt-c.instances = 1
CFG

if ! "$bin/ompl_parc_benchmark" "$tmp/tiny.cfg" 2>"$tmp/err"; then
    fail "tiny benchmark exited non-zero"; cat "$tmp/err"
fi
grep -q '^\[18/18\] tiny' "$tmp/err" || fail "no progress line for the last run"
version=$("$bin/ompl_parc_demo" --version | cut -d' ' -f2)
[ "$(wc -l <"$tmp/out/tiny.csv")" -eq 19 ] || fail "CSV does not have a header and 18 rows"
head -1 "$tmp/out/tiny.csv" | grep -q '^case,case_title,task_index,seed,method,time_limit_seconds,success,first_solution_time_seconds,planning_time_seconds,makespan_timesteps,sum_of_cost_timesteps,metrics_json,scenario,robots,type,workers,status,' ||
    fail "the CSV does not start with the authors' columns"
csv_has "$tmp/out/tiny.csv" case=mobile_cross_4 "case_title=Mobile Cross, 4 robots" task_index=0 seed=4 method=P-ARC-2 \
    time_limit_seconds=5 success=1 type=parc workers=2 "status=Exact solution" ompl_parc_version="$version" ||
    fail "CSV lacks P-ARC-2's second run (seed 4)"
if command -v ompl_benchmark_statistics >/dev/null; then
    ompl_benchmark_statistics "$tmp/out/tiny.log" -d "$tmp/tiny.db" >/dev/null || fail "ompl_benchmark_statistics failed"
    runs=$(sql "$tmp/tiny.db" 'select count(*) from runs')
    [ "$runs" = 18 ] || fail "the database has $runs runs, not 18"
    # OMPL's `solved` (what Planner Arena shows) against the validated success in the CSV, planner by planner.
    for planner in arc P-ARC-2 orparc pp-st-rrt or-pp-st-rrt rrtconnect ep-rrt-c or-rrt-c or-ep-rrt-c; do
        db=$(sql "$tmp/tiny.db" "select sum(solved) from runs r join plannerConfigs c on r.plannerid = c.id where c.name = 'geometric_$planner'")
        ours=$(python3 -c "import csv, sys; print(sum(r['success'] == '1' for r in csv.DictReader(open(sys.argv[1])) if r['method'] == sys.argv[2]))" "$tmp/out/tiny.csv" "$planner")
        [ "$db" = "$ours" ] && [ "$ours" = 2 ] || fail "$planner: the database says $db runs solved, the CSV $ours (both should be 2)"
    done
    versions=$(sql "$tmp/tiny.db" 'select version || " / " || ompl_parc_version from experiments')
    [[ "$versions" =~ ^OMPL\ [0-9]+\.[0-9]+\.[0-9]+\ /\ $version$ ]] || fail "the database records the versions as '$versions'"
else
    fail "ompl_benchmark_statistics is missing: run scripts/setup.sh"
fi

# The ARC family's progress properties fill the database's progress table (runs of ~0.2 s, sampled every 10 ms):
# the stages up to smoothing (3; 4, solved, if a sample falls after the smoothing), with conflicts resolved.
cat >"$tmp/progress.cfg" <<'CFG'
[problem]
name = progress
scenario = mobile_circle
robots = 8

[benchmark]
time_limit = 10
mem_limit = 4096
run_count = 1
output = out
workers = 2

[planner]
arc =
arc.smooth = 0.2
parc =
parc.workers = 2
parc.smooth = 0.2
orparc =
orparc.smooth = 0.2
CFG
if "$bin/ompl_parc_benchmark" "$tmp/progress.cfg" >/dev/null 2>"$tmp/err" &&
    ompl_benchmark_statistics "$tmp/out/progress.log" -d "$tmp/progress.db" >/dev/null; then
    for planner in arc parc orparc; do
        sampled=$(sql "$tmp/progress.db" "select count(*) || ' ' || max(p.stage) || ' ' || max(p.conflicts_resolved) from progress p join runs r on p.runid = r.id join plannerConfigs c on r.plannerid = c.id where c.name = 'geometric_$planner'")
        read -r samples stage resolved <<<"$sampled"
        [ "$samples" -gt 0 ] && [ "$stage" -ge 3 ] && [ "$resolved" -gt 0 ] ||
            fail "$planner: progress table has '$sampled' (samples, furthest stage, conflicts resolved)"
    done
else
    fail "progress benchmark failed: $(cat "$tmp/err")"
fi

# A scenario file instead of a built-in scenario, relative to the config's folder.
cp "$(dirname "$0")/../demos/scenarios/doorway_swap.json" "$tmp/"
cat >"$tmp/file.cfg" <<'CFG'
[problem]
name = swap
file = doorway_swap.json

[benchmark]
time_limit = 10
mem_limit = 4096
run_count = 1
output = out

[planner]
arc =
CFG
"$bin/ompl_parc_benchmark" "$tmp/file.cfg" 2>"$tmp/err" || { fail "scenario-file benchmark exited non-zero"; cat "$tmp/err"; }
csv_has "$tmp/out/swap.csv" case=doorway_swap_4 method=arc seed=1 success=1 || fail "CSV lacks the solved doorway_swap run"
# A missing file, or a file and a built-in scenario at once: exit 2 with a one-line reason.
for broken in 's|^file = .*|file = missing.json|' 's|^file = .*|file = doorway_swap.json\nscenario = mobile_cross|'; do
    sed "$broken" "$tmp/file.cfg" >"$tmp/broken.cfg"
    out=$("$bin/ompl_parc_benchmark" "$tmp/broken.cfg" 2>&1)
    rc=$?
    if [ "$rc" -ne 2 ] || [ "$(wc -l <<<"$out")" -ne 1 ]; then
        fail "broken scenario-file config ($broken): exit $rc, output: $out"
    else
        echo "ok:   $out"
    fi
done

# A generated family over several instances: one log per instance, one CSV, and the success-rate table.
cat >"$tmp/family.cfg" <<'CFG'
[problem]
name = rings
scenario = ring
robots = 6
task = 3
instances = 2

[benchmark]
time_limit = 20
mem_limit = 4096
run_count = 1
output = out

[planner]
arc =
arc.name = ARC
CFG
if ! "$bin/ompl_parc_benchmark" "$tmp/family.cfg" >"$tmp/table" 2>"$tmp/err"; then
    fail "family benchmark exited non-zero"; cat "$tmp/err"
fi
[ -f "$tmp/out/rings_3.log" ] && [ -f "$tmp/out/rings_4.log" ] || fail "no log per instance (rings_3.log, rings_4.log)"
for task in 3 4; do
    csv_has "$tmp/out/rings.csv" case=ring_6_${task}_6 task_index=$task method=ARC success=1 ||
        fail "CSV lacks the solved run of instance $task"
done
grep -q '^| ARC | 2/2 | ' "$tmp/table" || { fail "no success-rate table"; cat "$tmp/table"; }

# Every shipped suite config is valid (problem, planners and parameters, worker budgets), checked without a run.
for cfg in "$(dirname "$0")"/../demos/benchmarks/*/*.cfg; do
    "$bin/ompl_parc_benchmark" --check "$cfg" >/dev/null 2>"$tmp/err" || { fail "$cfg: $(cat "$tmp/err")"; }
done

# bad CONFIG_TAIL PATTERN: a config with this [planner] section must exit 2 with PATTERN on one line.
bad() {
    sed '/^\[planner\]/,$d' "$tmp/tiny.cfg" >"$tmp/bad.cfg"
    printf '%b' "$1" >>"$tmp/bad.cfg"
    local out rc
    out=$("$bin/ompl_parc_benchmark" "$tmp/bad.cfg" 2>&1)
    rc=$?
    if [ "$rc" -ne 2 ] || [ "$(wc -l <<<"$out")" -ne 1 ] || ! grep -q -- "$2" <<<"$out"; then
        fail "bad config ($2): exit $rc, output: $out"
    else
        echo "ok:   $out"
    fi
}
bad '[planner]\nrrt =\n' "unknown planner 'rrt' (valid: "
bad '[planner]\nparc =\nparc.threads = 2\n' "no parameter 'threads' (valid: "
bad '[planner]\nparc =\nparc.workers = 4\n' "needs 4 workers but \[benchmark\] workers = 2"
bad '[planner]\narc =\n[ablation]\nx = 1\n' "unknown section \[ablation\]"
touch "$tmp/file"
sed -i "s|^output = .*|output = $tmp/file/sub|" "$tmp/tiny.cfg"
bad '[planner]\narc =\n' "cannot create output folder"

echo "$failures failure(s)"
[ "$failures" -eq 0 ]
