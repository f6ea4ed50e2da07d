"""ROS maps from Python: the same plans as the documents of `cargo xtask solve`, the costmap as
an array, errors as exceptions."""

import json

import numpy as np
import pytest

import trailmark
from conftest import EXAMPLES, REPOSITORY, ROSMAPS, need

OFFICE = REPOSITORY / "examples" / "maps" / "office.yaml"


@pytest.mark.parametrize("example", ["office-ros-astar.json", "office-ros-theta-star.json"])
def test_plans_equal_the_documents(example):
    document = json.loads((EXAMPLES / example).read_text())
    spec = document["world"]["ros_map"]
    office = trailmark.RosMap(EXAMPLES / spec.pop("yaml"), **spec)
    planner = document["planner"]
    plan = office.plan(document["start"], document["goal"], planner.pop("name"), **planner)
    result = trailmark.solve(EXAMPLES / example)
    assert plan.status == result["status"] and plan.cost == result["cost"]
    assert plan.path.tolist() == result["path"]
    assert plan.stats["expansions"] == result["stats"]["expansions"]


def test_hybrid_astar_equals_the_document():
    document = json.loads((EXAMPLES / "office-hybrid-astar.json").read_text())
    spec = document["world"]["ros_map"]
    office = trailmark.RosMap(EXAMPLES / spec.pop("yaml"), **spec)
    planner = document["planner"]
    del planner["name"]
    plan = office.hybrid_astar(document["start"], document["goal"], **planner)
    result = trailmark.solve(EXAMPLES / "office-hybrid-astar.json")
    assert plan.status == "solved" and plan.path.shape[1] == 3
    assert plan.path.tolist() == result["path"] and plan.cost == result["cost"]


def test_costmap_array():
    office = trailmark.RosMap(OFFICE, robot_radius=0.15, inflation_radius=0.5)
    costs = office.costs()
    assert costs.dtype == np.uint8 and costs.shape == (office.height, office.width)
    # Lethal cells and their inscribed ring are there, free cells too, and nothing between
    # 253 and 254 is missing from the ring around each lethal cell.
    assert (costs == 254).any() and (costs == 253).any() and (costs == 0).any()
    left, right, bottom, top = office.extent()
    assert right - left == pytest.approx(office.width * office.resolution)
    assert top - bottom == pytest.approx(office.height * office.resolution)
    # A plan's waypoints lie on cells the robot may occupy.
    plan = office.astar((-4.2, -2.2), (4.3, 2.3))
    for x, y in plan.path:
        column = int((x - left) / office.resolution)
        row = office.height - 1 - int((y - bottom) / office.resolution)
        assert costs[row, column] < 253


def test_nav2_maps_plan():
    """Every Nav2 example map beside the repository loads and plans between free cells."""
    folder = need(ROSMAPS, "the Nav2 example maps")
    for yaml in sorted(folder.glob("*.yaml")):
        ros = trailmark.RosMap(yaml, robot_radius=0.2)
        costs = ros.costs()
        free = np.argwhere(costs == 0)
        left, _, bottom, _ = ros.extent()
        (r0, c0), (r1, c1) = free[0], free[len(free) // 2]
        metres = lambda r, c: (left + (c + 0.5) * ros.resolution, bottom + (ros.height - r - 0.5) * ros.resolution)
        plan = ros.astar(metres(r0, c0), metres(r1, c1))
        assert plan.status in ("solved", "no_path")


def test_errors():
    with pytest.raises(trailmark.MapError):
        trailmark.RosMap("/nonexistent/map.yaml")
    with pytest.raises(trailmark.DocumentError):
        trailmark.RosMap(OFFICE, robot_radius=0.2, footprint=[[0, 0], [1, 0], [0, 1]])
    office = trailmark.RosMap(OFFICE)
    with pytest.raises(trailmark.DocumentError, match="outside"):
        office.astar((-400.0, 0.0), (4.3, 2.3))
    with pytest.raises(trailmark.DocumentError):
        office.astar((float("nan"), 0.0), (4.3, 2.3))
    with pytest.raises(trailmark.DocumentError):
        office.plan((-4.2, -2.2), (4.3, 2.3), "rrt_connect")
    with pytest.raises(trailmark.MapError):
        trailmark.RosMap(OFFICE, cost_factor=-1.0)
