"""ompl_parc from Python: multi-robot motion planning with ARC, P-ARC, OR-P-ARC and the paper's baselines on OMPL.

    import ompl_parc
    problem = ompl_parc.scenario("mobile_cross", robots=8)
    result = ompl_parc.solve(problem, "parc", workers=2, seed=1, time_limit=30)
    if result.solved:
        print(result.plan.makespan, ompl_parc.validate(problem, result.plan).valid)
        times, configs = result.plan.waypoints(0)   # robot 0: timesteps and configurations (NumPy)

Problems come from the built-in scenarios (scenario()), scenario files (load()) or a team built here (team() with
disc(), planar_arm(), urdf_arm() and the obstacles box(), box2d(), sphere(), cylinder(), mesh()). Bad input raises
ValueError with the same one-line message the command-line tools print.
"""
import csv as _csv
import json as _json
import os as _os
import warnings as _warnings
from typing import Any, Dict, List, Optional, Sequence, Union

from ._ompl_parc import OMPL_VERSION, Plan, Problem, SolveResult, Validation, __version__
from ._ompl_parc import planner_names, planner_parameters, read_solution, scenario_names, write_html, write_solution, write_svg
from . import _ompl_parc

__all__ = ["OMPL_VERSION", "Plan", "Problem", "SolveResult", "Validation", "__version__", "box", "box2d",
           "cylinder", "disc", "load", "planar_arm", "planner_names", "planner_parameters", "read_solution", "run_benchmark", "scenario",
           "scenario_names", "set_log_level", "solve", "sphere", "team", "urdf_arm", "validate", "write_solution",
           "write_html", "write_svg", "time_parameterize", "read_trajectory", "write_trajectory"]


def scenario(name: str, robots: int, task: int = 0, resolution: float = 128.0) -> Problem:
    """A built-in scenario (scenario_names(): mobile_cross, mobile_circle, planar_cross, panda_cage, and the generated
    families rooms, crossing, ring, field, planar_cell, panda_cell) with \\p robots robots; \\p task picks a Panda Cage
    task or a family's random instance; \\p resolution is timesteps per unit of distance."""
    return Problem.scenario(name, robots, task, resolution)


def load(path: str) -> Problem:
    """A problem from a scenario file (JSON, "format": "ompl_parc.scenario"); Problem.save(path) writes one."""
    return Problem.load(path)


def _pose(position: Sequence[float], orientation: Sequence[float]) -> Dict[str, Any]:
    return {"position": list(position), "orientation": list(orientation)}


def disc(name: str, radius: float, start: Sequence[float], goal: Sequence[float], low: Sequence[float] = (-10, -10),
         high: Sequence[float] = (10, 10)) -> Dict[str, Any]:
    """A disc robot moving in the plane within the box [low, high]; start and goal are (x, y)."""
    return {"name": name, "kind": "disc", "radius": radius, "bounds": {"low": list(low), "high": list(high)},
            "start": list(start), "goal": list(goal)}


def planar_arm(name: str, link_lengths: Sequence[float], start: Sequence[float], goal: Sequence[float],
               base: Sequence[float] = (0, 0, 0), link_width: float = 0.1, low: Optional[Sequence[float]] = None,
               high: Optional[Sequence[float]] = None) -> Dict[str, Any]:
    """A planar arm with its base at (x, y, yaw), revolute joints limited to [low, high] (default [-pi, pi])."""
    n = len(link_lengths)
    low = list(low) if low is not None else [-3.14159] * n
    high = list(high) if high is not None else [3.14159] * n
    return {"name": name, "kind": "planar_arm", "base": {"x": base[0], "y": base[1], "yaw": base[2]},
            "link_lengths": list(link_lengths), "link_width": link_width, "joint_limits": {"low": low, "high": high},
            "start": list(start), "goal": list(goal)}


def urdf_arm(name: str, start: Sequence[float], goal: Sequence[float], builtin: Optional[str] = "panda",
             urdf_file: Optional[str] = None, base_link: str = "panda_link0", tip_link: str = "panda_link8",
             position: Sequence[float] = (0, 0, 0), orientation: Sequence[float] = (1, 0, 0, 0),
             srdf_file: Optional[str] = None, group: Optional[str] = None,
             limits: Optional[Dict[str, Any]] = None, mesh_path: Optional[Sequence[str]] = None,
             mesh_capsules: Optional[int] = None) -> Dict[str, Any]:
    """A serial arm from a URDF: a built-in model (builtin="panda") or a file (urdf_file=..., builtin=None), the
    chain base_link .. tip_link (or an SRDF's chain group: srdf_file=..., group=...; the SRDF's disabled collisions
    apply too), its base placed at position with the unit quaternion orientation (w, x, y, z); limits
    ({"velocity": ..., "acceleration": ...}, a number or one per joint) for time_parameterize(). Mesh collision
    geometry is found from the URDF's folder (relative paths, and package://NAME/... in a folder above it named
    NAME) and in the folders of mesh_path, and is fitted by at most mesh_capsules capsules a mesh (default 4)."""
    robot: Dict[str, Any] = {"name": name, "kind": "urdf_arm", "base_pose": _pose(position, orientation),
                             "start": list(start), "goal": list(goal)}
    if srdf_file is not None:
        robot["srdf_file"] = _os.path.abspath(srdf_file)
    if group is not None:
        robot["group"] = group
    else:
        robot["base_link"], robot["tip_link"] = base_link, tip_link
    if limits is not None:
        robot["limits"] = dict(limits)
    if mesh_path is not None:
        robot["mesh_path"] = [_os.path.abspath(folder) for folder in mesh_path]
    if mesh_capsules is not None:
        robot["mesh_capsules"] = mesh_capsules
    if urdf_file is not None:
        robot["urdf_file"] = _os.path.abspath(urdf_file)
    else:
        robot["builtin_urdf"] = builtin
    return robot


