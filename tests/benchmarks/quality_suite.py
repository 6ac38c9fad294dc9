#!/usr/bin/python3
"""Plan quality on the generated problem families, as a new user gets it: `ompl_parc_demo` with its default settings
(1 s of smoothing, the plan validated) on every family, three team sizes, instances 0-7, one seed, each planner on the
same instances. Per run: solved, the makespan and sum of costs as multiples of the straight-line bounds and of the
obstacle-aware (path) bounds (each robot alone on its shortest path around the obstacles), the time to the first
solution (the solve's time less its smoothing) and the smoothing's time. Summary: per family and planner the median
makespan ratio to either bound and the median of the per-instance ratio planner / reference planner (default
PP-ST-RRT), and over all instances the median and 90th percentile to either bound.

Runs are independent processes; --jobs runs several at once (quality is what this measures: with more jobs than
cores, leave the times aside).

Usage: tests/benchmarks/quality_suite.py [--planners arc,pp-st-rrt] [--families rooms,crossing,...] [--sizes 8,24,48]
       [--instances 0-7] [--seed 1] [--time-limit 30] [--jobs 1] [--csv out.csv] [-- extra demo arguments]
"""
import argparse
import concurrent.futures
import csv
import os
import re
import statistics
import subprocess
import sys

DEMO = os.path.join(os.path.dirname(__file__), "..", "..", "build", "bin", "ompl_parc_demo")
FAMILIES = ["rooms", "crossing", "ring", "field", "planar_cell", "panda_cell"]
# panda_cell has teams of 2, 4, 8 or 16 only.
SIZES = {"panda_cell": [4, 8, 16]}
PLANNER_ARGS = {"parc": ["--planner", "parc", "--workers", "2"]}


def run(demo, family, robots, instance, planner, seed, limit, extra):
    command = [demo, "--scenario", family, "--robots", str(robots), "--task", str(instance), "--seed", str(seed),
               "--time-limit", str(limit)] + PLANNER_ARGS.get(planner, ["--planner", planner]) + extra
    if family.startswith("panda"):
        command += ["--param", "profile=panda"] if planner in ("arc", "parc", "orparc") else []
    out = subprocess.run(command, capture_output=True, text=True).stdout
    row = {"family": family, "robots": robots, "instance": instance, "planner": planner,
           "solved": "validated  yes" in out}
    if row["solved"]:
        row["seconds"] = float(re.search(r"status\s+Exact solution after ([0-9.]+) s", out).group(1))
        smoothing = re.search(r"smoothing\s+([0-9.]+) s", out)
        row["smoothing"] = float(smoothing.group(1)) if smoothing else 0.
        row["first_solution"] = row["seconds"] - row["smoothing"]
        row["makespan_ratio"] = float(re.search(r"makespan\s+\d+ timesteps.*?([0-9.]+)x the lower bound", out).group(1))
        row["soc_ratio"] = float(re.search(r"sum costs\s+\d+ timesteps, ([0-9.]+)x the lower bound", out).group(1))
        path = re.search(r"path bound makespan ([0-9.]+)x of \d+, sum of costs ([0-9.]+)x of \d+", out)
        row["makespan_path_ratio"], row["soc_path_ratio"] = float(path.group(1)), float(path.group(2))
        row["breakdown"] = breakdown(out)
    return row


def breakdown(out):
    """Where the makespan comes from (ARC-family planners): the straight-line bound, what the initial plan adds to it,
    what each repair solver's repairs add, what smoothing and the anytime phase take away; in timesteps, summing to
    the final makespan."""
    length = re.search(r"length\s+initial plan makespan (\d+), sum of costs \d+; repairs added(.*?); global", out)
    if not length:
        return None
    bound = int(re.search(r"makespan\s+\d+ timesteps.*?x the lower bound (\d+)", out).group(1))
    final = int(re.search(r"makespan\s+(\d+) timesteps", out).group(1))
    parts = {"initial plan": int(length.group(1)) - bound}
    for solver, added in re.findall(r", ([a-z-]+) \(\d+\): -?\d+ to arrivals, (-?\d+) to the makespan", length.group(2)):
        parts["repairs " + solver] = int(added)
    parts["smoothing, anytime"] = final - bound - sum(parts.values())
    return {"bound": bound, "parts": parts}


