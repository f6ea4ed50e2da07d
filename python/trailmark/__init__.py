"""trailmark: motion planning at Rust speed, with NumPy arrays in and out.

Grids from arrays and MovingAI maps searched by A*, Dijkstra, BFS, JPS, JPS+ and Theta*
(:class:`Grid`); replanners kept between plans as costs change (:class:`Replanner`: D* Lite,
LPA*, MPGAA*, Adaptive A*); ROS maps made into costmaps and planned on in metres, Hybrid A* for a car
(:class:`RosMap`); robot arms from their URDF, SRDF and MoveIt scene, their states checked in
batches and planned in (:class:`RobotWorld`); sampling planners in a box with your own validity function, one state or a
whole batch per call (:func:`plan_in_box`); and every problem of ``cargo xtask solve`` (grids,
ROS maps, polygon worlds, cars, robot arms) as a document, one at a time or in parallel on every
core (:func:`solve`, :func:`solve_many`).

>>> import numpy as np, trailmark
>>> free = np.ones((64, 64), dtype=bool)
>>> free[10:54, 32] = False                      # a wall in column 32, rows 10 to 53
>>> plan = trailmark.Grid(free).astar((2, 32), (60, 32))
>>> plan.status, round(plan.cost, 3), plan.path.shape
('solved', 76.225, (59, 2))
"""

from ._trailmark import __version__
from .documents import MAX_DOCUMENT_BYTES, solve, solve_many
from .errors import *  # noqa: F403 (every exception class, listed in errors.__all__)
from .errors import __all__ as _errors
from .grid import Grid
from .plan import Plan
from .replanner import Replanner
from .robot import RobotWorld
from .ros_map import RosMap
from .sampling import plan_in_box

__all__ = [
    "__version__",
    "Grid",
    "Plan",
    "Replanner",
    "RobotWorld",
    "RosMap",
    "plan_in_box",
    "solve",
    "solve_many",
    "MAX_DOCUMENT_BYTES",
    *_errors,
]
