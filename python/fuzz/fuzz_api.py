"""A fuzz target for the Python API (atheris): hostile arrays, cells, settings, callbacks and
documents given to Grid, Replanner, plan_in_box, RosMap, RobotWorld and solve.

Every call must either return a plan that holds (its ends where asked, its cells free, its
states valid) or raise one of the exceptions the API documents: a ``TrailmarkError``, or the
``TypeError`` / ``ValueError`` / ``OverflowError`` of an argument Python cannot take as it is.
Anything else fails the run: another exception, a panic inside the extension (an "internal
error" ``SolveError``, or pyo3's ``PanicException``), a crash or a hang.

    pip install atheris ./python
    python python/fuzz/fuzz_api.py -runs=20000 -seed=1    # from the repository's root

(``.ci/fuzz-python`` runs a fixed-seed campaign.) The arguments after the script are
libFuzzer's.
"""

import math
import sys
from pathlib import Path

import atheris

with atheris.instrument_imports():
    import numpy as np

    import trailmark

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
EXPECTED = (trailmark.TrailmarkError, TypeError, ValueError, OverflowError)
GRID_PLANNERS = ["astar", "dijkstra", "bfs", "dfs", "jps", "jps_plus", "theta_star", "weighted_astar",
                 "lpa_star", "dstar_lite", "ara_star", "ad_star", "rrt", "hybrid_astar", "nonsense"]
# The sampling planners, then two names that are not (every input must plan or be refused).
SAMPLING = ["rrt", "rrt_connect", "rrt_star", "informed_rrt_star", "bit_star", "prm", "prm_star", "lazy_prm", "lazy_prm_star"]
SAMPLING_PLANNERS = SAMPLING + ["astar", "nonsense"]
REPLANNERS = ["dstar_lite", "lpa_star", "mpgaa_star", "adaptive_astar", "ad_star", "astar", "bfs"]
_ARM = []


def allowed(error):
    """An exception the API documents for a bad argument; a panic inside the extension (a
    `SolveError` saying "internal error") is a bug, whatever the input."""
    if "internal error" in str(error):
        raise AssertionError(f"a panic inside the extension: {error!r}") from error


def hostile_float(fdp):
    """A float from a list that breaks naive code, or any double."""
    choice = fdp.ConsumeIntInRange(0, 9)
    specials = [0.0, -0.0, math.nan, math.inf, -math.inf, 1e-300, -1.0, 1e308, 0.5]
    if choice < len(specials):
        return specials[choice]
    return fdp.ConsumeRegularFloat()


def number(fdp):
    """An int, a float or something that is not a number at all."""
    kind = fdp.ConsumeIntInRange(0, 5)
    if kind == 0:
        return fdp.ConsumeIntInRange(-5, 70)
    if kind == 1:
        return fdp.ConsumeInt(9)  # up to 2**71: beyond every integer type
    if kind == 2:
        return hostile_float(fdp)
    if kind == 3:
        return fdp.ConsumeUnicodeNoSurrogates(3)
    if kind == 4:
        return None
    return fdp.ConsumeProbability() * 10.0


def point(fdp, dims):
    n = dims if fdp.ConsumeIntInRange(0, 7) else fdp.ConsumeIntInRange(0, 4)
    return tuple(number(fdp) if fdp.ConsumeIntInRange(0, 9) == 0 else fdp.ConsumeProbability() * 10.0
                 for _ in range(n))


