#!/usr/bin/env bash
# Exit codes and one-line messages of the command-line tools, on good and bad input.
# Usage: tools_test.sh BIN_DIR
set -u
bin=$1
here=$(cd "$(dirname "$0")" && pwd)
scenarios=$(cd "$here/../demos/scenarios" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failures=0

# expect CODE PATTERN COMMAND...: run COMMAND, require exit code CODE and PATTERN in its output.
expect() {
    local code=$1 pattern=$2
    shift 2
    local out rc
    out=$("$@" 2>&1)
    rc=$?
    if [ "$rc" -ne "$code" ] || ! grep -q -- "$pattern" <<<"$out"; then
        echo "FAIL: '$*' exited $rc (want $code), output:"
        echo "$out" | head -5
        failures=$((failures + 1))
    else
        echo "ok:   $* -> $rc"
    fi
}

expect 2 "unknown argument '--all'" bash "$scenarios/../../scripts/setup.sh" --all
# The meshed arm's cell: the fits reported, the plan validated and drawn (mesh obstacles in the 3D page); a scenario
# naming a mesh that is not there is one line and exit 2.
cell="$scenarios/../assets/meshed_arm/meshed_cell.json"
expect 0 "^meshes     obstacle table: [0-9]* boxes" "$bin/ompl_parc_demo" --scenario-file "$cell" --smooth 0 \
    --picture "$tmp/cell.html"
expect 0 '"shape":"mesh"' grep -o '"shape":"mesh"' "$tmp/cell.html"
sed 's|meshes/table.stl|meshes/no_table.stl|' "$cell" >"$tmp/no_table.json"
expect 2 "obstacles\[0\]: TriangleMesh: mesh file '.*no_table.stl' does not exist" "$bin/ompl_parc_demo" \
    --scenario-file "$tmp/no_table.json"
expect 0 "profile panda (from the robots" "$bin/ompl_parc_demo" --scenario panda_cage --robots 2 --smooth 0
expect 0 "profile mobile$" "$bin/ompl_parc_demo" --scenario panda_cage --robots 2 --smooth 0 --param profile=mobile
expect 0 "validated  yes" "$bin/ompl_parc_demo" --scenario mobile_cross --robots 4 --seed 3 --out "$tmp/sol.json"
expect 0 "^valid: 4 robots" "$bin/ompl_parc_validate" --scenario mobile_cross --robots 4 "$tmp/sol.json"
expect 2 "robots' has 4 entries" "$bin/ompl_parc_validate" --scenario mobile_cross --robots 8 "$tmp/sol.json"
# The plan drawn by the validate tool and by the demo as a 3D page; an unwritable page is a one-line error.
expect 0 "^picture: $tmp/sol.html" "$bin/ompl_parc_validate" --scenario mobile_cross --robots 4 "$tmp/sol.json" \
    --picture "$tmp/sol.html"
expect 0 "<!DOCTYPE html>" head -c 20 "$tmp/sol.html"
expect 2 "cannot write '$tmp/none/sol.html'" "$bin/ompl_parc_validate" --scenario mobile_cross --robots 4 \
    "$tmp/sol.json" --picture "$tmp/none/sol.html"
expect 2 "cannot write '$tmp/none/p.html'" "$bin/ompl_parc_demo" --scenario mobile_cross --robots 4 \
    --picture "$tmp/none/p.html"
expect 0 "^picture    $tmp/cage.html$" "$bin/ompl_parc_demo" --scenario panda_cage --robots 2 --picture "$tmp/cage.html"
expect 2 "picture-static applies to SVG pictures" "$bin/ompl_parc_demo" --scenario panda_cage --robots 2 \
    --picture "$tmp/cage.html" --picture-static

# A tampered solution: robot r1 made to wait at its start (its start no longer clear of r0's path).
jump=$(python3 - "$tmp/sol.json" "$tmp/bad.json" <<'PY'
import json, sys
doc = json.load(open(sys.argv[1]))
piece = doc["robots"][0]["pieces"][1]   # [start, offset, steps, from, to]: moving the anchor moves its first state
piece[3][0] += 0.5                      # a teleporting step from the timestep before it
json.dump(doc, open(sys.argv[2], "w"))
print(piece[0] - 1)
PY
)
expect 1 "^invalid: t=$jump: robot 'r0' moves" "$bin/ompl_parc_validate" "$tmp/bad.json"

# Trajectories and delayed execution (ompl_parc_execute; the demo's --trajectory).
expect 0 "coordinated:  0/3 runs collide" "$bin/ompl_parc_execute" --scenario mobile_cross --robots 4 --runs 3 \
    --trajectory "$tmp/traj.json" "$tmp/sol.json"
expect 0 '"format":"ompl_parc.trajectory"' head -c 40 "$tmp/traj.json"
expect 0 "^trajectory $tmp/traj2.json (" "$bin/ompl_parc_demo" --scenario mobile_cross --robots 4 --trajectory \
    "$tmp/traj2.json"
expect 1 "^invalid solution: t=$jump: robot 'r0' moves" "$bin/ompl_parc_execute" --scenario mobile_cross --robots 4 \
    "$tmp/bad.json"
expect 2 "min-speed" "$bin/ompl_parc_execute" --scenario mobile_cross --robots 4 --min-speed 0 "$tmp/sol.json"
expect 2 "runs" "$bin/ompl_parc_execute" --scenario mobile_cross --robots 4 --runs -1 "$tmp/sol.json"
expect 2 "cannot write '$tmp/none/t.json'" "$bin/ompl_parc_execute" --scenario mobile_cross --robots 4 --runs 0 \
    --trajectory "$tmp/none/t.json" "$tmp/sol.json"
expect 2 "no solution file" "$bin/ompl_parc_execute" --scenario mobile_cross --robots 4

echo '{"format": "ompl_parc.solution", "version": 1' >"$tmp/truncated.json"
expect 2 "not valid JSON" "$bin/ompl_parc_validate" "$tmp/truncated.json"
expect 2 "cannot open" "$bin/ompl_parc_validate" "$tmp/missing.json"
expect 2 "no solution file" "$bin/ompl_parc_validate"
expect 2 "substeps must be a whole number from 1 to 1024 (got '0')" "$bin/ompl_parc_validate" --substeps 0 "$tmp/sol.json"
expect 2 "substeps must be a whole number from 1 to 1024 (got '4294967295')" \
    "$bin/ompl_parc_validate" --substeps 4294967295 "$tmp/sol.json"
expect 2 "unknown scenario 'warehouse' (valid: crossing, field, mobile_circle, mobile_cross, panda_cage, panda_cell, planar_cell, planar_cross, ring, rooms)" \
    "$bin/ompl_parc_demo" --scenario warehouse
expect 2 "even number of robots" "$bin/ompl_parc_demo" --robots 5
expect 2 "time-limit must be positive" "$bin/ompl_parc_demo" --time-limit 0
expect 2 "unrecognised option\|unrecognized option" "$bin/ompl_parc_demo" --bogus
expect 2 "robots" "$bin/ompl_parc_demo" --robots many
expect 0 "Usage: ompl_parc_demo" "$bin/ompl_parc_demo" --help
# Numbers are read whole and range-checked: no wrapping of negatives, no unbounded limits (issue 15's reproducers).
expect 2 "robots must be a whole number from 1 to 20000 (got '-2')" "$bin/ompl_parc_demo" --robots -2
expect 2 "robots must be a whole number from 1 to 20000 (got '100000')" "$bin/ompl_parc_demo" --robots 100000
expect 2 "parameter 'workers' must be a whole number from 1 to 64 (got '-1')" "$bin/ompl_parc_demo" --planner parc --workers -1
expect 2 "parameter 'workers' must be a whole number from 1 to 64 (got '1000')" \
    "$bin/ompl_parc_demo" --planner parc --param workers=1000
expect 2 "parameter 'window' must be a whole number from 1 to 2000 (got '-1')" "$bin/ompl_parc_demo" --param window=-1
expect 2 "parameter 'optimistic' must be 1/0, true/false, on/off or yes/no (got 'maybe')" "$bin/ompl_parc_demo" --planner parc --param optimistic=maybe
expect 2 "parameter 'seed' must be a whole number from 0 to 4294967295 (got '-1')" "$bin/ompl_parc_demo" --param seed=-1
expect 2 "time-limit must be a number from 0 to 1e+07 (got 'inf')" "$bin/ompl_parc_demo" --time-limit inf
expect 2 "time-limit must be a number from 0 to 1e+07 (got '1e10')" "$bin/ompl_parc_demo" --time-limit 1e10
# Smoothing (issue 16): on by default, the plan it returns validated; off leaves the planner's plan; a bad budget
# is refused; OMPL's own planners are smoothed by the demo; a 3D picture says it is a top view.
expect 0 "smoothing  .*before it, makespan" "$bin/ompl_parc_demo" --scenario mobile_circle --robots 8 --seed 2
expect 0 "validated  yes" "$bin/ompl_parc_demo" --scenario mobile_circle --robots 8 --planner rrtconnect --smooth 0.5
# The whole-team solve on a dense crossing of discs: LaCAM's plan replaces the repairs' (validated as every plan).
expect 0 "whole-team solve kept" "$bin/ompl_parc_demo" --scenario crossing --robots 24 --task 3 --smooth 3
expect 0 "lower bound 1630" "$bin/ompl_parc_demo" --scenario mobile_circle --robots 8 --smooth 0
expect 2 "smooth must be a number from 0 to 3600 (got '-1')" "$bin/ompl_parc_demo" --smooth -1
expect 0 "3D problem: top view only" "$bin/ompl_parc_demo" --scenario panda_cage --robots 2 --param profile=panda \
    --smooth 0 --picture "$tmp/panda.svg"
expect 2 "seed must be a whole number from 0 to 4294967295 (got '4294967296')" "$bin/ompl_parc_demo" --seed 4294967296
expect 2 "'/dev/zero' is not a regular file" "$bin/ompl_parc_demo" --scenario-file /dev/zero
expect 2 "'$tmp' is not a regular file" "$bin/ompl_parc_validate" "$tmp"
expect 2 "robots must be a whole number from 0 to 1000 (got '-2')" \
    "$bin/ompl_parc_generate_panda_cage" --out-dir "$tmp" --robots -2
# A 1 ms limit on a 64-robot composite problem cannot be met: a clean "not solved" exit.
expect 1 "status     " "$bin/ompl_parc_demo" --scenario mobile_circle --robots 64 --time-limit 0.001

# Scenario files, --workers and pictures.
expect 0 "validated  yes" "$bin/ompl_parc_demo" --scenario-file "$scenarios/doorway_swap.json" \
    --out "$tmp/door.json" --picture "$tmp/door.svg"
expect 0 "^valid: 4 robots" "$bin/ompl_parc_validate" --scenario-file "$scenarios/doorway_swap.json" "$tmp/door.json"
expect 0 "<animate " cat "$tmp/door.svg"
expect 0 "validated  yes" "$bin/ompl_parc_demo" --planner parc --workers 2 --robots 8 --picture "$tmp/cross.svg" \
    --picture-static
expect 0 'class="trace"' cat "$tmp/cross.svg"
expect 2 "planner 'arc' has no 'workers' parameter\|'arc' has no 'workers'" "$bin/ompl_parc_demo" --workers 2
expect 2 "unknown planner 'astar' (valid: arc, ep-rrt-c, or-ep-rrt-c, or-pp-st-rrt, or-rrt-c, orparc, parc, pp-st-rrt, rrtconnect)" \
    "$bin/ompl_parc_demo" --planner astar
expect 2 "not both" "$bin/ompl_parc_demo" --scenario mobile_circle --scenario-file "$scenarios/doorway_swap.json"
expect 2 "cannot open" "$bin/ompl_parc_demo" --scenario-file "$tmp/missing_scenario.json"
edit_scenario() {  # edit_scenario IN OUT PYTHON: write scenario file IN changed by the Python statement (on doc) to OUT
    python3 - "$1" "$2" "$3" <<'PY'
import json, sys
doc = json.load(open(sys.argv[1]))
exec(sys.argv[3])
json.dump(doc, open(sys.argv[2], "w"))
PY
}
edit() { edit_scenario "$scenarios/doorway_swap.json" "$1" "$2"; }
edit "$tmp/radius.json" 'doc["robots"][2]["radius"] = 0'
expect 2 "robots\[2\].radius must be a positive number" "$bin/ompl_parc_demo" --scenario-file "$tmp/radius.json"
edit "$tmp/dup.json" 'doc["robots"][1]["name"] = "west_a"'
expect 2 "robots\[1\].name 'west_a' is already used" "$bin/ompl_parc_demo" --scenario-file "$tmp/dup.json"
edit "$tmp/wall.json" 'doc["robots"][0]["start"] = [0, 4]'
expect 2 "start of robot 'west_a' is" "$bin/ompl_parc_validate" --scenario-file "$tmp/wall.json" "$tmp/door.json"
edit "$tmp/urdf.json" 'doc["robots"][0] = {"name": "a", "kind": "urdf_arm", "urdf_file": "/nonexistent/arm.urdf", "base_link": "b", "tip_link": "t", "start": [0], "goal": [0]}'
expect 2 "nonexistent/arm.urdf" "$bin/ompl_parc_demo" --scenario-file "$tmp/urdf.json"
# Issue 15: at resolution 1e-9 a timestep carried discs through each other and the planner claimed a solution.
edit "$tmp/coarse.json" 'doc["resolution"] = 1e-9'
expect 2 "resolution 1e-09 is too coarse to plan robot 'west_a'.*at least 2$" \
    "$bin/ompl_parc_demo" --scenario-file "$tmp/coarse.json"
head -c 200 "$scenarios/doorway_swap.json" >"$tmp/cut.json"
expect 2 "not valid JSON at line" "$bin/ompl_parc_demo" --scenario-file "$tmp/cut.json"
edit "$tmp/escape.json" 'doc["robots"][1]["name"] = "west\x1b[2J"'
expect 2 "robots\[1\].name must be printable: it holds a control character at byte 4$" \
    "$bin/ompl_parc_demo" --scenario-file "$tmp/escape.json"
# Bad input is reported on exactly one line.
expect 0 "^1$" bash -c "'$bin/ompl_parc_demo' --scenario-file '$tmp/dup.json' 2>&1 | wc -l"

# Panda Cage: stored tasks by --task, the same problem as their scenario files; the generator; bad input.
expect 0 "validated  yes" "$bin/ompl_parc_demo" --scenario panda_cage --robots 2 --task 1 --param profile=panda \
    --out "$tmp/panda.json" --geometry "$tmp/panda_geometry.json"
expect 0 "^valid: 2 robots" "$bin/ompl_parc_validate" --scenario-file "$scenarios/panda_cage/panda_cage_2_1.json" \
    "$tmp/panda.json"
expect 2 "task must be below 5, got 5" "$bin/ompl_parc_demo" --scenario panda_cage --robots 2 --task 5
expect 2 "scenario 'mobile_cross' has only task 0" "$bin/ompl_parc_demo" --task 1
expect 2 "not both" "$bin/ompl_parc_demo" --task 1 --scenario-file "$scenarios/doorway_swap.json"
mkdir -p "$tmp/cage"
expect 0 "panda_cage_2_4.json  generated in .* conflicting pairs 1 of 1" \
    "$bin/ompl_parc_generate_panda_cage" --out-dir "$tmp/cage" --robots 2 --task 4
expect 0 "validated  yes" "$bin/ompl_parc_demo" --scenario-file "$tmp/cage/panda_cage_2_4.json" --param profile=panda
expect 2 "no --out-dir" "$bin/ompl_parc_generate_panda_cage"
expect 2 "needs 2, 4, 8 or 16 robots, got 5" "$bin/ompl_parc_generate_panda_cage" --out-dir "$tmp" --robots 5
panda_edit() { edit_scenario "$scenarios/panda_cage/panda_cage_2_0.json" "$1" "$2"; }
panda_edit "$tmp/in_bar.json" 'doc["robots"][0]["base_pose"]["position"] = [-0.5, -1.0, -0.3]'
expect 2 "robot 'panda0': link 'panda_link0', fixed to the base, collides with obstacle 'bar0'" \
    "$bin/ompl_parc_demo" --scenario-file "$tmp/in_bar.json"
panda_edit "$tmp/no_limit.json" "import re; r = doc['robots'][1]; r.pop('builtin_urdf'); \
r['urdf'] = re.sub(r'<limit[^>]*/>', '', open('$scenarios/../../ompl_parc/robots/models/panda.urdf').read(), count=1)"
expect 2 "malformed URDF: Joint \[panda_joint1\] is of type REVOLUTE but it does not specify limits" \
    "$bin/ompl_parc_demo" --scenario-file "$tmp/no_limit.json"
expect 0 "^1$" bash -c "'$bin/ompl_parc_demo' --scenario-file '$tmp/no_limit.json' 2>&1 | wc -l"
# A collision element urdfdom cannot read (a radius of nan) refuses the URDF instead of leaving its link bodiless.
panda_edit "$tmp/nan_radius.json" "import re; r = doc['robots'][1]; r.pop('builtin_urdf'); \
r['urdf'] = re.sub(r'radius=\"[^\"]*\"', 'radius=\"nan\"', open('$scenarios/../../ompl_parc/robots/models/panda.urdf').read(), count=1)"
expect 2 "malformed URDF: radius \[nan\] is not a valid float" "$bin/ompl_parc_demo" --scenario-file "$tmp/nan_radius.json"
# The validator checks between timesteps whatever --substeps says.
expect 0 "^valid: 2 robots" "$bin/ompl_parc_validate" --substeps 1 --scenario-file "$scenarios/panda_cage/panda_cage_2_1.json" \
    "$tmp/panda.json"

# Generated problem families as scenario files; each reads back and plans.
expect 0 "rooms_6_2.json" "$bin/ompl_parc_generate" --scenario rooms --robots 6 --task 1 --count 2 --out-dir "$tmp/rooms"
expect 0 "validated  yes" "$bin/ompl_parc_demo" --scenario-file "$tmp/rooms/rooms_6_1.json"
expect 2 "unknown scenario 'hall'" "$bin/ompl_parc_generate" --scenario hall --out-dir "$tmp/rooms"
expect 2 "count must be a whole number from 1 to 100000 (got '0')" "$bin/ompl_parc_generate" --scenario ring \
    --count 0 --out-dir "$tmp/rooms"
expect 2 "no --out-dir" "$bin/ompl_parc_generate" --scenario ring

# Ctrl-C. A background job of a non-interactive shell starts with SIGINT ignored (and the tools leave an ignored
# SIGINT ignored, as shells expect of their jobs): python3 sets the action each check wants before it runs the tool.
# interrupt ACTION DELAY PRESSES BOUND OUT COMMAND...: runs COMMAND with SIGINT at ACTION (SIG_DFL or SIG_IGN),
# output to OUT; after DELAY seconds sends a SIGINT, and with PRESSES 2 another one $DELAY2 seconds later (default
# 0); waits up to BOUND seconds from the first for it to end (then kills it: rc 124). Sets rc and took (seconds from
# the first SIGINT to the end).
interrupt() {
    local action=$1 delay=$2 presses=$3 bound=$4 out=$5
    shift 5
    python3 -c 'import os, signal, sys
signal.signal(signal.SIGINT, getattr(signal, sys.argv[1]))
os.execv(sys.argv[2], sys.argv[2:])' "$action" "$@" >"$out" 2>&1 &
    local pid=$! sent
    sleep "$delay"
    sent=$EPOCHREALTIME
    kill -INT "$pid"
    if [ "$presses" -gt 1 ]; then
        sleep "${DELAY2:-0}"
        kill -INT "$pid" 2>/dev/null
    fi
    while kill -0 "$pid" 2>/dev/null &&
        awk -v s="$sent" -v n="$EPOCHREALTIME" -v b="$bound" 'BEGIN { exit !(n - s < b) }'; do
        sleep 0.05
    done
    took=$(awk -v s="$sent" -v n="$EPOCHREALTIME" 'BEGIN { printf "%.3f", n - s }')
    if kill -0 "$pid" 2>/dev/null; then
        kill -KILL "$pid"
        wait "$pid"
        rc=124
    else
        wait "$pid"
        rc=$?
    fi
}
# check NAME OUT CONDITION: ok if the shell condition holds (it sees rc, took), else FAIL with OUT's head.
check() {
    if eval "$3"; then
        echo "ok:   $1: exit $rc, $took s after the first SIGINT"
    else
        echo "FAIL: $1: exit $rc, $took s after the first SIGINT, output:"
        head -8 "$2"
        failures=$((failures + 1))
    fi
}
# Two discs that must swap in a corridor too narrow to pass: no plan exists, so ARC and P-ARC repair until their
# limit however fast they get, and a SIGINT at 2 s lands in the solve: the planner stops through its termination
# condition (P-ARC's workers joined), the summary says "Interrupted", no --out for an unfinished plan, exit 130;
# within 20 s (milliseconds here).
hard=(--scenario-file "$here/data/corridor_swap.json")
for planner in "arc" "parc --workers 2"; do
    name=${planner%% *}
    # shellcheck disable=SC2086
    interrupt SIG_DFL 2 1 20 "$tmp/int_$name.out" "$bin/ompl_parc_demo" "${hard[@]}" --time-limit 60 \
        --planner $planner --out "$tmp/int_$name.json"
    check "Ctrl-C stops $planner" "$tmp/int_$name.out" '[ $rc -eq 130 ] && ! [ -e "$tmp/int_$name.json" ] &&
        grep -q "^status     Interrupted after" "$tmp/int_$name.out"'
done
# Two at once: exit 130 at once either way (the first may have stopped it before the second arrives).
interrupt SIG_DFL 2 2 10 "$tmp/int_twice.out" "$bin/ompl_parc_demo" "${hard[@]}" --time-limit 60
check "Ctrl-C twice" "$tmp/int_twice.out" '[ $rc -eq 130 ]'
# SIGINT ignored at the start stays ignored: the run goes on to its 4 s limit (exit 1: no plan).
interrupt SIG_IGN 1 1 30 "$tmp/int_ignored.out" "$bin/ompl_parc_demo" "${hard[@]}" --time-limit 4
check "an ignored SIGINT stays ignored" "$tmp/int_ignored.out" \
    '[ $rc -eq 1 ] && ! grep -qi "interrupted" "$tmp/int_ignored.out"'
# The validator has nothing to report half-way: one line and exit 130 at the first SIGINT (the whole check of this
# plan at 1024 substeps takes 40 s here).
"$bin/ompl_parc_demo" --scenario panda_cage --robots 4 --seed 1 --quiet --out "$tmp/panda4.json" >/dev/null
interrupt SIG_DFL 1.5 1 5 "$tmp/int_validate.out" "$bin/ompl_parc_validate" --scenario panda_cage --robots 4 \
    --substeps 1024 --threads 1 "$tmp/panda4.json"
check "Ctrl-C in the validator" "$tmp/int_validate.out" \
    '[ $rc -eq 130 ] && [ "$(cat "$tmp/int_validate.out")" = "ompl_parc_validate: interrupted" ]'
# The benchmark: after the first SIGINT no run starts, the one in progress ends at its 4 s limit (OMPL's Benchmark
# owns its termination condition), its CSV row is written, exit 130. A second SIGINT quits at once: a run with a 60 s
# limit ends 1 s after the first SIGINT, no row written.
for limit in 4 60; do
    cat >"$tmp/int_$limit.cfg" <<CFG
[problem]
name = int
scenario = panda_cage
robots = 16
task = 3

[benchmark]
time_limit = $limit
mem_limit = 8192
run_count = 3
output = $tmp/int_$limit
seed = 1

[planner]
arc =
CFG
done
interrupt SIG_DFL 1.5 1 20 "$tmp/int_bench.out" "$bin/ompl_parc_benchmark" "$tmp/int_4.cfg"
check "Ctrl-C in a benchmark: the run in progress ends" "$tmp/int_bench.out" '[ $rc -eq 130 ] &&
    grep -q "^ompl_parc_benchmark: interrupted after 1 of 3 runs$" "$tmp/int_bench.out" &&
    [ "$(wc -l <"$tmp/int_4/int.csv")" -eq 2 ] && ! [ -e "$tmp/int_4/int.log" ]'
DELAY2=1 interrupt SIG_DFL 1.5 2 5 "$tmp/int_bench2.out" "$bin/ompl_parc_benchmark" "$tmp/int_60.cfg"
check "Ctrl-C twice in a benchmark: quits at once" "$tmp/int_bench2.out" '[ $rc -eq 130 ] &&
    awk -v t="$took" "BEGIN { exit !(t >= 1 && t < 5) }" && [ "$(wc -l <"$tmp/int_60/int.csv")" -le 1 ]'

# The Panda Cage picture (if Debian's matplotlib is there): geometry file -> PNG.
if /usr/bin/python3 -c "import matplotlib" 2>/dev/null; then
    expect 0 "PNG" bash -c "/usr/bin/python3 '$(dirname "$0")/../scripts/draw_panda_cage.py' \
        '$tmp/panda_geometry.json' '$tmp/panda.png' && head -c 4 '$tmp/panda.png'"
else
    echo "skip: no python3-matplotlib, the Panda Cage picture is not drawn"
fi

if [ "$failures" -ne 0 ]; then
    echo "$failures tool check(s) failed"
    exit 1
fi
echo "all tool checks passed"
