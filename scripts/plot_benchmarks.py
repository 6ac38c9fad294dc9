#!/usr/bin/python3
"""Turn ompl_parc_benchmark CSVs into the P-ARC paper's views (Section IV):

  speedup.png     heatmap of P-ARC's median-time speedup over ARC, per scenario size x workers
  success.png     cumulative success over wall-clock time, one panel per scenario size, one line per planner
  summary.md      Markdown table: median time of successful runs, success rate and speedup vs ARC

Medians are over successful runs only (as in the paper); a cell is empty when a planner solved nothing.
Usage: scripts/plot_benchmarks.py [--out FOLDER] RESULTS.csv...
(Debian's /usr/bin/python3 with python3-matplotlib, from scripts/setup.sh)
"""
import argparse
import collections
import csv
import os
import statistics

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402 (the backend must be chosen first)


def read_runs(paths):
    runs = []
    for path in paths:
        with open(path, newline="") as f:
            for row in csv.DictReader(f):
                row["robots"] = int(row["robots"])
                row["workers"] = int(row["workers"])
                row["success"] = row["success"] == "1"
                row["time"] = float(row["time"])
                runs.append(row)
    return runs


def problem_key(run):
    return (run["scenario"], run["robots"])


def problem_label(key):
    return f"{key[0].replace('_', ' ')} {key[1]}"


def median_time(runs):
    times = [r["time"] for r in runs if r["success"]]
    return statistics.median(times) if times else None


def group(runs):
    """{problem: {planner: [runs]}} with planners in first-seen order."""
    table = collections.OrderedDict()
    for r in runs:
        table.setdefault(problem_key(r), collections.OrderedDict()).setdefault(r["planner"], []).append(r)
    return collections.OrderedDict(sorted(table.items()))


def arc_median(planners):
    arc = [runs for runs in planners.values() if runs[0]["type"] == "arc"]
    return median_time(arc[0]) if arc else None


def speedup_heatmap(table, path):
    problems = list(table)
    workers = sorted({r["workers"] for p in table.values() for runs in p.values() for r in runs
                      if r["type"] == "parc"})
    if not problems or not workers:
        return False
    values = [[float("nan")] * len(workers) for _ in problems]
    labels = [[""] * len(workers) for _ in problems]
    for i, key in enumerate(problems):
        base = arc_median(table[key])
        for runs in table[key].values():
            if runs[0]["type"] != "parc" or base is None:
                continue
            m = median_time(runs)
            if m:
                j = workers.index(runs[0]["workers"])
                values[i][j] = base / m
                labels[i][j] = f"{m:.3g} s\n{base / m:.2f}x"
    fig, ax = plt.subplots(figsize=(1.6 * len(workers) + 2, 0.8 * len(problems) + 1.5))
    finite = [v for row in values for v in row if v == v]
    image = ax.imshow(values, cmap="RdYlGn", vmin=0., vmax=max([2.] + finite))
    ax.set_xticks(range(len(workers)), [f"W={w}" for w in workers])
    ax.set_yticks(range(len(problems)), [problem_label(k) for k in problems])
    for i in range(len(problems)):
        for j in range(len(workers)):
            ax.text(j, i, labels[i][j], ha="center", va="center", fontsize=8)
    ax.set_title("P-ARC median-runtime speedup over ARC")
    fig.colorbar(image, ax=ax, label="speedup")
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return True


def success_curves(table, path):
    problems = list(table)
    fig, axes = plt.subplots(1, len(problems), figsize=(4 * len(problems), 3.5), squeeze=False)
    for ax, key in zip(axes[0], problems):
        for name, runs in table[key].items():
            times = sorted(r["time"] for r in runs if r["success"])
            xs, ys = [0.], [0.]
            for k, t in enumerate(times, 1):
                xs += [t, t]
                ys += [ys[-1], k / len(runs)]
            xs.append(max([r["time"] for r in runs] + xs))
            ys.append(ys[-1])
            ax.plot(xs, ys, label=name)
        ax.set_xscale("symlog", linthresh=0.01)
        ax.set_ylim(0, 1.05)
        ax.set_title(problem_label(key))
        ax.set_xlabel("wall-clock time (s)")
    axes[0][0].set_ylabel("cumulative success")
    axes[0][-1].legend(fontsize=7, loc="lower right")
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def markdown(table):
    problems = list(table)
    planners = list(collections.OrderedDict((n, None) for p in table.values() for n in p))
    lines = ["| Planner | " + " | ".join(problem_label(k) for k in problems) + " |",
             "|---|" + "---|" * len(problems)]
    for name in planners:
        cells = []
        for key in problems:
            runs = table[key].get(name)
            if not runs:
                cells.append("")
                continue
            m, base = median_time(runs), arc_median(table[key])
            rate = f"{sum(r['success'] for r in runs)}/{len(runs)}"
            if m is None:
                cells.append(f"– ({rate})")
            else:
                speed = f", {base / m:.2f}x" if base and runs[0]["type"] != "arc" else ""
                cells.append(f"{m:.3g} s ({rate}{speed})")
        lines.append(f"| {name} | " + " | ".join(cells) + " |")
    return "\n".join(lines) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("csv", nargs="+", help="CSV files written by ompl_parc_benchmark")
    parser.add_argument("--out", default=".", help="folder for speedup.png, success.png and summary.md")
    args = parser.parse_args()
    table = group(read_runs(args.csv))
    os.makedirs(args.out, exist_ok=True)
    if not speedup_heatmap(table, os.path.join(args.out, "speedup.png")):
        print("no ARC/P-ARC runs: speedup.png skipped")
    success_curves(table, os.path.join(args.out, "success.png"))
    text = markdown(table)
    with open(os.path.join(args.out, "summary.md"), "w") as f:
        f.write(text)
    print(text, end="")


if __name__ == "__main__":
    main()
