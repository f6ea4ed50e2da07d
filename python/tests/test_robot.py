"""Robot arms as objects: states checked in batches by both checkers, plans equal to the
documents', paths free, and the errors."""

import numpy as np
import pytest

import trailmark
from conftest import EXAMPLES, SHARED, need, sigint_after

ROBOT = EXAMPLES / "robot"
START, GOAL = (1.2, 0.6, 1.2, 0.8), (-0.5, 0.9, 0.9, 0.3)


def arm(checker="batch"):
    return trailmark.RobotWorld(ROBOT / "arm.urdf", ROBOT / "arm.srdf", "arm", scene=ROBOT / "shelf.yaml",
                                checker=checker)


def random_states(world, n, seed):
    limits = world.limits
    rng = np.random.default_rng(seed)
    return limits[:, 0] + rng.random((n, len(limits))) * (limits[:, 1] - limits[:, 0])


def test_the_group_and_its_limits():
    world = arm()
    assert len(world.joint_names) == 4 and len(set(world.joint_names)) == 4
    assert world.limits.shape == (4, 2) and (world.limits[:, 0] < world.limits[:, 1]).all()
    assert "4 joints" in repr(world)


def agree(batch, scalar, states):
    """The SIMD checker (f32 lanes, its spheres grown by their rounding) and the scalar one
    (f64) are two implementations of one test: a state the batch calls free is free for the
    scalar one, and they part only within the rounding (here: at most 1% of the states). The
    batch's answers."""
    free, exact = batch.is_valid(states), scalar.is_valid(states)
    assert not (free & ~exact).any(), "the batch checker freed a state in collision"
    assert (free != exact).sum() <= len(states) // 100
    assert 0 < free.sum() < len(states), "free and blocked states both occur"
    return free


def test_the_batch_and_scalar_checkers_agree_state_by_state():
    batch, scalar = arm("batch"), arm("scalar")
    states = random_states(batch, 2000, seed=1)
    free = agree(batch, scalar, states)
    assert free.dtype == np.bool_ and free.shape == (2000,)
    assert [batch.is_valid(q) for q in states[:50]] == free[:50].tolist()
    # Any layout and float dtype: the same answers.
    assert np.array_equal(batch.is_valid(np.asfortranarray(states)), free)
    assert np.array_equal(batch.is_valid(np.repeat(states, 2, axis=0)[::2]), free)
    assert np.array_equal(batch.is_valid(states.astype(np.float32)), batch.is_valid(states.astype(np.float32).astype(np.float64)))
    # Beyond the limits: not free for either checker, as the planners refuse such ends.
    for world in (batch, scalar):
        assert world.is_valid((0.0, 1.9, 0.0, 0.0)) is False
        assert world.motion_is_valid(START, (0.0, 1.9, 0.0, 0.0)) is False
    assert batch.is_valid(START) is True and batch.is_valid((0.0, 1.6, 0.0, 0.0)) is False
    assert batch.is_valid((np.nan, 0.6, 1.2, 0.8)) is False
    assert batch.is_valid(np.empty((0, 4))).shape == (0,)


@pytest.mark.parametrize("planner", ["rrt_connect", "rrt_star", "informed_rrt_star", "bit_star", "prm", "prm_star", "lazy_prm", "lazy_prm_star"])
def test_plans_equal_the_documents_and_are_free(planner):
    world = arm()
    plan = world.plan(START, GOAL, planner, seed=3, max_iterations=1500)
    assert plan.solved, plan.stats
    assert np.allclose(plan.path[0], START) and np.allclose(plan.path[-1], GOAL)
    assert world.is_valid(plan.path).all()
    assert all(world.motion_is_valid(a, b) for a, b in zip(plan.path[:-1], plan.path[1:]))
    document = {"world": world.world(), "start": list(START), "goal": list(GOAL), "seed": 3,
                "planner": {"name": planner, "max_iterations": 1500}}
    result = trailmark.solve(document)
    assert np.array_equal(np.asarray(result["path"]), plan.path)
    assert result["cost"] == plan.cost