def settings(fdp, planner):
    """`planner`'s settings: one time in eight any names with hostile values, else settings
    the planner takes with values in range, so that most inputs are planned."""
    out = {}
    if fdp.ConsumeIntInRange(0, 7) == 0:
        names = ["max_iterations", "time_limit_s", "range", "goal_bias", "simplify", "heuristic", "weight",
                 "epsilon", "max_expansions", "turning_radius", "sampler", "colour"]
        for _ in range(fdp.ConsumeIntInRange(1, 3)):
            name = names[fdp.ConsumeIntInRange(0, len(names) - 1)]
            value = number(fdp)
            if name == "max_iterations" and isinstance(value, int) and fdp.ConsumeBool():
                value = min(abs(value), 500)
            if name == "time_limit_s" and isinstance(value, float) and not (0.0 <= value <= 0.2):
                value = 0.05
            if name == "sampler":
                value = {"name": ["uniform", "bridge", "gaussian", "x"][fdp.ConsumeIntInRange(0, 3)],
                         "std_dev": number(fdp)}
            out[name] = value
    elif planner in SAMPLING:
        if fdp.ConsumeBool():
            out["simplify"] = fdp.ConsumeBool()
        if (planner.startswith("rrt") or planner == "informed_rrt_star") and fdp.ConsumeBool():
            out["range"] = 0.05 + 5.0 * fdp.ConsumeProbability()
            out["goal_bias"] = fdp.ConsumeProbability()
        if fdp.ConsumeIntInRange(0, 3) == 0:
            out["sampler"] = {"name": "bridge", "std_dev": 0.1 + fdp.ConsumeProbability()}
    elif planner in ("weighted_astar",):
        out["weight"] = 1.0 + 3.0 * fdp.ConsumeProbability()
    elif planner in ("ara_star", "ad_star") and fdp.ConsumeBool():
        out["epsilon"] = 1.0 + 3.0 * fdp.ConsumeProbability()
    elif planner == "hybrid_astar":
        out["turning_radius"] = 0.2 + 2.0 * fdp.ConsumeProbability()
    # Bounded work: an iteration limit on every sampling planner, an expansion limit on Hybrid A*.
    if planner in SAMPLING:
        out.setdefault("max_iterations", 300)
    elif planner == "hybrid_astar":
        out.setdefault("max_expansions", 2000)
    return out


def grid_array(fdp):
    height, width = fdp.ConsumeIntInRange(0, 12), fdp.ConsumeIntInRange(0, 12)
    kind = fdp.ConsumeIntInRange(0, 5)
    if kind == 0:
        return np.array(fdp.ConsumeIntListInRange(height * width, 0, 1), dtype=bool).reshape(height, width)
    if kind == 1:
        values = [hostile_float(fdp) if fdp.ConsumeIntInRange(0, 6) == 0 else 1.0 + fdp.ConsumeProbability()
                  for _ in range(height * width)]
        return np.array(values, dtype=np.float64).reshape(height, width)
    if kind == 2:
        return np.array(fdp.ConsumeIntListInRange(height * width, -3, 300), dtype=np.int64).reshape(height, width)
    if kind == 3:  # a view with strides, transposed
        return np.ones((width + 1, height + 1), dtype=bool)[::2].T
    if kind == 4:
        return np.zeros((height, width, 2))
    return [[fdp.ConsumeBool() for _ in range(width)] for _ in range(height)]


def check_grid_plan(grid, plan, start, goal):
    if plan.status != "solved":
        return
    path = plan.path
    assert path.shape[1] == 2 and tuple(path[0]) == tuple(start) and tuple(path[-1]) == tuple(goal), plan
    free = grid.free()
    for x, y in path:
        assert free[y, x], f"the path crosses the blocked cell {(x, y)}"
    assert plan.cost is not None and plan.cost >= 0.0 and math.isfinite(plan.cost), plan.cost


def cell(fdp, grid_shape):
    if fdp.ConsumeIntInRange(0, 7) == 0:
        return point(fdp, 2)
    height, width = grid_shape
    return (fdp.ConsumeIntInRange(-1, width), fdp.ConsumeIntInRange(-1, height))


def fuzz_grid(fdp):
    grid = trailmark.Grid(grid_array(fdp), connectivity=[8, 4, 6][fdp.ConsumeIntInRange(0, 2)],
                          corner_cutting=fdp.ConsumeBool())
    for _ in range(fdp.ConsumeIntInRange(1, 3)):
        start, goal = cell(fdp, grid.shape), cell(fdp, grid.shape)
        planner = GRID_PLANNERS[fdp.ConsumeIntInRange(0, len(GRID_PLANNERS) - 1)]
        try:
            plan = grid.plan(start, goal, planner, **settings(fdp, planner))
        except EXPECTED as error:
            allowed(error)
            continue
        check_grid_plan(grid, plan, start, goal)
    if fdp.ConsumeBool():
        replanner = trailmark.Replanner(grid, cell(fdp, grid.shape), cell(fdp, grid.shape),
                                        REPLANNERS[fdp.ConsumeIntInRange(0, len(REPLANNERS) - 1)])
        for _ in range(fdp.ConsumeIntInRange(0, 3)):
            action = fdp.ConsumeIntInRange(0, 3)
            try:
                if action == 0:
                    replanner.plan()
                elif action == 1:
                    replanner.set_costs([cell(fdp, grid.shape)], hostile_float(fdp))
                elif action == 2:
                    replanner.move_to(cell(fdp, grid.shape))
                else:
                    replanner.next_step()
            except EXPECTED as error:
                allowed(error)


