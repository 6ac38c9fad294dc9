#!/usr/bin/env bash
# The layers of docs/architecture.md, checked on every header and source: statespaces/ includes nothing of
# ours outside itself; the core (ompl_parc/) nothing from planners/ or the demos' scenarios; planners/ nothing
# from the demos. Prints each forbidden include and exits 1 if there is one.
# Usage: layers_test.sh SOURCE_DIR
set -u
cd "$1"
status=0
forbid() {  # forbid FOLDER PATTERN WHY
    local hits
    hits=$(grep -rnE "^[[:space:]]*#[[:space:]]*include[[:space:]]*[<\"]$2" "$1" --include='*.h' --include='*.cpp' --include='*.in')
    if [ -n "$hits" ]; then
        echo "layer violation ($3):"
        echo "$hits"
        status=1
    fi
}
forbid statespaces 'ompl_parc/([^s]|s[^t]|st[^a])' "statespaces/ includes nothing of ours but itself"
forbid ompl_parc 'ompl_parc/(planners|scenarios)/' "the core includes no planner or demo header"
forbid ompl_parc '(planners|demos)/' "the core includes no planner or demo header"
forbid planners 'ompl_parc/scenarios/' "planners include no demo header"
exit $status
