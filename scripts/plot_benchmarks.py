#!/usr/bin/python3
"""Turn benchmark CSVs into the P-ARC paper's views (Section IV):

  speedup.png     heatmap of P-ARC's median-time speedup over ARC, per problem (case) x workers
  success.png     cumulative success over wall-clock time, one panel per problem, one line per planner
  summary.md      Markdown table: median time of successful runs, success rate and speedup vs ARC

Reads the CSVs ompl_parc_benchmark writes and the P-ARC authors' results.csv alike: problems are grouped by
`case` (labelled by `case_title` when there is one), planners by `method`; a run's time is planning_time_seconds,
or first_solution_time_seconds where that column is missing or empty (the authors' files); success is 1/0 or
True/False. Without `type`/`workers` columns (the authors' files) the method names them: ARC -> arc,
P-ARC-<W> or PARC-<W> -> parc with W workers, any other -> its own name with 1 worker.

Medians are over successful runs only (as in the paper); a planner that solved nothing has none ("–" in
summary.md, an empty heatmap cell).
A speedup over ARC is plain only when the planner solved as many runs as ARC; otherwise it is marked "†"
(the two medians are then over different runs).
Usage: scripts/plot_benchmarks.py [--out FOLDER] RESULTS.csv...
(Debian's /usr/bin/python3 with python3-matplotlib, from scripts/setup.sh; another python3 without matplotlib
hands over to it, or exits 2 when it is not there)
"""
import argparse
import collections
import csv
import math
import os
import re
import statistics
import sys

from debian_matplotlib import pyplot

plt = pyplot()

DIFFERENT_RUNS = "† solved a different number of runs than ARC: the speedup compares medians over different runs"


def fail(message):
    print("plot_benchmarks.py: " + message, file=sys.stderr)
    sys.exit(2)


def cell(row, *names):
    """The first non-empty cell among the columns `names`, or None."""
    for name in names:
        if row.get(name):
            return row[name]
    return None


def infer_planner(method):
    """(type, workers) from a method name, for files without those columns."""
    if method.lower() == "arc":
        return "arc", 1
    match = re.fullmatch(r"p-?arc-(\d+)", method, re.IGNORECASE)
    if match:
        return "parc", int(match.group(1))
    return method, 1


def read_runs(paths):
    runs = []
    for path in paths:
        with open(path, newline="") as f:
            reader = csv.DictReader(f)
            missing = {"case", "method", "success"} - set(reader.fieldnames or [])
            if missing:
                fail(f"{path} has no column {', '.join(sorted(missing))} (not a benchmark CSV of this format)")
            for line, row in enumerate(reader, 2):
                where = f"{path}:{line}"
                success = (row["success"] or "").lower()
                if not row["case"] or not row["method"] or success not in ("1", "0", "true", "false"):
                    fail(f"{where}: needs a case, a method and a success of 1/0 or True/False")
                time = cell(row, "planning_time_seconds", "first_solution_time_seconds")
                kind, workers = infer_planner(row["method"])
                runs.append({
                    "case": row["case"],
                    "label": row.get("case_title") or row["case"].replace("_", " "),
                    "planner": row["method"],
                    "type": row.get("type") or kind,
                    "workers": int(row.get("workers") or workers),
                    "success": success in ("1", "true"),
                    "time": float(time) if time else None,
                    "limit": float(row["time_limit_seconds"]) if row.get("time_limit_seconds") else None,
                })
                if runs[-1]["success"] and runs[-1]["time"] is None:
                    fail(f"{where}: a solved run without a time")
    return runs


def natural(text):
    """Sort key that puts mobile_cross_8 before mobile_cross_16."""
    return [int(part) if part.isdigit() else part for part in re.split(r"(\d+)", text)]


def median_time(runs):
    times = [r["time"] for r in runs if r["success"]]
    return statistics.median(times) if times else None


def solved(runs):
    return sum(r["success"] for r in runs)


def group(runs):
    """{case: {planner: [runs]}} with cases in natural order, planners in first-seen order; and the labels."""
    table, labels = {}, {}
    for r in runs:
        table.setdefault(r["case"], collections.OrderedDict()).setdefault(r["planner"], []).append(r)
        labels.setdefault(r["case"], r["label"])
    return collections.OrderedDict((k, table[k]) for k in sorted(table, key=natural)), labels


def arc_runs(planners):
    arc = [runs for runs in planners.values() if runs[0]["type"] == "arc"]
    return arc[0] if arc else None


def speedup(runs, planners):
    """(speedup over ARC, mark) with mark "†" when the two solved different numbers of runs; None if none."""
    base, m = arc_runs(planners), median_time(runs)
    if base is None or median_time(base) is None or m is None:
        return None
    return median_time(base) / m, ("" if solved(runs) == solved(base) else "†")


