"""Grids from NumPy arrays, MovingAI maps or rows of text, and the graph searches over them:
:class:`Grid`."""

import os
from typing import Any, Dict, Optional, Sequence, Tuple, Union

import numpy as np

from . import _args, _trailmark
from .errors import GridError
from .plan import Plan, _plan

__all__ = ["Grid"]

CellLike = Union[Tuple[int, int], Sequence[int], np.ndarray]


def _connectivity(value: Any) -> int:
    if value not in (4, 8) or isinstance(value, bool):
        raise GridError(f"connectivity must be 4 or 8, not {value!r}")
    return int(value)


class Grid:
    """A grid of cells, each free with a cost or blocked, moved on 4- or 8-connected
    (``connectivity``), diagonal moves never cutting a blocked cell's corner unless
    ``corner_cutting`` (MovingAI's rule). A move costs its length (1, or ``sqrt(2)``
    diagonally) times the mean of its two cells' costs.

    ``cells`` is a 2-D array indexed ``[row, column]``: booleans (``True`` where the robot may
    go, each such cell of cost 1) or numbers (each cell's cost, positive and finite, ``inf``
    where blocked; an occupancy array of 0 and 1 is ``Grid(occupancy == 0)``). Cells are named ``(x, y)``: ``x`` the column, ``y`` the
    row, as in MovingAI's files and in problem documents; a path's ``(n, 2)`` array indexes the
    grid as ``cells[path[:, 1], path[:, 0]]``.

    >>> import numpy as np, trailmark
    >>> free = np.ones((3, 4), dtype=bool)
    >>> free[1, 1:3] = False                  # a wall in the middle row
    >>> grid = trailmark.Grid(free)
    >>> plan = grid.astar((0, 1), (3, 1))
    >>> plan.cost, plan.path.tolist()
    (5.0, [[0, 1], [0, 0], [1, 0], [2, 0], [3, 0], [3, 1]])
    """

    def __init__(self, cells: Any, *, connectivity: int = 8, corner_cutting: bool = False) -> None:
        array = np.asarray(cells)
        connectivity = _connectivity(connectivity)
        if array.ndim != 2:
            raise GridError(f"a grid is a 2-D array, not one of shape {array.shape}")
        if array.size > _trailmark.MAX_GRID_CELLS:
            raise GridError(f"a {array.shape[1]} x {array.shape[0]} grid is too large (at most {_trailmark.MAX_GRID_CELLS} cells)")
        if array.dtype.kind == "b":
            # Read in place, strides and all: no copy of the caller's array.
            self._grid = _trailmark.Grid.from_free(array, connectivity, bool(corner_cutting))
        elif array.dtype.kind in "iuf":
            costs = np.asarray(array, dtype=np.float64)
            self._grid = _trailmark.Grid.from_costs(costs, connectivity, bool(corner_cutting))
        else:
            raise GridError(f"a grid's cells are booleans or real costs, not {array.dtype}")

    @classmethod
    def _wrap(cls, grid: Any) -> "Grid":
        made = cls.__new__(cls)
        made._grid = grid
        return made

    @classmethod
    def from_movingai(
        cls, path: Union[str, "os.PathLike[str]"], *, connectivity: int = 8, corner_cutting: bool = False
    ) -> "Grid":
        """The grid of a MovingAI ``.map`` file (``.``, ``G``, ``S`` free; ``@``, ``O``, ``T``,
        ``W`` blocked)."""
        return cls._wrap(_trailmark.Grid.from_movingai(os.fspath(path), _connectivity(connectivity), corner_cutting))

    @classmethod
    def from_rows(cls, rows: Sequence[str], *, connectivity: int = 8, corner_cutting: bool = False) -> "Grid":
        """A grid from rows of text in MovingAI's characters.

        >>> import trailmark
        >>> trailmark.Grid.from_rows(["..@", "..."]).bfs((0, 0), (2, 1)).path.tolist()
        [[0, 0], [1, 1], [2, 1]]
        """
        if isinstance(rows, (str, bytes)):
            raise GridError("rows are a list of strings, one per row, not one string")
        return cls._wrap(_trailmark.Grid.from_rows([str(r) for r in rows], _connectivity(connectivity), corner_cutting))

    @property
    def width(self) -> int:
        """Columns."""
        return int(self._grid.width)

    @property
    def height(self) -> int:
        """Rows."""
        return int(self._grid.height)

    @property
    def shape(self) -> Tuple[int, int]:
        """``(height, width)``, as the array's shape."""
        return (self.height, self.width)

    @property
    def connectivity(self) -> int:
        """4 or 8."""
        return int(self._grid.connectivity)

    @property
    def corner_cutting(self) -> bool:
        """Whether diagonal moves may cut a blocked cell's corner."""
        return bool(self._grid.corner_cutting)

    def costs(self) -> np.ndarray:
        """Each cell's cost, ``float64 (height, width)``, ``inf`` where blocked."""
        costs: np.ndarray = self._grid.costs()
        return costs

    def free(self) -> np.ndarray:
        """Where the robot may go, ``bool (height, width)``."""
        free: np.ndarray = np.isfinite(self.costs())
        return free

    def world(self) -> Dict[str, Any]:
        """The grid world of a problem document (for :func:`trailmark.solve`)."""
        world: Dict[str, Any] = self._grid.world()
        return world

    def plan(self, start: CellLike, goal: CellLike, planner: str = "astar", **settings: Any) -> Plan:
        """Plans from ``start`` to ``goal`` with the graph search ``planner`` and its settings,
        as a problem document's ``"planner"`` names them: ``astar``, ``dijkstra``, ``bfs``,
        ``dfs``, ``weighted_astar`` (``weight``), ``theta_star``, ``jps``, ``jps_plus``,
        ``lpa_star``, ``dstar_lite``, ``adaptive_astar``, ``mpgaa_star``, ``ara_star`` and
        ``ad_star`` (``epsilon``, ``time_limit_s``, ...). Ctrl-C is not needed: a grid search
        ends within its grid.

        >>> import trailmark
        >>> grid = trailmark.Grid.from_rows(["....", ".@@.", "...."])
        >>> grid.plan((0, 0), (3, 2), "weighted_astar", weight=1.5).cost
        5.0
        """
        spec = _args.planner(planner, settings)
        return _plan(self._grid.plan_json(_args.cell(start, "start"), _args.cell(goal, "goal"), spec))

    def astar(self, start: CellLike, goal: CellLike, *, heuristic: Optional[str] = None) -> Plan:
        """A*: least cost, guided by ``heuristic`` (octile on 8-connected grids, Manhattan on
        4-connected by default; ``"euclidean"``, ``"chebyshev"``, ``"zero"``)."""
        return self.plan(start, goal, "astar", **({} if heuristic is None else {"heuristic": heuristic}))

    def dijkstra(self, start: CellLike, goal: CellLike) -> Plan:
        """Dijkstra's algorithm: least cost."""
        return self.plan(start, goal, "dijkstra")

    def bfs(self, start: CellLike, goal: CellLike) -> Plan:
        """Breadth-first search: fewest moves, whatever their costs."""
        return self.plan(start, goal, "bfs")

    def jps(self, start: CellLike, goal: CellLike) -> Plan:
        """Jump point search: A*'s least cost on an 8-connected grid whose free cells all cost
        the same, expanding only where a path may turn."""
        return self.plan(start, goal, "jps")

    def jps_plus(self, start: CellLike, goal: CellLike) -> Plan:
        """JPS+: jump point search with its jumps read from a table made for the grid first
        (the table's time is part of the plan's)."""
        return self.plan(start, goal, "jps_plus")

    def theta_star(self, start: CellLike, goal: CellLike) -> Plan:
        """Theta*: any-angle paths, straight lines between cell centres priced by the cells
        they cross; waypoints as ``(x, y)`` cells."""
        return self.plan(start, goal, "theta_star")

    def __reduce__(self) -> Tuple[Any, ...]:
        # Pickled as its costs and moves (for multiprocessing and Ray).
        return (_from_state, (self.costs(), self.connectivity, self.corner_cutting))

    def __repr__(self) -> str:
        return str(self._grid.__repr__())


def _from_state(costs: np.ndarray, connectivity: int, corner_cutting: bool) -> Grid:
    return Grid(costs, connectivity=connectivity, corner_cutting=corner_cutting)
