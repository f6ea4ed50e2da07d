"""Shared paths of the test suite: the repository, and the reference data beside it."""

import os
from pathlib import Path

import pytest

REPOSITORY = Path(__file__).resolve().parents[2]
SHARED = Path(os.environ.get("TRAILMARK_SHARED", REPOSITORY.parent / "shared"))
MOVINGAI = SHARED / "movingai"
ROSMAPS = SHARED / "rosmaps"
EXAMPLES = REPOSITORY / "examples" / "problems"


def need(path: Path, what: str) -> Path:
    """`path`, or the test is skipped saying what is missing."""
    if not path.exists():
        pytest.skip(f"{what} not found at {path} (the reference data beside the repository)")
    return path


def sigint_after(seconds: float) -> None:
    """Ctrl-C, `seconds` from now: a real SIGINT sent by another process (a thread of this
    one would need the GIL, which a plan holds while it calls compiled functions)."""
    import signal
    import subprocess

    subprocess.Popen(["sh", "-c", f"sleep {seconds}; kill -{int(signal.SIGINT)} {os.getpid()}"])
