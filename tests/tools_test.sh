#!/usr/bin/env bash
# Exit codes and one-line messages of the command-line tools, on good and bad input.
# Usage: tools_test.sh BIN_DIR
set -u
bin=$1
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
python3 - "$tmp/sol.json" "$tmp/bad.json" <<'PY'
import json, sys
doc = json.load(open(sys.argv[1]))
doc["robots"][0]["states"][5][0] += 0.5   # a teleporting step
json.dump(doc, open(sys.argv[2], "w"))
PY
expect 1 "^invalid: t=4: robot 'r0' moves" "$bin/ompl_parc_validate" "$tmp/bad.json"

echo '{"format": "ompl_parc.solution", "version": 1' >"$tmp/truncated.json"
expect 2 "not valid JSON" "$bin/ompl_parc_validate" "$tmp/truncated.json"
expect 2 "cannot open" "$bin/ompl_parc_validate" "$tmp/missing.json"
expect 2 "no solution file" "$bin/ompl_parc_validate"
expect 2 "unknown scenario 'warehouse' (valid: mobile_circle, mobile_cross, panda_cage, planar_cross)" \
    "$bin/ompl_parc_demo" --scenario warehouse
expect 2 "even number of robots" "$bin/ompl_parc_demo" --robots 5
expect 2 "time-limit must be positive" "$bin/ompl_parc_demo" --time-limit 0
expect 2 "unrecognised option\|unrecognized option" "$bin/ompl_parc_demo" --bogus
expect 2 "robots" "$bin/ompl_parc_demo" --robots many
expect 0 "Usage: ompl_parc_demo" "$bin/ompl_parc_demo" --help
# A 1 ms limit on a 64-robot composite problem cannot be met: a clean "not solved" exit.
expect 1 "status     " "$bin/ompl_parc_demo" --scenario mobile_circle --robots 64 --time-limit 0.001

if [ "$failures" -ne 0 ]; then
    echo "$failures tool check(s) failed"
    exit 1
fi
echo "all tool checks passed"
