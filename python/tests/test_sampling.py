"""Sampling planners with a Python validity function, one state or a batch per call."""

import time

import numpy as np
import pytest

import trailmark
from conftest import sigint_after

BOUNDS = [(0.0, 10.0), (0.0, 10.0)]


def wall(states, grow=0.0):
    """Free outside the wall x in [4.5, 5.5], y <= 8, grown by `grow` (a batch of states)."""
    x, y = states[:, 0], states[:, 1]
    return ~((x >= 4.5 - grow) & (x <= 5.5 + grow) & (y <= 8.0 + grow))


def grown_wall(states):
    """The wall grown by 0.02: motions checked every 0.0283 (0.002 of the diagonal) between
    free states then never touch the wall itself."""
    return wall(states, grow=0.02)


def grown_wall_one(state):
    return bool(grown_wall(state[None, :])[0])


def path_is_free(path, resolution=1e-3):
    """Every leg free of the wall itself, sampled every `resolution` (here, not by trailmark)."""
    for a, b in zip(path[:-1], path[1:]):
        n = max(2, int(np.ceil(np.linalg.norm(b - a) / resolution)) + 1)
        states = a + np.linspace(0.0, 1.0, n)[:, None] * (b - a)
        if not wall(states).all():
            return False
    return True


@pytest.mark.parametrize("planner", ["rrt", "rrt_connect", "rrt_star", "informed_rrt_star", "bit_star", "prm", "prm_star", "lazy_prm", "lazy_prm_star"])
@pytest.mark.parametrize("batch", [False, True])
def test_plans_around_a_wall_the_world_does_not_know(planner, batch):
    check = grown_wall if batch else grown_wall_one
    # RRT* rewires through many motions, PRM* joins each sample to tens: fewer iterations when
    # each state is a call.
    iterations = {"rrt_star": 400, "informed_rrt_star": 400, "bit_star": 400, "prm_star": 300}.get(planner, 2000) if not batch else 2000
    plan = trailmark.plan_in_box(BOUNDS, (1, 1), (9, 1), check, planner=planner, batch=batch,
                                 resolution=2e-3, max_iterations=iterations)
    assert plan.solved, plan.stats
    assert plan.path.dtype == np.float64 and plan.path.shape[1] == 2
    assert np.allclose(plan.path[0], (1, 1)) and np.allclose(plan.path[-1], (9, 1))
    assert plan.path[:, 1].max() > 8.0  # over the wall's top
    assert path_is_free(plan.path, resolution=1e-3)
    legs = np.diff(plan.path, axis=0)
    assert plan.cost == pytest.approx(np.linalg.norm(legs, axis=1).sum())


def test_batch_and_single_calls_plan_the_same():
    """The same seed gives the same path whether the function sees one state or a batch."""
    one = trailmark.plan_in_box(BOUNDS, (1, 1), (9, 1), grown_wall_one, seed=4)
    many = trailmark.plan_in_box(BOUNDS, (1, 1), (9, 1), grown_wall, batch=True, seed=4)
    assert np.array_equal(one.path, many.path)
    assert one.stats["sampling"]["collision_checks"] == many.stats["sampling"]["collision_checks"]


def test_batches_are_the_motions_states():
    calls = []

    def record(states):
        calls.append(states.shape)
        return wall(states)

    trailmark.plan_in_box(BOUNDS, (1, 1), (9, 1), record, batch=True, resolution=0.01, seed=2)
    assert calls[0] == (1, 2)  # the start state alone
    assert max(n for n, _ in calls) > 1 and all(d == 2 for _, d in calls)
    assert max(n for n, _ in calls) <= 1024


def test_with_boxes_and_in_more_axes():
    """Eight axes, a box obstacle and a validity function together, both across the straight
    line from start to goal: every leg of the path avoids both (checked finely here)."""
    bounds = [(0.0, 1.0)] * 8
    box = ([0.2] * 8, [0.3] * 8)
    def ball(states):
        return np.linalg.norm(states - 0.6, axis=1) > 0.15
    plan = trailmark.plan_in_box(bounds, [0.05] * 8, [0.95] * 8, ball, obstacles=[box], batch=True,
                                 resolution=0.001, seed=3)
    assert plan.solved and plan.path.shape[1] == 8
    for a, b in zip(plan.path[:-1], plan.path[1:]):
        states = a + np.linspace(0.0, 1.0, 400)[:, None] * (b - a)
        assert ball(states).all()
        assert not np.any(np.all((states >= 0.2) & (states <= 0.3), axis=1))
    # Without a function: the box world alone, as a document would plan it.
    alone = trailmark.plan_in_box(bounds, [0.05] * 8, [0.95] * 8, obstacles=[box])
    assert alone.solved and alone.path.shape[1] == 8


