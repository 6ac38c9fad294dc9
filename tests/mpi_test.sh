#!/usr/bin/env bash
# ompl_parc_mpi under mpirun with 2 ranks (oversubscribed; --allow-run-as-root where the tests run as root): OR-P-ARC
# over the ranks solves Mobile Cross 16 and Panda Cage 4 task 0 (validated by rank 0, and the written plan again by
# ompl_parc_validate); a 0.5 s limit stops every rank within 200 ms of it; a rank that throws ends the run with exit 1
# and its message, no hang; a SIGINT to mpirun ends every rank; bad input exits 2 with one line; a benchmark sweep
# over 2 ranks writes the same CSV rows and OMPL log as ompl_parc_benchmark in one process, and refuses the race's
# options beside it. Every mpirun has a timeout: a hang fails the test.
# With --sanitized (a ThreadSanitizer build): the races only, with the stop bound at 1.5 s for the slower build, over
# shared memory (Open MPI's TCP transport has a lock-order report of its own), TSAN_OPTIONS passed to the ranks.
# Usage: mpi_test.sh BIN_DIR MPIEXEC [--sanitized]
set -u
bin=$1
mpiexec=$2
sanitized=${3:-}
here=$(cd "$(dirname "$0")" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
flags=(--oversubscribe -np 2)
[ "$(id -u)" -eq 0 ] && flags+=(--allow-run-as-root)
stop_bound=0.7
if [ "$sanitized" = --sanitized ]; then
    flags+=(--mca btl self,vader -x TSAN_OPTIONS)
    stop_bound=1.5
fi
# mpi NAME ARGS...: ompl_parc_mpi over 2 ranks, stdout+stderr to $tmp/NAME.out; returns its exit code (124: hung).
mpi() {
    local name=$1
    shift
    timeout 120 "$mpiexec" "${flags[@]}" "$bin/ompl_parc_mpi" "$@" >"$tmp/$name.out" 2>&1
}

# Solved over two ranks, validated on rank 0 and once more from the written file.
for problem in "mobile_cross 16 0" "panda_cage 4 0"; do
    read -r scenario robots task <<<"$problem"
    mpi "$scenario" --scenario "$scenario" --robots "$robots" --task "$task" --param seed=3 --workers 2 \
        --time-limit 100 --out "$tmp/$scenario.json"
    rc=$?
    if [ $rc -ne 0 ] || ! grep -q '^validated  yes' "$tmp/$scenario.out" || ! grep -q '^status     Exact solution from rank [01]' "$tmp/$scenario.out" ||
        [ "$(grep -c '^rank [01] ' "$tmp/$scenario.out")" -ne 2 ]; then
        fail "$scenario $robots: exit $rc, not solved and validated over 2 ranks"
        cat "$tmp/$scenario.out"
    elif ! "$bin/ompl_parc_validate" --scenario "$scenario" --robots "$robots" --task "$task" "$tmp/$scenario.json" >/dev/null; then
        fail "$scenario $robots: the written plan does not validate"
    else
        echo "ok:   $scenario $robots: $(grep '^status' "$tmp/$scenario.out")"
    fi
done

# A 0.5 s limit on a problem no rank solves in it: exit 1, every rank's solve back within 200 ms of the limit (1 s in
# a sanitizer build).
mpi limit --scenario panda_cage --robots 16 --task 3 --time-limit 0.5
rc=$?
late=$(awk '/^rank [0-9]+ / { for (i = 1; i < NF; ++i) if ($i == "after") { t = $(i + 1) + 0; if (t > worst) worst = t } }
            END { print worst + 0 }' "$tmp/limit.out")
if [ $rc -ne 1 ] || [ "$(grep -c '^rank [01] .*returned after' "$tmp/limit.out")" -ne 2 ] ||
    ! python3 -c "import sys; sys.exit(0 if $late <= $stop_bound else 1)"; then
    fail "0.5 s limit: exit $rc, slowest rank returned after $late s (at most $stop_bound s)"
    cat "$tmp/limit.out"
else
    echo "ok:   0.5 s limit: every rank stopped, the slowest after $late s"
fi

# A rank that throws: exit 1 with its message, no hang (the timeout would say 124). The other rank works on a problem
# it cannot solve before the failure arrives (as above): an exact solution claimed first would rightly win the race,
# and Mobile Cross 16 is now solved in milliseconds, so it raced the injected failure.
mpi crash --scenario panda_cage --robots 16 --task 3 --time-limit 30 --fail-rank 1
rc=$?
if [ $rc -ne 1 ] || ! grep -q '^ompl_parc_mpi: rank 1 failed: failure injected by --fail-rank 1$' "$tmp/crash.out"; then
    fail "a failing rank: exit $rc"
    cat "$tmp/crash.out"
else
    echo "ok:   $(grep '^ompl_parc_mpi: rank 1 failed' "$tmp/crash.out")"
fi

if [ "$sanitized" = --sanitized ]; then
    echo "$failures failure(s) (races only: a sanitizer build)"
    [ "$failures" -eq 0 ]
    exit
fi

# Ctrl-C on mpirun: ompl_parc_mpi installs no SIGINT handler (its ranks are mpirun's to end), and mpirun ends every
# rank (Open MPI 4.1: exit 1 about 1 s after the SIGINT, no summary). Checked: it ends within 30 s, not with success,
# and no rank runs on. python3 gives mpirun a default SIGINT (a background job of this shell starts with it ignored).
# The problem has no plan (two discs that must swap in a corridor too narrow to pass), so the ranks are still
# solving when the SIGINT comes, however fast they get.
python3 -c 'import os, signal, sys
signal.signal(signal.SIGINT, signal.SIG_DFL)
os.execv(sys.argv[1], sys.argv[1:])' "$mpiexec" "${flags[@]}" "$bin/ompl_parc_mpi" \
    --scenario-file "$here/data/corridor_swap.json" --time-limit 60 >"$tmp/sigint.out" 2>&1 &
pid=$!
sleep 3
ranks=$(pgrep -P "$pid" | tr '\n' ' ')
kill -INT "$pid"
sent=$EPOCHREALTIME
elapsed() { awk -v s="$sent" -v n="$EPOCHREALTIME" 'BEGIN { printf "%.1f", n - s }'; }
while kill -0 "$pid" 2>/dev/null && awk -v t="$(elapsed)" 'BEGIN { exit !(t < 30) }'; do
    sleep 0.1
done
took=$(elapsed)
if kill -0 "$pid" 2>/dev/null; then
    kill -KILL "$pid"
    rc=124
else
    wait "$pid"
    rc=$?
fi
running=""
for rank in $ranks; do  # a rank ended but not yet reaped (state Z) has stopped
    [ -e "/proc/$rank/stat" ] && [ "$(awk '{ print $3 }' "/proc/$rank/stat" 2>/dev/null)" != Z ] && running+="$rank "
done
if [ $rc -eq 0 ] || [ $rc -eq 124 ] || [ -z "$ranks" ] || [ -n "$running" ]; then
    fail "SIGINT to mpirun: exit $rc $took s after it, ranks '$ranks', still running '$running'"
    cat "$tmp/sigint.out"
else
    echo "ok:   SIGINT to mpirun: exit $rc $took s after it, ranks ${ranks}ended"
fi

# Bad input: exit 2 on every rank, one line from rank 0.
for bad in "--robots -3" "--scenario-file $tmp/missing.json" "--param instances=3" "--param objective=makespan" \
    "--fail-rank 2" "--time-limit 0" "--out $tmp/no/such/folder/plan.json" "--robots 4 --scenario-file $tmp/x.json"; do
    # shellcheck disable=SC2086
    mpi bad $bad
    rc=$?
    lines=$(grep -c '^ompl_parc_mpi: ' "$tmp/bad.out")
    if [ $rc -ne 2 ] || [ "$lines" -ne 1 ]; then
        fail "'$bad': exit $rc with $lines message lines (want 2 and 1)"
        cat "$tmp/bad.out"
    else
        echo "ok:   $(grep '^ompl_parc_mpi: ' "$tmp/bad.out")"
    fi
done

# A sweep over 2 ranks against one process: the same rows (in the columns a seeded, deterministic planner repeats:
# all but times and memory), in the same order, and an OMPL log that ompl_benchmark_statistics reads.
cat >"$tmp/sweep.cfg" <<'CFG'
[problem]
name = sweep
scenario = field
robots = 8
instances = 2

[benchmark]
time_limit = 20
mem_limit = 4096
run_count = 2
output = single
seed = 5
workers = 1

[planner]
arc =
parc =
pp-st-rrt =
CFG
sed 's/^output = single/output = ranks/' "$tmp/sweep.cfg" >"$tmp/ranks.cfg"
"$bin/ompl_parc_benchmark" "$tmp/sweep.cfg" >/dev/null 2>"$tmp/single.err" || fail "the single-process sweep failed"
mpi sweep --benchmark "$tmp/ranks.cfg"
rc=$?
if [ $rc -ne 0 ] || ! grep -q 'runs over 2 ranks' "$tmp/sweep.out" || ! grep -q 'on rank 1\]' "$tmp/sweep.out"; then
    fail "the sweep over 2 ranks: exit $rc"
    cat "$tmp/sweep.out"
fi
if ! python3 - "$tmp/single/sweep.csv" "$tmp/ranks/sweep.csv" <<'PY'; then
import csv, sys
kept = ("case case_title task_index seed method time_limit_seconds success makespan_timesteps sum_of_cost_timesteps "
        "scenario robots type workers status").split()
def rows(path):
    return [tuple(r[c] for c in kept) for r in csv.DictReader(open(path, newline=""))]
single, ranks = rows(sys.argv[1]), rows(sys.argv[2])
print("single process: %d rows, 2 ranks: %d rows, identical: %s" % (len(single), len(ranks), single == ranks))
sys.exit(0 if single == ranks and len(single) == 12 else 1)
PY
    fail "the CSV rows of the sweep over 2 ranks differ from the single process's"
fi
for log in sweep_0 sweep_1; do
    # OMPL's log: per planner its name, then "N runs" before the run data and before the progress data.
    shape() { grep -E '^(geometric_.*|[0-9]+ runs)$' "$1"; }
    if [ -z "$(shape "$tmp/single/$log.log")" ] || [ "$(shape "$tmp/single/$log.log")" != "$(shape "$tmp/ranks/$log.log")" ]; then
        fail "$log.log: planners and run counts differ between 2 ranks and one process"
    fi
done
# The race's options beside --benchmark would be ignored (the configuration names the problem, planners, seed and
# limits): refused, exit 2, one line naming them.
for extra in "--scenario panda_cage" "--robots 8 --task 1" "--fail-rank 1" "--seed 2 --time-limit 5" \
    "--scenario-file $tmp/x.json" "--param window=10" "--workers 2" "--smooth 0" "--out $tmp/x.json" "--no-validate"; do
    # shellcheck disable=SC2086
    mpi ignored --benchmark "$tmp/ranks.cfg" $extra
    rc=$?
    given=$(awk '{ for (i = 1; i <= NF; ++i) if ($i ~ /^--/) printf "%s%s", (n++ ? ", " : ""), $i }' <<<"$extra")
    if [ $rc -ne 2 ] || [ "$(grep -c '^ompl_parc_mpi: ' "$tmp/ignored.out")" -ne 1 ] ||
        ! grep -q "^ompl_parc_mpi: with --benchmark the configuration names .*: drop $given$" "$tmp/ignored.out"; then
        fail "--benchmark with '$extra': exit $rc (want 2 and one line naming $given)"
        cat "$tmp/ignored.out"
    else
        echo "ok:   $(grep '^ompl_parc_mpi: ' "$tmp/ignored.out")"
    fi
done
if command -v ompl_benchmark_statistics >/dev/null; then
    ompl_benchmark_statistics "$tmp/ranks/sweep_0.log" "$tmp/ranks/sweep_1.log" -d "$tmp/ranks.db" >/dev/null
    runs=$(python3 -c "import sqlite3, sys; print(sqlite3.connect(sys.argv[1]).execute('select count(*) from runs').fetchone()[0])" "$tmp/ranks.db")
    [ "$runs" = 12 ] && echo "ok:   the merged logs load into OMPL's database: $runs runs" ||
        fail "OMPL's database has $runs runs from the merged logs, not 12"
else
    fail "ompl_benchmark_statistics is missing: run scripts/setup.sh"
fi

echo "$failures failure(s)"
[ "$failures" -eq 0 ]
