#!/usr/bin/env bash
# ompl_parc_benchmark end to end: a tiny config runs every planner family, its OMPL log goes through
# Debian's ompl_benchmark_statistics into SQLite, the CSV has one row per run, and bad input exits 2 with
# a one-line reason before any run.
# Usage: benchmark_test.sh BIN_DIR
set -u
bin=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

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
or-rrt-c =
or-pp-st-rrt =
CFG

if ! "$bin/ompl_parc_benchmark" "$tmp/tiny.cfg" 2>"$tmp/err"; then
    fail "tiny benchmark exited non-zero"; cat "$tmp/err"
fi
grep -q '^\[8/8\] tiny' "$tmp/err" || fail "no progress line for the last run"
[ "$(wc -l <"$tmp/out/tiny.csv")" -eq 9 ] || fail "CSV does not have a header and 8 rows"
grep -q '^mobile_cross,4,4,P-ARC-2,parc,2,1,' "$tmp/out/tiny.csv" || fail "CSV lacks P-ARC-2's second run (seed 4)"
if command -v ompl_benchmark_statistics >/dev/null; then
    ompl_benchmark_statistics "$tmp/out/tiny.log" -d "$tmp/tiny.db" >/dev/null || fail "ompl_benchmark_statistics failed"
    runs=$(python3 -c "import sqlite3; print(sqlite3.connect('$tmp/tiny.db').execute('select count(*) from runs').fetchone()[0])")
    [ "$runs" = 8 ] || fail "the database has $runs runs, not 8"
else
    fail "ompl_benchmark_statistics is missing: run scripts/setup.sh"
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
grep -q '^doorway_swap,4,1,arc,arc,1,1,' "$tmp/out/swap.csv" || fail "CSV lacks the solved doorway_swap run"
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
grep -q '^ring_6_3,6,1,ARC,arc,1,1,' "$tmp/out/rings.csv" || fail "CSV lacks the solved run of instance 3"
grep -q '^ring_6_4,6,1,ARC,arc,1,1,' "$tmp/out/rings.csv" || fail "CSV lacks the solved run of instance 4"
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
