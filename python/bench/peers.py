"""The Python peers of bench.py: RRT-Connect of OMPL 2.0 (its nanobind bindings, `pip install
ompl`) and of oxmpl-py 0.7 (`pip install oxmpl-py`), with one signature.

    solved, path, n_validity_calls = fn(lo, hi, start, goal, is_valid, range_,
                                        time_limit_s, seed, resolution=None)

* is_valid(point) -> bool receives a list of d floats.
* range_: RRT-Connect step length (OMPL setRange / oxmpl max_distance);
  None or 0 means OMPL's automatic range (0.2 * maximum extent); oxmpl has no
  automatic range, so it uses the same 0.2 * extent.
* resolution: optional absolute motion-check step length in state units.
  None keeps each library's own default:
    OMPL : longest valid segment = 0.01 * max extent        (0.1414 for 10x10)
    oxmpl: step = 0.1 * 0.05 * max extent = 0.005 * extent  (0.0707 for 10x10)
* LAST_STATS (module dict) is updated after each call with solve-only time etc.
"""
import time

import numpy as np

LAST_STATS = {}


# --------------------------------------------------------------------------- OMPL
def _ompl_setup(lo, hi, start, goal, range_, seed, resolution):
    from ompl import base as ob, geometric as og, util as ou

    ou.setLogLevel(ou.LogLevel.LOG_NONE)  # silence OMPL's log output
    # Global seed for RNGs created afterwards (OMPL ignores 0, so use seed + 1).
    ou.RNG.setSeed(int(seed) + 1)
    d = len(start)
    space = ob.RealVectorStateSpace(d)
    bounds = ob.RealVectorBounds(d)
    for i in range(d):
        bounds.setLow(i, float(lo[i]))
        bounds.setHigh(i, float(hi[i]))
    space.setBounds(bounds)
    ss = og.SimpleSetup(space)
    si = ss.getSpaceInformation()
    if resolution:  # OMPL takes a fraction of the maximum extent
        si.setStateValidityCheckingResolution(resolution / space.getMaximumExtent())
    s = si.allocState()
    g = si.allocState()
    for i in range(d):  # (open slices like s[:] do not work in these bindings)
        s[i] = float(start[i])
        g[i] = float(goal[i])
    planner = og.RRTConnect(si)
    if range_:
        planner.setRange(float(range_))
    return ob, og, ss, si, space, planner, s, g, d


def _ompl_finish(ob, ss, planner, time_limit_s, d):
    ss.setPlanner(planner)  # set a planner before setup(): the default-planner path segfaults
    ss.setup()
    t0 = time.perf_counter()
    # Pass a thread-free timed PTC: ss.solve(seconds) with seconds >= 1 starts a helper thread that
    # polls the clock, which added ~0.8 ms per solve here.
    ss.solve(ob.timedPlannerTerminationCondition(float(time_limit_s)))
    LAST_STATS["solve_s"] = time.perf_counter() - t0
    LAST_STATS["range"] = planner.getRange()
    LAST_STATS["resolution"] = ss.getStateSpace().getLongestValidSegmentLength()
    solved = ss.haveExactSolutionPath()  # RRTConnect may also report approximate solutions
    path = []
    if solved:
        path = [[st[i] for i in range(d)] for st in ss.getSolutionPath().getStates()]
    return solved, path


def ompl_rrt_connect(lo, hi, start, goal, is_valid, range_, time_limit_s, seed, resolution=None):
    LAST_STATS.clear()
    ob, og, ss, si, space, planner, s, g, d = _ompl_setup(lo, hi, start, goal, range_, seed, resolution)
    calls = [0]

    def svc(state):  # called by OMPL for one state at a time
        calls[0] += 1
        return bool(is_valid([state[i] for i in range(d)]))

    ss.setStateValidityChecker(svc)
    ss.setStartAndGoalStates(s, g)
    solved, path = _ompl_finish(ob, ss, planner, time_limit_s, d)
    return solved, path, calls[0]


