#!/usr/bin/python3
"""OR-P-ARC-2x1 over MPI against OR-P-ARC-2x1 in threads, side by side in one run: the same problems and seeds (the
race seed given, so rank k and thread k run the same instance), no smoothing, no validation. Reports per problem the
solved runs of each and whether the same seeds solved (by exit code: the winner may differ, it is a race), the median
solve time (the race until every instance joined, as each tool reports it), the median wall
time of the whole command (mpirun's launch included), and the MPI-only costs ompl_parc_mpi reports: start-up on
rank 0 (MPI_Init, the problem on every rank) and the plan's transfer (serialise, send, parse).
Rounds alternate threads and MPI. Run on a quiet machine: the two ranks and the two threads each want a core.

Usage: tests/benchmarks/mpi_overhead.py BIN_DIR [--seeds 5] [--mpiexec mpirun]
"""
import argparse
import os
import re
import statistics
import subprocess
import time

PROBLEMS = [("mobile_cross", 32, 0), ("mobile_cross", 128, 0), ("panda_cage", 8, 0), ("panda_cage", 16, 0), ("field", 24, 1)]


def timed(command):
    start = time.perf_counter()
    run = subprocess.run(command, capture_output=True, text=True)
    return run, time.perf_counter() - start


def number(pattern, text, default=float("nan")):
    found = re.search(pattern, text, re.M)
    return float(found.group(1)) if found else default


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("bin", help="the folder of ompl_parc_demo and ompl_parc_mpi")
    parser.add_argument("--seeds", type=int, default=5)
    parser.add_argument("--mpiexec", default="mpirun")
    parser.add_argument("--time-limit", default="60")
    args = parser.parse_args()
    mpi_flags = ["--oversubscribe", "-np", "2"] + (["--allow-run-as-root"] if os.geteuid() == 0 else [])
    print("| problem | seeds | solved threads / MPI | same runs solved (exit codes) | median solve threads / MPI (s) "
          "| median wall threads / MPI (s) | MPI start-up (s) | plan transfer (ms) |")
    print("|---|---|---|---|---|---|---|---|")
    for scenario, robots, task in PROBLEMS:
        common = ["--scenario", scenario, "--robots", str(robots), "--task", str(task), "--smooth", "0",
                  "--no-validate", "--time-limit", args.time_limit]
        rows = []
        for seed in range(1, args.seeds + 1):
            threads, threads_wall = timed([f"{args.bin}/ompl_parc_demo", *common, "--planner", "orparc", "--param",
                                           "instances=2", "--workers", "1", "--param", f"seed={seed}", "--quiet"])
            mpi, mpi_wall = timed([args.mpiexec, *mpi_flags, f"{args.bin}/ompl_parc_mpi", *common, "--workers", "1",
                                   "--param", f"seed={seed}"])
            rows.append({
                "threads_ok": threads.returncode == 0, "mpi_ok": mpi.returncode == 0,
                "threads_solve": number(r"^status .* after ([0-9.]+) s", threads.stdout),
                "mpi_solve": number(r"^status .* after ([0-9.]+) s", mpi.stdout),
                "threads_wall": threads_wall, "mpi_wall": mpi_wall,
                "startup": number(r"^start-up +([0-9.]+) s", mpi.stdout),
                # A plan made on rank 0 does not travel: no transfer to count.
                "transfer": number(r"^plan .* bytes in ([0-9.]+) s", mpi.stdout, None),
            })
        med = lambda key: statistics.median(r[key] for r in rows)
        transfers = [r["transfer"] for r in rows if r["transfer"] is not None]
        print(f"| {scenario} {robots} task {task} | 1-{args.seeds} | {sum(r['threads_ok'] for r in rows)} / "
              f"{sum(r['mpi_ok'] for r in rows)} | {all(r['threads_ok'] == r['mpi_ok'] for r in rows)} | "
              f"{med('threads_solve'):.3f} / {med('mpi_solve'):.3f} | {med('threads_wall'):.3f} / {med('mpi_wall'):.3f} | "
              f"{med('startup'):.3f} | "
              + (f"{1000 * statistics.median(transfers):.2f} ({len(transfers)} sent)" if transfers else "- (rank 0 won)")
              + " |")


if __name__ == "__main__":
    main()
