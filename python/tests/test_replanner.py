"""Replanners from Python: after every change of costs and move of the robot, each plan costs
what scipy's Dijkstra finds from the robot's cell on the changed grid."""

import numpy as np
import pytest

import trailmark
from test_grid import check_path, csgraph_distances


@pytest.mark.parametrize("planner", ["dstar_lite", "lpa_star", "mpgaa_star", "adaptive_astar", "astar"])
@pytest.mark.parametrize("seed", range(3))
def test_replans_equal_dijkstra_from_scratch(planner, seed):
    pytest.importorskip("scipy", reason="scipy is not installed")
    rng = np.random.default_rng(seed)
    costs = rng.uniform(1.0, 3.0, size=(24, 24))
    costs[rng.random(costs.shape) < 0.15] = np.inf
    start, goal = (0, 0), (23, 23)
    costs[0, 0] = costs[23, 23] = 1.0
    robot = trailmark.Replanner(trailmark.Grid(costs), start, goal, planner)
    here = start
    for _ in range(8):
        plan = robot.plan()
        expected = csgraph_distances(costs, 8, [here])[0][goal[1] * 24 + goal[0]]
        if np.isinf(expected):
            assert plan.status == "no_path"
        else:
            assert plan.solved and plan.cost == pytest.approx(expected, rel=1e-9)
            check_path(None, costs, plan, here, goal, 8)
        assert np.array_equal(robot.costs(), costs)
        # New costs and walls near the path, as a robot's sensor finds them.
        cells = rng.integers(0, 24, size=(12, 2))
        cells = cells[[tuple(c) not in (here, goal) for c in cells.tolist()]]
        values = np.where(rng.random(len(cells)) < 0.4, np.inf, rng.uniform(1.0, 3.0, len(cells)))
        robot.set_costs(cells, values)
        costs[cells[:, 1], cells[:, 0]] = values
        step = robot.next_step() if plan.solved else None
        if step is not None and np.isfinite(costs[step[1], step[0]]):
            robot.move_to(step)
            here = step


def test_replanner_errors():
    grid = trailmark.Grid.from_rows(["....", ".@..", "...."])
    with pytest.raises(trailmark.DocumentError, match="does not replan"):
        trailmark.Replanner(grid, (0, 0), (3, 2), "dijkstra")
    with pytest.raises(trailmark.DocumentError, match="blocked"):
        trailmark.Replanner(grid, (1, 1), (3, 2))
    with pytest.raises(TypeError):
        trailmark.Replanner(np.ones((3, 3), dtype=bool), (0, 0), (2, 2))
    robot = trailmark.Replanner(grid, (0, 0), (3, 2))
    with pytest.raises(trailmark.GridError):
        robot.set_costs([(9, 9)], 1.0)
    with pytest.raises(trailmark.GridError):
        robot.set_costs([(2, 2), (3, 1)], [1.0, -2.0])  # the second is refused: none applied
    assert robot.costs()[2, 2] == 1.0
    with pytest.raises(trailmark.DocumentError):
        robot.set_costs([(2.5, 2)], 1.0)
    with pytest.raises(trailmark.DocumentError):
        robot.set_costs([1, 2, 3], 1.0)
    robot.set_costs([], [])
    assert robot.plan().solved