def mesh(file: str, scale: Union[float, Sequence[float]] = 1., position: Sequence[float] = (0, 0, 0),
         orientation: Sequence[float] = (1, 0, 0, 0), fit_resolution: int = 64, name: str = "") -> Dict[str, Any]:
    """A mesh obstacle (STL, OBJ, COLLADA, ...) scaled by a factor or one per axis: exact for validation,
    planned around as boxes fitted with fit_resolution cells along its longest side."""
    return {"name": name, "shape": "mesh", "file": _os.path.abspath(file),
            "scale": scale if isinstance(scale, (int, float)) else list(scale), "fit_resolution": fit_resolution,
            **_pose(position, orientation)}


def box(size: Sequence[float], position: Sequence[float] = (0, 0, 0), orientation: Sequence[float] = (1, 0, 0, 0),
        name: str = "") -> Dict[str, Any]:
    """A box obstacle of full extents size."""
    return {"name": name, "shape": "box", "size": list(size), **_pose(position, orientation)}


def box2d(center: Sequence[float], size: Sequence[float], yaw: float = 0.0, name: str = "") -> Dict[str, Any]:
    """A 2D box obstacle (a footprint extruded over z in [-1, 1])."""
    return {"name": name, "shape": "box2d", "center": list(center), "size": list(size), "yaw": yaw}


def sphere(radius: float, position: Sequence[float] = (0, 0, 0), name: str = "") -> Dict[str, Any]:
    """A sphere obstacle."""
    return {"name": name, "shape": "sphere", "radius": radius, "position": list(position)}


def cylinder(radius: float, length: float, position: Sequence[float] = (0, 0, 0),
             orientation: Sequence[float] = (1, 0, 0, 0), name: str = "") -> Dict[str, Any]:
    """A cylinder obstacle along its local z axis."""
    return {"name": name, "shape": "cylinder", "radius": radius, "length": length, **_pose(position, orientation)}


def team(robots: Sequence[Dict[str, Any]], obstacles: Sequence[Dict[str, Any]] = (), resolution: float = 128.0,
         name: str = "team") -> Problem:
    """A problem from robots (disc(), planar_arm(), urdf_arm()) among obstacles (box(), box2d(), sphere(),
    cylinder(), mesh()), checked like a scenario file (unique names, valid and collision-free starts and goals)."""
    text = _json.dumps({"format": "ompl_parc.scenario", "version": 1, "name": name, "resolution": resolution,
                        "obstacles": [{k: v for k, v in o.items() if k != "name" or v} for o in obstacles],
                        "robots": list(robots)})
    return Problem.from_json(text, _os.getcwd())


_LOG_LEVELS = {"debug": 0, "info": 1, "warn": 2, "error": 3, "none": 4}


def set_log_level(level: str) -> None:
    """OMPL's log level for everything ompl_parc logs: "debug" (every conflict and repair), "info" (the planners'
    stages), "warn" (the default here), "error" or "none"."""
    if level not in _LOG_LEVELS:
        raise ValueError(f"unknown log level '{level}' (valid: {', '.join(_LOG_LEVELS)})")
    _ompl_parc.set_log_level(_LOG_LEVELS[level])


def _parameter(value: Any) -> str:
    if isinstance(value, bool):
        return "1" if value else "0"
    return str(value)


def solve(problem: Problem, planner: str = "arc", time_limit: float = 30.0, **params: Any) -> SolveResult:
    """Solve problem with the registry planner named planner (planner_names(): arc, parc, orparc, pp-st-rrt,
    or-pp-st-rrt, rrtconnect, ep-rrt-c, or-rrt-c, or-ep-rrt-c; any spelling of case, '-' and '_') for at most
    time_limit seconds; params are the planner's declared parameters (workers=2, seed=1, smooth=0.5,
    profile="panda", ...), checked against their ranges.

    Returns a SolveResult: status (OMPL's status text), solved, planner, time, plan (a Plan, or None) and properties
    (the planner's per-stage times and counters as a dict). The GIL is released while planning; Ctrl-C stops the
    planner (all its threads joined) and raises KeyboardInterrupt."""
    assignments = [f"{key}={_parameter(value)}" for key, value in params.items()]
    return _ompl_parc.solve(problem, planner, float(time_limit), assignments)


