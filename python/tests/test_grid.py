"""Grid searches from Python, checked against what no one here wrote: MovingAI's published
optima, and Dijkstra of scipy.sparse.csgraph on random cost grids."""

import math

import numpy as np
import pytest

import trailmark
from conftest import MOVINGAI, need

SQRT2 = math.sqrt(2.0)


def read_scenarios(path):
    """(start, goal, optimal length) of a MovingAI .scen file, parsed here from its format."""
    rows = []
    for line in path.read_text().splitlines()[1:]:
        fields = line.split()
        if len(fields) < 9:
            continue
        sx, sy, gx, gy = (int(v) for v in fields[4:8])
        rows.append(((sx, sy), (gx, gy), float(fields[8])))
    return rows


@pytest.mark.parametrize(
    "family,name,every",
    [
        ("dao", "arena.map", 25),
        ("rooms", "32room_000.map", 50),
        ("mazes", "maze512-4-0.map", 200),
        ("bg512", "AR0011SR.map", 50),
    ],
)
def test_movingai_published_optima(family, name, every):
    """A*, JPS, JPS+ and Dijkstra find MovingAI's published optimal lengths (rounded: the
    tolerance of the project's design notes) on every `every`th scenario."""
    map_path = need(MOVINGAI / "maps" / family / name, "the MovingAI maps")
    scen_path = need(MOVINGAI / "scenarios" / family / f"{name}.scen", "the MovingAI scenarios")
    grid = trailmark.Grid.from_movingai(map_path)
    scenarios = read_scenarios(scen_path)[::every]
    assert scenarios, f"no scenarios read from {scen_path}"
    for start, goal, optimum in scenarios:
        tolerance = 1e-4 * max(1.0, optimum) + 0.006
        for planner in ("astar", "jps", "jps_plus", "dijkstra"):
            plan = grid.plan(start, goal, planner)
            assert plan.solved, (planner, start, goal)
            assert abs(plan.cost - optimum) <= tolerance, (planner, start, goal, plan.cost, optimum)
            assert tuple(plan.path[0]) == start and tuple(plan.path[-1]) == goal


def csgraph_distances(costs, connectivity, sources, unweighted=False):
    """Shortest path costs from `sources` by scipy's Dijkstra, on the graph built here from the
    grid's rule: a move costs its length times the mean of its two cells' costs; diagonals only
    when both orthogonal neighbours are free."""
    scipy_sparse = pytest.importorskip("scipy.sparse", reason="scipy is not installed")
    from scipy.sparse.csgraph import dijkstra

    h, w = costs.shape
    index = np.arange(h * w).reshape(h, w)
    free = np.isfinite(costs)
    rows, cols, weights = [], [], []
    steps = [(0, 1), (1, 0), (0, -1), (-1, 0)]
    if connectivity == 8:
        steps += [(1, 1), (1, -1), (-1, 1), (-1, -1)]
    for dy, dx in steps:
        y0, y1 = max(0, -dy), h - max(0, dy)
        x0, x1 = max(0, -dx), w - max(0, dx)
        a = (slice(y0, y1), slice(x0, x1))
        b = (slice(y0 + dy, y1 + dy), slice(x0 + dx, x1 + dx))
        ok = free[a] & free[b]
        if dx and dy:
            ok &= free[(slice(y0, y1), slice(x0 + dx, x1 + dx))] & free[(slice(y0 + dy, y1 + dy), slice(x0, x1))]
        length = SQRT2 if dx and dy else 1.0
        rows.append(index[a][ok])
        cols.append(index[b][ok])
        weights.append(length * (costs[a][ok] + costs[b][ok]) / 2.0)
    graph = scipy_sparse.csr_matrix(
        (np.concatenate(weights), (np.concatenate(rows), np.concatenate(cols))), shape=(h * w, h * w)
    )
    return dijkstra(graph, indices=[y * w + x for x, y in sources], unweighted=unweighted)


@pytest.mark.parametrize("connectivity", [4, 8])
@pytest.mark.parametrize("seed", range(6))
def test_costs_equal_scipy_dijkstra(connectivity, seed):
    """On random cost grids with obstacles, A*, Dijkstra and the replanners' first plans cost
    what scipy's Dijkstra finds, and no path exactly where scipy finds none."""
    rng = np.random.default_rng(seed)
    h, w = rng.integers(5, 40, size=2)
    costs = rng.uniform(1.0, 5.0, size=(h, w))
    costs[rng.random((h, w)) < 0.25] = np.inf
    grid = trailmark.Grid(costs, connectivity=connectivity)
    free = np.argwhere(np.isfinite(costs))
    picks = free[rng.choice(len(free), size=min(6, len(free)), replace=False)]
    sources = [(int(x), int(y)) for y, x in picks]
    distances = csgraph_distances(costs, connectivity, sources)
    for i, start in enumerate(sources):
        for goal in sources:
            expected = distances[i][goal[1] * w + goal[0]]
            for planner in ("astar", "dijkstra", "dstar_lite", "lpa_star", "mpgaa_star", "adaptive_astar"):
                plan = grid.plan(start, goal, planner)
                if np.isinf(expected):
                    assert plan.status == "no_path" and plan.cost is None, (planner, start, goal)
                else:
                    assert plan.solved, (planner, start, goal)
                    assert plan.cost == pytest.approx(expected, rel=1e-9, abs=1e-9), (planner, start, goal)
                    check_path(grid, costs, plan, start, goal, connectivity)