def test_the_example_documents_world_plans_as_they_do():
    """The world of examples/problems/shelf-arm-rrt-connect.json, planned as the document."""
    import json

    document = json.loads((EXAMPLES / "shelf-arm-rrt-connect.json").read_text())
    world = arm()
    settings = {k: v for k, v in document["planner"].items() if k != "name"}
    plan = world.plan(document["start"], document["goal"], document["planner"]["name"], seed=document["seed"],
                      **settings)
    result = trailmark.solve(EXAMPLES / "shelf-arm-rrt-connect.json")
    assert np.array_equal(np.asarray(result["path"]), plan.path)


def test_bad_worlds_states_and_plans_raise_typed_errors():
    with pytest.raises(trailmark.RobotError):
        trailmark.RobotWorld(ROBOT / "arm.urdf", ROBOT / "arm.srdf", "legs")
    with pytest.raises(trailmark.RobotError):
        trailmark.RobotWorld(ROBOT / "no-such.urdf", ROBOT / "arm.srdf", "arm")
    with pytest.raises(trailmark.RobotError):
        trailmark.RobotWorld(ROBOT / "arm.urdf", ROBOT / "arm.srdf", "arm", scene=ROBOT / "no-such-scene.yaml")
    with pytest.raises(trailmark.DocumentError):
        trailmark.RobotWorld(ROBOT / "arm.urdf", ROBOT / "arm.srdf", "arm", checker="fast")
    with pytest.raises(trailmark.DocumentError):
        trailmark.RobotWorld(ROBOT / "arm.urdf", ROBOT / "arm.srdf", None)  # type: ignore[arg-type]
    world = arm()
    with pytest.raises(trailmark.DocumentError, match="columns"):
        world.is_valid(np.zeros((3, 5)))
    with pytest.raises(trailmark.DocumentError):
        world.is_valid(np.zeros((2, 2, 4)))
    with pytest.raises(trailmark.DocumentError):
        world.plan((1.0, 2.0, 3.0), GOAL)
    with pytest.raises(trailmark.DocumentError):
        world.plan(START, (np.nan, 0.0, 0.0, 0.0))
    with pytest.raises(trailmark.RobotError, match="limits"):
        world.plan((0.0, 1.9, 0.0, 0.0), GOAL)
    with pytest.raises(trailmark.PlanError):
        world.plan((0.0, 1.6, 0.0, 0.0), GOAL)  # the start in collision
    with pytest.raises(trailmark.DocumentError):
        world.plan(START, GOAL, "astar")
    with pytest.raises(trailmark.DocumentError):
        world.plan(START, GOAL, "prm", range=0.5)
    with pytest.raises(trailmark.DocumentError):
        world.plan(START, GOAL, "rrt_connect", time_limit_s=-1)
    assert world.motion_is_valid(START, START) is True
    with pytest.raises(trailmark.DocumentError):
        world.motion_is_valid(START, (1.0, "a", 0.0, 0.0))
    with pytest.raises(trailmark.DocumentError, match="4 joints"):
        world.motion_is_valid(START, (1.0, 0.0, 0.0))
    for seed in (-1, 2**64, 1.5):
        with pytest.raises(trailmark.DocumentError, match="seed"):
            world.plan(START, GOAL, seed=seed)


def test_ctrl_c_stops_a_plan():
    """A plan with no end in sight (RRT* for a minute) stops at Ctrl-C."""
    import time

    world = arm()
    sigint_after(0.5)
    clock = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        world.plan(START, GOAL, "rrt_star", time_limit_s=60)
    assert time.monotonic() - clock < 10


def test_the_panda_among_a_motionbenchmaker_scene():
    """The Panda's spherized URDF and a scene of MotionBenchMaker: the checkers agree, and a
    plan between two free states is free."""
    panda = need(SHARED / "mbm" / "panda", "the Panda of MotionBenchMaker")
    scene = panda / "problems" / "table_under_pick_panda" / "scene0002.yaml"
    worlds = [trailmark.RobotWorld(panda / "panda_spherized.urdf", panda / "panda.srdf", "panda_arm", scene=scene,
                                   checker=checker) for checker in ("batch", "scalar")]
    states = random_states(worlds[0], 1000, seed=2)
    free = agree(worlds[0], worlds[1], states)
    start, goal = states[free][:2]
    plan = worlds[0].plan(start, goal, "rrt_connect", seed=1, time_limit_s=10)
    assert plan.solved and worlds[0].is_valid(plan.path).all()
