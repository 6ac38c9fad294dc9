#!/usr/bin/python3
"""VAMP-MR's planning benchmark problems (vamp-mr/vamp-mr, IROS 2026: composite RRT and CBS-PRM over VAMP's SIMD
checker) as scenario files, and ARC, P-ARC-2 and OR-P-ARC-2x1 run on them: the peer benchmark of issue 52.

The problems are VAMP-MR's three named Panda environments, with the start/goal pairs its own benchmark forms
(mr_planner_core/scripts/benchmarks/core_planning_benchmark.py as its README runs it: --pose-mode all_pairs
--max-poses 12): the first 12 named poses of the SRDF's planning group `panda_multi_arm` in its order, those in
collision left out, and every ordered pair (start, goal) of two different ones, n (n - 1) instances:

  two_rod    2 Pandas facing each other across a table with a hole under each base, each holding a rod
             (r 0.015 m, 0.5 m) across its gripper                                   (VAMP-MR env panda_two_rod)
  four       4 Pandas at the corners of a square table, facing its centre           (VAMP-MR env panda_four)
  four_bins  the same 4 Pandas 4 cm further out, 5 open bins on the table, each holding a rod (r 0.01 m, 0.3 m)
                                                                                      (VAMP-MR env panda_four_bins)

Each problem comes in two robot models: `sphere`, VAMP's own spherized Panda (KavrakiLab/vamp
resources/panda/panda_spherized.urdf: 59 spheres, the model VAMP-MR plans with, VAMP's joint limits), and `capsule`,
this project's Panda (ompl_parc/robots/models/panda.urdf: primitives in capsules with 1-2 cm of margin, Franka's joint
limits). Both have Franka's kinematics (the same joint origins), so a named pose is the same arm configuration in
both. A rod is a fixed link added to a copy of the URDF (see ROD_FRAMES for the frame it hangs on).

Only facts are taken from VAMP-MR: the numbers below, each with the file it comes from, and the named poses, read
from its SRDFs at --write-scenarios. A pose that collides under this project's checker is left out, the reason
printed and kept in poses.csv (VAMP-MR's benchmark likewise skips the poses its checker finds in collision). With the
spheres, this checker finds contacts VAMP-MR's benchmark evidently does not (it plans 132 = 12 x 11 pairs on
panda_two_rod and panda_four): on panda_four 7 of the 12 poses put a hand or finger sphere into another arm (by 0.3 to
2.2 cm; without the hand and finger spheres all 12 are free), on panda_two_rod `mirror` puts a rod into the other
arm's finger (1.2 cm). Those pairs are not in the suite.

panda_four_bins with the spheres is a knife edge: each base stands 0.14 m from the outer faces of two bin walls, and
the spheres of panda_link1 and panda_link2 that only joint 1 moves (radius 0.06 m, 0.08 m off its axis) touch those
walls exactly (clearance 0.0000 m) at four joint-1 angles per robot. This checker's safety margins (1e-6 and the
single-precision inflation, about 2e-5 m) make each such angle a thin wall joint 1 cannot cross, so only the pairs
where no robot's joint 1 has to pass one are solvable: 14 of the 132 (e.g. up -> blue), the others time out for
every planner. The capsule Panda's link 1 lies on joint 1's axis and has no such angles (ARC solved its 12
four_bins instances); its fatter links rule out other poses instead (poses.csv).

Writing the problems (needs a VAMP-MR checkout or its git directory, VAMP's spherized Panda URDF, and the demo to
check every pose; a few seconds):

  tests/benchmarks/vamp_mr_suite.py --vamp-mr ../vamp-mr --vamp-urdf ../vamp/resources/panda/panda_spherized.urdf \\
      --write-scenarios build/vamp_mr [--rod-frame flange] [--max-poses 12]

writes DIR/<problem>-<model>/<start>__<goal>.json, the URDFs they name (DIR/*.urdf, VAMP's copied, the rod
versions derived), DIR/poses.csv (every named pose, valid or why not) and DIR/instances.csv (the instances).

Running them (each run one `ompl_parc_demo` process: `--param profile=panda --smooth 0`, the plan validated;
solved = `validated  yes`):

  tests/benchmarks/vamp_mr_suite.py --scenarios build/vamp_mr [--problems two_rod,four,four_bins]
      [--models sphere,capsule] [--planners arc,parc,orparc] [--seeds 1-5] [--time-limit 60] [--every 1]
      [--jobs 1] [--csv out.csv] [--demo build/bin/ompl_parc_demo]

prints per problem, model and planner: runs solved / runs, the median and 90th percentile of the time to the first
solution over all runs (an unsolved run counts as the time limit: `>60 s` where the percentile falls on one) and the
median makespan over the straight-line lower bound (solved runs), then every unsolved run. `--every K` keeps every
K-th instance only. Runs are independent processes; with --jobs above 1 or other work on the machine the times mean
little (P-ARC-2 and OR-P-ARC-2x1 want two cores each).
"""
import argparse
import concurrent.futures
import csv
import json
import math
import os
import re
import statistics
import subprocess
import sys
import xml.etree.ElementTree as ElementTree