def fuzz_box(fdp):
    dims = fdp.ConsumeIntInRange(0, 9)
    bounds = [(0.0, 10.0) if fdp.ConsumeIntInRange(0, 5) else (number(fdp), number(fdp)) for _ in range(dims)]
    answer = fdp.ConsumeIntInRange(0, 5)

    def is_valid(states):
        if answer == 0:  # everything free, in the form asked
            return np.ones(len(states), dtype=bool) if states.ndim == 2 else True
        if answer == 1:
            return 0.5  # not a boolean
        if answer == 2:
            raise RuntimeError("the user's function failed")
        if answer == 3:
            return np.ones(3, dtype=bool)  # a batch of the wrong length
        if answer == 4:
            return "yes"
        return np.ones(len(states), dtype=np.uint8) if states.ndim == 2 else 1  # 0/1 answers

    function = is_valid if fdp.ConsumeBool() else None
    batch = fdp.ConsumeBool()
    start, goal = point(fdp, dims), point(fdp, dims)
    planner = SAMPLING_PLANNERS[fdp.ConsumeIntInRange(0, len(SAMPLING_PLANNERS) - 1)]
    obstacles = [(point(fdp, dims), point(fdp, dims)) for _ in range(fdp.ConsumeIntInRange(0, 2))]
    try:
        plan = trailmark.plan_in_box(bounds, start, goal, function, obstacles=obstacles, planner=planner, batch=batch,
                                     resolution=[0.01, 0.0, -1.0, math.nan, 1e-12, 0.5][fdp.ConsumeIntInRange(0, 5)],
                                     seed=fdp.ConsumeIntInRange(0, 3), **settings(fdp, planner))
    except RuntimeError as error:
        if answer != 2 or function is None:
            raise
        assert "the user's function failed" in str(error)
        return
    except EXPECTED as error:
        allowed(error)
        return
    if plan.status == "solved":
        assert np.allclose(plan.path[0], start) and np.allclose(plan.path[-1], goal), plan


def fuzz_ros_map(fdp):
    values = {"robot_radius": number(fdp), "inflation_radius": number(fdp), "cost_scaling_factor": number(fdp),
              "cost_factor": number(fdp)}
    chosen = {k: v for k, v in values.items() if fdp.ConsumeBool()}
    office = trailmark.RosMap(EXAMPLES / "maps" / "office.yaml", **chosen)
    planner = GRID_PLANNERS[fdp.ConsumeIntInRange(0, len(GRID_PLANNERS) - 1)]
    left, right, bottom, top = office.extent()

    def place():
        if fdp.ConsumeIntInRange(0, 7) == 0:
            return point(fdp, 2)
        return (left + (right - left) * fdp.ConsumeProbability(), bottom + (top - bottom) * fdp.ConsumeProbability())

    try:
        office.plan(place(), place(), planner, **settings(fdp, planner))
    except EXPECTED as error:
        allowed(error)


