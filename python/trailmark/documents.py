"""Problem documents, the same as ``cargo xtask solve`` reads: :func:`solve` and
:func:`solve_many`."""

import json
import os
from pathlib import Path
from typing import Any, Dict, Iterable, List, Optional, Union

from . import _args, _trailmark
from . import errors as _errors

__all__ = ["solve", "solve_many", "MAX_DOCUMENT_BYTES"]

#: The longest document read, as ``cargo xtask solve`` caps it.
MAX_DOCUMENT_BYTES: int = _trailmark.MAX_DOCUMENT_BYTES

Document = Union[Dict[str, Any], str, "os.PathLike[str]"]


def _text(document: Document, base_dir: Optional[Union[str, "os.PathLike[str]"]]) -> "tuple[str, str]":
    if isinstance(document, dict):
        return _args.to_json(document), os.fspath(base_dir) if base_dir is not None else os.getcwd()
    if isinstance(document, (str, os.PathLike)):
        path = Path(document)
        with open(path, "rb") as f:
            data = f.read(MAX_DOCUMENT_BYTES + 1)
        if len(data) > MAX_DOCUMENT_BYTES:
            raise _errors.DocumentError(f"{path}: longer than {MAX_DOCUMENT_BYTES} bytes")
        try:
            text = data.decode("utf-8")
        except UnicodeDecodeError as e:
            raise _errors.DocumentError(f"{path}: not UTF-8: {e}") from None
        return text, os.fspath(base_dir) if base_dir is not None else str(path.parent)
    raise TypeError(f"a problem document is a dict or the path of a JSON file, not {type(document).__name__}")


def solve(document: Document, base_dir: Optional[Union[str, "os.PathLike[str]"]] = None) -> Dict[str, Any]:
    """Solves a problem document (a dict, or the path of a JSON file) and returns its result
    document, as ``cargo xtask solve`` prints it. Relative file paths in the document are
    resolved against ``base_dir`` (default: the file's folder, or the current directory for a
    dict). A document that cannot be solved raises a subclass of :class:`TrailmarkError`;
    Ctrl-C raises ``KeyboardInterrupt`` at once.

    >>> import trailmark
    >>> result = trailmark.solve({
    ...     "world": {"grid": {"rows": ["....", ".@@.", "...."]}},
    ...     "start": [0, 0], "goal": [3, 2], "planner": {"name": "astar"},
    ... })
    >>> result["status"], result["cost"], result["path"][-1]
    ('solved', 5.0, [3, 2])
    """
    text, base = _text(document, base_dir)
    result: Dict[str, Any] = json.loads(_trailmark.solve_json(text, base))
    return result


def solve_many(
    documents: Iterable[Document],
    workers: Optional[int] = None,
    base_dir: Optional[Union[str, "os.PathLike[str]"]] = None,
    errors: str = "report",
) -> List[Dict[str, Any]]:
    """Solves many documents in parallel, on ``workers`` threads (default: one per core),
    without the GIL; the results in the documents' order, each as :func:`solve` returns it.

    A document that cannot be solved gives ``{"status": "error", "error": message}`` in its
    place (what ``cargo xtask solve`` prints for it) with ``errors="report"``, or raises its
    exception once all are done with ``errors="raise"``. Ctrl-C stops the batch: no new
    document is started and ``KeyboardInterrupt`` is raised at once.

    >>> import trailmark
    >>> grid = {"grid": {"rows": ["....", ".@@.", "...."]}}
    >>> docs = [{"world": grid, "start": [0, 0], "goal": [x, 2], "planner": {"name": "astar"}}
    ...         for x in range(4)]
    >>> [r["cost"] for r in trailmark.solve_many(docs, workers=2)]
    [2.0, 3.0, 4.0, 5.0]
    """
    if errors not in ("report", "raise"):
        raise ValueError(f'errors is "report" or "raise", not {errors!r}')
    documents = list(documents)
    # Written one by one as the planning threads take them: the interpreter writes the next
    # documents while the first are planned.
    jobs = (_text(document, base_dir) for document in documents)
    results: List[Dict[str, Any]] = []
    for failed, payload in _trailmark.solve_many_json(jobs, len(documents), workers):
        if failed is None:
            results.append(json.loads(payload))
        elif errors == "raise":
            raise getattr(_errors, failed)(payload)
        else:
            results.append({"status": "error", "error": payload})
    return results
