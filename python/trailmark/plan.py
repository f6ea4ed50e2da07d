"""The result of one plan: :class:`Plan`."""

from dataclasses import dataclass, field
from typing import Any, Dict, Optional

import numpy as np

__all__ = ["Plan"]


@dataclass(frozen=True, eq=False)
class Plan:
    """One planner's answer.

    ``status`` is ``"solved"``, ``"no_path"`` (a search proved that none exists),
    ``"approximate"`` (a sampling planner's path that ends short of the goal) or ``"stopped"``
    (a limit ended the planner first); ``cost`` is the path's cost (``None`` without a path);
    ``path`` has one row per waypoint: ``(x, y)`` cells as ``int64`` on grids, coordinates as
    ``float64`` elsewhere; ``stats`` holds what the planner did, as the ``"stats"`` of a
    ``cargo xtask solve`` result (expansions, time, samples, ...).
    """

    status: str
    cost: Optional[float]
    path: np.ndarray
    stats: Dict[str, Any] = field(default_factory=dict)

    @property
    def solved(self) -> bool:
        """Whether the path reaches the goal."""
        return self.status == "solved"

    @property
    def expansions(self) -> Optional[int]:
        """Nodes expanded by a graph search (``None`` for sampling planners)."""
        value = self.stats.get("expansions")
        return None if value is None else int(value)

    @property
    def time_s(self) -> float:
        """The planner's own time in seconds, as it measured it."""
        return float(self.stats.get("time_s", 0.0))


def _plan(parts: Any) -> Plan:
    import json

    status, cost, path, stats = parts
    return Plan(status=status, cost=cost, path=path, stats=json.loads(stats))
