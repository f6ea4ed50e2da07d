"""Speed from Python, side by side in one run (issue 50's figures; docs/benchmarks.md records
them). Run from the repository with the package and the peers installed:

    pip install ./python pathfinding oxmpl-py ompl
    python python/bench/bench.py [--quick]

1. A* on a 512 x 512 NumPy grid: Grid.astar from Python (wall clock of the call), the same
   query from Rust on the grid prepared the same way (`cargo xtask time --prepared`:
   PreparedGrid::search), and the pure-Python `pathfinding` package (costs compared too).
2. RRT-Connect over built-in worlds (the polygon world of examples/problems/wall-rrt-connect.json
   and the 4-joint arm of shelf-arm-rrt-connect.json): trailmark.solve from Python against solve
   from Rust (`cargo xtask time`) on the same document; and the arm held as a RobotWorld in both
   (`cargo xtask time --prepared`), only the plan timed.
3. RRT-Connect with a Python validity function on one problem: trailmark with the batch form,
   trailmark one state per call, oxmpl-py and OMPL 2.0's Python bindings one state per call
   (neither has a batch form), the same wall, range and motion step, at OMPL's default step
   (1% of the extent) and at a finer one (0.1%).
4. solve_many on every core against solve in a loop.

Ratios are medians of the per-query ratios where there are several queries (A*), ratios of the
medians otherwise.

A peer that is not installed is reported as such and skipped.
"""

import argparse
import json
import math
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

import trailmark

REPOSITORY = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(Path(__file__).resolve().parent))  # peers.py beside this file


def median_time(function, repeats):
    times = []
    result = None
    for _ in range(repeats):
        clock = time.perf_counter()
        result = function()
        times.append(time.perf_counter() - clock)
    return statistics.median(times), result


def rust_time(document, repeat, prepared=False):
    """The Rust side: `cargo xtask time` on the same document, in one process."""
    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / "problem.json"
        path.write_text(json.dumps(document))
        command = ["cargo", "xtask", "time", str(path), "--repeat", str(repeat)] + (["--prepared"] if prepared else [])
        done = subprocess.run(command, cwd=REPOSITORY, capture_output=True, text=True, check=True)
    return json.loads(done.stdout.strip().splitlines()[-1])


def grid_section(repeats, queries):
    rng = np.random.default_rng(0)
    free = rng.random((512, 512)) > 0.25
    cells = np.argwhere(free)
    picks = cells[rng.choice(len(cells), size=2 * queries, replace=False)]
    pairs = [((int(a[1]), int(a[0])), (int(b[1]), int(b[0]))) for a, b in zip(picks[0::2], picks[1::2])]
    grid = trailmark.Grid(free)
    world = grid.world()
    ours, rust, theirs, agree = [], [], [], 0
    try:
        from pathfinding.core.diagonal_movement import DiagonalMovement
        from pathfinding.core.grid import Grid as PfGrid
        from pathfinding.finder.a_star import AStarFinder
    except ImportError:
        PfGrid = None
    for start, goal in pairs:
        wall, plan = median_time(lambda: grid.astar(start, goal), repeats)
        ours.append(wall)
        document = {"world": {"grid": world}, "start": list(start), "goal": list(goal), "planner": {"name": "astar"}}
        timed = rust_time(document, repeats, prepared=True)
        assert timed["cost"] == plan.cost, (timed, plan.cost)
        rust.append(timed["median_s"])
        if PfGrid is not None:
            matrix = free.astype(int)
            def peer():
                pf = PfGrid(matrix=matrix)
                finder = AStarFinder(diagonal_movement=DiagonalMovement.only_when_no_obstacle)
                path, _ = finder.find_path(pf.node(*start), pf.node(*goal), pf)
                return path
            # The peer's grid is built inside the timed call: its search marks the nodes.
            peer_time, path = median_time(peer, 1)
            theirs.append(peer_time)
            length = sum(math.dist((a.x, a.y), (b.x, b.y)) for a, b in zip(path[:-1], path[1:])) if path else None
            if (length is None and plan.cost is None) or (
                length is not None and plan.cost is not None and abs(length - plan.cost) < 1e-6
            ):
                agree += 1
    rows = [
        ("A* 512x512 (Grid.astar), trailmark from Python", statistics.median(ours)),
        ("A* 512x512, the same search from Rust (PreparedGrid::search)", statistics.median(rust)),
    ]
    ratios = [o / r for o, r in zip(ours, rust)]
    note = f"A*: Python {statistics.median(ratios):.2f}x Rust (median of per-query ratios)"
    if theirs:
        rows.append(("A* 512x512, pathfinding (pure Python)", statistics.median(theirs)))
        speedups = [t / o for t, o in zip(theirs, ours)]
        note += f"; pathfinding {statistics.median(speedups):.0f}x slower (median per query)"
        note += f"; costs equal on {agree} of {len(pairs)} queries"
    else:
        note += "; pathfinding (pure Python) not installed"
    return rows, note