HERE = os.path.dirname(os.path.abspath(__file__))
DEMO = os.path.join(HERE, "..", "..", "build", "bin", "ompl_parc_demo")
CAPSULE_URDF = os.path.join(HERE, "..", "..", "ompl_parc", "robots", "models", "panda.urdf")

# The VAMP-MR commit the numbers below were read from (its files change; a checkout at another commit gets a warning).
VAMP_MR_COMMIT = "c224702f"
FACTORY = "mr_planner_core/src/backends/vamp_env_factory.cpp"


def hollow_box(cx, cy, cz, length, width, height, thickness=0.02):
    """An open bin as five boxes (position, size), as FACTORY's add_hollow_box_obstacles builds it: a bottom plate
    centred at (cx, cy, cz) and four walls of the given thickness standing on it, centred on its edges."""
    wall_z = cz + thickness / 2 + height / 2
    return [((cx, cy, cz), (length, width, thickness)),
            ((cx, cy + width / 2, wall_z), (length, thickness, height)),
            ((cx, cy - width / 2, wall_z), (length, thickness, height)),
            ((cx - length / 2, cy, wall_z), (thickness, width, height)),
            ((cx + length / 2, cy, wall_z), (thickness, width, height))]


# Table segments (x, y, z, length, width, height: a box's centre and full extents), FACTORY's
# add_panda_table_segments (panda_two, panda_two_rod): a hole 0.2 m x 0.2 m under each base.
TWO_TABLE = [(0.0, 0.0, 0.05, 0.6, 2.0, 0.1), (0.75, 0.0, 0.05, 0.5, 2.0, 0.1), (-0.75, 0.0, 0.05, 0.5, 2.0, 0.1),
             (0.4, 0.55, 0.05, 0.2, 0.9, 0.1), (0.4, -0.55, 0.05, 0.2, 0.9, 0.1),
             (-0.4, 0.55, 0.05, 0.2, 0.9, 0.1), (-0.4, -0.55, 0.05, 0.2, 0.9, 0.1)]
# FACTORY's add_panda_four_table_segments (panda_four, panda_four_bins): (x, y, length, width), z 0.05, 0.1 thick.
FOUR_TABLE = [(x, y, 0.05, length, width, 0.1) for x, y, length, width in
              [(0.0, 0.0, 2.0, 0.5), (0.0, 0.0, 0.5, 2.0), (0.77, 0.0, 0.46, 2.0), (-0.77, 0.0, 0.46, 2.0),
               (0.0, 0.77, 2.0, 0.46), (0.0, -0.77, 2.0, 0.46)]]
# FACTORY's add_environment_obstacles, panda_four_bins: five bins of 0.5 m x 0.5 m x 0.5 m (walls 0.02 m) centred at
# these points (their bottoms inside the table's top, which VAMP-MR has too).
BIN_SIZE = (0.5, 0.5, 0.5)
BIN_CENTRES = [(0.0, 0.0, 0.0), (0.5, 0.0, 0.0), (-0.5, 0.0, 0.0), (0.0, 0.5, 0.0), (0.0, -0.5, 0.0)]
# Bases (x, y, z, yaw about z), FACTORY's default_base_transforms: VampVariant::PandaPair (panda_two_rod; also
# mr_planner_core/scripts/plugins/config/panda_two_base_transforms.json) and PandaQuad (panda_four, panda_four_bins).
TWO_BASES = [(0.4, 0.0, 0.1, math.pi), (-0.4, 0.0, 0.1, 0.0)]
FOUR_YAWS = [2.28, 0.66, -0.66, -2.28]
FOUR_BASES = [(x, y, 0.1, yaw) for (x, y), yaw in zip([(0.36, -0.36), (-0.36, -0.36), (-0.36, 0.36), (0.36, 0.36)],
                                                        FOUR_YAWS)]
