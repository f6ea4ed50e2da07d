//! Which states and motions a planner may use.
//!
//! A [`Validity`] answers two questions, as OMPL's state validity checker and motion validator
//! do: may the robot be at this state, and may it move from this state to that one along the
//! space's motion. For a `PolygonWorld`, the [`CollisionChecker`] answers both *exactly* in
//! [`R2`], [`Se2`] (a disc robot: the heading does not matter, the position moves in a straight
//! line), [`Dubins`](crate::space::Dubins) and [`ReedsShepp`](crate::space::ReedsShepp) (every arc and segment of the curve tested against the grown
//! obstacles), with no sampling resolution. For any other space or world, [`Sampled`] wraps a
//! state test and checks motions at a resolution, a fraction of the space's extent (OMPL's
//! longest valid segment fraction).
//!
//! ```
//! use trailmark_core::geometry::Point;
//! use trailmark_core::world::{Bounds, PolygonWorld};
//! use trailmark_space::space::{R2, StateSpace};
//! use trailmark_space::validity::{Sampled, Validity};
//!
//! let bounds = Bounds::new(0.0, 0.0, 10.0, 10.0)?;
//! let wall = vec![Point::new(4.0, 0.0), Point::new(6.0, 0.0), Point::new(6.0, 8.0), Point::new(4.0, 8.0)];
//! let checker = PolygonWorld::new(bounds, vec![wall], 0.0)?.checker();
//! let space = R2::new(bounds);
//! let (a, b) = (Point::new(1.0, 1.0), Point::new(9.0, 1.0));
//! assert!(checker.state_is_valid(&space, &a));
//! assert!(!checker.motion_is_valid(&space, &a, &b)); // through the wall: exact
//! // The same question by sampling a closure every 1% of the space's extent.
//! let sampled = Sampled::new(|p: &Point| !(p.x > 4.0 && p.x < 6.0 && p.y < 8.0), 0.01)?;
//! assert!(!sampled.motion_is_valid(&space, &a, &b));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use trailmark_core::footprint::{Footprint, sweep_margin};
use trailmark_core::geometry::{Point, Pose};
use trailmark_core::world::{Bounds, CollisionChecker, PolygonWorld};

use crate::space::{Car, CarCurves, R2, Se2, SpaceError, StateSpace};

/// Whether states and motions of a space are allowed.
pub trait Validity<S: StateSpace> {
    /// Whether the robot may be at `state`.
    fn state_is_valid(&self, space: &S, state: &S::State) -> bool;

    /// Whether the robot may move from `from` to `to` along the space's motion (both ends
    /// included).
    fn motion_is_valid(&self, space: &S, from: &S::State, to: &S::State) -> bool;
}

impl Validity<R2> for CollisionChecker {
    fn state_is_valid(&self, _: &R2, p: &Point) -> bool {
        self.point_is_free(*p)
    }

    fn motion_is_valid(&self, _: &R2, a: &Point, b: &Point) -> bool {
        self.segment_is_free(*a, *b)
    }
}

fn position(pose: &Pose) -> Point {
    Point::from(pose.translation.vector)
}

impl Validity<Se2> for CollisionChecker {
    fn state_is_valid(&self, _: &Se2, s: &Pose) -> bool {
        self.point_is_free(position(s))
    }

    fn motion_is_valid(&self, _: &Se2, a: &Pose, b: &Pose) -> bool {
        self.segment_is_free(position(a), position(b))
    }
}

impl<C: CarCurves> Validity<Car<C>> for CollisionChecker {
    fn state_is_valid(&self, _: &Car<C>, s: &Pose) -> bool {
        self.point_is_free(position(s))
    }

    fn motion_is_valid(&self, space: &Car<C>, a: &Pose, b: &Pose) -> bool {
        C::is_free(self, &space.path(a, b))
    }
}

/// A car's footprint in a polygon world, for the car spaces ([`Dubins`](crate::space::Dubins),
/// [`ReedsShepp`](crate::space::ReedsShepp)), where the world's own checker moves a disc of the
/// world's radius.
///
/// - A **disc** of radius `r`: the world's obstacles grown by `r` as well, states and curves
///   tested exactly, with no step.
/// - A **polygon** (a car's rectangle about its rear axle): a state is valid when the polygon
///   there is free exactly ([`CollisionChecker::polygon_is_free`]); a motion when it is free at
///   poses along the curve at most `step` apart, each checked grown by half the farthest any
///   point of it moves over a step (and against the bounds drawn in by as much), so that the
///   poses in between are covered too.
///
/// ```
/// use trailmark_core::footprint::Footprint;
/// use trailmark_core::geometry::{Point, Pose, Vector};
/// use trailmark_core::world::{Bounds, Polygon, PolygonWorld};
/// use trailmark_space::space::ReedsShepp;
/// use trailmark_space::validity::{FootprintValidity, Validity};
///
/// let bounds = Bounds::new(0.0, 0.0, 10.0, 10.0)?;
/// let post = vec![Point::new(4.0, 4.0), Point::new(5.0, 4.0), Point::new(5.0, 5.0), Point::new(4.0, 5.0)];
/// let world = PolygonWorld::new(bounds, vec![post], 0.0)?;
/// let space = ReedsShepp::new(bounds, 1.0)?;
/// // A 1.6 m x 0.8 m car about its rear axle.
/// let corners = [(-0.3, -0.4), (1.3, -0.4), (1.3, 0.4), (-0.3, 0.4)];
/// let car = Footprint::Polygon(Polygon::new(corners.iter().map(|&(x, y)| Point::new(x, y)).collect())?);
/// let validity = FootprintValidity::new(&world, &car, &space, 0.05)?;
/// // Its reference point is clear of the post, but its nose is not.
/// let parked = Pose::new(Vector::new(3.0, 4.5), 0.0);
/// assert!(world.checker().point_is_free(Point::new(3.0, 4.5)));
/// assert!(!validity.state_is_valid(&space, &parked));
/// assert!(validity.state_is_valid(&space, &Pose::new(Vector::new(3.0, 4.5), std::f64::consts::PI)));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Clone, Debug)]
pub struct FootprintValidity {
    shape: FootprintShape,
}