WALL_LO, WALL_HI = (4.5, 0.0), (5.5, 8.0)


def wall_batch(states):
    x, y = states[:, 0], states[:, 1]
    return ~((x >= WALL_LO[0]) & (x <= WALL_HI[0]) & (y >= WALL_LO[1]) & (y <= WALL_HI[1]))


def wall_one(p):
    return not (WALL_LO[0] <= p[0] <= WALL_HI[0] and WALL_LO[1] <= p[1] <= WALL_HI[1])


def box_section(repeats):
    """RRT-Connect over built-in worlds, as documents: trailmark.solve from Python against
    `cargo xtask time` (solve from Rust, in one process) on the same document."""
    examples = REPOSITORY / "examples" / "problems"
    cases = [
        ("polygon world (examples/problems/wall-rrt-connect.json)", examples / "wall-rrt-connect.json"),
        ("4-joint arm (examples/problems/shelf-arm-rrt-connect.json)", examples / "shelf-arm-rrt-connect.json"),
    ]
    rows, notes = [], []
    for label, path in cases:
        wall, result = median_time(lambda: trailmark.solve(path), repeats)
        command = ["cargo", "xtask", "time", str(path), "--repeat", str(repeats)]
        done = subprocess.run(command, cwd=REPOSITORY, capture_output=True, text=True, check=True)
        timed = json.loads(done.stdout.strip().splitlines()[-1])
        assert timed["cost"] == result["cost"] and result["status"] == "solved"
        rows.append((f"RRT-Connect, {label}, trailmark.solve from Python", wall))
        rows.append((f"RRT-Connect, {label}, solve from Rust", timed["median_s"]))
        notes.append(f"{label.split(' (')[0]} {wall / timed['median_s']:.2f}x")
    # The arm held by the program in both languages: RobotWorld.plan from Python against
    # RobotWorld::plan from Rust (`cargo xtask time --prepared`), the files read once.
    path = examples / "shelf-arm-rrt-connect.json"
    document = json.loads(path.read_text())
    robot, planner = document["world"]["robot"], dict(document["planner"])
    arm = trailmark.RobotWorld(examples / robot["urdf"], examples / robot["srdf"], robot["group"],
                               scene=examples / document["world"]["scene"])
    name = planner.pop("name")
    # A tenth of a millisecond a plan: ten times the repetitions, on both sides.
    held = 10 * repeats
    wall, plan = median_time(
        lambda: arm.plan(document["start"], document["goal"], name, seed=document["seed"], **planner), held
    )
    command = ["cargo", "xtask", "time", str(path), "--repeat", str(held), "--prepared"]
    done = subprocess.run(command, cwd=REPOSITORY, capture_output=True, text=True, check=True)
    timed = json.loads(done.stdout.strip().splitlines()[-1])
    assert timed["cost"] == plan.cost and plan.solved
    rows.append(("RRT-Connect, 4-joint arm held as a RobotWorld, RobotWorld.plan from Python", wall))
    rows.append(("RRT-Connect, 4-joint arm held as a RobotWorld, RobotWorld::plan from Rust", timed["median_s"]))
    notes.append(f"arm held as a RobotWorld {wall / timed['median_s']:.2f}x")
    return rows, "RRT-Connect from Python / from Rust: " + ", ".join(notes)