def speedup_heatmap(table, labels, path):
    problems = list(table)
    workers = sorted({r["workers"] for p in table.values() for runs in p.values() for r in runs
                      if r["type"] == "parc"})
    if not problems or not workers:
        return False
    values = [[float("nan")] * len(workers) for _ in problems]
    texts = [[""] * len(workers) for _ in problems]
    marked = False
    for i, key in enumerate(problems):
        for runs in table[key].values():
            s = speedup(runs, table[key]) if runs[0]["type"] == "parc" else None
            if s:
                j = workers.index(runs[0]["workers"])
                values[i][j] = s[0]
                texts[i][j] = f"{median_time(runs):.3g} s\n{s[0]:.2f}x{s[1]}"
                marked = marked or bool(s[1])
    fig, ax = plt.subplots(figsize=(1.6 * len(workers) + 3, 0.8 * len(problems) + 1.5), layout="constrained")
    finite = [v for row in values for v in row if not math.isnan(v)]
    image = ax.imshow(values, cmap="RdYlGn", vmin=0., vmax=max([2.] + finite))
    ax.set_xticks(range(len(workers)), [f"W={w}" for w in workers])
    ax.set_yticks(range(len(problems)), [labels[k] for k in problems])
    for i in range(len(problems)):
        for j in range(len(workers)):
            ax.text(j, i, texts[i][j], ha="center", va="center", fontsize=8)
    ax.set_title("P-ARC median-runtime speedup over ARC")
    fig.colorbar(image, ax=ax, label="speedup")
    if marked:
        fig.text(0.01, 0, DIFFERENT_RUNS, ha="left", va="top", fontsize=7)
    fig.savefig(path, dpi=120, bbox_inches="tight")
    plt.close(fig)
    return True


def success_curves(table, labels, path):
    problems = list(table)
    columns = min(4, len(problems))
    rows = -(-len(problems) // columns)
    fig, axes = plt.subplots(rows, columns, figsize=(4 * columns, 3.2 * rows), squeeze=False, layout="constrained")
    for ax, key in zip([ax for row in axes for ax in row], problems):
        for name, runs in table[key].items():
            times = sorted(r["time"] for r in runs if r["success"])
            xs, ys = [0.], [0.]
            for k, t in enumerate(times, 1):
                xs += [t, t]
                ys += [ys[-1], k / len(runs)]
            xs.append(max([r["time"] or r["limit"] or 0. for r in runs] + xs))
            ys.append(ys[-1])
            ax.plot(xs, ys, label=name)
        ax.set_xscale("symlog", linthresh=0.01)
        ax.set_ylim(0, 1.05)
        ax.set_title(labels[key], fontsize=10)
        ax.legend(fontsize=6, loc="upper left")
    for ax in [ax for row in axes for ax in row][len(problems):]:
        ax.set_visible(False)
    fig.supxlabel("wall-clock time (s)")
    fig.supylabel("cumulative success")
    fig.savefig(path, dpi=120, bbox_inches="tight")
    plt.close(fig)


def markdown(table, labels):
    problems = list(table)
    planners = list(collections.OrderedDict((n, None) for p in table.values() for n in p))
    lines = ["| Planner | " + " | ".join(labels[k] for k in problems) + " |",
             "|---|" + "---|" * len(problems)]
    marked = False
    for name in planners:
        cells = []
        for key in problems:
            runs = table[key].get(name)
            if not runs:
                cells.append("")
                continue
            m = median_time(runs)
            rate = f"{solved(runs)}/{len(runs)}"
            s = speedup(runs, table[key]) if runs[0]["type"] != "arc" else None
            marked = marked or bool(s and s[1])
            if m is None:
                cells.append(f"– ({rate})")
            else:
                cells.append(f"{m:.3g} s ({rate}" + (f", {s[0]:.2f}x{s[1]}" if s else "") + ")")
        lines.append(f"| {name} | " + " | ".join(cells) + " |")
    if marked:
        lines += ["", DIFFERENT_RUNS]
    return "\n".join(lines) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("csv", nargs="+", help="CSV files written by ompl_parc_benchmark or the P-ARC authors")
    parser.add_argument("--out", default=".", help="folder for speedup.png, success.png and summary.md")
    args = parser.parse_args()
    for path in args.csv:
        if not os.path.isfile(path):
            fail(f"no file {path}")
    table, labels = group(read_runs(args.csv))
    if not table:
        fail("no runs in " + " ".join(args.csv))
    os.makedirs(args.out, exist_ok=True)
    if not speedup_heatmap(table, labels, os.path.join(args.out, "speedup.png")):
        print("no ARC/P-ARC runs: speedup.png skipped")
    success_curves(table, labels, os.path.join(args.out, "success.png"))
    text = markdown(table, labels)
    with open(os.path.join(args.out, "summary.md"), "w") as f:
        f.write(text)
    print(text, end="")


if __name__ == "__main__":
    main()
