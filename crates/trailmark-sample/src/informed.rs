//! Informed sampling (Gammell, Srinivasa and Barfoot 2014): once a planner holds a solution of
//! cost `c`, only states through which a cheaper path can pass are worth drawing, those whose
//! distance from a start plus their [`cost_to_go`](crate::Goal::cost_to_go) is below `c`.
//! Where the problem has one start, the goal is one state ([`Goal::focus`](crate::Goal::focus))
//! and the space draws from that set directly
//! ([`StateSpace::sample_informed`](crate::StateSpace::sample_informed): an ellipsoid in
//! straight-line spaces), and while the set is smaller than the space, states come from it;
//! otherwise from the planner's sampler, refused until one falls inside (OMPL's
//! `PathLengthDirectInfSampler` and `RejectionInfSampler`). Informed RRT* and BIT* draw through
//! it; both prune with its [`estimate`](Informed::estimate).

use trailmark_core::termination::Stop;

use crate::problem::{Goal, Problem};
use crate::run::Run;
use crate::sampler::StateSampler;
use crate::space::StateSpace;
use crate::validity::Validity;

/// The share by which the best cost must fall before an informed planner prunes again (OMPL's
/// `pruneThreshold`, 5%): pruning rebuilds the nearest-neighbour structure.
pub(crate) const PRUNE_THRESHOLD: f64 = 0.05;

/// The relative slack of a pruning's comparison: a straight solution's cost, summed leg by leg,
/// can round below the distance of its ends, the estimate of its own last state.
pub(crate) const PRUNE_SLACK: f64 = 1e-9;

/// Draws per informed sample before the run moves on (OMPL's `numSampleAttempts_`).
pub(crate) const ATTEMPTS: usize = 100;

/// The informed set of one problem.
pub(crate) struct Informed<'p, S: StateSpace> {
    starts: &'p [S::State],
    goal: &'p dyn Goal<S>,
}

impl<'p, S: StateSpace> Informed<'p, S> {
    pub(crate) fn new<V>(problem: &'p Problem<'p, S, V>) -> Self {
        Informed { starts: &problem.starts, goal: &*problem.goal }
    }

    /// A lower bound on the cost of any solution through `state`: its distance from the
    /// nearest start plus the goal's bound from it.
    pub(crate) fn estimate(&self, space: &S, state: &S::State) -> f64 {
        self.come(space, state) + self.go(space, state)
    }

    /// A lower bound on the cost from the starts to `state`: its distance from the nearest.
    pub(crate) fn come(&self, space: &S, state: &S::State) -> f64 {
        self.starts.iter().map(|s| space.distance(s, state)).fold(f64::INFINITY, f64::min)
    }

    /// A lower bound on the cost from `state` to the goal ([`Goal::cost_to_go`]).
    pub(crate) fn go(&self, space: &S, state: &S::State) -> f64 {
        self.goal.cost_to_go(space, state)
    }

    /// A state of the space whose [`estimate`](Self::estimate) is below `best` (all of them
    /// while `best` is infinite): drawn from the set directly where it can be, else from
    /// `sampler` until one falls inside. `Ok(None)` after [`ATTEMPTS`] draws without one;
    /// `Err` when the run must stop.
    pub(crate) fn sample<V: Validity<S>, Q: StateSampler<S>>(
        &self,
        run: &mut Run<'_>,
        space: &S,
        validity: &V,
        sampler: &Q,
        best: f64,
    ) -> Result<Option<S::State>, Stop> {
        if best == f64::INFINITY {
            return run.sample(space, validity, sampler);
        }
        // No state is cheaper than a start's own bound to the goal: then the set is empty.
        if self.starts.iter().all(|s| self.go(space, s) >= best) {
            return Ok(None);
        }
        if let ([start], Some((goal, tolerance))) = (self.starts, self.goal.focus()) {
            let cost = best + tolerance;
            if space.informed_measure(start, goal, cost).is_some_and(|m| m < space.measure()) {
                for _ in 0..ATTEMPTS {
                    let Some(state) = space.sample_informed(start, goal, cost, &mut run.rng) else { break };
                    // The ellipsoid grown by the tolerance holds states inside the goal's ball
                    // whose distance from the start alone reaches `best`.
                    if space.satisfies_bounds(&state) && self.estimate(space, &state) < best {
                        return Ok(Some(state));
                    }
                }
                return Ok(None);
            }
        }
        for _ in 0..ATTEMPTS {
            if let Some(state) = run.sample(space, validity, sampler)?
                && self.estimate(space, &state) < best
            {
                return Ok(Some(state));
            }
        }
        Ok(None)
    }
}

#[cfg(test)]
mod tests {
    use trailmark_core::geometry::Point;
    use trailmark_core::termination::{Termination, Watch};
    use trailmark_core::world::{Bounds, PolygonWorld};

    use super::Informed;
    use crate::run::Run;
    use crate::{Goal, GoalState, Problem, R2, StateSpace, Uniform};

    /// A strip along the east wall: a region with a bound on the cost left and no state to
    /// focus on, so that states are drawn and refused.
    struct Strip;

    impl Goal<R2> for Strip {
        fn is_satisfied(&self, _: &R2, p: &Point) -> bool {
            p.x >= 9.0
        }
        fn distance(&self, _: &R2, p: &Point) -> f64 {
            (9.0 - p.x).max(0.0)
        }
        fn cost_to_go(&self, space: &R2, p: &Point) -> f64 {
            self.distance(space, p)
        }
    }

    /// Every state drawn, directly (a goal state) or by rejection (a region), lies in the
    /// informed set, and the draws reach across it (both halves of the set hold some); none
    /// once the best cost is the least any solution can have.
    #[test]
    fn draws_only_inside_the_informed_set() {
        let bounds = Bounds::new(0.0, 0.0, 10.0, 10.0).unwrap();
        let checker = PolygonWorld::new(bounds, vec![], 0.0).unwrap().checker();
        let space = R2::new(bounds);
        let start = Point::new(1.0, 5.0);
        let state = Problem::with_goal(&space, &checker, start, GoalState::within(Point::new(9.0, 5.0), 0.5));
        let region = Problem::with_goal(&space, &checker, start, Strip);
        let limit = Termination::iterations(1);
        for (problem, best) in [(&state, 8.0), (&region, 8.5)] {
            let set = Informed::new(problem);
            let mut run = Run::checked(problem, Watch::start(&limit), 1.0, 3).unwrap();
            let drawn: Vec<Point> = (0..2000)
                .filter_map(|_| set.sample(&mut run, &space, &checker, &Uniform, best).unwrap())
                .collect();
            assert!(drawn.len() > 1000, "{}", drawn.len());
            assert!(drawn.iter().all(|p| space.satisfies_bounds(p) && set.estimate(&space, p) < best));
            assert!(drawn.iter().any(|p| p.y > 5.5) && drawn.iter().any(|p| p.y < 4.5));
            // The least any solution costs: the start's own bound.
            let least = set.go(&space, &start);
            assert_eq!(set.sample(&mut run, &space, &checker, &Uniform, least).unwrap(), None);
        }
    }
}