def fuzz_robot(fdp):
    if not _ARM:
        robot = EXAMPLES / "problems" / "robot"
        for checker in ("batch", "scalar"):
            _ARM.append(trailmark.RobotWorld(robot / "arm.urdf", robot / "arm.srdf", "arm",
                                             scene=robot / "shelf.yaml", checker=checker))
    arm = _ARM[fdp.ConsumeIntInRange(0, 1)]
    rows = fdp.ConsumeIntInRange(0, 20)
    columns = 4 if fdp.ConsumeIntInRange(0, 5) else fdp.ConsumeIntInRange(0, 6)
    low, high = arm.limits[:, 0], arm.limits[:, 1]
    values = [hostile_float(fdp) if fdp.ConsumeIntInRange(0, 3) == 0 else -4.0 + 8.0 * fdp.ConsumeProbability()
              for _ in range(rows * columns)]
    states = np.array(values, dtype=np.float64).reshape(rows, columns)
    layout = fdp.ConsumeIntInRange(0, 3)
    if layout == 1:
        states = np.asfortranarray(states)
    elif layout == 2 and rows:
        states = np.repeat(states, 2, axis=0)[::2]  # a strided view
    elif layout == 3:
        states = states.astype(np.float32)
    try:
        free = arm.is_valid(states)
        assert free.shape == (rows,)
        inside = (np.isfinite(states) & (states >= low) & (states <= high)).all(axis=1)
        assert not (free & ~inside).any(), "a state beyond the limits or not finite was called free"
        # One by one as in a batch.
        assert [arm.is_valid(q) for q in states[:9]] == free[:9].tolist()
        if rows >= 2:
            arm.motion_is_valid(states[0], states[1])
    except EXPECTED as error:
        allowed(error)
    planner = SAMPLING_PLANNERS[fdp.ConsumeIntInRange(0, len(SAMPLING_PLANNERS) - 1)]
    # Mostly states within the limits (free or not), now and then anything.
    low, high = arm.limits[:, 0], arm.limits[:, 1]
    start, goal = (
        tuple(low + (high - low) * np.array([fdp.ConsumeProbability() for _ in range(4)]))
        if fdp.ConsumeIntInRange(0, 4) else point(fdp, 4)
        for _ in range(2)
    )
    try:
        plan = arm.plan(start, goal, planner, seed=fdp.ConsumeIntInRange(0, 3), **settings(fdp, planner))
    except EXPECTED as error:
        allowed(error)
        return
    if plan.status == "solved":
        assert arm.is_valid(plan.path).all(), "a planned state is in collision"
        assert all(arm.motion_is_valid(a, b) for a, b in zip(plan.path[:-1], plan.path[1:])), "a blocked motion"
        # The ends, within the limits' tolerance and continuous joints taken by whole turns.
        for asked, got in ((start, plan.path[0]), (goal, plan.path[-1])):
            turns = np.round((np.asarray(asked) - got) / (2 * np.pi)) * 2 * np.pi
            assert np.allclose(np.asarray(asked) - turns, got, atol=1e-3), (asked, got)


def fuzz_document(fdp):
    world = [{"grid": {"rows": ["...", ".@.", "..."]}}, {"boxes": {"bounds": [[0, 1], [0, 1]]}},
             {"polygons": {"bounds": [0, 0, 10, 10], "obstacles": [[[4, 0], [6, 0], [6, 8], [4, 8]]]}},
             {"grid": {"map": "no-such.map"}}, number(fdp)][fdp.ConsumeIntInRange(0, 4)]
    names = GRID_PLANNERS + SAMPLING_PLANNERS
    name = names[fdp.ConsumeIntInRange(0, len(names) - 1)]
    planner = {"name": name, **settings(fdp, name)}
    document = {"world": world, "start": list(point(fdp, 2)), "goal": list(point(fdp, 2)), "planner": planner,
                "seed": number(fdp)}
    if fdp.ConsumeIntInRange(0, 3) == 0:
        del document[["world", "start", "goal", "planner", "seed"][fdp.ConsumeIntInRange(0, 4)]]
    try:
        if fdp.ConsumeBool():
            trailmark.solve(document)
        else:
            for report in trailmark.solve_many([document, document], workers=fdp.ConsumeIntInRange(0, 3)):
                if report["status"] == "error":
                    assert "internal error" not in report["error"], report
    except EXPECTED as error:
        allowed(error)


TARGETS = [fuzz_grid, fuzz_box, fuzz_ros_map, fuzz_robot, fuzz_document]


def test_one_input(data):
    fdp = atheris.FuzzedDataProvider(data)
    target = TARGETS[fdp.ConsumeIntInRange(0, len(TARGETS) - 1)]
    try:
        target(fdp)
    except EXPECTED as error:  # raised outside the guarded calls: an argument refused early
        allowed(error)


if __name__ == "__main__":
    atheris.Setup(sys.argv, test_one_input)
    atheris.Fuzz()