def ompl_rrt_connect_batch(lo, hi, start, goal, is_valid_batch, range_, time_limit_s, seed,
                           resolution=None):
    """Batch variant. OMPL 2.0.1 has NO batch/vectorized validity API; this emulates one by
    subclassing ob.MotionValidator in Python (the bindings have a trampoline for it): each
    motion's discretized states (same count as OMPL's DiscreteMotionValidator,
    space.validSegmentCount(s1, s2), endpoint included) go to is_valid_batch(ndarray (n, d))
    -> bool array in a single call. Single states (start/goal, goal-tree samples) go through
    the same function with n = 1. Return value's third item = number of states checked."""
    LAST_STATS.clear()
    ob, og, ss, si, space, planner, s, g, d = _ompl_setup(lo, hi, start, goal, range_, seed, resolution)
    n_states = [0]
    n_calls = [0]

    def svc(state):
        n_states[0] += 1
        n_calls[0] += 1
        p = np.array([[state[i] for i in range(d)]])
        return bool(np.asarray(is_valid_batch(p))[0])

    class BatchMotionValidator(ob.MotionValidator):
        def checkMotion(self, s1, s2):  # RRTConnect only uses the 2-argument form
            n = space.validSegmentCount(s1, s2)
            a = np.array([s1[i] for i in range(d)])
            b = np.array([s2[i] for i in range(d)])
            pts = a + (np.arange(1, n + 1) / n)[:, None] * (b - a)
            n_states[0] += n
            n_calls[0] += 1
            return bool(np.all(is_valid_batch(pts)))

    ss.setStateValidityChecker(svc)
    mv = BatchMotionValidator(si)
    si.setMotionValidator(mv)  # kept alive by the local `mv` until we return
    ss.setStartAndGoalStates(s, g)
    solved, path = _ompl_finish(ob, ss, planner, time_limit_s, d)
    LAST_STATS["batch_calls"] = n_calls[0]
    return solved, path, n_states[0]


# --------------------------------------------------------------------------- oxmpl
class _OxGoal:
    """oxmpl-py goals are duck-typed Python objects: is_satisfied, sample_goal (+ distance_goal)."""

    def __init__(self, space, goal, tol=1e-9):
        from oxmpl_py.base import RealVectorState

        self.space, self.target, self.tol = space, RealVectorState(list(goal)), tol

    def is_satisfied(self, state):
        return self.space.distance(self.target, state) <= self.tol

    def distance_goal(self, state):
        return self.space.distance(self.target, state)

    def sample_goal(self):
        return self.target


def oxmpl_rrt_connect(lo, hi, start, goal, is_valid, range_, time_limit_s, seed, resolution=None,
                      goal_bias=0.0):
    from oxmpl_py.base import PlannerConfig, ProblemDefinition, RealVectorState, RealVectorStateSpace
    from oxmpl_py.geometric import RRTConnect

    LAST_STATS.clear()
    space = RealVectorStateSpace(len(start), bounds=[(float(a), float(b)) for a, b in zip(lo, hi)])
    extent = space.get_maximum_extent()
    if resolution:  # oxmpl motion step = 0.1 * fraction * extent (default fraction 0.05)
        space.set_longest_valid_segment_fraction(min(1.0, resolution / (0.1 * extent)))
    pdef = ProblemDefinition.from_real_vector(space, RealVectorState([float(x) for x in start]),
                                              _OxGoal(space, [float(x) for x in goal]))
    max_distance = float(range_) if range_ else 0.2 * extent
    planner = RRTConnect(max_distance=max_distance, goal_bias=goal_bias,
                         problem_definition=pdef, planner_config=PlannerConfig(seed=int(seed)))
    calls = [0]

    def svc(state):  # state: oxmpl_py.base.RealVectorState, one at a time
        calls[0] += 1
        return bool(is_valid(state.values))

    planner.setup(svc)
    t0 = time.perf_counter()
    try:
        path = planner.solve(timeout_secs=float(time_limit_s))  # raises on timeout
        solved, pts = True, [list(st.values) for st in path.states]
    except Exception as e:  # "No solution found within timeout."
        LAST_STATS["error"] = str(e)
        solved, pts = False, []
    LAST_STATS["solve_s"] = time.perf_counter() - t0
    LAST_STATS["range"] = max_distance
    LAST_STATS["resolution"] = 0.1 * extent * (min(1.0, resolution / (0.1 * extent)) if resolution else 0.05)
    return solved, pts, calls[0]
