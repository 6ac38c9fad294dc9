#!/usr/bin/python3
"""The Python binding's overhead on one solve, side by side in one run: Mobile Cross 64 (or --robots N), ARC, seed 1,
no smoothing, from C++ (ompl_parc_demo's solve time: the planner's solve() alone) and from Python (the wall time of
ompl_parc.solve(): the problem handed over, the planner made and set up, the solve with the GIL released, the plan
and the properties copied back). Python's side counts more work than C++'s, so the ratio is an upper bound.
Rounds alternate C++ and Python; medians are reported.

Usage: PYTHONPATH=build/python /usr/bin/python3 tests/benchmarks/python_overhead.py BIN_DIR [--robots N] [--rounds K]
"""
import argparse
import re
import statistics
import subprocess
import time

import ompl_parc


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("bin", help="the folder of ompl_parc_demo")
    parser.add_argument("--robots", type=int, default=64)
    parser.add_argument("--rounds", type=int, default=5)
    args = parser.parse_args()
    problem = ompl_parc.scenario("mobile_cross", robots=args.robots)
    cpp, python, makespans = [], [], set()
    for _ in range(args.rounds):
        demo = [f"{args.bin}/ompl_parc_demo", "--scenario", "mobile_cross", "--robots", str(args.robots),
                "--planner", "arc", "--param", "seed=1", "--smooth", "0", "--no-validate"]
        run = subprocess.run(demo, capture_output=True, text=True, check=True)
        cpp.append(float(re.search(r"^status .* after ([0-9.]+) s", run.stdout, re.M).group(1)))
        makespans.add(int(re.search(r"^makespan +([0-9]+)", run.stdout, re.M).group(1)))
        start = time.perf_counter()
        result = ompl_parc.solve(problem, "arc", seed=1, smooth=0)
        python.append(time.perf_counter() - start)
        makespans.add(result.plan.makespan)
    c, p = statistics.median(cpp), statistics.median(python)
    print(f"Mobile Cross {args.robots}, ARC, seed 1, {args.rounds} rounds (same plan: {len(makespans) == 1})")
    print(f"  C++    solve()          median {c:.4f} s  (min {min(cpp):.4f}, max {max(cpp):.4f})")
    print(f"  Python ompl_parc.solve  median {p:.4f} s  (min {min(python):.4f}, max {max(python):.4f})")
    print(f"  Python / C++ = {p / c:.3f} (overhead {100 * (p / c - 1):+.1f} %)")


if __name__ == "__main__":
    main()
