"""Problem documents from Python: the same results as `cargo xtask solve`, in parallel the same
as one by one, and errors as exceptions."""

import json
import os
import shutil
import subprocess
import time

import pytest

import trailmark
from conftest import EXAMPLES, REPOSITORY, sigint_after


def without_times(value):
    """The document without measured times (keys naming a time), as .ci/same-across-builds
    compares them."""
    if isinstance(value, dict):
        return {k: without_times(v) for k, v in value.items() if "time" not in k}
    if isinstance(value, list):
        return [without_times(v) for v in value]
    return value


def xtask_solve(path):
    """`cargo xtask solve PATH`'s document: the release binary when it is built, else cargo."""
    binary = REPOSITORY / "target" / "release" / "xtask"
    if binary.exists() and os.environ.get("TRAILMARK_XTASK") != "cargo":
        command = [str(binary), "solve", str(path)]
    elif shutil.which("cargo"):
        command = ["cargo", "xtask", "solve", str(path)]
    else:
        pytest.skip("neither target/release/xtask nor cargo is available to run `cargo xtask solve`")
    done = subprocess.run(command, cwd=REPOSITORY, capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)


EXAMPLE_FILES = sorted(EXAMPLES.glob("*.json"))


def test_there_are_examples():
    assert len(EXAMPLE_FILES) >= 10, EXAMPLES


@pytest.mark.parametrize("path", EXAMPLE_FILES, ids=[p.stem for p in EXAMPLE_FILES])
def test_solve_equals_cargo_xtask_solve(path):
    """Every example problem gives the document `cargo xtask solve` prints, times aside."""
    ours = trailmark.solve(path)
    theirs = xtask_solve(path)
    assert without_times(ours) == without_times(theirs)
    # A dict with the file's folder as base gives the same.
    document = json.loads(path.read_text())
    assert without_times(trailmark.solve(document, base_dir=path.parent)) == without_times(ours)


def test_solve_many_equals_solve_in_a_loop():
    """Every example (and a wrong one, reported in its place) in parallel, in order."""
    documents = [json.loads(p.read_text()) for p in EXAMPLE_FILES]
    bad = {"world": {"grid": {"rows": ["..."]}}, "start": [0, 0], "goal": [9, 0], "planner": {"name": "astar"}}
    documents.insert(3, bad)
    one_by_one = []
    for document in documents:
        try:
            one_by_one.append(trailmark.solve(document, base_dir=EXAMPLES))
        except trailmark.DocumentError as e:
            one_by_one.append({"status": "error", "error": str(e)})
    for workers in (None, 1, 2, 5):
        many = trailmark.solve_many(documents, workers=workers, base_dir=EXAMPLES)
        assert [without_times(r) for r in many] == [without_times(r) for r in one_by_one]
    assert many[3]["status"] == "error" and "outside" in many[3]["error"]
    with pytest.raises(trailmark.DocumentError, match="outside"):
        trailmark.solve_many(documents, base_dir=EXAMPLES, errors="raise")
    # Files, each relative to its own folder.
    files = trailmark.solve_many(EXAMPLE_FILES[:4])
    assert [without_times(r) for r in files] == [without_times(trailmark.solve(p)) for p in EXAMPLE_FILES[:4]]
    assert trailmark.solve_many([]) == []
    with pytest.raises(ValueError):
        trailmark.solve_many(documents, workers=0)
    with pytest.raises(TypeError):
        trailmark.solve_many(documents, workers=1.5)
    # A document that is neither a dict nor a path, after others have started: raised (the
    # next call plans as before).
    with pytest.raises(TypeError, match="not int"):
        trailmark.solve_many(documents[:5] + [42] + documents[5:], base_dir=EXAMPLES)
    assert [without_times(r) for r in trailmark.solve_many(documents[:2], base_dir=EXAMPLES)] == [
        without_times(r) for r in one_by_one[:2]
    ]
    # Any iterable, a generator too.
    assert len(trailmark.solve_many(d for d in documents[:3])) == 3
    # More workers than documents, or than any machine has: capped, the same results.
    assert [without_times(r) for r in trailmark.solve_many(documents[:3], workers=10_000, base_dir=EXAMPLES)] == [
        without_times(r) for r in one_by_one[:3]
    ]


