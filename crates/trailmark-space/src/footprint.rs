//! A robot's footprint checked in a world, for the car spaces: one [`FootprintValidity`] for
//! every world that can say where a footprint fits ([`FootprintWorld`]): a polygon world here,
//! exactly; a map's cells in `trailmark-car`, as Hybrid A* checks them.

use std::fmt::Debug;

use trailmark_core::footprint::{Footprint, sweep_margin};
use trailmark_core::geometry::{Point, Pose};
use trailmark_core::world::{Bounds, CollisionChecker, PolygonWorld};

use crate::space::{Car, CarCurves, SpaceError};
use crate::validity::Validity;

/// A world a footprint is checked in: it prepares a test of one footprint grown by a margin,
/// and answers whether that footprint is free at a pose.
///
/// [`FootprintValidity`] checks states with the footprint as it is, and motions at poses along
/// the curve at most a step apart with the footprint grown by
/// [`sweep_margin`], so that the poses in between are
/// covered too; a world that can check a whole curve exactly says so in
/// [`curve_is_free`](Self::curve_is_free).
pub trait FootprintWorld {
    /// `footprint` grown by a margin, made ready for this world's checks.
    type Test: Clone + Debug;

    /// The test of `footprint` grown by `margin`. Errors: a footprint or a growth the world
    /// cannot take.
    fn footprint_test(&self, footprint: &Footprint, margin: f64) -> Result<Self::Test, SpaceError>;

    /// Whether the footprint of `test` at `pose` (world coordinates) is free.
    fn footprint_is_free(&self, test: &Self::Test, pose: &Pose) -> bool;

    /// Whether the footprint of `test` (not grown) stays free along `path`, where the world
    /// checks a whole curve exactly; `None` (the default) where it does not, and the curve is
    /// checked at poses a step apart.
    fn curve_is_free<C: CarCurves>(&self, test: &Self::Test, path: &C::Path) -> Option<bool> {
        let _ = (test, path);
        None
    }
}

impl<W: FootprintWorld + ?Sized> FootprintWorld for &W {
    type Test = W::Test;

    fn footprint_test(&self, footprint: &Footprint, margin: f64) -> Result<Self::Test, SpaceError> {
        (**self).footprint_test(footprint, margin)
    }

    fn footprint_is_free(&self, test: &Self::Test, pose: &Pose) -> bool {
        (**self).footprint_is_free(test, pose)
    }

    fn curve_is_free<C: CarCurves>(&self, test: &Self::Test, path: &C::Path) -> Option<bool> {
        (**self).curve_is_free::<C>(test, path)
    }
}

/// A car's footprint in a world, for the car spaces ([`Dubins`](crate::space::Dubins),
/// [`ReedsShepp`](crate::space::ReedsShepp)): a state is valid when the footprint there is free
/// (as the world decides it); a motion when it is free at poses along the curve at most `step`
/// apart, each checked grown by half the farthest any point of it moves over a step, so that
/// the poses in between are covered too (or, where the world checks whole curves, exactly).
///
/// In a [`PolygonWorld`], where the world's own checker moves a disc of the world's radius:
///
/// - a **disc** of radius `r`: the world's obstacles grown by `r` as well, states and curves
///   tested exactly, with no step;
/// - a **polygon** (a car's rectangle about its rear axle): a state is valid when the polygon
///   there is free exactly ([`CollisionChecker::polygon_is_free`]); a motion when it is free at
///   poses `step` apart, grown by the margin (and the bounds drawn in by as much).
///
/// On a map's cells, `trailmark-car`'s `CarMap` is the world (`MapFootprintValidity`).
///
/// ```
/// use trailmark_core::footprint::Footprint;
/// use trailmark_core::geometry::{Point, Pose, Vector};
/// use trailmark_core::world::{Bounds, Polygon, PolygonWorld};
/// use trailmark_space::space::ReedsShepp;
/// use trailmark_space::{FootprintValidity, Validity};
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
pub struct FootprintValidity<W: FootprintWorld> {
    world: W,
    /// The footprint as it is, for states (and whole curves where the world checks them).
    exact: W::Test,
    /// The footprint grown by the sweep margin, for poses along a motion.
    swept: W::Test,
    step: f64,
}

