"""Sampling planners in a box of any 1 to 8 axes, around boxes and with the user's own
validity function: :func:`plan_in_box`."""

import json
from typing import Any, Callable, Dict, Optional, Sequence

import numpy as np

from . import _args, _trailmark
from .plan import Plan, _plan

__all__ = ["plan_in_box"]


def plan_in_box(
    bounds: Any,
    start: Sequence[float],
    goal: Sequence[float],
    is_valid: Optional[Callable[[np.ndarray], Any]] = None,
    *,
    obstacles: Any = (),
    planner: str = "rrt_connect",
    batch: bool = False,
    resolution: float = 0.01,
    seed: int = 0,
    **settings: Any,
) -> Plan:
    """Plans from ``start`` to ``goal`` with a sampling planner (``rrt``, ``rrt_connect``,
    ``rrt_star``, ``informed_rrt_star``, ``bit_star``, ``prm``, ``prm_star``, ``lazy_prm``, ``lazy_prm_star``) in the box ``bounds`` (one ``(low, high)`` per axis, 1
    to 8 axes), around the axis-aligned boxes ``obstacles`` (each ``(low_corner,
    high_corner)``) and, when given, only through states that ``is_valid`` accepts.

    ``is_valid`` is asked of one state at a time (a ``float64 (d,)`` array; it returns a truth
    value) or, with ``batch=True``, of all the states a motion checks at once (a
    ``float64 (n, d)`` array; it returns ``n`` booleans), which pays when the function is
    vectorized. Motions are checked every ``resolution`` of the box's diagonal (OMPL's longest
    valid segment fraction). ``settings`` are the planner's settings of a problem document:
    ``range``, ``goal_bias``, ``max_iterations``, ``time_limit_s``, ``simplify``, ``sampler``
    (the roadmaps PRM, PRM*, Lazy PRM and Lazy PRM*, and BIT*, take neither ``range`` nor
    ``goal_bias``).
    An exception raised by ``is_valid`` (Ctrl-C too) stops the planner and is raised again here.

    >>> import numpy as np, trailmark
    >>> def free(states):                       # a wall at x in [4.5, 5.5], below y = 8
    ...     x, y = states[:, 0], states[:, 1]
    ...     return ~((x >= 4.5) & (x <= 5.5) & (y <= 8))
    >>> plan = trailmark.plan_in_box([(0, 10), (0, 10)], (1, 1), (9, 1), free, batch=True)
    >>> plan.status, plan.path.shape[1], bool(plan.path[:, 1].max() > 8)
    ('solved', 2, True)
    """
    starts = _args.point(start, "start")
    document: Dict[str, Any] = {
        "world": {
            "boxes": {
                "bounds": [_args.point(axis, "bounds' axis") for axis in _args.sequence(bounds, "bounds")],
                "obstacles": [
                    [_args.point(corner, "obstacle's corner") for corner in _args.sequence(box, "an obstacle")]
                    for box in _args.sequence(obstacles, "obstacles")
                ],
            }
        },
        "start": starts,
        "goal": _args.point(goal, "goal"),
        "planner": _args.planner_spec(planner, settings),
        "seed": _args.seed(seed),
    }
    text = _args.to_json(document)
    if is_valid is None:
        result = json.loads(_trailmark.solve_json(text, "."))
        path = np.asarray(result["path"], dtype=np.float64).reshape(-1, len(starts))
        return Plan(status=result["status"], cost=result["cost"], path=path, stats=result["stats"])
    return _plan(_trailmark.plan_boxes_json(text, is_valid, batch, float(resolution)))