def callback_section(repeats, fraction):
    """RRT-Connect with the wall as a Python function, motions checked every `fraction` of the
    extent in all three (OMPL's default is 0.01), range 1, no goal bias (OMPL's RRT-Connect has
    none)."""
    extent = math.hypot(10.0, 10.0)
    step = fraction * extent
    bounds = [(0.0, 10.0), (0.0, 10.0)]
    rows, times = [], {}
    for name, batch in (("batch", True), ("one state per call", False)):
        function = wall_batch if batch else wall_one
        samples = []
        for seed in range(repeats):
            clock = time.perf_counter()
            plan = trailmark.plan_in_box(bounds, (1, 1), (9, 1), function, range=1.0, resolution=fraction, seed=seed,
                                         goal_bias=0.0, batch=batch)
            samples.append(time.perf_counter() - clock)
            assert plan.solved
        times[name] = statistics.median(samples)
        rows.append((f"RRT-Connect + Python validity (step {fraction:g} of extent), trailmark ({name})", times[name]))
    try:
        import peers
    except ImportError as e:
        return rows, f"peers unavailable: {e}"
    for name, run in (("oxmpl-py 0.7", peers.oxmpl_rrt_connect), ("OMPL 2.0 Python", peers.ompl_rrt_connect)):
        try:
            samples = []
            for seed in range(repeats):
                clock = time.perf_counter()
                solved, _, _ = run([0, 0], [10, 10], [1, 1], [9, 1], wall_one, 1.0, 5.0, seed, resolution=step)
                samples.append(time.perf_counter() - clock)
                assert solved
            times[name] = statistics.median(samples)
            rows.append((f"RRT-Connect + Python validity (step {fraction:g} of extent), {name} (one state per call)", times[name]))
        except ImportError as e:
            rows.append((f"RRT-Connect + Python validity, {name}: not installed ({e})", float("nan")))
    best = times["batch"]
    note = f"step {fraction:g}: " + "; ".join(
        f"{name} {t / best:.2f}x trailmark batch's time" for name, t in times.items() if name != "batch"
    )
    return rows, note


def many_section(count):
    """solve_many on every core against solve in a loop: grid documents that carry their
    128 x 128 map inline (JSON-heavy: Python's json works on one core in both), and
    RRT-Connect documents over a polygon world, one seed each (planning-heavy)."""
    rows_text = ["." * 128] * 128
    rows_text = [r[:64] + ("@" if 8 <= y < 120 else ".") + r[65:] for y, r in enumerate(rows_text)]
    grids = [
        {
            "world": {"grid": {"rows": rows_text}},
            "start": [i % 60, (7 * i) % 128],
            "goal": [127 - i % 60, (11 * i) % 128],
            "planner": {"name": "astar"},
        }
        for i in range(count)
    ]
    wall = json.loads((REPOSITORY / "examples" / "problems" / "wall-rrt-connect.json").read_text())
    sampling = [dict(wall, seed=i) for i in range(count // 20)]
    rows, notes = [], []
    for label, documents in ((f"{count} grid documents", grids), (f"{len(sampling)} RRT-Connect documents", sampling)):
        # Alternated, three of each: the machine's speed drifts over seconds.
        loops, manys = [], []
        for _ in range(3):
            loops.append(median_time(lambda: [trailmark.solve(d) for d in documents], 1)[0])
            manys.append(median_time(lambda: trailmark.solve_many(documents), 1)[0])
        loop, many = statistics.median(loops), statistics.median(manys)
        rows += [(f"solve in a loop, {label}", loop), (f"solve_many, {label}", many)]
        notes.append(f"{label}: {loop / many:.2f}x")
    return rows, "solve_many against solve in a loop: " + "; ".join(notes)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="fewer repetitions (a smoke run)")
    args = parser.parse_args()
    repeats, queries, count = (3, 5, 200) if args.quick else (21, 30, 2000)
    print("| measurement | median |")
    print("|---|---:|")
    notes = []
    for rows, note in (
        grid_section(repeats, queries),
        box_section(repeats),
        callback_section(repeats * 2, 0.01),
        callback_section(repeats * 2, 0.001),
        many_section(count),
    ):
        for label, seconds in rows:
            print(f"| {label} | {seconds * 1e3:.3f} ms |")
        notes.append(note)
    print()
    for note in notes:
        print("-", note)


if __name__ == "__main__":
    main()
