//! MoveIt planning scenes (`moveit_msgs/PlanningScene` as YAML): the world's collision objects
//! (boxes, cylinders and spheres with their poses) and the allowed collision matrix; and the
//! point clouds a robot's sensors see ([`Scene::add_cloud`]).
//!
//! ```
//! use trailmark_robot::scene::{Scene, Shape};
//!
//! let scene = Scene::parse("
//! world:
//!   collision_objects:
//!     - id: table
//!       primitives: [{type: box, dimensions: [1.0, 0.6, 0.04]}]
//!       primitive_poses: [{position: [0.5, 0, -0.02], orientation: [0, 0, 0, 1]}]
//! ")?;
//! assert_eq!(scene.obstacles[0].id, "table");
//! assert!(matches!(scene.obstacles[0].shape, Shape::Box { .. }));
//! # Ok::<(), trailmark_robot::RobotError>(())
//! ```

use std::path::Path;

use nalgebra::{Isometry3, Quaternion, Translation3, UnitQuaternion, Vector3};
use trailmark_core::yaml::{self, Yaml};

use crate::cloud::PointCloud;
use crate::error::RobotError;
use crate::urdf::read;

/// The most collision objects and primitives a scene may have.
pub const MAX_OBSTACLES: usize = 100_000;

/// A scene: obstacles, and the pairs allowed to touch.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Scene {
    /// Every primitive of every collision object, in the world frame.
    pub obstacles: Vec<Obstacle>,
    /// Pairs of names (links, or objects) the matrix allows to collide: never checked.
    pub allowed: Vec<(String, String)>,
    /// Point clouds, each point a ball ([`Scene::add_cloud`]).
    pub clouds: Vec<PointCloud>,
}

/// One primitive of a collision object.
#[derive(Debug, Clone, PartialEq)]
pub struct Obstacle {
    /// The object's id.
    pub id: String,
    /// Its shape, about its own origin.
    pub shape: Shape,
    /// Its pose in the world frame.
    pub pose: Isometry3<f64>,
}

/// An obstacle's shape (MoveIt's `shape_msgs/SolidPrimitive`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Shape {
    /// A box of these half side lengths.
    Box {
        /// Half its sides along x, y and z.
        half: Vector3<f64>,
    },
    /// A cylinder along z, centred on its origin.
    Cylinder {
        /// Its radius.
        radius: f64,
        /// Half its height.
        half_height: f64,
    },
    /// A ball.
    Sphere {
        /// Its radius.
        radius: f64,
    },
}

impl Scene {
    /// Reads a scene's YAML text: `world.collision_objects`, each with `id`, `primitives`
    /// (`type` box, cylinder or sphere and their `dimensions`: box `[x, y, z]`, cylinder
    /// `[height, radius]`, sphere `[radius]`) and as many `primitive_poses` (`position`,
    /// `orientation` as `[x, y, z, w]`), under the object's `pose` when it has one; and
    /// `allowed_collision_matrix` (`entry_names`, `entry_values`). Errors on YAML that is not
    /// well formed, anchors and aliases, a size that is not positive and finite, a pose that is
    /// not finite or a zero quaternion, and a matrix that is not square.
    pub fn parse(text: &str) -> Result<Scene, RobotError> {
        let doc = yaml::load(text, "scene files").map_err(RobotError::Yaml)?;
        let mut scene = Scene::default();
        if let Some(objects) = doc["world"]["collision_objects"].as_vec() {
            for object in objects {
                scene.add(object)?;
            }
        }
        let matrix = &doc["allowed_collision_matrix"];
        if let Some(names) = matrix["entry_names"].as_vec() {
            let names: Vec<&str> = names.iter().map(|n| n.as_str().unwrap_or("")).collect();
            let rows = matrix["entry_values"].as_vec().map_or(&[][..], Vec::as_slice);
            if rows.len() != names.len() {
                return Err(invalid(
                    "allowed_collision_matrix",
                    "entry_values",
                    "a row per name",
                    rows.len(),
                ));
            }
            for (i, row) in rows.iter().enumerate() {
                let row = row.as_vec().filter(|r| r.len() == names.len());
                let row = row.ok_or_else(|| {
                    invalid("allowed_collision_matrix", "entry_values", "a square matrix", i)
                })?;
                for (j, allowed) in row.iter().enumerate() {
                    if j > i && allowed.as_bool() == Some(true) {
                        scene.allowed.push((names[i].to_string(), names[j].to_string()));
                    }
                }
            }
        }
        Ok(scene)
    }