@pytest.mark.parametrize(
    "document,error",
    [
        ({"world": {}, "start": [0, 0], "goal": [1, 1], "planner": {"name": "astar"}}, trailmark.DocumentError),
        ({"world": {"grid": {"rows": [".."]}}, "start": [0, 0], "goal": [1, 0], "planner": {"name": "nope"}},
         trailmark.DocumentError),
        ({"world": {"grid": {"map": "missing.map"}}, "start": [0, 0], "goal": [1, 0], "planner": {"name": "astar"}},
         trailmark.ReadError),
        ({"world": {"grid": {"rows": [".", ".."]}}, "start": [0, 0], "goal": [0, 1], "planner": {"name": "astar"}},
         trailmark.GridError),
        ({"world": {"ros_map": {"yaml": "missing.yaml"}}, "start": [0, 0], "goal": [1, 0],
          "planner": {"name": "astar"}}, trailmark.MapError),
        ({"world": {"polygons": {"bounds": [0, 0, 10, 10], "obstacles": [[[1, 1], [2, 2]]]}}, "graph": "visibility",
          "start": [0, 0], "goal": [9, 9], "planner": {"name": "astar"}}, trailmark.TrailmarkError),
        ({"world": {"grid": {"rows": [".."]}}, "start": [0, 0], "goal": [1, 0],
          "planner": {"name": "rrt", "time_limit_s": float("nan")}}, trailmark.DocumentError),
    ],
)
def test_bad_documents_raise_typed_errors(document, error, tmp_path):
    with pytest.raises(error):
        trailmark.solve(document, base_dir=tmp_path)


def test_non_finite_numbers_are_refused():
    document = {"world": {"grid": {"rows": [".."]}}, "start": [0, float("nan")], "goal": [1, 0],
                "planner": {"name": "astar"}}
    with pytest.raises(trailmark.DocumentError, match="finite"):
        trailmark.solve(document)
    with pytest.raises(trailmark.DocumentError):
        trailmark.solve({"world": object()})


def test_bad_files_raise(tmp_path):
    path = tmp_path / "bad.json"
    path.write_bytes(b"\xff\xfe not json")
    with pytest.raises(trailmark.DocumentError):
        trailmark.solve(path)
    path.write_text("{")
    with pytest.raises(trailmark.DocumentError, match="invalid problem"):
        trailmark.solve(path)
    with pytest.raises(FileNotFoundError):
        trailmark.solve(tmp_path / "missing.json")
    with pytest.raises(TypeError):
        trailmark.solve(42)


LONG = {
    "world": {"polygons": {"bounds": [0, 0, 100, 100], "obstacles": [[[40, 0], [60, 0], [60, 80], [40, 80]]]}},
    "start": [5, 5], "goal": [95, 5], "seed": 1,
    "planner": {"name": "rrt_star", "time_limit_s": 60},
}


def busy_cpu_seconds(over=1.0):
    """CPU seconds this process's threads spend in `over` seconds of waiting."""
    cpu = time.process_time()
    time.sleep(over)
    return time.process_time() - cpu


@pytest.mark.parametrize("call", [lambda: trailmark.solve(LONG), lambda: trailmark.solve_many([LONG] * 4, workers=2)])
def test_ctrl_c_stops_a_long_plan(call):
    """Ctrl-C (here a real SIGINT) raises KeyboardInterrupt within a moment, not after 60 s,
    and the planners stop too, not only the wait: the process falls idle."""
    clock = time.perf_counter()
    sigint_after(0.3)
    with pytest.raises(KeyboardInterrupt):
        call()
    assert time.perf_counter() - clock < 5.0
    time.sleep(0.5)
    assert busy_cpu_seconds() < 0.3, "planning threads are still working"


def test_a_solve_after_ctrl_c_runs_to_its_own_limit():
    """The stop flag of an interrupted solve does not reach the next solve on the same
    planning thread: it runs to its own time limit."""
    sigint_after(0.3)
    with pytest.raises(KeyboardInterrupt):
        trailmark.solve(LONG)
    time.sleep(0.3)
    short = dict(LONG, planner={"name": "rrt_star", "time_limit_s": 0.5})
    result = trailmark.solve(short)
    assert result["status"] == "solved"
    assert result["stats"]["time_s"] >= 0.45


@pytest.mark.skipif(not hasattr(os, "fork"), reason="needs os.fork")
def test_solve_in_a_forked_child():
    """A child forked after the parent planned (multiprocessing's default on Linux) plans too:
    the parent's planning threads are not the child's."""
    import select

    document = {"world": {"grid": {"rows": ["...."]}}, "start": [0, 0], "goal": [3, 0], "planner": {"name": "astar"}}
    assert trailmark.solve(document)["cost"] == 3.0
    read, write = os.pipe()
    pid = os.fork()
    if pid == 0:
        try:
            ok = trailmark.solve(document)["cost"] == 3.0 and trailmark.solve_many([document] * 3)[2]["cost"] == 3.0
            os.write(write, b"1" if ok else b"0")
        finally:
            os._exit(0)
    os.close(write)
    ready, _, _ = select.select([read], [], [], 20.0)
    answer = os.read(read, 1) if ready else b""
    if not ready:
        os.kill(pid, 9)
    os.waitpid(pid, 0)
    os.close(read)
    assert answer == b"1", "the forked child did not plan within 20 s"
