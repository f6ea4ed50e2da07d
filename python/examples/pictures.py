"""The pictures of docs/python.md, drawn with matplotlib from plans made here:

    pip install ./python matplotlib
    python python/examples/pictures.py docs/img
"""

import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import trailmark  # noqa: E402

REPOSITORY = Path(__file__).resolve().parents[2]


def numpy_map(out):
    """A NumPy occupancy map with rooms, A* and Theta* across it."""
    free = np.ones((60, 90), dtype=bool)
    free[20, :70] = False
    free[40, 20:] = False
    free[:12, 45] = False
    grid = trailmark.Grid(free)
    astar = grid.astar((2, 2), (85, 57))
    theta = grid.theta_star((2, 2), (85, 57))
    figure, axes = plt.subplots(figsize=(7.5, 5))
    axes.imshow(~free, cmap="Greys", origin="upper")
    axes.plot(astar.path[:, 0], astar.path[:, 1], color="tab:blue", lw=1.5, label=f"A*  {astar.cost:.1f}")
    axes.plot(theta.path[:, 0], theta.path[:, 1], color="tab:red", lw=1.5, label=f"Theta*  {theta.cost:.1f}")
    axes.legend(loc="lower left")
    axes.set_title("trailmark.Grid(free).astar / .theta_star on a NumPy map")
    figure.tight_layout()
    figure.savefig(out / "python-grid.png", dpi=90)


def ros_map(out):
    """The office ROS map's costmap, Theta* and a car's Hybrid A* path."""
    office = trailmark.RosMap(REPOSITORY / "examples" / "maps" / "office.yaml", inflation_radius=0.5,
                              cost_scaling_factor=8)
    theta = office.theta_star((-4.2, -2.2), (4.3, 2.3))
    car = [[-0.15, -0.2], [0.45, -0.2], [0.45, 0.2], [-0.15, 0.2]]
    hybrid = office.hybrid_astar((-4.2, -2.2, 0.0), (4.3, 2.3, 3.14159), turning_radius=0.5, footprint=car)
    figure, axes = plt.subplots(figsize=(7.5, 5))
    axes.imshow(office.costs(), cmap="Greys", extent=office.extent(), vmin=0, vmax=255)
    axes.plot(theta.path[:, 0], theta.path[:, 1], color="tab:red", lw=1.5, label="Theta* (robot radius 0.1 m)")
    axes.plot(hybrid.path[:, 0], hybrid.path[:, 1], color="tab:blue", lw=1.5, label="Hybrid A* (a car, 0.5 m turns)")
    axes.set_xlabel("x (m)")
    axes.set_ylabel("y (m)")
    axes.legend(loc="lower right")
    axes.set_title("trailmark.RosMap('office.yaml'): the costmap and two plans in metres")
    figure.tight_layout()
    figure.savefig(out / "python-rosmap.png", dpi=90)


if __name__ == "__main__":
    out = Path(sys.argv[1] if len(sys.argv) > 1 else ".")
    out.mkdir(parents=True, exist_ok=True)
    numpy_map(out)
    ros_map(out)
    print(f"wrote {out / 'python-grid.png'} and {out / 'python-rosmap.png'}")