def test_errors_of_the_function_are_raised():
    with pytest.raises(ZeroDivisionError):
        trailmark.plan_in_box(BOUNDS, (1, 1), (9, 1), lambda s: 1 / 0)
    with pytest.raises(trailmark.CallbackError, match="one boolean per state"):
        trailmark.plan_in_box(BOUNDS, (1, 1), (9, 1), lambda s: np.ones(1, dtype=bool), batch=True)
    with pytest.raises(trailmark.CallbackError):
        trailmark.plan_in_box(BOUNDS, (1, 1), (9, 1), lambda s: "yes", batch=True)
    # A distance is not an answer (it would let every state with a non-zero distance through).
    with pytest.raises(trailmark.CallbackError, match="dtype"):
        trailmark.plan_in_box(BOUNDS, (1, 1), (9, 1), lambda s: np.abs(s[:, 0] - 5) - 0.5, batch=True)
    with pytest.raises(trailmark.CallbackError):
        trailmark.plan_in_box(BOUNDS, (1, 1), (9, 1), lambda s: ["False"] * len(s), batch=True)
    with pytest.raises(trailmark.CallbackError):
        trailmark.plan_in_box(BOUNDS, (1, 1), (9, 1), lambda s: 0.7)
    # Integers 0 and 1 are answers.
    plan = trailmark.plan_in_box(BOUNDS, (1, 1), (9, 1), lambda s: grown_wall(s).astype(np.int8), batch=True)
    assert plan.solved and path_is_free(plan.path)
    with pytest.raises(TypeError):
        trailmark.plan_in_box(BOUNDS, (1, 1), (9, 1), "not callable")


def test_bad_problems_raise_typed_errors():
    with pytest.raises(trailmark.PlanError):  # the start is not valid
        trailmark.plan_in_box(BOUNDS, (5, 5), (9, 1), wall, batch=True)
    with pytest.raises(trailmark.DocumentError):
        trailmark.plan_in_box(BOUNDS, (1, 1, 1), (9, 1), wall, batch=True)
    with pytest.raises(trailmark.DocumentError):
        trailmark.plan_in_box([(0, 1)] * 9, [0.5] * 9, [0.6] * 9, lambda s: True)
    with pytest.raises(trailmark.DocumentError):
        trailmark.plan_in_box(BOUNDS, (1, 1), (9, 1), wall, planner="astar")
    with pytest.raises(trailmark.SpaceError):
        trailmark.plan_in_box(BOUNDS, (1, 1), (9, 1), wall, resolution=0.0)
    with pytest.raises(trailmark.DocumentError):
        trailmark.plan_in_box(BOUNDS, (1, 1), (9, 1), wall, time_limit_s=-1)
    with pytest.raises(trailmark.SpaceError):
        trailmark.plan_in_box(BOUNDS, (1, 1), (9, 1), wall, resolution=1e-300)
    with pytest.raises(trailmark.DocumentError, match="finite"):
        trailmark.plan_in_box(BOUNDS, (1, float("nan")), (9, 1), wall)
    with pytest.raises(trailmark.DocumentError):
        trailmark.plan_in_box(BOUNDS, (1, 1), (9, 1), wall, seed=1.5)


@pytest.mark.parametrize(
    "function,batch", [(wall, True), (np.logical_and.reduce, False)], ids=["python", "compiled"]
)
def test_ctrl_c_in_the_function_stops_the_planner(function, batch):
    """Ctrl-C ends a 60-second plan at once, whether the function runs Python code or is
    compiled (a ufunc's method runs no bytecode, where Python would look for signals)."""
    clock = time.perf_counter()
    sigint_after(0.3)
    with pytest.raises(KeyboardInterrupt):
        trailmark.plan_in_box(BOUNDS, (1, 1), (9, 1), function, batch=batch, planner="rrt_star", time_limit_s=60)
    assert time.perf_counter() - clock < 5.0
