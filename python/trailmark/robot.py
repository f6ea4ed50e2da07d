"""Robot arms from their URDF, SRDF and MoveIt planning scene, asked about states in batches
and planned in by the sampling planners: :class:`RobotWorld`."""

import os
from pathlib import Path
from typing import Any, Dict, List, Optional, Sequence, Union

import numpy as np

from . import _args, _trailmark
from .errors import DocumentError
from .plan import Plan, _plan

__all__ = ["RobotWorld"]

PathLike = Union[str, "os.PathLike[str]"]


class RobotWorld:
    """The planning group ``group`` of the robot of ``urdf`` and ``srdf`` among the obstacles of
    a MoveIt planning ``scene`` (YAML; none: an empty world), read once. States are one value
    per group joint in :attr:`joint_names` order; the joints outside the group stay at zero (or
    their limits' middle). ``checker`` is ``"batch"`` (eight different states at once in SIMD
    lanes) or ``"scalar"``; both are conservative (spheres that cover the links, motions proven free
    between their states), the batch one a little more (its ``f32`` rounding grows the
    spheres: a state within that of touching may be blocked for it and free for the other).

    >>> import trailmark
    >>> arm = trailmark.RobotWorld("examples/problems/robot/arm.urdf", "examples/problems/robot/arm.srdf",
    ...                            "arm", scene="examples/problems/robot/shelf.yaml")
    >>> len(arm.joint_names), arm.is_valid([[1.2, 0.6, 1.2, 0.8], [0.0, 1.6, 0.0, 0.0]]).tolist()
    (4, [True, False])
    >>> plan = arm.plan((1.2, 0.6, 1.2, 0.8), (-0.5, 0.9, 0.9, 0.3), seed=3)
    >>> plan.status, plan.path.shape[1], bool(arm.is_valid(plan.path).all())
    ('solved', 4, True)
    """

    def __init__(
        self,
        urdf: PathLike,
        srdf: PathLike,
        group: str,
        *,
        scene: Optional[PathLike] = None,
        checker: str = "batch",
    ) -> None:
        if not isinstance(group, str):
            raise DocumentError(f"the group must be a name, not {group!r}")
        robot = {"urdf": str(Path(urdf).resolve()), "srdf": str(Path(srdf).resolve()), "group": group, "checker": checker}
        self._spec: Dict[str, Any] = {"robot": robot}
        if scene is not None:
            self._spec["scene"] = str(Path(scene).resolve())
        self._world = _trailmark.RobotWorld.load(_args.to_json(self._spec), os.getcwd())

    @property
    def joint_names(self) -> List[str]:
        """The group's joints, in the order of a state's values."""
        return list(self._world.joint_names)

    @property
    def limits(self) -> np.ndarray:
        """The joints' limits, ``float64 (d, 2)``: ``(lower, upper)`` per joint; a continuous
        joint's are ``(-pi, pi)`` (:meth:`plan` takes any angle of it, by whole turns;
        :meth:`is_valid` only those within)."""
        limits: np.ndarray = self._world.limits()
        return limits

    def is_valid(self, states: Any) -> Any:
        """Whether each state is free: a ``bool (n,)`` array for ``(n, d)`` states, a ``bool``
        for one ``(d,)`` state. A state that is not finite, or beyond the joints' limits
        (:attr:`limits`), is not free."""
        array = np.asarray(states, dtype=np.float64)
        if array.ndim == 1:
            return bool(self._world.are_free(array[None, :])[0])
        if array.ndim != 2:
            raise DocumentError(f"states must be (d,) or (n, d), not of shape {array.shape}")
        free: np.ndarray = self._world.are_free(array)
        return free

    def motion_is_valid(self, a: Sequence[float], b: Sequence[float]) -> bool:
        """Whether the straight motion in joint space from ``a`` to ``b`` is free (continuous
        joints turning the short way), proven as the planners prove theirs; ``False`` when an end is
        beyond the joints' limits."""
        ends = [_args.point(a, "motion's start"), _args.point(b, "motion's end")]
        for end in ends:
            if len(end) != len(self.joint_names):
                raise DocumentError(f"a motion's end has {len(end)} values; the group has {len(self.joint_names)} joints")
        return bool(self._world.motion_is_free(*ends))

    def world(self) -> Dict[str, Any]:
        """The robot world of a problem document (for :func:`trailmark.solve`)."""
        return {"robot": dict(self._spec["robot"]), **({"scene": self._spec["scene"]} if "scene" in self._spec else {})}

    def plan(
        self,
        start: Sequence[float],
        goal: Sequence[float],
        planner: str = "rrt_connect",
        *,
        seed: int = 0,
        **settings: Any,
    ) -> Plan:
        """Plans from ``start`` to ``goal`` (a value per group joint) with a sampling planner
        (``rrt``, ``rrt_connect``, ``rrt_star``, ``informed_rrt_star``, ``bit_star``, ``prm``, ``prm_star``, ``lazy_prm``, ``lazy_prm_star``) and its settings as a
        problem document gives them (``max_iterations``, ``time_limit_s``, ``range``,
        ``simplify``, ...); the path as ``(n, d)`` joint values. Ctrl-C stops the planner."""
        spec = _args.planner(planner, settings)
        found = self._world.plan_json(_args.point(start, "start"), _args.point(goal, "goal"), spec, _args.seed(seed))
        return _plan(found)

    def __repr__(self) -> str:
        return str(self._world.__repr__())