#[derive(Clone, Debug)]
enum FootprintShape {
    /// The world grown by the disc's radius.
    Disc(CollisionChecker),
    /// The polygon's corners about the reference point, checked exactly at states and, along
    /// motions, at poses `step` apart against the world grown by the margin (`swept`).
    Polygon { corners: Vec<Point>, exact: Box<CollisionChecker>, swept: Box<CollisionChecker>, step: f64 },
}

impl FootprintValidity {
    /// The footprint `footprint` in `world` for motions of `space`'s curves, polygons checked
    /// every `step` along them.
    ///
    /// Errors: a footprint radius that is negative or not finite, a `step` that is not positive
    /// and finite, or a growth the world cannot take ([`SpaceError::NotPositive`] names which).
    pub fn new<C: CarCurves>(
        world: &PolygonWorld,
        footprint: &Footprint,
        space: &Car<C>,
        step: f64,
    ) -> Result<Self, SpaceError> {
        let reach = footprint.circumscribed_radius().map_err(|_| SpaceError::NotPositive {
            what: "footprint radius",
            value: match footprint {
                Footprint::Radius(r) => *r,
                Footprint::Polygon(_) => f64::NAN,
            },
        })?;
        if !(step > 0.0 && step.is_finite()) {
            return Err(SpaceError::NotPositive { what: "step", value: step });
        }
        // The obstacles grown by `extra`, and for a polygon's sweep the bounds shrunk by `shrink`.
        let grown = |extra: f64, shrink: f64| {
            let obstacles = world.obstacles().iter().map(|o| o.vertices().to_vec()).collect();
            let (lo, hi) = (world.bounds().min(), world.bounds().max());
            Bounds::new(lo.x + shrink, lo.y + shrink, hi.x - shrink, hi.y - shrink)
                .and_then(|bounds| PolygonWorld::new(bounds, obstacles, world.robot_radius() + extra))
                .map(|w| w.checker())
                .map_err(|_| SpaceError::NotPositive { what: "footprint growth", value: extra })
        };
        let shape = match footprint {
            Footprint::Radius(r) => FootprintShape::Disc(grown(*r, 0.0)?),
            Footprint::Polygon(polygon) => {
                let margin = sweep_margin(step, reach, space.turning_radius());
                FootprintShape::Polygon {
                    corners: polygon.vertices().to_vec(),
                    exact: Box::new(grown(0.0, 0.0)?),
                    swept: Box::new(grown(margin, margin)?),
                    step,
                }
            }
        };
        Ok(FootprintValidity { shape })
    }
}

impl<C: CarCurves> Validity<Car<C>> for FootprintValidity {
    fn state_is_valid(&self, _: &Car<C>, s: &Pose) -> bool {
        match &self.shape {
            FootprintShape::Disc(checker) => checker.point_is_free(position(s)),
            FootprintShape::Polygon { corners, exact, .. } => exact.polygon_is_free(&placed(corners, s)),
        }
    }

    fn motion_is_valid(&self, space: &Car<C>, a: &Pose, b: &Pose) -> bool {
        match &self.shape {
            FootprintShape::Disc(checker) => C::is_free(checker, &space.path(a, b)),
            FootprintShape::Polygon { corners, swept, step, .. } => C::sample(&space.path(a, b), *step)
                .is_some_and(|poses| poses.iter().all(|p| swept.polygon_is_free(&placed(corners, p)))),
        }
    }
}

/// `corners` about the reference point, placed at `pose`.
fn placed(corners: &[Point], pose: &Pose) -> Vec<Point> {
    corners.iter().map(|c| pose * c).collect()
}

/// A state test (a closure) with motions checked at a resolution: states every `resolution x
/// extent` along the motion, both ends included, each also within the space's bounds (a curve
/// between two states in bounds may leave them). Not exact: an obstacle thinner than the step
/// can be missed, as with any sampled check.
#[derive(Clone, Debug)]
pub struct Sampled<F> {
    is_valid: F,
    resolution: f64,
}

impl<F> Sampled<F> {
    /// `is_valid` checked every `resolution` (a fraction of the space's extent, in `(0, 1]`).
    pub fn new(is_valid: F, resolution: f64) -> Result<Self, SpaceError> {
        if !(resolution > 0.0 && resolution <= 1.0) {
            return Err(SpaceError::NotPositive { what: "resolution (at most 1)", value: resolution });
        }
        Ok(Sampled { is_valid, resolution })
    }
}

impl<S: StateSpace, F: Fn(&S::State) -> bool> Validity<S> for Sampled<F> {
    fn state_is_valid(&self, _: &S, state: &S::State) -> bool {
        (self.is_valid)(state)
    }

    fn motion_is_valid(&self, space: &S, from: &S::State, to: &S::State) -> bool {
        let step = self.resolution * space.extent();
        let steps = (space.distance(from, to) / step).ceil();
        if !steps.is_finite() {
            return false;
        }
        let n = (steps as u64).max(1);
        (0..=n).all(|i| {
            let state = space.interpolate(from, to, i as f64 / n as f64);
            space.satisfies_bounds(&state) && (self.is_valid)(&state)
        })
    }
}
