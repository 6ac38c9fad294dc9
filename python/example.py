#!/usr/bin/python3
"""ompl_parc from Python: solve Mobile Cross 16 with ARC and with P-ARC at 1, 2 and 4 workers (seeds 1-3), check
every plan with the independent validator, and plot the median planning time and makespan against the workers.

Usage: python/example.py [--out makespan_vs_workers.png] [--robots 16]
(Debian's /usr/bin/python3, for which the module is built, with python3-matplotlib; PYTHONPATH=build/python for the
module as built)
"""
import argparse
import statistics

import matplotlib

import ompl_parc

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402 (the backend must be chosen first)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", default="makespan_vs_workers.png", help="the plot to write")
    parser.add_argument("--robots", type=int, default=16, help="team size of Mobile Cross")
    args = parser.parse_args()

    problem = ompl_parc.scenario("mobile_cross", robots=args.robots)
    print(f"ompl_parc {ompl_parc.__version__} (OMPL {ompl_parc.OMPL_VERSION}), {problem.name}: "
          f"{problem.robot_count} robots")
    configurations = [("ARC", "arc", {}), *[(f"P-ARC-{w}", "parc", {"workers": w}) for w in (1, 2, 4)]]
    workers, times, makespans = [], [], []
    for label, planner, params in configurations:
        runs = []
        for seed in (1, 2, 3):
            result = ompl_parc.solve(problem, planner, time_limit=30, seed=seed, smooth=0, **params)
            report = ompl_parc.validate(problem, result.plan) if result.solved else None
            if not (report and report.valid):
                raise SystemExit(f"{label} seed {seed}: {result.status} {report.message if report else ''}")
            runs.append((result.time, result.plan.makespan))
        time, makespan = statistics.median(r[0] for r in runs), statistics.median(r[1] for r in runs)
        print(f"{label:8} median {time:.3f} s, makespan {makespan:.0f} timesteps (3 seeds, all validated)")
        if planner == "parc":
            workers.append(params["workers"])
            times.append(time)
            makespans.append(makespan)
        else:
            arc = (time, makespan)

    figure, (left, right) = plt.subplots(1, 2, figsize=(9, 3.5), constrained_layout=True)
    left.plot(workers, times, "o-", label="P-ARC")
    left.axhline(arc[0], color="grey", linestyle="--", label="ARC")
    left.set(xlabel="workers", ylabel="median planning time (s)", xticks=workers)
    right.plot(workers, makespans, "o-", label="P-ARC")
    right.axhline(arc[1], color="grey", linestyle="--", label="ARC")
    right.set(xlabel="workers", ylabel="median makespan (timesteps)", xticks=workers)
    for axis in (left, right):
        axis.legend(fontsize=8)
    figure.suptitle(f"Mobile Cross {problem.robot_count}: P-ARC against ARC "
                    f"(workers beyond this machine's cores are oversubscribed)")
    figure.savefig(args.out, dpi=120)
    print(f"plot: {args.out}")


if __name__ == "__main__":
    main()
