#!/usr/bin/python3
"""P-ARC-W's speedup over ARC on Mobile Cross N (issue 14's line: P-ARC-2 / ARC >= 1.85x, median of seeds 1-5), in
one process, side by side: per seed and round, ARC pinned to the first core, P-ARC-W on the first W cores, ARC pinned
to the second core. Times are the planners' solve() (`Result.time`, OMPL's plan computation time), no smoothing; every
planner's last plan of a seed is validated after the seed's rounds. Per seed the median of the rounds; the ratio is reported against ARC on each of
the two cores, because on a shared VM one core can run 1.3-1.7x slower than the other for minutes: a ratio taken then
says more about the machine than about P-ARC (the script warns when ARC's medians on the two cores differ by more than
10 %).

Usage: PYTHONPATH=build/python /usr/bin/python3 tests/benchmarks/parc_speedup.py [--robots N] [--rounds K] [--workers W]
"""
import argparse
import os
import statistics

import ompl_parc


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--robots", type=int, default=256)
    parser.add_argument("--rounds", type=int, default=7)
    parser.add_argument("--workers", type=int, default=2)
    args = parser.parse_args()
    cores = sorted(os.sched_getaffinity(0))
    if len(cores) < max(2, args.workers):
        raise SystemExit(f"parc_speedup.py: needs {max(2, args.workers)} cores, has {len(cores)}")
    problem = ompl_parc.scenario("mobile_cross", robots=args.robots)

    last = {}  # each planner's last plan, validated after the seed's rounds (validating between the solves changes
    # the heap the next solve gets: fresh pages cost about 12 us each on this VM, and ARC and P-ARC take them unequally)

    def solve(planner, on, seed, **params):
        os.sched_setaffinity(0, on)  # the planner's threads inherit it
        result = ompl_parc.solve(problem, planner, seed=seed, time_limit=60, smooth=0, **params)
        if not result.solved:
            raise SystemExit(f"parc_speedup.py: {planner} seed {seed}: {result.status}")
        last[(planner, frozenset(on))] = result.plan
        return result.time

    first, second, team = {cores[0]}, {cores[1]}, set(cores[:args.workers])
    ratios = ([], [])
    for seed in range(1, 6):
        arc0, parc, arc1 = [], [], []
        for _ in range(args.rounds):
            arc0.append(solve("arc", first, seed))
            parc.append(solve("parc", team, seed, workers=args.workers))
            arc1.append(solve("arc", second, seed))
        for (planner, _), plan in last.items():
            if not ompl_parc.validate(problem, plan).valid:
                raise SystemExit(f"parc_speedup.py: {planner} seed {seed}: the plan does not validate")
        last.clear()
        a0, p, a1 = (statistics.median(x) for x in (arc0, parc, arc1))
        ratios[0].append(a0 / p)
        ratios[1].append(a1 / p)
        skew = " (cores differ by more than 10 %)" if max(a0, a1) > 1.1 * min(a0, a1) else ""
        print(f"seed {seed}: ARC {a0 * 1e3:.2f} / {a1 * 1e3:.2f} ms (core {cores[0]} / {cores[1]}), "
              f"P-ARC-{args.workers} {p * 1e3:.2f} ms, ratio {a0 / p:.3f} / {a1 / p:.3f}{skew}", flush=True)
    print(f"Mobile Cross {args.robots}: P-ARC-{args.workers} / ARC, median of seeds 1-5: "
          f"{statistics.median(ratios[0]):.3f} against ARC on core {cores[0]}, "
          f"{statistics.median(ratios[1]):.3f} against ARC on core {cores[1]}")


if __name__ == "__main__":
    main()