BINS_BASES = [(x, y, 0.1, yaw) for (x, y), yaw in zip([(0.4, -0.4), (-0.4, -0.4), (-0.4, 0.4), (0.4, 0.4)], FOUR_YAWS)]
# Rods, FACTORY's add_environment_attachments: (radius, length) on every robot, a cylinder along its local z turned by
# rpy (0, pi/2, 0) (so along the frame's x) and shifted (0, 0, -0.005) from VAMP's end effector frame. VAMP-MR covers a
# cylinder 1 % longer with spheres (vamp_instance.h, makeAttachmentFromObject); ours is the capsule within that
# cylinder: a URDF cylinder becomes the capsule of its radius around its axis, so its axis is 1.01 length - 2 radius.
PROBLEMS = {
    "two_rod": {"env": "panda_two_rod", "table": TWO_TABLE, "bins": [], "bases": TWO_BASES, "rod": (0.015, 0.5)},
    "four": {"env": "panda_four", "table": FOUR_TABLE, "bins": [], "bases": FOUR_BASES, "rod": None},
    "four_bins": {"env": "panda_four_bins", "table": FOUR_TABLE, "bins": BIN_CENTRES, "bases": BINS_BASES,
                  "rod": (0.01, 0.3)},
}
# The end effector frame the rod hangs on, as (parent link, offset along its z) for our URDFs: "flange" is
# panda_link8's axes 0.1 m along its z, "grasptarget" the frame of VAMP's published Panda::eefk (KavrakiLab/vamp
# src/impl/vamp/robots/panda.hh, end_effector "panda_grasptarget": panda_hand, turned -pi/4 about z from
# panda_link8, 0.105 m on) moved 0.005 m back: the same point, the rod turned by 45 degrees about the flange's axis.
# VAMP-MR builds on a fork of VAMP (philip-huang/vamp, branch vamp-mr; not public here) whose end effector frame
# could not be read. The named poses were evidently made for "flange" (the default): with it every rod of the 24 named
# poses clears the table, the bins, the other rods and the other arms (but for one finger, see above); with
# "grasptarget" 5 of the 12 two_rod poses and 5 of the 12 four_bins poses put a rod into another arm, the other rod or
# a bin wall (VAMP-MR's 132 pairs on panda_two_rod rule that out for its checker).
ROD_FRAMES = {"flange": {"sphere": ("panda_link8", 0.1), "capsule": ("panda_link8", 0.1)},
              "grasptarget": {"sphere": ("panda_grasptarget", -0.005), "capsule": ("panda_hand", 0.1)}}
# The order in which core_planning_benchmark.py takes the named poses (preferred_pose_names, then the SRDF's other
# group states of MOVE_GROUP in document order); with its README's --max-poses 12 it plans between the first 12 valid.
PREFERRED = {
    "panda_two_rod": ["ready_pose", "twist_left", "twist_right", "mirror", "mirror_down", "left_push", "right_push",
                      "coop_up", "coop_down", "tiled_up", "tiled_down", "left_up"],
    "panda_four": ["ready", "down", "front", "back", "up_and_down", "front_and_back", "left_and_right", "center",
                   "tiled_mess", "tiled_clean", "up"],
    "panda_four_bins": ["up", "four_bins_1", "four_bins_2", "three_bins_1", "three_bins_2", "three_bins_3",
                        "purple_yellow_1", "purple_yellow_2", "red_green", "blue", "red", "ready_pose"],
}
MODELS = ["sphere", "capsule"]
MOVE_GROUP = "panda_multi_arm"  # VAMP-MR's move_group of the Panda environments (FACTORY's make_environment_config)
PLANNERS = {"arc": ["--planner", "arc"],
            "parc": ["--planner", "parc", "--workers", "2"],
            "orparc": ["--planner", "orparc", "--param", "instances=2", "--param", "workers=1"]}
