"""agvbench from Python, stage 1 (issue 48): the catalogue, maps and single plans, each checked
against the command line of the same build, and bad input raising ValueError naming the field."""

import math

import numpy
import pytest

import agvbench

# Planners whose runs the sweep's random stream drives, and deterministic ones, on one map.
COMPARED = ["astar", "dijkstra", "ma_star", "improved_astar", "rrt", "prm", "aco"]


def test_version_is_the_command_lines(cli):
    assert cli("--version").split()[1] == agvbench.__version__


def test_catalogue_is_list_json(cli):
    listing = cli("list", "--json", json_out=True)
    assert agvbench.planners() == listing["planners"]
    assert agvbench.generators() == listing["generators"]
    assert agvbench.map_sources() == listing["map_sources"]
    assert "astar" in [p["name"] for p in agvbench.planners()]


@pytest.mark.parametrize("generator,size,density,seed,index", [
    ("uniform", 32, 0.2, 1, 0), ("uniform", (40, 24), 0.3, 7, 5), ("maze", 31, 0.0, 2, 1),
    ("rooms", 48, 0.1, 3, 2), ("blocks", 64, 0.25, 11, 0)])
def test_make_map_is_plans_map(cli, generator, size, density, seed, index):
    text = f"{size[0]}x{size[1]}" if isinstance(size, tuple) else str(size)
    doc = cli("plan", "--generator", generator, "--size", text, "--density", density, "--seed", seed,
              "--map-index", index, "--json", json_out=True)["map"]
    m = agvbench.make_map(generator, size, density, seed, index)
    assert m.grid.dtype == numpy.bool_
    assert m.grid.shape == (doc["height"], doc["width"])
    rows = ["".join("@" if b else "." for b in row) for row in m.grid]
    assert rows == doc["rows"]
    assert list(m.start) == doc["start"] and list(m.goal) == doc["goal"]
    assert m.cell == doc["cell"] and m.map_index == index and m.seed == seed
    assert m.params == doc["params"]


def test_make_map_takes_a_configs_map_object_and_shape_parameters():
    m = agvbench.make_map("uniform", 32, 0.2, 5, 3,
                          map={"endpoints": "random", "min_distance": 10, "cell_edge": 0.05})
    assert m.cell_edge == 0.05
    assert math.dist(m.start, m.goal) >= 10
    assert not m.grid[m.start[1], m.start[0]] and not m.grid[m.goal[1], m.goal[0]]
    fixed = agvbench.make_map("uniform", 20, 0.3, 1, map={"endpoints": "fixed", "start": [2, 3],
                                                          "goal": [17, 15]})
    assert fixed.start == (2, 3) and fixed.goal == (17, 15)
    rooms = agvbench.make_map("rooms", 64, 0.0, 1, room_size=12, door_width=3)
    assert rooms.params["room_size"] == 12 and rooms.params["door_width"] == 3
    again = agvbench.make_map("rooms", 64, 0.0, 1, room_size=numpy.int64(12), door_width=3)
    assert numpy.array_equal(again.grid, rooms.grid)


def plan_runs(cli, planners, *args):
    options = [x for p in planners for x in ("--planner", p)]
    return cli("plan", *options, *args, "--json", json_out=True)["runs"]


@pytest.mark.parametrize("seed,index", [(1, 0), (4, 2)])
def test_plan_is_the_command_lines_run(cli, seed, index):
    m = agvbench.make_map("uniform", 40, 0.2, seed, index)
    runs = plan_runs(cli, COMPARED, "--size", 40, "--density", 0.2, "--seed", seed,
                     "--map-index", index)
    for run in runs:
        got = agvbench.plan(m, planner=run["planner"])
        assert got.outcome == run["outcome"], run["planner"]
        assert got.rule == run["rule"]
        assert got.path.shape == (len(run["path"]), 2)
        assert got.path.tolist() == run["path"], run["planner"]
        assert got.metrics == run["metrics"], run["planner"]
        assert got.params == run["params"]
        assert got.plan_time_ns > 0 and set(got.phases) == set(run["timing"]["phases"])


