"""The Python module end to end (run by ctest as python.pytest, with PYTHONPATH at the built module and
OMPL_PARC_BIN at the tools): every planner from Python on Mobile Cross 8, validated; plans as NumPy arrays; scenario
and solution files round-tripped; bad input as ValueError with the tools' own message; prompt timeouts and Ctrl-C."""
import json
import os
import signal
import subprocess
import sys
import textwrap
import threading
import time

import numpy as np
import pytest

import ompl_parc

BIN = os.environ.get("OMPL_PARC_BIN", "")


# Two discs of radius 0.5 swapping in a corridor 0.6 wide: they can never pass, so a solve runs until it is stopped,
# whatever the seed.
BLOCKED_SWAP = """ompl_parc.team([ompl_parc.disc("west", 0.5, (-4, 0), (4, 0), low=(-5, -0.3), high=(5, 0.3)),
                 ompl_parc.disc("east", 0.5, (4, 0), (-4, 0), low=(-5, -0.3), high=(5, 0.3))], name="blocked_swap")"""


def tool_message(*args):
    """The one-line reason a tool prints for bad input, without its "tool: " prefix."""
    run = subprocess.run([os.path.join(BIN, "ompl_parc_demo"), *args], capture_output=True, text=True)
    assert run.returncode == 2, run.stderr
    line = run.stderr.strip()
    assert line.count("\n") == 0
    return line.split(": ", 1)[1]


@pytest.mark.parametrize("planner", ompl_parc.planner_names())
def test_every_planner_solves_mobile_cross_8_and_validates(planner):
    problem = ompl_parc.scenario("mobile_cross", robots=8)
    params = {"seed": 3} if "seed" in ompl_parc.planner_parameters(planner) else {}
    result = ompl_parc.solve(problem, planner, time_limit=60, **params)
    assert result.solved, result.status
    assert result.status == "Exact solution"
    report = ompl_parc.validate(problem, result.plan)
    assert report.valid, report.message
    assert result.plan.makespan == max(result.plan.arrival(i) for i in range(8))


def test_plans_are_numpy_arrays_from_start_to_goal():
    problem = ompl_parc.scenario("mobile_cross", robots=4)
    result = ompl_parc.solve(problem, "parc", workers=2, seed=1, smooth=0.1)
    plan = result.plan
    assert ompl_parc.validate(problem, plan).valid
    for robot in range(problem.robot_count):
        times, configs = plan.waypoints(robot)
        assert times.dtype == np.int64 and configs.shape == (len(times), 2)
        assert times[0] == 0 and times[-1] == plan.arrival(robot) and np.all(np.diff(times) > 0)
        np.testing.assert_allclose(configs[0], problem.start(robot))
        np.testing.assert_allclose(configs[-1], problem.goal(robot), atol=1e-9)
        dense = plan.dense(robot)
        assert dense.shape == (plan.arrival(robot) + 1, 2)
        # Linear between waypoints: the dense path is the waypoints' interpolation.
        for axis in range(2):
            np.testing.assert_allclose(np.interp(np.arange(len(dense)), times, configs[:, axis]), dense[:, axis],
                                       atol=1e-9)
        np.testing.assert_allclose(plan.at(robot, 10**9), problem.goal(robot), atol=1e-9)
    assert result.properties["conflicts"] >= 1
    assert isinstance(result.properties["initial_wall_time"], float)
    assert result.properties["smoothing_time"] > 0


def test_waypoints_keep_a_wait_before_a_move(tmp_path):
    # r0 holds its start for 100 timesteps, then crosses; r1 crosses at once and waits for nothing: the waypoints
    # must hold r0 still until t=100 (not spread its motion over the wait).
    (tmp_path / "wait.json").write_text(
        '{"format": "ompl_parc.solution", "version": 2, "resolution": 128, "robots": ['
        '{"name": "r0", "kind": "disc", "arrival": 753, "pieces": [[0, 0, 0, [5, 0], [5, 0]],'
        ' [100, 0, 653, [5, 0], [0, 1]], [753, 0, 0, [0, 1], [0, 1]]]},'
        '{"name": "r1", "kind": "disc", "arrival": 1306, "pieces": [[0, 0, 653, [-5, 0], [0, -1]],'
        ' [653, 0, 653, [0, -1], [5, 0]]]}]}')
    problem = ompl_parc.team([ompl_parc.disc("r0", 0.5, (5, 0), (0, 1)), ompl_parc.disc("r1", 0.5, (-5, 0), (5, 0))])
    plan = ompl_parc.read_solution(str(tmp_path / "wait.json"), problem)
    times, configs = plan.waypoints(0)
    assert {99, 100} <= set(times) and times[0] == 0 and times[-1] == 753
    np.testing.assert_allclose(configs[list(times).index(99)], (5, 0))
    for robot in range(2):
        times, configs = plan.waypoints(robot)
        dense = plan.dense(robot)
        for axis in range(2):
            np.testing.assert_allclose(np.interp(np.arange(len(dense)), times, configs[:, axis]), dense[:, axis],
                                       atol=1e-9)