LABELS = {"arc": "ARC", "parc": "P-ARC-2", "orparc": "OR-P-ARC-2x1"}


# ---- reading VAMP-MR ------------------------------------------------------------------------------------------------

def read_vamp_mr(root, path):
    """The text of \a path in VAMP-MR: \a root is a checkout (a folder holding mr_planner_core) or a git directory
    (bare or .git; its HEAD is read)."""
    if os.path.isdir(os.path.join(root, "mr_planner_core")):
        with open(os.path.join(root, path), encoding="utf-8") as f:
            return f.read()
    return subprocess.run(["git", "--git-dir", root, "show", "HEAD:" + path], check=True, capture_output=True,
                          text=True).stdout


def vamp_mr_commit(root):
    """VAMP-MR's HEAD commit, or None where it cannot be read (a folder without git)."""
    args = ["git", "-C", root] if os.path.isdir(os.path.join(root, "mr_planner_core")) else ["git", "--git-dir", root]
    run = subprocess.run(args + ["rev-parse", "HEAD"], capture_output=True, text=True)
    return run.stdout.strip() if run.returncode == 0 else None


def named_poses(srdf_text, robots):
    """The SRDF's group states of MOVE_GROUP in document order, as core_planning_benchmark.py reads them (one
    group_state per name, the first kept): name -> per robot the values of panda<k>_joint1..7."""
    poses = {}
    for state in ElementTree.fromstring(srdf_text).iter("group_state"):
        if state.get("group") != MOVE_GROUP or state.get("name") in poses:
            continue
        values = {j.get("name"): float(j.get("value")) for j in state.iter("joint")}
        poses[state.get("name")] = [[values[f"panda{k}_joint{j}"] for j in range(1, 8)] for k in range(robots)]
    return poses


# ---- writing the problems -------------------------------------------------------------------------------------------

def with_rod(urdf_text, parent, origin_z, rod):
    """\a urdf_text with the rod as a link fixed to \a parent, centred origin_z along the parent's z, its axis along
    the parent's x (a cylinder's axis is its local z, turned by pitch pi/2)."""
    radius, length = rod
    axis = 1.01 * length - 2 * radius
    extra = (f'  <link name="rod">\n    <collision>\n      <origin xyz="0 0 0" rpy="0 0 0"/>\n'
             f'      <geometry><cylinder radius="{radius:g}" length="{axis:g}"/></geometry>\n    </collision>\n'
             f'  </link>\n  <joint name="rod_joint" type="fixed">\n    <parent link="{parent}"/>\n'
             f'    <child link="rod"/>\n    <origin xyz="0 0 {origin_z:g}" rpy="0 {math.pi / 2!r} 0"/>\n  </joint>\n')
    end = urdf_text.rindex("</robot>")
    return urdf_text[:end] + extra + urdf_text[end:]


def write_urdfs(out, vamp_urdf, rod_frame):
    """Writes the URDFs the scenario files name; returns {(model, rod): file name, or None for the built-in}."""
    with open(vamp_urdf, encoding="utf-8") as f:
        texts = {"sphere": f.read()}
    if texts["sphere"].count("<sphere") != 59 or 'name="panda_grasptarget"' not in texts["sphere"]:
        raise SystemExit(f"vamp_mr_suite.py: {vamp_urdf} is not VAMP's spherized Panda (59 spheres, panda_grasptarget)")
    with open(CAPSULE_URDF, encoding="utf-8") as f:
        texts["capsule"] = f.read()
    files = {("sphere", None): "panda_spherized.urdf", ("capsule", None): None}
    written = {"panda_spherized.urdf": texts["sphere"]}
    for rod in {p["rod"] for p in PROBLEMS.values() if p["rod"]}:
        for model, prefix in [("sphere", "panda_spherized"), ("capsule", "panda_capsules")]:
            files[(model, rod)] = f"{prefix}_rod_{rod[0]:g}_{rod[1]:g}_{rod_frame}.urdf"
            written[files[(model, rod)]] = with_rod(texts[model], *ROD_FRAMES[rod_frame][model], rod)
    for name, text in written.items():
        with open(os.path.join(out, name), "w", encoding="utf-8") as f:
            f.write(text)
    return files


