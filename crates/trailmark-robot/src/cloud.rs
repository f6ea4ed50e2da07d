//! Point clouds as obstacles: the points a depth camera or a lidar saw, each the centre of a
//! ball of one radius (the sensor's noise and resolution), kept in a k-d tree (kiddo's
//! immutable tree, which takes any number of points on one plane) so that a sphere's nearest
//! point is found in logarithmic time.
//!
//! ```
//! use trailmark_robot::cloud::PointCloud;
//! use trailmark_robot::nalgebra::Point3;
//!
//! // A wall of points 1 cm apart at x = 0.6, seen with 5 mm of noise.
//! let wall: Vec<Point3<f64>> = (0..100 * 100)
//!     .map(|i| Point3::new(0.6, -0.5 + (i % 100) as f64 * 0.01, (i / 100) as f64 * 0.01))
//!     .collect();
//! let cloud = PointCloud::new("camera", wall, 0.005)?;
//! assert_eq!(cloud.len(), 10_000);
//! // How far a ball's surface at (0.5, 0, 0.5) is from the nearest point's ball.
//! assert!((cloud.clearance(&Point3::new(0.5, 0.0, 0.5)) - 0.095).abs() < 1e-12);
//! # Ok::<(), trailmark_robot::RobotError>(())
//! ```

use std::sync::Arc;

use kiddo::SquaredEuclidean;
use kiddo::immutable::float::kdtree::ImmutableKdTree;
use nalgebra::Point3;

use crate::error::RobotError;

/// The most points of one cloud (a depth camera gives about 300,000 a frame).
pub const MAX_CLOUD_POINTS: usize = 20_000_000;

/// Points seen as obstacles, each a ball of `radius` about it; see the [module](self).
#[derive(Clone)]
pub struct PointCloud {
    id: String,
    points: Arc<Vec<Point3<f64>>>,
    radius: f64,
    tree: Arc<ImmutableKdTree<f64, u32, 3, 32>>,
}

impl std::fmt::Debug for PointCloud {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("PointCloud")
            .field("id", &self.id)
            .field("points", &self.points.len())
            .field("radius", &self.radius)
            .finish()
    }
}

impl PartialEq for PointCloud {
    fn eq(&self, other: &Self) -> bool {
        self.id == other.id && self.radius == other.radius && self.points == other.points
    }
}

impl PointCloud {
    /// The cloud `id` (the name an allowed collision matrix calls it by) of `points`, each a
    /// ball of `radius`. Errors on no points, more than [`MAX_CLOUD_POINTS`], a point that is
    /// not finite, and a radius that is negative or not finite.
    pub fn new(
        id: impl Into<String>,
        points: Vec<Point3<f64>>,
        radius: f64,
    ) -> Result<PointCloud, RobotError> {
        let id = id.into();
        let invalid = |reason: &'static str, value: String| RobotError::Invalid {
            element: id.clone(),
            attribute: "point cloud",
            reason,
            value,
        };
        if points.is_empty() {
            return Err(invalid("at least one point", "none".into()));
        }
        if points.len() > MAX_CLOUD_POINTS {
            return Err(RobotError::TooLarge {
                what: "a point cloud",
                count: points.len(),
                max: MAX_CLOUD_POINTS,
            });
        }
        if let Some(p) = points.iter().find(|p| !p.coords.iter().all(|x| x.is_finite())) {
            return Err(invalid("finite points", format!("{p:?}")));
        }
        if !(radius.is_finite() && radius >= 0.0) {
            return Err(invalid("a radius not negative and finite", radius.to_string()));
        }
        let coordinates: Vec<[f64; 3]> = points.iter().map(|p| [p.x, p.y, p.z]).collect();
        let tree = ImmutableKdTree::new_from_slice(&coordinates);
        Ok(PointCloud { id, points: Arc::new(points), radius, tree: Arc::new(tree) })
    }

    /// Its name.
    pub fn id(&self) -> &str {
        &self.id
    }

    /// The points.
    pub fn points(&self) -> &[Point3<f64>] {
        &self.points
    }

    /// How many points it has.
    pub fn len(&self) -> usize {
        self.points.len()
    }

    /// Whether it has no points (never: [`PointCloud::new`] refuses that).
    pub fn is_empty(&self) -> bool {
        self.points.is_empty()
    }

    /// The radius of each point's ball.
    pub fn radius(&self) -> f64 {
        self.radius
    }

    /// The points within `distance` of `c`.
    pub fn within(&self, c: &Point3<f64>, distance: f64) -> Vec<Point3<f64>> {
        let found = self.tree.within_unsorted::<SquaredEuclidean>(&[c.x, c.y, c.z], distance * distance);
        found.iter().map(|n| self.points[n.item as usize]).collect()
    }

    /// How far `c` is from the nearest point's ball (negative inside one).
    pub fn clearance(&self, c: &Point3<f64>) -> f64 {
        let nearest = self.tree.nearest_one::<SquaredEuclidean>(&[c.x, c.y, c.z]);
        nearest.distance.sqrt() - self.radius
    }
}