def validate(problem: Problem, plan: Plan, substeps: int = 4) -> Validation:
    """The independent validator's verdict (valid, message: the earliest violation) on plan for problem."""
    return _ompl_parc.validate(problem, plan, substeps)


_TEXT_COLUMNS = {"case", "case_title", "method", "metrics_json", "scenario", "type", "status", "ompl_parc_version"}


def _trajectory_arrays(doc: Dict[str, Any]) -> Dict[str, Any]:
    import numpy as np
    robots = []
    for robot in doc["robots"]:
        points = robot["points"]
        robots.append({"name": robot["name"], "kind": robot["kind"], "joint_names": list(robot["joint_names"]),
                       "limits": robot["limits"], "arrival_time": robot["arrival_time"],
                       "max_deviation": robot["max_deviation"],
                       "time_from_start": np.array([p["time_from_start"] for p in points], dtype=float),
                       "positions": np.array([p["positions"] for p in points], dtype=float),
                       "velocities": np.array([p["velocities"] for p in points], dtype=float),
                       "accelerations": np.array([p["accelerations"] for p in points], dtype=float)})
    return {"duration": doc["duration"], "robots": robots, "temporal_plan_graph": doc.get("temporal_plan_graph")}


def time_parameterize(problem: Problem, plan: Plan, phase_steps: int = 4, max_deviation: float = 0.1) -> Dict[str, Any]:
    """The plan as trajectories within each robot's velocity and acceleration limits, conflict-free (checked by the
    validator), and its temporal plan graph: {"duration", "robots": [{"name", "joint_names", "time_from_start",
    "positions", "velocities", "accelerations" (NumPy, a row per point), "arrival_time", "limits",
    "max_deviation" (how far it leaves the plan's path at most, rounding corners)}],
    "temporal_plan_graph"}. Rounding a corner takes a robot off the plan's path by at most max_deviation (its
    configuration units; 0: sharp corners). The same as read_trajectory() of the file write_trajectory() or the tools
    write."""
    return _trajectory_arrays(_json.loads(_ompl_parc.trajectory_json(problem, plan, phase_steps, max_deviation)))


def write_trajectory(path: str, problem: Problem, plan: Plan, phase_steps: int = 4, max_deviation: float = 0.1) -> None:
    """Write time_parameterize()'s trajectories and graph as a trajectory file ("format": "ompl_parc.trajectory")."""
    text = _ompl_parc.trajectory_json(problem, plan, phase_steps, max_deviation)
    with open(path, "w") as out:
        out.write(text + "\n")


def read_trajectory(path: str) -> Dict[str, Any]:
    """A trajectory file (ompl_parc_demo --trajectory, ompl_parc_execute --trajectory, write_trajectory()) as
    time_parameterize() returns it."""
    with open(path) as f:
        doc = _json.load(f)
    if doc.get("format") != "ompl_parc.trajectory":
        raise ValueError(f"{path}: not a trajectory file (\"format\" is not \"ompl_parc.trajectory\")")
    return _trajectory_arrays(doc)


def _typed(column: str, text: str) -> Any:
    """A CSV cell as the number it is (int or float), text for the text columns, None when empty."""
    if text == "":
        return None
    if column in _TEXT_COLUMNS:
        return text
    for kind in (int, float):
        try:
            return kind(text)
        except ValueError:
            pass
    return text


def run_benchmark(config: str, verbose: bool = False, as_frame: bool = False) -> Any:
    """Run a benchmark configuration (the INI format of ompl_parc_benchmark) and return its runs: one dict per run
    with the CSV's columns (numbers as numbers; metrics_json parsed into "metrics"), or a pandas DataFrame with
    as_frame=True (pandas must be installed). The OMPL log and the CSV are written as by the tool. A solution the
    independent validator refuses is a failed run (success 0, the reason in metrics["validation"]) and a warning.
    Ctrl-C takes effect when the benchmark ends (OMPL's Benchmark takes no termination condition of ours)."""
    csv_path, _summary, invalid = _ompl_parc.run_benchmark(config, verbose)
    if invalid:
        _warnings.warn(f"{invalid} solution(s) failed the independent validation (see the rows' metrics['validation'])")
    with open(csv_path, newline="") as f:
        rows: List[Dict[str, Any]] = []
        for row in _csv.DictReader(f):
            typed = {key: _typed(key, value) for key, value in row.items()}
            typed["metrics"] = _json.loads(row["metrics_json"]) if row["metrics_json"] else {}
            rows.append(typed)
    if as_frame:
        import pandas  # optional: only for as_frame
        return pandas.DataFrame(rows)
    return rows
