#!/usr/bin/env bash
# Exit codes and one-line messages of the command-line tools, on good and bad input.
# Usage: tools_test.sh BIN_DIR
set -u
bin=$1
scenarios=$(cd "$(dirname "$0")/../demos/scenarios" && pwd)
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

expect 0 "validated  yes" "$bin/ompl_parc_demo" --scenario mobile_cross --robots 4 --seed 3 --out "$tmp/sol.json"
expect 0 "^valid: 4 robots" "$bin/ompl_parc_validate" --scenario mobile_cross --robots 4 "$tmp/sol.json"
expect 2 "robots' has 4 entries" "$bin/ompl_parc_validate" --scenario mobile_cross --robots 8 "$tmp/sol.json"

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
expect 2 "parameter 'workers' must be a number from 1 to 64 (got '-1')" "$bin/ompl_parc_demo" --planner parc --workers -1
expect 2 "parameter 'workers' must be a number from 1 to 64 (got '1000')" \
    "$bin/ompl_parc_demo" --planner parc --param workers=1000
expect 2 "parameter 'window' must be a number from 1 to 2000 (got '-1')" "$bin/ompl_parc_demo" --param window=-1
expect 2 "time-limit must be a number from 0 to 1e+07 (got 'inf')" "$bin/ompl_parc_demo" --time-limit inf
expect 2 "time-limit must be a number from 0 to 1e+07 (got '1e10')" "$bin/ompl_parc_demo" --time-limit 1e10
# Smoothing (issue 16): on by default, the plan it returns validated; off leaves the planner's plan; a bad budget
# is refused; OMPL's own planners are smoothed by the demo; a 3D picture says it is a top view.
expect 0 "smoothing  .*before it, makespan" "$bin/ompl_parc_demo" --scenario mobile_circle --robots 8 --seed 2
expect 0 "validated  yes" "$bin/ompl_parc_demo" --scenario mobile_circle --robots 8 --planner rrtconnect --smooth 0.5
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

# Generated problem families as scenario files; each reads back and plans.
expect 0 "rooms_6_2.json" "$bin/ompl_parc_generate" --scenario rooms --robots 6 --task 1 --count 2 --out-dir "$tmp/rooms"
expect 0 "validated  yes" "$bin/ompl_parc_demo" --scenario-file "$tmp/rooms/rooms_6_1.json"
expect 2 "unknown scenario 'hall'" "$bin/ompl_parc_generate" --scenario hall --out-dir "$tmp/rooms"
expect 2 "count must be a whole number from 1 to 100000 (got '0')" "$bin/ompl_parc_generate" --scenario ring \
    --count 0 --out-dir "$tmp/rooms"
expect 2 "no --out-dir" "$bin/ompl_parc_generate" --scenario ring

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