def test_scenario_and_solution_files_round_trip(tmp_path):
    problem = ompl_parc.team(
        [ompl_parc.disc("west", 0.5, start=(-5, 0), goal=(5, 0)), ompl_parc.disc("east", 0.5, start=(5, 0), goal=(-5, 0)),
         ompl_parc.planar_arm("arm", [0.5, 0.5], start=(0, 0), goal=(1.5, 0), base=(0, 6, 0))],
        obstacles=[ompl_parc.box2d(center=(0, -4), size=(1, 2), name="pillar"), ompl_parc.sphere(0.5, (6, 6, 0))],
        name="python_team")
    assert problem.robot_names == ["west", "east", "arm"]
    problem.save(str(tmp_path / "team.json"))
    loaded = ompl_parc.load(str(tmp_path / "team.json"))
    assert loaded.to_json() == problem.to_json() and loaded.name == "python_team"

    result = ompl_parc.solve(loaded, "arc", seed=2)
    assert result.solved, result.status
    ompl_parc.write_solution(str(tmp_path / "solution.json"), loaded, result.plan)
    read = ompl_parc.read_solution(str(tmp_path / "solution.json"), loaded)
    assert read.makespan == result.plan.makespan and read.sum_of_costs == result.plan.sum_of_costs
    for robot in range(3):
        np.testing.assert_array_equal(read.dense(robot), result.plan.dense(robot))
    assert ompl_parc.validate(loaded, read).valid
    ompl_parc.write_svg(str(tmp_path / "team.svg"), loaded, read)
    assert (tmp_path / "team.svg").read_text().startswith("<?xml")
    ompl_parc.write_html(str(tmp_path / "team.html"), loaded, read)
    page = (tmp_path / "team.html").read_text()
    assert page.startswith("<!DOCTYPE html>") and '"robots":[{' in page
    with pytest.raises(Exception, match="cannot write"):
        ompl_parc.write_html(str(tmp_path / "missing" / "team.html"), loaded, read)


def test_a_plan_of_another_team_is_not_written(tmp_path):
    eight = ompl_parc.scenario("mobile_cross", 8)
    plan = ompl_parc.solve(eight, "arc", seed=1).plan
    arms = ompl_parc.scenario("planar_cross", 8)
    for problem, reason in ((ompl_parc.scenario("mobile_cross", 4), "plan has 8 robots, problem has 4"),
                            (ompl_parc.scenario("mobile_cross", 16), "plan has 8 robots, problem has 16"),
                            (arms, "has the wrong configuration size")):
        path = tmp_path / "solution.json"
        with pytest.raises(ValueError, match=reason):
            ompl_parc.write_solution(str(path), problem, plan)
        assert not path.exists()


def test_truth_values_are_read_strictly():
    problem = ompl_parc.scenario("mobile_cross", 4)
    assert ompl_parc.solve(problem, "parc", workers=2, optimistic=False, seed=1).solved
    with pytest.raises(ValueError, match="parameter 'optimistic' must be 1/0, true/false"):
        ompl_parc.solve(problem, "parc", optimistic="maybe")
    with pytest.raises(ValueError, match="parameter 'window' must be a whole number"):
        ompl_parc.solve(problem, "arc", window=100.7)


def test_planner_parameters_are_listed_with_their_ranges():
    parameters = ompl_parc.planner_parameters("P-ARC")
    assert parameters["workers"] == "1:1:64" and "seed" in parameters and "smooth" in parameters
    assert "seed" not in ompl_parc.planner_parameters("rrtconnect")


def test_bad_input_raises_value_error_with_the_tools_message(tmp_path):
    with pytest.raises(ValueError) as error:
        ompl_parc.scenario("warehouse", 4)
    assert str(error.value) == tool_message("--scenario", "warehouse")
    problem = ompl_parc.scenario("mobile_cross", 4)
    with pytest.raises(ValueError) as error:
        ompl_parc.solve(problem, "prm")
    assert str(error.value) == tool_message("--planner", "prm")
    with pytest.raises(ValueError) as error:
        ompl_parc.solve(problem, "parc", workers=-1)
    assert str(error.value) == tool_message("--planner", "parc", "--param", "workers=-1")
    (tmp_path / "broken.json").write_text('{"format": "ompl_parc.scenario", "version": 1, "robots": [{"name": "r"}]}')
    with pytest.raises(ValueError) as error:
        ompl_parc.load(str(tmp_path / "broken.json"))
    assert str(error.value) == tool_message("--scenario-file", str(tmp_path / "broken.json"))
    with pytest.raises(ValueError, match="has no parameter 'threads'"):
        ompl_parc.solve(problem, "arc", threads=2)
    with pytest.raises(ValueError, match="robots\\[0\\].radius must be a positive number"):
        ompl_parc.team([ompl_parc.disc("r", -1, (0, 0), (1, 1))])