def scenario(name, problem, urdf, starts, goals):
    """A scenario file's JSON text (one obstacle or robot a line)."""
    obstacles = [{"name": f"table_segment_{i}", "shape": "box", "size": [l, w, h], "position": [x, y, z]}
                 for i, (x, y, z, l, w, h) in enumerate(problem["table"])]
    for b, centre in enumerate(problem["bins"]):
        for part, (position, size) in zip(["bottom", "front", "back", "left", "right"], hollow_box(*centre, *BIN_SIZE)):
            obstacles.append({"name": f"bin_{b}_{part}", "shape": "box", "size": list(size),
                              "position": list(position)})
    robots = []
    for k, (x, y, z, yaw) in enumerate(problem["bases"]):
        robot = {"name": f"panda{k}", "kind": "urdf_arm"}
        robot.update({"urdf_file": "../" + urdf} if urdf else {"builtin_urdf": "panda"})
        robot.update({"base_link": "panda_link0", "tip_link": "panda_hand",
                      "base_pose": {"position": [x, y, z], "orientation": [math.cos(yaw / 2), 0, 0, math.sin(yaw / 2)]},
                      "start": starts[k], "goal": goals[k]})
        robots.append(robot)
    lines = [f'{{"format": "ompl_parc.scenario", "version": 1, "name": {json.dumps(name)}, "resolution": 128,',
             ' "obstacles": [']
    lines += ["  " + json.dumps(o) + ("," if i + 1 < len(obstacles) else "") for i, o in enumerate(obstacles)]
    lines += [" ],", ' "robots": [']
    lines += ["  " + json.dumps(r) + ("," if i + 1 < len(robots) else "") for i, r in enumerate(robots)]
    lines += [" ]}", ""]
    return "\n".join(lines)


def check_pose(demo, path):
    """None if the demo accepts the scenario at \a path (start = goal = the pose), else its one-line reason."""
    run = subprocess.run([demo, "--scenario-file", path, "--param", "profile=panda", "--smooth", "0", "--quiet",
                          "--time-limit", "10"], capture_output=True, text=True)
    if run.returncode == 0 and "validated  yes" in run.stdout:
        return None
    return (run.stderr.strip() or run.stdout.strip()).splitlines()[-1] if (run.stderr or run.stdout) else \
        f"exit status {run.returncode}"


def write_scenarios(args):
    out = args.write_scenarios
    os.makedirs(out, exist_ok=True)
    commit = vamp_mr_commit(args.vamp_mr)
    if commit and not commit.startswith(VAMP_MR_COMMIT):
        print(f"vamp_mr_suite.py: warning: VAMP-MR is at {commit[:8]}; the environments in this script were read at "
              f"{VAMP_MR_COMMIT} ({FACTORY})", file=sys.stderr)
    urdfs = write_urdfs(out, args.vamp_urdf, args.rod_frame)
    pose_rows, instance_rows = [], []
    for problem_name in args.problems.split(","):
        problem = PROBLEMS[problem_name]
        srdf = f"mr_planner_core/config/srdf/{problem['env']}.srdf"
        poses = named_poses(read_vamp_mr(args.vamp_mr, srdf), len(problem["bases"]))
        order = [p for p in PREFERRED[problem["env"]] if p in poses] + \
            [p for p in poses if p not in PREFERRED[problem["env"]]]
        order = order[:args.max_poses] if args.max_poses > 0 else order
        for model in args.models.split(","):
            folder = f"{problem_name}-{model}"
            os.makedirs(os.path.join(out, folder), exist_ok=True)
            urdf = urdfs[(model, problem["rod"])]
            valid = []
            for pose in order:
                path = os.path.join(out, folder, f"pose_{pose}.json")
                with open(path, "w", encoding="utf-8") as f:
                    f.write(scenario(f"vamp_mr_{folder}_{pose}", problem, urdf, poses[pose], poses[pose]))
                reason = check_pose(args.demo, path)
                os.remove(path)
                pose_rows.append({"problem": problem_name, "model": model, "pose": pose, "valid": reason is None,
                                  "reason": reason or "", "source": srdf})
                if reason is None:
                    valid.append(pose)
                elif "fixed to the base" in reason:  # no configuration at all is valid at these bases
                    print(f"{folder}: no instances: {reason}")
                    break
                else:
                    print(f"{folder}: pose '{pose}' left out: {reason}")
            for start in valid:
                for goal in valid:
                    if start == goal:
                        continue
                    name = f"{start}__{goal}"
                    with open(os.path.join(out, folder, name + ".json"), "w", encoding="utf-8") as f:
                        f.write(scenario(f"vamp_mr_{folder}_{name}", problem, urdf, poses[start], poses[goal]))
                    instance_rows.append({"problem": problem_name, "model": model, "start": start, "goal": goal,
                                          "file": os.path.join(folder, name + ".json")})
            print(f"{folder}: {len(valid)} of {len(order)} named poses valid, "
                  f"{len(valid) * (len(valid) - 1)} instances in {os.path.join(out, folder)}")
    for name, rows in [("poses.csv", pose_rows), ("instances.csv", instance_rows)]:
        with open(os.path.join(out, name), "w", newline="", encoding="utf-8") as f:
            writer = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
            writer.writeheader()
            writer.writerows(rows)