def check_path(grid, costs, plan, start, goal, connectivity):
    """The path's cells are free neighbours from start to goal, and its cost is their sum."""
    path = plan.path
    assert path.dtype == np.int64 and path.shape[1] == 2
    assert tuple(path[0]) == start and tuple(path[-1]) == goal
    total = 0.0
    for (x0, y0), (x1, y1) in zip(path[:-1], path[1:]):
        dx, dy = abs(x1 - x0), abs(y1 - y0)
        assert max(dx, dy) == 1 and (connectivity == 8 or dx + dy == 1)
        assert np.isfinite(costs[y1, x1])
        if dx and dy:
            assert np.isfinite(costs[y0, x1]) and np.isfinite(costs[y1, x0])
        total += (SQRT2 if dx and dy else 1.0) * (costs[y0, x0] + costs[y1, x1]) / 2.0
    assert total == pytest.approx(plan.cost, rel=1e-9)


def test_bfs_counts_moves_as_unweighted_dijkstra():
    """BFS's moves equal the fewest hops of scipy's unweighted shortest paths."""
    pytest.importorskip("scipy", reason="scipy is not installed")
    rng = np.random.default_rng(7)
    for _ in range(5):
        free = rng.random((30, 30)) > 0.3
        free[0, 0] = free[29, 29] = True
        costs = np.where(free, 1.0, np.inf)
        grid = trailmark.Grid(free)
        hops = csgraph_distances(costs, 8, [(0, 0)], unweighted=True)[0][-1]
        plan = grid.bfs((0, 0), (29, 29))
        if np.isinf(hops):
            assert plan.status == "no_path"
        else:
            assert plan.solved and len(plan.path) - 1 == hops
            check_path(grid, costs, plan, (0, 0), (29, 29), 8)


def test_theta_star_is_never_longer_than_the_grid_path():
    """Any-angle paths are at most as long as 8-connected ones on an occupancy grid, and on
    it their cost is the sum of their straight legs' lengths."""
    rng = np.random.default_rng(3)
    free = rng.random((40, 40)) > 0.2
    free[0, 0] = free[39, 39] = True
    grid = trailmark.Grid(free)
    octile = grid.astar((0, 0), (39, 39))
    theta = grid.theta_star((0, 0), (39, 39))
    assert theta.status == octile.status
    if octile.solved:
        assert theta.cost <= octile.cost + 1e-9
        legs = np.diff(theta.path.astype(float), axis=0)
        assert theta.cost == pytest.approx(np.hypot(legs[:, 0], legs[:, 1]).sum(), rel=1e-12)
        assert tuple(theta.path[0]) == (0, 0) and tuple(theta.path[-1]) == (39, 39)


def test_arrays_and_conversions():
    free = np.ones((3, 5), dtype=bool)
    free[1, 2] = False
    grid = trailmark.Grid(free, connectivity=4)
    assert grid.shape == (3, 5) and grid.width == 5 and grid.height == 3
    assert grid.connectivity == 4 and not grid.corner_cutting
    assert np.array_equal(grid.free(), free)
    assert np.isinf(grid.costs()[1, 2]) and grid.costs()[0, 0] == 1.0
    # Integer and Fortran-ordered arrays are read as costs, views too.
    costs = np.asfortranarray(np.full((4, 4), 2, dtype=np.int32))
    assert trailmark.Grid(costs).astar((0, 0), (3, 0)).cost == 6.0
    assert trailmark.Grid(np.ones((8, 8), dtype=bool)[::2, ::2]).shape == (4, 4)
    # The grid world of a document plans the same.
    world = grid.world()
    result = trailmark.solve({"world": {"grid": world}, "start": [0, 1], "goal": [4, 1], "planner": {"name": "astar"}})
    assert result["cost"] == grid.astar((0, 1), (4, 1)).cost


@pytest.mark.parametrize(
    "make,error",
    [
        (lambda: trailmark.Grid(np.ones((0, 3), dtype=bool)), trailmark.GridError),
        (lambda: trailmark.Grid(np.ones(5, dtype=bool)), trailmark.GridError),
        (lambda: trailmark.Grid(np.array([[1.0, -1.0]])), trailmark.GridError),
        (lambda: trailmark.Grid(np.array([[1.0, np.nan]])), trailmark.GridError),
        (lambda: trailmark.Grid(np.array([["a"]])), trailmark.GridError),
        (lambda: trailmark.Grid(np.ones((2, 2), dtype=bool), connectivity=6), trailmark.GridError),
        (lambda: trailmark.Grid.from_movingai("/nonexistent/x.map"), trailmark.ReadError),
        (lambda: trailmark.Grid.from_rows(["..", "."]), trailmark.GridError),
    ],
)
def test_bad_grids_raise_typed_errors(make, error):
    with pytest.raises(error):
        make()