def test_plan_takes_parameters_collision_and_a_plain_array(cli):
    m = agvbench.make_map("uniform", 32, 0.25, 9)
    run = plan_runs(cli, ["astar"], "--size", 32, "--density", 0.25, "--seed", 9, "--param",
                    "heuristic=manhattan", "--corner-rule", "allow")[0]
    got = agvbench.plan(m.grid, m.start, m.goal, "astar", heuristic="manhattan",
                        collision={"corner_rule": "allow"}, cell=m.cell, seed=9)
    assert got.path.tolist() == run["path"] and got.metrics == run["metrics"]
    assert got.rule == "allow" and got.params["heuristic"] == "manhattan"
    view = numpy.ascontiguousarray(m.grid.T).T  # same cells, Fortran order
    assert agvbench.plan(view, m.start, m.goal, "astar").path.tolist() == \
        agvbench.plan(m.grid, m.start, m.goal, "astar").path.tolist()


def test_plan_outcomes_and_time_limit():
    grid = numpy.zeros((10, 10), dtype=bool)
    grid[:, 5] = True  # a wall: no path
    walled = agvbench.plan(grid, (0, 0), (9, 9), "astar")
    assert walled.outcome == "no_path" and walled.path.shape == (0, 2)
    assert walled.metrics["path_length"] is None
    # Dijkstra over a million free cells takes tens of ms; the deadline is 1 ms.
    limited = agvbench.plan(numpy.zeros((1024, 1024), dtype=bool), (0, 0), (1023, 1023),
                            "dijkstra", time_limit_s=1e-3)
    assert limited.outcome == "limit"


def test_load_map_reads_files_as_a_sweep(cli, tmp_path):
    rows = ["@@@@@@", "@....@", "@.@@.@", "@....@", "@@@@@@"]
    path = tmp_path / "small.map"
    path.write_text("type octile\nheight 5\nwidth 6\nmap\n" + "\n".join(rows) + "\n")
    m = agvbench.load_map(path)
    assert m.start is None and m.cell == str(path)
    assert ["".join("@" if b else "." for b in r) for r in m.grid] == rows
    run = plan_runs(cli, ["astar"], "--map", path, "--start", "1,1", "--goal", "4,3")[0]
    assert agvbench.plan(m, (1, 1), (4, 3), "astar").path.tolist() == run["path"]
    pgm = tmp_path / "small.pgm"
    pixels = bytes(0 if b else 254 for r in m.grid for b in r)
    pgm.write_bytes(b"P5\n6 5\n255\n" + pixels)
    assert numpy.array_equal(agvbench.load_map(pgm).grid, m.grid)


@pytest.mark.parametrize("call,field", [
    (lambda m: agvbench.plan(m.grid.astype(int), m.start, m.goal, "astar"), "grid"),
    (lambda m: agvbench.plan(m.grid[0], m.start, m.goal, "astar"), "grid"),
    (lambda m: agvbench.plan([[False, False]], (0, 0), (1, 0), "astar"), "grid"),
    (lambda m: agvbench.plan(m, (99, 0), None, "astar"), "start"),
    (lambda m: agvbench.plan(m, None, (0.5, 3), "astar"), "goal"),
    (lambda m: agvbench.plan(m.grid, m.start, None, "astar"), "goal"),
    (lambda m: agvbench.plan(m, planner="no_such"), "planner"),
    (lambda m: agvbench.plan(m, planner="astar", heuristic="bogus"), "planner.params.heuristic"),
    (lambda m: agvbench.plan(m, planner="astar", no_such_param=1), "planner.params.no_such_param"),
    (lambda m: agvbench.plan(m, planner="astar", collision={"corner_rule": "x"}),
     "collision.corner_rule"),
    (lambda m: agvbench.plan(m, planner="astar", time_limit_s=-1), "time_limit_s"),
    (lambda m: agvbench.plan(m, planner="astar", seed=-3), "seed"),
    (lambda m: agvbench.make_map("nope", 32, 0.2, 1), "generator"),
    (lambda m: agvbench.make_map("uniform", 1, 0.2, 1), "size"),
    (lambda m: agvbench.make_map("uniform", (32, 99999), 0.2, 1), "size[1]"),
    (lambda m: agvbench.make_map("uniform", 32, 1.5, 1), "density"),
    (lambda m: agvbench.make_map("uniform", 32, 0.2, 1, -1), "map_index"),
    (lambda m: agvbench.make_map("uniform", 32, 0.2, 1, map={"endpoints": "x"}), "map.endpoints"),
    (lambda m: agvbench.make_map("uniform", 32, 0.2, 1, map={"bogus": 1}), "map.bogus"),
    (lambda m: agvbench.make_map("rooms", 32, 0.2, 1, room_size=0), "params.room_size"),
    (lambda m: agvbench.load_map("grid.txt"), "grid.txt"),
    (lambda m: agvbench.load_map("/no/such/file.map"), "map file \"/no/such/file.map\""),
])
def test_bad_input_raises_value_error_naming_the_field(call, field):
    m = agvbench.make_map("uniform", 16, 0.2, 1)
    with pytest.raises(ValueError) as raised:
        call(m)
    assert str(raised.value).startswith(field), str(raised.value)