def test_a_team_over_the_limit_is_refused_before_it_is_built():
    # Each robot costs memory before any planning: the limit is checked first, as the tools check theirs.
    with pytest.raises(ValueError, match="a team of 1000000 robots is over the limit of 20000"):
        ompl_parc.scenario("mobile_cross", robots=10**6)


def test_a_short_limit_returns_promptly_as_a_timeout():
    problem = ompl_parc.scenario("panda_cage", robots=16, task=3)
    start = time.monotonic()
    result = ompl_parc.solve(problem, "parc", time_limit=0.2, workers=2, profile="panda", seed=1)
    elapsed = time.monotonic() - start
    assert result.status == "Timeout" and not result.solved and result.plan is None
    assert elapsed < 2.0, elapsed  # the limit plus the joins, far above the typical few milliseconds late


def test_the_gil_is_released_while_planning():
    ticks = []
    done = threading.Event()

    def count():
        while not done.is_set():
            ticks.append(1)
            time.sleep(0.001)

    problem = eval(BLOCKED_SWAP)
    counter = threading.Thread(target=count)
    counter.start()
    before = len(ticks)
    result = ompl_parc.solve(problem, "arc", time_limit=0.5, seed=1)
    during = len(ticks) - before
    done.set()
    counter.join()
    assert result.status == "Timeout"
    # Counted through the half second the planner held: about 500 ticks on a quiet machine, none if the GIL were held;
    # the bound leaves room for a machine whose cores other tests keep busy.
    assert during > 10, during


def test_ctrl_c_stops_a_solve_cleanly():
    script = textwrap.dedent(f"""
        import ompl_parc, sys
        problem = {BLOCKED_SWAP}
        print("planning", flush=True)
        try:
            ompl_parc.solve(problem, "parc", time_limit=60, workers=2, seed=1)
        except KeyboardInterrupt:
            print("interrupted", flush=True)
            sys.exit(0)
        sys.exit(1)
    """)
    process = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                               text=True)
    assert process.stdout.readline().strip() == "planning"
    time.sleep(0.5)
    start = time.monotonic()
    process.send_signal(signal.SIGINT)
    out, err = process.communicate(timeout=30)
    assert process.returncode == 0 and out.strip() == "interrupted", out + err
    assert time.monotonic() - start < 5.0


def test_a_benchmark_config_gives_its_rows(tmp_path):
    (tmp_path / "tiny.cfg").write_text(textwrap.dedent("""
        [problem]
        name = tiny
        scenario = mobile_cross
        robots = 4
        [benchmark]
        time_limit = 10
        mem_limit = 4096
        run_count = 2
        workers = 2
        [planner]
        arc =
        parc =
        parc.workers = 2
        parc.name = P-ARC-2
    """))
    rows = ompl_parc.run_benchmark(str(tmp_path / "tiny.cfg"))
    assert [(r["method"], r["seed"], r["success"]) for r in rows] == [
        ("arc", 1, 1), ("arc", 2, 1), ("P-ARC-2", 1, 1), ("P-ARC-2", 2, 1)]
    assert rows[0]["case"] == "mobile_cross_4" and rows[0]["ompl_parc_version"] == ompl_parc.__version__
    assert rows[2]["metrics"]["conflicts"] >= 1 and rows[2]["workers"] == 2
    assert (tmp_path / "tiny.log").exists()