    /// Adds a point cloud's balls to the obstacles (an allowed collision matrix names it by
    /// its id).
    pub fn add_cloud(&mut self, cloud: PointCloud) {
        self.clouds.push(cloud);
    }

    /// Reads the scene file at `path`.
    pub fn from_file(path: impl AsRef<Path>) -> Result<Scene, RobotError> {
        Scene::parse(&read(path.as_ref())?)
    }

    fn add(&mut self, object: &Yaml) -> Result<(), RobotError> {
        let id = object["id"].as_str().unwrap_or("").to_string();
        let base = match &object["pose"] {
            Yaml::BadValue => Isometry3::identity(),
            pose => pose_of(pose, &id)?,
        };
        let primitives = object["primitives"].as_vec().map_or(&[][..], Vec::as_slice);
        let poses = object["primitive_poses"].as_vec().map_or(&[][..], Vec::as_slice);
        if primitives.len() != poses.len() {
            return Err(invalid(&id, "primitive_poses", "a pose per primitive", poses.len()));
        }
        if self.obstacles.len() + primitives.len() > MAX_OBSTACLES {
            let count = self.obstacles.len() + primitives.len();
            return Err(RobotError::TooLarge { what: "the scene's primitives", count, max: MAX_OBSTACLES });
        }
        for (primitive, pose) in primitives.iter().zip(poses) {
            let dimensions: Vec<f64> = primitive["dimensions"]
                .as_vec()
                .map(|d| d.iter().filter_map(yaml::number).collect())
                .unwrap_or_default();
            if dimensions.is_empty() || !dimensions.iter().all(|d| d.is_finite() && *d > 0.0) {
                return Err(invalid(&id, "dimensions", "positive finite sizes", dimensions.len()));
            }
            let shape = match (primitive["type"].as_str(), dimensions.as_slice()) {
                (Some("box"), &[x, y, z]) => Shape::Box { half: Vector3::new(x, y, z) / 2.0 },
                (Some("cylinder"), &[height, radius]) => {
                    Shape::Cylinder { radius, half_height: height / 2.0 }
                }
                (Some("sphere"), &[radius]) => Shape::Sphere { radius },
                _ => {
                    return Err(invalid(
                        &id,
                        "type",
                        "box [x, y, z], cylinder [height, radius] or sphere [radius]",
                        dimensions.len(),
                    ));
                }
            };
            self.obstacles.push(Obstacle { id: id.clone(), shape, pose: base * pose_of(pose, &id)? });
        }
        Ok(())
    }
}

/// A pose of `position` `[x, y, z]` and `orientation` `[x, y, z, w]` (normalised).
pub(crate) fn pose_of(pose: &Yaml, id: &str) -> Result<Isometry3<f64>, RobotError> {
    let values = |field: &str, n: usize| -> Result<Vec<f64>, RobotError> {
        let v: Vec<f64> =
            pose[field].as_vec().map(|v| v.iter().filter_map(yaml::number).collect()).unwrap_or_default();
        if v.len() == n && v.iter().all(|x| x.is_finite()) {
            Ok(v)
        } else {
            Err(invalid(id, "pose", "a finite position [x, y, z] and orientation [x, y, z, w]", v.len()))
        }
    };
    let (p, o) = (values("position", 3)?, values("orientation", 4)?);
    let q = Quaternion::new(o[3], o[0], o[1], o[2]);
    if q.norm().is_nan() || q.norm() <= 1e-9 {
        return Err(invalid(id, "orientation", "a quaternion that is not zero", 0));
    }
    Ok(Isometry3::from_parts(Translation3::new(p[0], p[1], p[2]), UnitQuaternion::from_quaternion(q)))
}

fn invalid(element: &str, attribute: &'static str, reason: &'static str, value: usize) -> RobotError {
    RobotError::Invalid { element: element.to_string(), attribute, reason, value: value.to_string() }
}
