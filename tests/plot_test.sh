#!/usr/bin/env bash
# scripts/plot_benchmarks.py on small fixtures: our benchmark CSV and the P-ARC authors' short results.csv
# each give speedup.png, success.png and a summary.md with the expected medians, success rates and speedups
# (a speedup marked † where the planner solved a different number of runs than ARC).
# Usage: plot_test.sh FIXTURE_DIR  (runs `python3`: one without matplotlib hands over to Debian's /usr/bin/python3)
set -eu
data=$1
script="$(dirname "$0")/../scripts/plot_benchmarks.py"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failures=0

# check FIXTURE LINE...: plot FIXTURE.csv, require the three files and each LINE as a whole line of summary.md.
check() {
    local name=$1 out="$tmp/$1" line file
    shift
    if ! python3 "$script" --out "$out" "$data/$name.csv" >"$tmp/$name.log" 2>&1; then
        echo "FAIL: plot_benchmarks.py $name.csv exited non-zero:"
        head -5 "$tmp/$name.log"
        failures=$((failures + 1))
        return
    fi
    for file in speedup.png success.png summary.md; do
        if [ ! -s "$out/$file" ]; then
            echo "FAIL: $name.csv gave no $file"
            failures=$((failures + 1))
        fi
    done
    for line in "$@"; do
        if grep -qxF -- "$line" "$out/summary.md"; then
            echo "ok:   $name: $line"
        else
            echo "FAIL: $name: summary.md lacks the line '$line'; it is:"
            cat "$out/summary.md"
            failures=$((failures + 1))
        fi
    done
}

footnote="† solved a different number of runs than ARC: the speedup compares medians over different runs"

# planning_time_seconds: 8 robots: ARC 1/2/3 s, P-ARC-2 0.5/1/1.5 s; 16 robots: ARC 2/4/6 s, P-ARC-2 3 s, 2 s
# and a 10.2 s failure (not in its median). first_solution_time_seconds is half of it, to be ignored here.
check ours \
    "| Planner | Mobile Cross, 8 robots | Mobile Cross, 16 robots |" \
    "| ARC | 2 s (3/3) | 4 s (3/3) |" \
    "| P-ARC-2 | 1 s (3/3, 2.00x) | 2.5 s (2/3, 1.60x†) |" \
    "$footnote"

# Success as True/False, time = first_solution_time_seconds, type and workers from the method name.
check authors \
    "| Planner | Planar Cross, 8 robots | Planar Cross, 24 robots |" \
    "| ARC | 0.2 s (3/3) | 0.6 s (2/3) |" \
    "| P-ARC-4 | 0.1 s (3/3, 2.00x) | 0.2 s (3/3, 3.00x†) |" \
    "$footnote"

if [ "$failures" -ne 0 ]; then
    echo "$failures plot check(s) failed"
    exit 1
fi
echo "all plot checks passed"
