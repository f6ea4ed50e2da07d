"""Speed from Python, side by side in one run (issue 50's figures; docs/benchmarks.md records
them). Run from the repository with the package and the peers installed:

    pip install ./python pathfinding oxmpl-py ompl
    python python/bench/bench.py [--quick]

1. A* on a 512 x 512 NumPy grid: trailmark from Python (wall clock of the call), the same
   search timed inside Rust (the plan's own time_s: the query from Rust without Python), and
   the pure-Python `pathfinding` package on the same grid and query (costs compared too).
2. RRT-Connect in a box world (a built-in world): the call from Python against the planner's
   own time inside Rust.
3. RRT-Connect with a Python validity function on one problem: trailmark with the batch form,
   trailmark one state per call, oxmpl-py and OMPL 2.0's Python bindings one state per call
   (neither has a batch form), the same wall, range and motion step.
4. solve_many on every core against solve in a loop.

A peer that is not installed is reported as such and skipped.
"""

import argparse
import math
import statistics
import time

import numpy as np

import trailmark


def median_time(function, repeats):
    times = []
    result = None
    for _ in range(repeats):
        clock = time.perf_counter()
        result = function()
        times.append(time.perf_counter() - clock)
    return statistics.median(times), result


def grid_section(repeats, queries):
    rng = np.random.default_rng(0)
    free = rng.random((512, 512)) > 0.25
    cells = np.argwhere(free)
    picks = cells[rng.choice(len(cells), size=2 * queries, replace=False)]
    pairs = [((int(a[1]), int(a[0])), (int(b[1]), int(b[0]))) for a, b in zip(picks[0::2], picks[1::2])]
    grid = trailmark.Grid(free)
    rows = []
    ours, inside, theirs, agree = [], [], [], 0
    try:
        from pathfinding.core.diagonal_movement import DiagonalMovement
        from pathfinding.core.grid import Grid as PfGrid
        from pathfinding.finder.a_star import AStarFinder
    except ImportError:
        PfGrid = None
    for start, goal in pairs:
        wall, plan = median_time(lambda: grid.astar(start, goal), repeats)
        ours.append(wall)
        inside.append(plan.stats["time_s"])
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
    rows.append(("A* 512x512, trailmark from Python (call)", statistics.median(ours)))
    rows.append(("A* 512x512, the same search inside Rust (time_s)", statistics.median(inside)))
    note = f"{statistics.median(ours) / statistics.median(inside):.2f}x the Rust search"
    if theirs:
        rows.append(("A* 512x512, pathfinding (pure Python)", statistics.median(theirs)))
        note += f"; pathfinding {statistics.median(theirs) / statistics.median(ours):.0f}x slower"
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
    bounds = [(0.0, 10.0), (0.0, 10.0)]
    obstacles = [(WALL_LO, WALL_HI)]
    seeds = range(repeats)
    calls, inside = [], []
    for seed in seeds:
        wall, plan = median_time(
            lambda: trailmark.plan_in_box(bounds, (1, 1), (9, 1), obstacles=obstacles, range=1.0, seed=seed), 1
        )
        calls.append(wall)
        inside.append(plan.stats["time_s"])
    rows = [
        ("RRT-Connect, box world, trailmark from Python (call)", statistics.median(calls)),
        ("RRT-Connect, box world, the planner inside Rust (time_s)", statistics.median(inside)),
    ]
    return rows, f"{statistics.median(calls) / statistics.median(inside):.2f}x the Rust planner"


def callback_section(repeats):
    bounds = [(0.0, 10.0), (0.0, 10.0)]
    extent = math.hypot(10.0, 10.0)
    fraction = 0.01  # OMPL's default longest valid segment: 1% of the extent
    step = fraction * extent
    rows = []
    times = {}
    for name, kwargs in (("batch", dict(batch=True)), ("one state per call", dict(batch=False))):
        function = wall_batch if kwargs["batch"] else (lambda s: wall_one(s))
        samples = []
        for seed in range(repeats):
            clock = time.perf_counter()
            plan = trailmark.plan_in_box(bounds, (1, 1), (9, 1), function, range=1.0, resolution=fraction, seed=seed,
                                         goal_bias=0.0, **kwargs)
            samples.append(time.perf_counter() - clock)
            assert plan.solved
        times[name] = statistics.median(samples)
        rows.append((f"RRT-Connect + Python validity, trailmark ({name})", times[name]))
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
            rows.append((f"RRT-Connect + Python validity, {name} (one state per call)", times[name]))
        except ImportError as e:
            rows.append((f"RRT-Connect + Python validity, {name}: not installed ({e})", float("nan")))
    best = times["batch"]
    note = "; ".join(f"{name} {t / best:.2f}x trailmark batch" for name, t in times.items() if name != "batch")
    return rows, note


def many_section(count):
    rows_text = ["." * 128] * 128
    rows_text = [r[:64] + ("@" if 8 <= y < 120 else ".") + r[65:] for y, r in enumerate(rows_text)]
    documents = [
        {
            "world": {"grid": {"rows": rows_text}},
            "start": [i % 60, (7 * i) % 128],
            "goal": [127 - i % 60, (11 * i) % 128],
            "planner": {"name": "astar"},
        }
        for i in range(count)
    ]
    loop, _ = median_time(lambda: [trailmark.solve(d) for d in documents], 1)
    many, _ = median_time(lambda: trailmark.solve_many(documents), 1)
    rows = [(f"solve in a loop, {count} grid documents", loop), (f"solve_many, {count} grid documents", many)]
    return rows, f"solve_many {loop / many:.2f}x solve in a loop"


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
        box_section(repeats * 5),
        callback_section(repeats * 5),
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
