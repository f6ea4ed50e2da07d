"""Checks of the arguments the Python API passes on: cells, numbers, settings. A value that
cannot be used is refused with a typed error, never rounded or truncated."""

import json
import math
import operator
from typing import Any, Dict, List, Sequence, Tuple

from .errors import DocumentError

#: The largest whole number a cell coordinate may be (the grids' cells are numbered in 32 bits).
MAX_COORDINATE = 2**32 - 1


def whole(value: Any, what: str) -> int:
    """`value` as an int when it is one (an int, a NumPy integer, or a float with no fraction);
    a `DocumentError` otherwise."""
    try:
        return operator.index(value)
    except TypeError:
        pass
    if isinstance(value, float) or hasattr(value, "is_integer"):
        number = float(value)
        if math.isfinite(number) and number.is_integer():
            return int(number)
    raise DocumentError(f"{what} must be a whole number, not {value!r}")


def seed(value: Any) -> int:
    """A seed: a whole number from 0 to 2**64 - 1, as the planners take it."""
    number = whole(value, "the seed")
    if not 0 <= number < 2**64:
        raise DocumentError(f"the seed must be from 0 to 2**64 - 1, not {number}")
    return number


def cell(value: Any, what: str) -> Tuple[int, int]:
    """`(x, y)` of a grid cell: two whole numbers from 0."""
    if isinstance(value, (str, bytes)):
        raise DocumentError(f"the {what} must be a cell (x, y), not {value!r}")
    try:
        parts = list(value)
    except TypeError:
        raise DocumentError(f"the {what} must be a cell (x, y), not {value!r}") from None
    if len(parts) != 2:
        raise DocumentError(f"the {what} must be a cell (x, y) of two numbers, not {value!r}")
    x, y = (whole(v, f"the {what}'s coordinates") for v in parts)
    if not (0 <= x <= MAX_COORDINATE and 0 <= y <= MAX_COORDINATE):
        raise DocumentError(f"the {what} {(x, y)} is not a grid cell: coordinates run from 0 to {MAX_COORDINATE}")
    return (x, y)


def point(value: Any, what: str) -> List[float]:
    """A list of finite floats."""
    if isinstance(value, (str, bytes)):
        raise DocumentError(f"the {what} must be numbers, not {value!r}")
    try:
        numbers = [float(v) for v in value]
    except (TypeError, ValueError):
        raise DocumentError(f"the {what} must be numbers, not {value!r}") from None
    if not all(math.isfinite(v) for v in numbers):
        raise DocumentError(f"the {what} must be finite numbers, not {numbers}")
    return numbers


def planner_spec(name: str, settings: Dict[str, Any]) -> Dict[str, Any]:
    """The planner `name` with its `settings`, as a document's `"planner"`."""
    if "name" in settings:
        raise TypeError("the planner is named by `planner`, not by a `name` setting")
    return {"name": name, **settings}


def planner(name: str, settings: Dict[str, Any]) -> str:
    """The planner `name` with its `settings`, as a document's `"planner"` in JSON."""
    return to_json(planner_spec(name, settings))


def to_json(value: Any) -> str:
    """JSON text of `value`; NaN and infinities are refused (JSON has none)."""
    try:
        return json.dumps(value, allow_nan=False)
    except ValueError as e:
        raise DocumentError(f"a value is not a finite number: {e}") from None
    except TypeError as e:
        raise DocumentError(f"a value cannot be written in a problem document: {e}") from None


def sequence(value: Any, what: str) -> Sequence[Any]:
    if isinstance(value, (str, bytes)):
        raise DocumentError(f"{what} must be a sequence, not a string")
    return list(value)