def test_start_on_an_obstacle_is_refused():
    grid = numpy.zeros((8, 8), dtype=bool)
    grid[2, 3] = True
    with pytest.raises(ValueError, match=r"^start: \(3, 2\) is an obstacle cell"):
        agvbench.plan(grid, (3, 2), (7, 7), "astar")


def test_plans_in_threads_agree_with_plans_in_turn():
    # plan() releases the GIL while the engine runs: threads overlap, results do not change.
    from concurrent.futures import ThreadPoolExecutor
    maps = [agvbench.make_map("uniform", 48, 0.25, seed, 0) for seed in range(1, 9)]
    in_turn = [agvbench.plan(m, planner="rrt").path.tolist() for m in maps]
    with ThreadPoolExecutor(max_workers=4) as pool:
        together = list(pool.map(lambda m: agvbench.plan(m, planner="rrt").path.tolist(), maps))
    assert together == in_turn


def test_cmake_install_puts_it_where_debians_python_finds_it(tmp_path):
    import os
    import subprocess
    import sys
    build = os.environ.get("AGVBENCH_BUILD_DIR")
    if not build:
        pytest.skip("AGVBENCH_BUILD_DIR not set (ctest sets it)")
    done = subprocess.run(["cmake", "--install", build, "--prefix", str(tmp_path)],
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    site = tmp_path / "lib" / f"python3.{sys.version_info.minor}" / "dist-packages"
    env = {**os.environ, "PYTHONPATH": str(site)}
    code = "import agvbench; print(agvbench.__file__); print(agvbench.plan(" \
           "agvbench.make_map('uniform', 16, 0.1, 1), planner='astar').outcome)"
    out = subprocess.run(["/usr/bin/python3", "-c", code], capture_output=True, text=True,
                         env=env, cwd=tmp_path)
    assert out.returncode == 0, out.stderr
    assert out.stdout.split() == [str(site / "agvbench" / "__init__.py"), "success"]


def test_a_maps_grid_alone_plans_as_the_map(cli):
    # plan(m.grid, m.start, m.goal, ...) draws the sweep's random stream as plan(m, ...) does.
    m = agvbench.make_map("uniform", 40, 0.2, 5, 3)
    runs = plan_runs(cli, ["rrt", "prm"], "--size", 40, "--density", 0.2, "--seed", 5,
                     "--map-index", 3)
    for run in runs:
        got = agvbench.plan(m.grid, m.start, m.goal, run["planner"])
        assert got.path.tolist() == run["path"] and got.metrics == run["metrics"]
    assert agvbench.plan(m.grid.copy(), m.start, m.goal, "astar").outcome == "success"
    assert isinstance(m.grid, numpy.ndarray) and m.grid.dtype == numpy.bool_
