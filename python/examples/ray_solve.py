"""Planning on a Ray cluster: problem documents in chunks, each chunk one Ray task of
`cpus_per_task` cores that plans it with trailmark.solve_many on as many threads (Ray places
the tasks so that each node's cores are used once). Results come back in the documents' order,
identical to trailmark.solve_many on one machine.

    pip install "ray[default]" ./python
    ray start --head                          # or connect to your cluster: RAY_ADDRESS=...
    python python/examples/ray_solve.py       # a demonstration on generated documents

Each node needs trailmark installed (the same wheel). Documents that read files (maps, URDFs)
need those files at the same paths on every node, or inline rows and values instead.
"""

from typing import Any, Dict, List, Optional, Sequence

import os

import ray

import trailmark


@ray.remote
def _solve_chunk(documents: Sequence[Dict[str, Any]], base_dir: str, workers: int) -> List[Dict[str, Any]]:
    # One task per chunk: trailmark plans it on the task's cores, without the GIL.
    return trailmark.solve_many(documents, workers=workers, base_dir=base_dir)


def solve_on_ray(
    documents: Sequence[Dict[str, Any]],
    chunk_size: int = 256,
    base_dir: Optional[str] = None,
    cpus_per_task: int = 1,
) -> List[Dict[str, Any]]:
    """Solves `documents` as Ray tasks of `chunk_size` documents each, on `cpus_per_task` cores
    each; the results in order (an error report in place of a document that cannot be solved,
    as solve_many gives). Relative paths in the documents are relative to `base_dir` (default:
    this process's working directory, the same folder on every node)."""
    if chunk_size < 1 or cpus_per_task < 1:
        raise ValueError("chunk_size and cpus_per_task must be at least 1")
    base = os.path.abspath(base_dir if base_dir is not None else os.getcwd())
    task = _solve_chunk.options(num_cpus=cpus_per_task)
    chunks = [documents[i : i + chunk_size] for i in range(0, len(documents), chunk_size)]
    futures = [task.remote(chunk, base, cpus_per_task) for chunk in chunks]
    results: List[Dict[str, Any]] = []
    for chunk_results in ray.get(futures):
        results.extend(chunk_results)
    return results


def demonstration_documents(n: int) -> List[Dict[str, Any]]:
    """`n` grid problems on one 64 x 64 map with a wall, start and goal moving along it."""
    rows = ["." * 64] * 64
    rows = [r[:32] + ("@" if 8 <= y < 56 else ".") + r[33:] for y, r in enumerate(rows)]
    return [
        {
            "world": {"grid": {"rows": rows}},
            "start": [i % 30, (7 * i) % 64],
            "goal": [63 - i % 30, (11 * i) % 64],
            "planner": {"name": "astar"},
        }
        for i in range(n)
    ]


if __name__ == "__main__":
    import time

    ray.init()
    documents = demonstration_documents(20_000)
    clock = time.perf_counter()
    on_ray = solve_on_ray(documents, chunk_size=2_000)
    print(f"{len(on_ray)} documents on Ray in {time.perf_counter() - clock:.2f} s")
    clock = time.perf_counter()
    here = trailmark.solve_many(documents)
    print(f"{len(here)} documents here in {time.perf_counter() - clock:.2f} s")
    strip = lambda r: {k: v for k, v in r.items() if k != "stats"}  # noqa: E731 (times differ)
    print("identical results:", [strip(r) for r in on_ray] == [strip(r) for r in here])
    ray.shutdown()
