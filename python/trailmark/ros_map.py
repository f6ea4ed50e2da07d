"""ROS maps (map_server's YAML and image) made into Nav2-style costmaps and planned on in
metres: :class:`RosMap`."""

import os
from pathlib import Path
from typing import Any, Dict, Optional, Sequence, Tuple, Union

import numpy as np

from . import _args, _trailmark
from .documents import solve
from .plan import Plan, _plan

__all__ = ["RosMap"]

PathLike = Union[str, "os.PathLike[str]"]


class RosMap:
    """A ROS map loaded from its YAML file, its obstacles inflated around the robot as Nav2's
    costmap does (a disc of ``robot_radius`` or a ``footprint`` polygon, costs falling off over
    ``inflation_radius`` at ``cost_scaling_factor``; unknown cells ``"lethal"`` unless
    ``unknown`` says otherwise), each setting defaulting to Nav2's. A move costs its length in
    metres times ``1 + cost_factor * cost / 252``.

    >>> import trailmark
    >>> office = trailmark.RosMap("examples/maps/office.yaml", robot_radius=0.15)
    >>> plan = office.theta_star((-4.2, -2.2), (4.3, 2.3))
    >>> plan.status, plan.path.shape[1], plan.path[-1].round(2).tolist()   # the goal's cell centre
    ('solved', 2, [4.33, 2.28])
    """

    def __init__(
        self,
        yaml: PathLike,
        *,
        robot_radius: Optional[float] = None,
        footprint: Optional[Sequence[Sequence[float]]] = None,
        inflation_radius: Optional[float] = None,
        cost_scaling_factor: Optional[float] = None,
        unknown: Optional[Any] = None,
        cost_factor: Optional[float] = None,
    ) -> None:
        settings = {
            "robot_radius": robot_radius,
            "footprint": None if footprint is None else [_args.point(p, "footprint's corner") for p in footprint],
            "inflation_radius": inflation_radius,
            "cost_scaling_factor": cost_scaling_factor,
            "unknown": unknown,
            "cost_factor": cost_factor,
        }
        self._spec: Dict[str, Any] = {"yaml": str(Path(yaml).resolve())}
        self._spec.update({k: v for k, v in settings.items() if v is not None})
        self._map = _trailmark.RosMap.load(_args.to_json(self._spec), os.getcwd())

    @property
    def width(self) -> int:
        """Columns."""
        return int(self._map.width)

    @property
    def height(self) -> int:
        """Rows."""
        return int(self._map.height)

    @property
    def resolution(self) -> float:
        """Metres per cell."""
        return float(self._map.resolution)

    @property
    def origin(self) -> Tuple[float, float, float]:
        """``(x, y, yaw)`` of the lower-left corner, metres and radians."""
        x, y, yaw = self._map.origin
        return (float(x), float(y), float(yaw))

    def extent(self) -> Tuple[float, float, float, float]:
        """``(left, right, bottom, top)`` in metres, for ``matplotlib``'s ``imshow`` of
        :meth:`costs` (a map whose origin has no yaw)."""
        x, y, _ = self.origin
        return (x, x + self.width * self.resolution, y, y + self.height * self.resolution)

    def costs(self) -> np.ndarray:
        """The costmap, ``uint8 (height, width)``, row 0 at the top as in the image: 0 free to
        252, 253 inscribed (the robot's centre may not be there), 254 lethal, 255 unknown."""
        costs: np.ndarray = self._map.costs()
        return costs

    def world(self) -> Dict[str, Any]:
        """The ROS-map world of a problem document (for :func:`trailmark.solve`)."""
        return {"ros_map": dict(self._spec)}

    def plan(self, start: Sequence[float], goal: Sequence[float], planner: str = "astar", **settings: Any) -> Plan:
        """Plans from ``start`` to ``goal`` (``(x, y)`` in metres) with a graph search of the
        registry (``astar``, ``dijkstra``, ``theta_star``, ``dstar_lite``, ``ara_star``, ...);
        the path in metres at cell centres."""
        spec = _args.planner(planner, settings)
        return _plan(self._map.plan_json(_args.point(start, "start"), _args.point(goal, "goal"), spec))

    def astar(self, start: Sequence[float], goal: Sequence[float]) -> Plan:
        """A* over the costmap's cells, 8-connected."""
        return self.plan(start, goal, "astar")

    def theta_star(self, start: Sequence[float], goal: Sequence[float]) -> Plan:
        """Theta*: any-angle paths, straight lines priced by the cells they cross."""
        return self.plan(start, goal, "theta_star")

    def hybrid_astar(
        self, start: Sequence[float], goal: Sequence[float], *, turning_radius: float, **settings: Any
    ) -> Plan:
        """Hybrid A* for a car-like robot: poses ``(x, y, heading)`` in metres and radians,
        forward and reverse arcs of ``turning_radius``, the footprint (``footprint=`` in
        ``settings``, else the map's robot) checked at every pose; the path as ``(n, 3)``
        poses. Settings as a document's ``hybrid_astar`` planner takes them.

        >>> import trailmark
        >>> office = trailmark.RosMap("examples/maps/office.yaml", inflation_radius=0.5, cost_scaling_factor=8)
        >>> car = [[-0.15, -0.2], [0.45, -0.2], [0.45, 0.2], [-0.15, 0.2]]
        >>> plan = office.hybrid_astar((-4.2, -2.2, 0.0), (4.3, 2.3, 3.14159), turning_radius=0.5, footprint=car)
        >>> plan.status, plan.path.shape[1]
        ('solved', 3)
        """
        document = {
            "world": self.world(),
            "start": _args.point(start, "start"),
            "goal": _args.point(goal, "goal"),
            "planner": _args.planner_spec("hybrid_astar", {"turning_radius": float(turning_radius), **settings}),
        }
        result = solve(document)
        path = np.asarray(result["path"], dtype=np.float64).reshape(-1, 3)
        return Plan(status=result["status"], cost=result["cost"], path=path, stats=result["stats"])

    def __repr__(self) -> str:
        return str(self._map.__repr__())