impl<W: FootprintWorld> FootprintValidity<W> {
    /// The footprint `footprint` in `world` for motions of `space`'s curves, checked every
    /// `step` along them.
    ///
    /// Errors: a footprint radius that is negative or not finite, a `step` that is not positive
    /// and finite, or a growth the world cannot take ([`SpaceError::NotPositive`] names which).
    pub fn new<C: CarCurves>(
        world: W,
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
        let margin = sweep_margin(step, reach, space.turning_radius());
        let exact = world.footprint_test(footprint, 0.0)?;
        let swept = world.footprint_test(footprint, margin)?;
        Ok(FootprintValidity { world, exact, swept, step })
    }
}

impl<C: CarCurves, W: FootprintWorld> Validity<Car<C>> for FootprintValidity<W> {
    fn state_is_valid(&self, _: &Car<C>, s: &Pose) -> bool {
        self.world.footprint_is_free(&self.exact, s)
    }

    fn motion_is_valid(&self, space: &Car<C>, a: &Pose, b: &Pose) -> bool {
        let path = space.path(a, b);
        self.world.curve_is_free::<C>(&self.exact, &path).unwrap_or_else(|| {
            C::sample(&path, self.step)
                .is_some_and(|poses| poses.iter().all(|p| self.world.footprint_is_free(&self.swept, p)))
        })
    }
}

/// A footprint grown by a margin in a polygon world.
#[derive(Clone, Debug)]
pub enum PolygonFootprint {
    /// A disc: the world with its obstacles grown by the disc's radius and the margin.
    Disc(CollisionChecker),
    /// A polygon's corners about the reference point, and the world with its obstacles grown by
    /// the margin and its bounds drawn in by as much.
    Polygon {
        /// The corners, in the robot's frame.
        corners: Vec<Point>,
        /// The grown world's checker.
        checker: Box<CollisionChecker>,
    },
}

impl FootprintWorld for PolygonWorld {
    type Test = PolygonFootprint;

    fn footprint_test(&self, footprint: &Footprint, margin: f64) -> Result<PolygonFootprint, SpaceError> {
        // The obstacles grown by `extra`, the bounds drawn in by `shrink`.
        let grown = |extra: f64, shrink: f64| {
            let obstacles = self.obstacles().iter().map(|o| o.vertices().to_vec()).collect();
            let (lo, hi) = (self.bounds().min(), self.bounds().max());
            Bounds::new(lo.x + shrink, lo.y + shrink, hi.x - shrink, hi.y - shrink)
                .and_then(|bounds| PolygonWorld::new(bounds, obstacles, self.robot_radius() + extra))
                .map(|w| w.checker())
                .map_err(|_| SpaceError::NotPositive { what: "footprint growth", value: extra })
        };
        Ok(match footprint {
            Footprint::Radius(r) => PolygonFootprint::Disc(grown(r + margin, 0.0)?),
            Footprint::Polygon(polygon) => PolygonFootprint::Polygon {
                corners: polygon.vertices().to_vec(),
                checker: Box::new(grown(margin, margin)?),
            },
        })
    }

    fn footprint_is_free(&self, test: &PolygonFootprint, pose: &Pose) -> bool {
        match test {
            PolygonFootprint::Disc(checker) => checker.point_is_free(Point::from(pose.translation.vector)),
            PolygonFootprint::Polygon { corners, checker } => {
                checker.polygon_is_free(&corners.iter().map(|c| pose * c).collect::<Vec<_>>())
            }
        }
    }

    /// A disc's curve exactly, every arc and segment against the grown obstacles.
    fn curve_is_free<C: CarCurves>(&self, test: &PolygonFootprint, path: &C::Path) -> Option<bool> {
        match test {
            PolygonFootprint::Disc(checker) => Some(C::is_free(checker, path)),
            PolygonFootprint::Polygon { .. } => None,
        }
    }
}
