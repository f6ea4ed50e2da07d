"""The Ray recipe (python/examples/ray_solve.py): a local Ray runtime started and stopped here,
its results identical to trailmark.solve_many on this machine."""

import importlib.util
import json

import pytest

import trailmark
from conftest import EXAMPLES, REPOSITORY

ray = pytest.importorskip("ray", reason="Ray is not installed (pip install ray): the Ray recipe is not tested")


def recipe():
    path = REPOSITORY / "python" / "examples" / "ray_solve.py"
    spec = importlib.util.spec_from_file_location("ray_solve", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def without_times(value):
    if isinstance(value, dict):
        return {k: without_times(v) for k, v in value.items() if "time" not in k}
    if isinstance(value, list):
        return [without_times(v) for v in value]
    return value


def test_ray_recipe_gives_the_single_machine_results():
    module = recipe()
    documents = module.demonstration_documents(120)
    # Example problems too (their files at the same paths: one machine), and a bad one.
    documents += [json.loads(p.read_text()) for p in sorted(EXAMPLES.glob("wall-*.json"))[:3]]
    documents.append({"world": {"grid": {"rows": ["."]}}, "start": [0, 0], "goal": [5, 5], "planner": {"name": "astar"}})
    ray.init(num_cpus=2, include_dashboard=False, log_to_driver=False)
    try:
        on_ray = module.solve_on_ray(documents, chunk_size=32, base_dir=str(EXAMPLES))
    finally:
        ray.shutdown()
    here = trailmark.solve_many(documents, base_dir=EXAMPLES)
    assert len(on_ray) == len(documents)
    assert [without_times(r) for r in on_ray] == [without_times(r) for r in here]
    assert on_ray[-1]["status"] == "error"
    assert sum(r["status"] == "solved" for r in on_ray) > 100
