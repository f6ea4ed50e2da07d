"""Sampling planners with a Python validity function, one state or a batch per call."""

import threading
import _thread
import time

import numpy as np
import pytest

import trailmark

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


@pytest.mark.parametrize("planner", ["rrt", "rrt_connect", "rrt_star"])
@pytest.mark.parametrize("batch", [False, True])
def test_plans_around_a_wall_the_world_does_not_know(planner, batch):
    check = grown_wall if batch else grown_wall_one
    plan = trailmark.plan_in_box(BOUNDS, (1, 1), (9, 1), check, planner=planner, batch=batch,
                                 resolution=2e-3, max_iterations=2000)
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
    """Eight axes, a box obstacle and a validity function together."""
    bounds = [(0.0, 1.0)] * 8
    box = ([0.4] * 8, [0.6] * 8)
    def sphere(states):
        return np.linalg.norm(states - 0.5, axis=1) > 0.1
    plan = trailmark.plan_in_box(bounds, [0.1] * 8, [0.9] * 8, sphere, obstacles=[box], batch=True)
    assert plan.solved and plan.path.shape[1] == 8
    for state in plan.path:
        assert not np.all((state >= 0.4) & (state <= 0.6))
    # Without a function: the box world alone, as a document would plan it.
    alone = trailmark.plan_in_box(bounds, [0.1] * 8, [0.9] * 8, obstacles=[box])
    assert alone.solved and alone.path.shape[1] == 8


def test_errors_of_the_function_are_raised():
    with pytest.raises(ZeroDivisionError):
        trailmark.plan_in_box(BOUNDS, (1, 1), (9, 1), lambda s: 1 / 0)
    with pytest.raises(trailmark.CallbackError, match="one boolean per state"):
        trailmark.plan_in_box(BOUNDS, (1, 1), (9, 1), lambda s: np.ones(1, dtype=bool), batch=True)
    with pytest.raises(trailmark.CallbackError):
        trailmark.plan_in_box(BOUNDS, (1, 1), (9, 1), lambda s: "yes", batch=True)
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


def test_ctrl_c_in_the_function_stops_the_planner():
    """A KeyboardInterrupt while Python runs the function ends a 60-second plan at once."""
    clock = time.perf_counter()
    threading.Timer(0.3, _thread.interrupt_main).start()
    with pytest.raises(KeyboardInterrupt):
        trailmark.plan_in_box(BOUNDS, (1, 1), (9, 1), wall, batch=True, planner="rrt_star", time_limit_s=60)
    assert time.perf_counter() - clock < 5.0