# ---- running them ---------------------------------------------------------------------------------------------------

def run(demo, folder, instance, planner, seed, limit):
    command = [demo, "--scenario-file", os.path.join(folder, instance["file"]), "--param", "profile=panda",
               "--smooth", "0", "--seed", str(seed), "--time-limit", str(limit), "--quiet"] + PLANNERS[planner]
    done = subprocess.run(command, capture_output=True, text=True)
    out = done.stdout
    row = dict(instance, planner=planner, seed=seed, exit=done.returncode, solved="validated  yes" in out)
    if row["solved"]:
        row["seconds"] = float(re.search(r"status\s+Exact solution after ([0-9.]+) s", out).group(1))
        row["makespan_ratio"] = float(re.search(r"makespan\s+\d+ timesteps.*?([0-9.]+)x the lower bound", out).group(1))
        row["soc_ratio"] = float(re.search(r"sum costs\s+\d+ timesteps, ([0-9.]+)x the lower bound", out).group(1))
    else:
        status = re.search(r"status\s+(.*)", out)
        row["status"] = status.group(1) if status else (done.stderr.strip().splitlines() or [""])[-1]
    return row


def percentile(values, q):
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, int(round(q * (len(ordered) - 1))))]


def seconds(value, limit):
    if math.isinf(value):
        return f">{limit:g} s"
    return f"{value * 1e3:.1f} ms" if value < 1 else f"{value:.2f} s"