def test_a_panda_trajectory_round_trips_and_follows_the_plan(tmp_path):
    problem = ompl_parc.scenario("panda_cage", robots=8)
    result = ompl_parc.solve(problem, "arc", seed=1, time_limit=60)
    assert result.solved and ompl_parc.validate(problem, result.plan).valid
    trajectory = ompl_parc.time_parameterize(problem, result.plan)
    path = str(tmp_path / "trajectory.json")
    ompl_parc.write_trajectory(path, problem, result.plan)
    again = ompl_parc.read_trajectory(path)
    assert len(again["robots"]) == 8 and again["duration"] == pytest.approx(trajectory["duration"])
    for robot, read in zip(trajectory["robots"], again["robots"]):
        assert robot["joint_names"] == read["joint_names"] and len(robot["joint_names"]) == 7
        for key in ("time_from_start", "positions", "velocities", "accelerations"):
            np.testing.assert_allclose(robot[key], read[key], rtol=0, atol=1e-12)
    for i, robot in enumerate(trajectory["robots"]):
        positions, velocities = robot["positions"], robot["velocities"]
        assert np.all(np.diff(robot["time_from_start"]) > 0)
        np.testing.assert_allclose(positions[0], problem.start(i), atol=1e-9)
        np.testing.assert_allclose(positions[-1], problem.goal(i), atol=1e-9)
        assert np.all(np.abs(velocities) <= np.array(robot["limits"]["velocity"]) * (1 + 1e-6))
        # Every point lies on the plan's path, up to the rounding of its corners (0.1 rad at most, the default).
        _, waypoints = result.plan.waypoints(i)
        assert 0 <= robot["max_deviation"] <= 0.1 + 1e-12
        for q in positions:
            a, b = waypoints[:-1], waypoints[1:]
            d = b - a
            s = np.clip(np.einsum("ij,ij->i", q - a, d) / np.maximum(np.einsum("ij,ij->i", d, d), 1e-300), 0, 1)
            assert np.min(np.linalg.norm(a + s[:, None] * d - q, axis=1)) <= robot["max_deviation"] + 1e-9
    assert len(trajectory["temporal_plan_graph"]["robots"]) == 8


def test_a_trajectory_file_of_another_kind_is_refused(tmp_path):
    path = tmp_path / "solution.json"
    path.write_text('{"format": "ompl_parc.solution"}')
    with pytest.raises(ValueError, match="not a trajectory file"):
        ompl_parc.read_trajectory(str(path))


def test_an_arm_named_by_its_srdf_group_with_its_own_limits(tmp_path):
    srdf = tmp_path / "panda.srdf"
    srdf.write_text('<robot name="panda"><group name="arm"><chain base_link="panda_link0" tip_link="panda_link8"/>'
                    '</group><disable_collisions link1="panda_link1" link2="panda_link3" reason="Never"/></robot>')
    q0, q1 = [0, 0, 0, -1.5, 0, 1.5, 0], [0.5, 0, 0, -1.5, 0, 1.5, 0]
    problem = ompl_parc.team([ompl_parc.urdf_arm("a", q0, q1, srdf_file=str(srdf), group="arm",
                                                 limits={"velocity": 1.0, "acceleration": 2.0})])
    result = ompl_parc.solve(problem, "arc", seed=1, time_limit=30)
    assert result.solved
    trajectory = ompl_parc.time_parameterize(problem, result.plan)
    robot = trajectory["robots"][0]
    assert robot["limits"] == {"velocity": [1.0] * 7, "acceleration": [2.0] * 7}
    assert np.all(np.abs(robot["velocities"]) <= 1.0 + 1e-9)
    # 0.5 rad at 1 rad/s and 2 rad/s^2 takes at least 0.5 s (accelerating and braking: 2 sqrt(0.25 / 2)).
    assert trajectory["duration"] >= 2 * (0.25 / 2) ** 0.5
    with pytest.raises(ValueError, match="no group 'hand'"):
        ompl_parc.team([ompl_parc.urdf_arm("a", q0, q1, srdf_file=str(srdf), group="hand")])


def test_a_meshed_arm_and_a_mesh_table_from_python():
    assets = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "demos", "assets", "meshed_arm")
    with open(os.path.join(assets, "meshed_cell.json")) as f:
        cell = json.load(f)
    arms = [ompl_parc.urdf_arm(r["name"], r["start"], r["goal"], builtin=None,
                               urdf_file=os.path.join(assets, "meshed_arm.urdf"),
                               srdf_file=os.path.join(assets, "meshed_arm.srdf"), group="arm_with_gripper",
                               position=r["base_pose"]["position"], orientation=r["base_pose"]["orientation"],
                               mesh_path=[os.path.join(assets, "..")], mesh_capsules=3)
            for r in cell["robots"][:2]]
    table = ompl_parc.mesh(os.path.join(assets, "meshes", "table.stl"), scale=[0.7, 0.7, 1.0], name="table")
    problem = ompl_parc.team(arms, [table], resolution=100)
    result = ompl_parc.solve(problem, "arc", seed=1, time_limit=30)
    assert result.solved
    report = ompl_parc.validate(problem, result.plan)
    assert report.valid, report.message
    with pytest.raises(ValueError, match="does not exist"):
        ompl_parc.team(arms, [ompl_parc.mesh(os.path.join(assets, "meshes", "no_table.stl"))], resolution=100)