def printBreakdown(rows, families, planners):
    """Per family and ARC-family planner: each part's share of the makespan, as a multiple of the bound (summed over
    the instances, so that the parts add up to the family's total makespan / total bound)."""
    print("\nwhere the makespan comes from (sum over the family's instances, as multiples of the summed bound):")
    for family in families:
        for planner in planners:
            got = [r["breakdown"] for r in rows if r["family"] == family and r["planner"] == planner and
                   r["solved"] and r.get("breakdown")]
            if not got:
                continue
            bound = sum(b["bound"] for b in got)
            names = sorted({name for b in got for name in b["parts"]})
            parts = ", ".join(f"{name} {sum(b['parts'].get(name, 0) for b in got) / bound:+.2f}" for name in names)
            print(f"{family:12} {planner:11} bound 1.00, {parts}")


def percentile(values, q):
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, int(round(q * (len(ordered) - 1))))]


def main():
    args, extra = sys.argv[1:], []
    if "--" in args:
        extra = args[args.index("--") + 1:]
        args = args[:args.index("--")]
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--planners", default="arc,pp-st-rrt")
    parser.add_argument("--reference", default="pp-st-rrt")
    parser.add_argument("--families", default=",".join(FAMILIES))
    parser.add_argument("--sizes", default="8,24,48")
    parser.add_argument("--instances", default="0-7")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--time-limit", type=float, default=30.)
    parser.add_argument("--jobs", type=int, default=1)
    parser.add_argument("--csv")
    parser.add_argument("--demo", default=DEMO)
    options = parser.parse_args(args)
    first, _, last = options.instances.partition("-")
    instances = range(int(first), int(last or first) + 1)
    planners = options.planners.split(",")
    runs = [(family, robots, instance, planner)
            for family in options.families.split(",")
            for robots in SIZES.get(family, [int(s) for s in options.sizes.split(",")])
            for instance in instances for planner in planners]
    with concurrent.futures.ThreadPoolExecutor(options.jobs) as pool:
        rows = list(pool.map(lambda r: run(options.demo, *r, options.seed, options.time_limit, extra), runs))
    if options.csv:
        with open(options.csv, "w", newline="") as f:
            writer = csv.DictWriter(f, fieldnames=["family", "robots", "instance", "planner", "solved", "seconds",
                                                   "smoothing", "first_solution", "makespan_ratio", "soc_ratio",
                                                   "makespan_path_ratio", "soc_path_ratio"],
                                    extrasaction="ignore")
            writer.writeheader()
            writer.writerows(rows)
    by = {(r["family"], r["robots"], r["instance"], r["planner"]): r for r in rows}
    print(f"{'family':12} {'planner':11} {'solved':>7} {'makespan':>9} {'p90':>6} {'soc':>6} {'vs ' + options.reference:>16}"
          f" {'first sol.':>11} {'path ms':>8} {'p90':>6} {'soc':>6}")
    for family in options.families.split(","):
        for planner in planners:
            mine = [r for r in rows if r["family"] == family and r["planner"] == planner]
            good = [r for r in mine if r["solved"]]
            versus = [r["makespan_ratio"] / by[(r["family"], r["robots"], r["instance"], options.reference)]
                      ["makespan_ratio"] for r in good
                      if by.get((r["family"], r["robots"], r["instance"], options.reference), {}).get("solved")]
            if not good:
                print(f"{family:12} {planner:11} {0:>3}/{len(mine):<3}")
                continue
            print(f"{family:12} {planner:11} {len(good):>3}/{len(mine):<3} "
                  f"{statistics.median(r['makespan_ratio'] for r in good):>8.2f}x "
                  f"{percentile([r['makespan_ratio'] for r in good], 0.9):>5.2f}x "
                  f"{statistics.median(r['soc_ratio'] for r in good):>5.2f}x "
                  f"{(statistics.median(versus) if versus else float('nan')):>15.2f}x "
                  f"{statistics.median(r['first_solution'] for r in good):>10.3f}s "
                  f"{statistics.median(r['makespan_path_ratio'] for r in good):>7.2f}x "
                  f"{percentile([r['makespan_path_ratio'] for r in good], 0.9):>5.2f}x "
                  f"{statistics.median(r['soc_path_ratio'] for r in good):>5.2f}x")
    printBreakdown(rows, options.families.split(","), planners)
    for planner in planners:
        good = [r for r in rows if r["planner"] == planner and r["solved"]]
        if good:
            straight = [r["makespan_ratio"] for r in good]
            path = [r["makespan_path_ratio"] for r in good]
            print(f"all          {planner:11} {len(good):>3}/{len([r for r in rows if r['planner'] == planner]):<3} "
                  f"median {statistics.median(straight):.2f}x, p90 {percentile(straight, 0.9):.2f}x the straight-line "
                  f"bound; median {statistics.median(path):.2f}x, p90 {percentile(path, 0.9):.2f}x the path bound")


if __name__ == "__main__":
    main()