def test_cells_are_whole_numbers_never_truncated():
    grid = trailmark.Grid.from_rows(["...", "...", "..."])
    assert grid.astar((0.0, 0), (np.int64(2), np.uint8(2))).cost == grid.astar((0, 0), (2, 2)).cost
    for bad in [(0.2, 0), (2.9, 2.7), "00", (0,), (0, 0, 0), (float("nan"), 0), (float("inf"), 0), (2**70, 0), (-1, 0), None]:
        with pytest.raises(trailmark.DocumentError):
            grid.astar(bad, (2, 2))


def test_arrays_are_read_in_place_and_sizes_checked_first():
    # A 1-byte broadcast view of 2**28 + 1 cells: refused before anything is allocated.
    huge = np.broadcast_to(np.True_, (1, 2**28 + 1))
    with pytest.raises(trailmark.GridError, match="too large"):
        trailmark.Grid(huge)
    with pytest.raises(trailmark.GridError):
        trailmark.Grid(np.broadcast_to(1.0, (2**15, 2**14)))
    # A strided view plans as its copy does.
    free = np.ones((20, 20), dtype=bool)
    free[5, :18] = False
    view = free[::2, ::2]
    assert trailmark.Grid(view).astar((0, 0), (9, 9)).cost == trailmark.Grid(view.copy()).astar((0, 0), (9, 9)).cost
    for bad in [np.array([[1 + 1j]]), np.array([[np.timedelta64(1, "s")]]), np.array([[None]])]:
        with pytest.raises(trailmark.GridError):
            trailmark.Grid(bad)
    for connectivity in (300, 6, True, 8.5):
        with pytest.raises(trailmark.GridError):
            trailmark.Grid(free, connectivity=connectivity)
    with pytest.raises(trailmark.GridError):
        trailmark.Grid.from_rows("...")


def test_grids_and_plans_are_picklable_and_comparable():
    import pickle

    costs = np.array([[1.0, 2.0, np.inf], [1.0, 3.0, 1.0]])
    grid = trailmark.Grid(costs, connectivity=4)
    copy = pickle.loads(pickle.dumps(grid))
    assert np.array_equal(copy.costs(), grid.costs()) and copy.connectivity == 4
    plan = grid.dijkstra((0, 0), (2, 1))
    assert plan == plan and plan != grid.dijkstra((0, 0), (2, 1))  # identity, no array truth
    assert copy.dijkstra((0, 0), (2, 1)).cost == plan.cost


def test_bad_queries_raise_typed_errors():
    grid = trailmark.Grid.from_rows(["...", ".@.", "..."])
    with pytest.raises(trailmark.DocumentError, match="blocked"):
        grid.astar((0, 0), (1, 1))
    with pytest.raises(trailmark.DocumentError, match="outside"):
        grid.astar((0, 0), (3, 0))
    with pytest.raises(trailmark.DocumentError):
        grid.astar((-1, 0), (2, 2))
    with pytest.raises(trailmark.DocumentError):
        grid.plan((0, 0), (2, 2), "no_such_planner")
    with pytest.raises(trailmark.DocumentError):
        grid.plan((0, 0), (2, 2), "astar", heuristic="manhattan")  # overestimates on 8-connected
    with pytest.raises(trailmark.DocumentError):
        grid.plan((0, 0), (2, 2), "rrt_connect")
    with pytest.raises(TypeError):
        grid.plan((0, 0), (2, 2), "astar", name="dijkstra")
    with pytest.raises(trailmark.DocumentError, match="finite"):
        grid.plan((0, 0), (2, 2), "weighted_astar", weight=float("inf"))
    with pytest.raises(trailmark.SearchError, match="uniform costs"):
        trailmark.Grid(np.array([[1.0, 2.0, 1.0]] * 3), connectivity=8).jps((0, 0), (2, 2))
    # Every one of them is also a ValueError and a TrailmarkError.
    with pytest.raises(ValueError):
        grid.astar((0, 0), (1, 1))
    with pytest.raises(trailmark.TrailmarkError):
        grid.astar((0, 0), (1, 1))


def test_one_grid_answers_every_planner_in_any_order_as_a_new_grid_does():
    """The grid keeps one search workspace for every query: any order of planners gives the
    answers of a grid made for each query."""
    rng = np.random.default_rng(11)
    free = rng.random((40, 40)) > 0.25
    free[0, 0] = free[39, 39] = free[0, 39] = True
    kept = trailmark.Grid(free)
    order = ["theta_star", "astar", "bfs", "jps", "theta_star", "dijkstra", "dfs", "jps_plus", "astar", "theta_star"]
    for i, planner in enumerate(order):
        goal = [(39, 39), (39, 0), (20, 20)][i % 3]
        if not free[goal[1], goal[0]]:
            continue
        ours = kept.plan((0, 0), goal, planner)
        fresh = trailmark.Grid(free).plan((0, 0), goal, planner)
        assert ours.status == fresh.status and ours.cost == fresh.cost, planner
        assert np.array_equal(ours.path, fresh.path), planner
