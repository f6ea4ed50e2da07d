"""Replanners as objects: plan, tell what changed, replan: :class:`Replanner`."""

from typing import Any, Optional, Tuple, Union

import numpy as np

from . import _args, _trailmark
from .errors import DocumentError
from .grid import CellLike, Grid
from .plan import Plan, _plan

__all__ = ["Replanner"]


class Replanner:
    """An incremental planner on its own copy of ``grid``, kept between plans while the cells'
    costs change and the robot moves: ``"dstar_lite"`` (default), ``"lpa_star"``,
    ``"mpgaa_star"``, ``"adaptive_astar"``, ``"ad_star"`` (anytime, ``epsilon`` and limits in
    ``settings``) or ``"astar"`` (from scratch at every plan, for comparison). Each plan repairs
    the last one where the changes reach, and costs what a search from scratch would.

    >>> import numpy as np, trailmark
    >>> robot = trailmark.Replanner(trailmark.Grid(np.ones((5, 7), dtype=bool)), (0, 2), (6, 2))
    >>> robot.plan().cost
    6.0
    >>> robot.block([(3, 1), (3, 2), (3, 3)])               # a wall the robot sees
    >>> robot.plan().cost                                   # around it, repaired
    7.65685424949238
    >>> robot.move_to(robot.next_step()); round(robot.plan().cost, 3)
    6.243
    """

    def __init__(self, grid: Grid, start: CellLike, goal: CellLike, planner: str = "dstar_lite", **settings: Any):
        if not isinstance(grid, Grid):
            raise TypeError(f"a Replanner plans on a trailmark.Grid, not {type(grid).__name__}")
        spec = _args.planner(planner, settings)
        self._planner = _trailmark.Replanner(grid._grid, _args.cell(start, "start"), _args.cell(goal, "goal"), spec)

    @property
    def planner(self) -> str:
        """The planner's name."""
        return str(self._planner.planner)

    def plan(self) -> Plan:
        """Plans from the robot's cell to the goal, repairing the last plan; this plan's own
        statistics (expansions, time)."""
        return _plan(self._planner.plan())

    def set_costs(self, cells: Any, costs: Union[float, Any]) -> None:
        """Sets the costs of ``cells`` (``(x, y)`` each, an ``(n, 2)`` array or a list) to
        ``costs`` (one number for all, or one each; ``inf`` blocks a cell). Every cell and
        cost is checked before any is changed."""
        array = np.asarray(cells)
        if array.size == 0:
            return
        if array.ndim != 2 or array.shape[1] != 2:
            raise DocumentError(f"cells are (x, y) pairs: an (n, 2) array, not one of shape {array.shape}")
        points = [_args.cell(c, "changed cell") for c in array.tolist()]
        values = np.broadcast_to(np.asarray(costs, dtype=np.float64), (len(points),))
        xs = np.array([p[0] for p in points], dtype=np.int64)
        ys = np.array([p[1] for p in points], dtype=np.int64)
        self._planner.set_costs(xs, ys, np.ascontiguousarray(values))

    def block(self, cells: Any) -> None:
        """Blocks ``cells``."""
        self.set_costs(cells, np.inf)

    def move_to(self, cell: CellLike) -> None:
        """Moves the robot, the start of the next plans, to ``cell``."""
        self._planner.move_to(_args.cell(cell, "robot's cell"))

    def next_step(self) -> Optional[Tuple[int, int]]:
        """The cell after the robot's on the last plan's path (``None`` without one)."""
        step = self._planner.next_step()
        return None if step is None else (int(step[0]), int(step[1]))

    def costs(self) -> np.ndarray:
        """The grid's costs now, ``float64 (height, width)``, ``inf`` where blocked."""
        costs: np.ndarray = self._planner.costs()
        return costs
