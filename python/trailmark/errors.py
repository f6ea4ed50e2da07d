"""The exceptions of trailmark: one class per error enum of the Rust library, all subclasses of
:class:`TrailmarkError`. The errors of inputs that are wrong in themselves (a document, a grid,
a setting, a space, a sampler, a search's or a planner's start, goal or settings) are also
``ValueError``; the errors of files (``ReadError``, ``MapError``, ``RobotError``) are not.

>>> import trailmark
>>> try:
...     trailmark.Grid([[True, False]]).astar((0, 0), (1, 0))
... except trailmark.DocumentError as e:
...     print(type(e).__name__, "-", e)
DocumentError - the goal (1, 0) is a blocked cell
"""

__all__ = [
    "TrailmarkError",
    "DocumentError",
    "GridError",
    "ReadError",
    "MapError",
    "SearchError",
    "VisibilityError",
    "TrapezoidError",
    "PrmError",
    "SamplerError",
    "PlanError",
    "SpaceError",
    "CurveError",
    "CarError",
    "RobotError",
    "SolveError",
    "CallbackError",
]


class TrailmarkError(Exception):
    """Every error trailmark raises."""


class DocumentError(TrailmarkError, ValueError):
    """A problem document, or a planner's settings, that cannot be planned as written."""


class GridError(TrailmarkError, ValueError):
    """A grid that cannot be built: no cells, too many, or a cost that is not a cell cost."""


class ReadError(TrailmarkError):
    """A MovingAI map or scenario file that cannot be read or parsed."""


class MapError(TrailmarkError):
    """A ROS map (YAML and image) that cannot be read, or a costmap setting that is wrong."""


class SearchError(TrailmarkError, ValueError):
    """A graph search that could not run (an unreachable goal is not an error)."""


class VisibilityError(TrailmarkError):
    """A visibility graph that cannot be built from the world's polygons."""


class TrapezoidError(TrailmarkError):
    """A trapezoidal decomposition that cannot be built from the world's polygons."""


class PrmError(TrailmarkError):
    """A probabilistic roadmap that cannot be built with these settings."""


class SamplerError(TrailmarkError, ValueError):
    """A state sampler with settings it cannot use."""


class PlanError(TrailmarkError, ValueError):
    """A sampling planner that could not start: its start or goal is invalid, or a setting."""


class SpaceError(TrailmarkError, ValueError):
    """A configuration space, or a state of it, that is not valid."""


class CurveError(TrailmarkError, ValueError):
    """A Dubins or Reeds-Shepp curve that cannot be made (a turning radius that is not positive)."""


class CarError(TrailmarkError):
    """A car-like robot's planner that cannot run with this car, map or settings."""


class RobotError(TrailmarkError):
    """A robot arm's URDF, SRDF, scene, request or mesh that cannot be read or used."""


class SolveError(TrailmarkError):
    """A problem that the planners could not answer for another reason (e.g. a roadmap's path
    that failed its exact re-check)."""


class CallbackError(TrailmarkError, TypeError):
    """A validity function that answered in a way trailmark cannot read."""