def run_suite(args):
    with open(os.path.join(args.scenarios, "instances.csv"), newline="", encoding="utf-8") as f:
        instances = [r for r in csv.DictReader(f)
                     if r["problem"] in args.problems.split(",") and r["model"] in args.models.split(",")]
    instances = instances[::args.every]
    first, _, last = args.seeds.partition("-")
    seeds = range(int(first), int(last or first) + 1)
    planners = args.planners.split(",")
    for planner in planners:
        if planner not in PLANNERS:
            raise SystemExit(f"vamp_mr_suite.py: unknown planner '{planner}' (valid: {', '.join(PLANNERS)})")
    runs = [(i, p, s) for i in instances for p in planners for s in seeds]
    print(f"{len(instances)} instances x {len(planners)} planners x {len(seeds)} seeds = {len(runs)} runs",
          flush=True)
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        rows = list(pool.map(lambda r: run(args.demo, args.scenarios, *r, args.time_limit), runs))
    if args.csv:
        with open(args.csv, "w", newline="", encoding="utf-8") as f:
            writer = csv.DictWriter(f, fieldnames=["problem", "model", "start", "goal", "planner", "seed", "exit",
                                                   "solved", "seconds", "makespan_ratio", "soc_ratio", "status"],
                                    extrasaction="ignore")
            writer.writeheader()
            writer.writerows(rows)
    print(f"{'problem':10} {'model':8} {'planner':13} {'solved':>9} {'median':>10} {'p90':>10} {'makespan':>9}")
    for problem in args.problems.split(","):
        for model in args.models.split(","):
            for planner in planners:
                mine = [r for r in rows if r["problem"] == problem and r["model"] == model and r["planner"] == planner]
                if not mine:
                    continue
                good = [r for r in mine if r["solved"]]
                times = [r["seconds"] if r["solved"] else math.inf for r in mine]
                ratio = f"{statistics.median(r['makespan_ratio'] for r in good):.2f}x" if good else "-"
                print(f"{problem:10} {model:8} {LABELS[planner]:13} {len(good):>4}/{len(mine):<4} "
                      f"{seconds(percentile(times, 0.5), args.time_limit):>10} "
                      f"{seconds(percentile(times, 0.9), args.time_limit):>10} {ratio:>9}")
    for r in rows:
        if not r["solved"]:
            print(f"not solved: {r['file']} {r['planner']} seed {r['seed']}: {r.get('status', '')}")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--write-scenarios", metavar="DIR", help="write the problems to DIR")
    parser.add_argument("--vamp-mr", help="VAMP-MR: a checkout or its git directory (for --write-scenarios)")
    parser.add_argument("--vamp-urdf", help="VAMP's resources/panda/panda_spherized.urdf (for --write-scenarios)")
    parser.add_argument("--rod-frame", choices=list(ROD_FRAMES), default="flange",
                        help="the frame the rods hang on (for --write-scenarios; see ROD_FRAMES)")
    parser.add_argument("--max-poses", type=int, default=12,
                        help="the first K named poses in VAMP-MR's order (its README's --max-poses 12; 0: all)")
    parser.add_argument("--scenarios", metavar="DIR", help="run the problems written to DIR")
    parser.add_argument("--problems", default=",".join(PROBLEMS))
    parser.add_argument("--models", default=",".join(MODELS))
    parser.add_argument("--planners", default="arc,parc,orparc")
    parser.add_argument("--seeds", default="1-5")
    parser.add_argument("--time-limit", type=float, default=60.)
    parser.add_argument("--every", type=int, default=1, help="keep every K-th instance")
    parser.add_argument("--jobs", type=int, default=1)
    parser.add_argument("--csv")
    parser.add_argument("--demo", default=DEMO)
    args = parser.parse_args()
    for problem in args.problems.split(","):
        if problem not in PROBLEMS:
            parser.error(f"unknown problem '{problem}' (valid: {', '.join(PROBLEMS)})")
    for model in args.models.split(","):
        if model not in MODELS:
            parser.error(f"unknown model '{model}' (valid: {', '.join(MODELS)})")
    if args.every < 1 or args.jobs < 1 or not args.time_limit > 0 or args.max_poses < 0:
        parser.error("--every and --jobs must be at least 1, --time-limit positive and --max-poses at least 0")
    if not re.fullmatch(r"[0-9]+(-[0-9]+)?", args.seeds):
        parser.error(f"--seeds must be N or N-M, not '{args.seeds}'")
    if args.write_scenarios and args.vamp_urdf and not os.path.isfile(args.vamp_urdf):
        parser.error(f"no file {args.vamp_urdf} (--vamp-urdf: VAMP's resources/panda/panda_spherized.urdf)")
    if args.write_scenarios and args.vamp_mr and not os.path.isdir(args.vamp_mr):
        parser.error(f"no folder {args.vamp_mr} (--vamp-mr: a VAMP-MR checkout or its git directory)")
    if args.scenarios and not args.write_scenarios and \
            not os.path.isfile(os.path.join(args.scenarios, "instances.csv")):
        listed = os.path.join(args.scenarios, "instances.csv")
        parser.error(f"no {listed}: write the problems first (--write-scenarios)")
    if not args.write_scenarios and not args.scenarios:
        parser.error("give --write-scenarios DIR (with --vamp-mr and --vamp-urdf), --scenarios DIR, or both")
    if args.write_scenarios:
        if not args.vamp_mr or not args.vamp_urdf:
            parser.error("--write-scenarios needs --vamp-mr and --vamp-urdf")
        write_scenarios(args)
    if args.scenarios:
        run_suite(args)


if __name__ == "__main__":
    main()
