//! The problem document: a world, a start, a goal, a planner and its parameters, as serde
//! types. Later planners extend these types with new variants and optional fields; existing
//! documents keep their meaning. Everything is checked when it is solved, not when it is read.
//!
//! ```
//! use trailmark::solve::{PlannerSpec, ProblemSpec, WorldSpec};
//!
//! let json = r#"{
//!     "world": {"grid": {"rows": ["....", ".@@.", "...."], "connectivity": 8}},
//!     "start": [0, 0], "goal": [3, 2],
//!     "planner": {"name": "weighted_astar", "weight": 1.5}
//! }"#;
//! let problem: ProblemSpec = serde_json::from_str(json)?;
//! assert_eq!(problem.planner, PlannerSpec::WeightedAStar { weight: 1.5, heuristic: None });
//! let WorldSpec::Grid(grid) = &problem.world else { unreachable!() };
//! assert_eq!(grid.rows.as_ref().map(Vec::len), Some(3));
//! # Ok::<(), serde_json::Error>(())
//! ```
//!
//! A polygon world is searched on a roadmap, named by `"graph"` with its parameters beside it:
//!
//! ```
//! use trailmark::solve::{GraphKind, ProblemSpec, WorldSpec};
//!
//! let json = r#"{
//!     "world": {"polygons": {"bounds": [0, 0, 10, 10],
//!                            "obstacles": [[[4, 0], [6, 0], [6, 8], [4, 8]]],
//!                            "robot_radius": 0.25}},
//!     "graph": "prm", "samples": 500, "k": 12,
//!     "start": [1, 1], "goal": [9, 1],
//!     "planner": {"name": "astar"}
//! }"#;
//! let problem: ProblemSpec = serde_json::from_str(json)?;
//! assert_eq!(problem.graph, Some(GraphKind::Prm));
//! assert_eq!((problem.samples, problem.k), (Some(500), Some(12)));
//! let WorldSpec::Polygons(world) = &problem.world else { unreachable!() };
//! assert_eq!(world.obstacles().len(), 1);
//! # Ok::<(), serde_json::Error>(())
//! ```

use std::path::PathBuf;

use serde::{Deserialize, Serialize};
use trailmark_core::grid::Connectivity;
use trailmark_core::world::PolygonWorld;
use trailmark_map::Unknown;

use super::planner::PlannerSpec;

/// A planning problem: a world, a start, a goal, a planner and a seed; for a polygon world,
/// also the roadmap to search and its parameters.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ProblemSpec {
    /// The world to plan in.
    pub world: WorldSpec,
    /// The start: a cell `[x, y]` of a grid, a point `[x, y]` of a polygon world or (in metres)
    /// of a ROS map, a pose `[x, y, θ]` (θ in radians) for a Dubins roadmap, or a value per joint
    /// of a robot's group (in the group's order). Every world needs one, except a robot world
    /// given a `request`.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub start: Vec<f64>,
    /// The goal, as the start.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub goal: Vec<f64>,
    /// The planner and its parameters.
    pub planner: PlannerSpec,
    /// The seed of every random choice (planners and graphs that draw none ignore it).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub seed: Option<u64>,
    /// Polygon worlds: the roadmap to build (default: the visibility graph).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub graph: Option<GraphKind>,
    /// Sampled roadmaps: the number of samples (default 1000).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub samples: Option<usize>,
    /// Sampled roadmaps: join each sample to its `k` nearest neighbours (default, without `k`
    /// or `radius`: PRM*'s k = ⌈e(1 + 1/d) ln n⌉).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub k: Option<usize>,
    /// Sampled roadmaps: join each sample to every neighbour within this distance instead.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub radius: Option<f64>,
    /// Dubins roadmaps: the turning radius (required).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub turning_radius: Option<f64>,
    /// Sampled roadmaps: how samples are drawn (default uniform, from `seed`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub sampler: Option<SamplerKind>,
    /// Sampling planners: the state space (default `r2`; `dubins` needs `turning_radius`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub space: Option<SpaceKind>,
    /// Robot worlds: a MoveIt motion plan request (YAML) giving the group, the start state of
    /// every joint and the goal's joint values, instead of `start` and `goal`; relative to the
    /// document's folder unless absolute.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub request: Option<PathBuf>,
}

impl ProblemSpec {
    /// A problem with no seed and no roadmap parameters.
    pub fn new(world: WorldSpec, start: Vec<f64>, goal: Vec<f64>, planner: PlannerSpec) -> Self {
        ProblemSpec {
            world,
            start,
            goal,
            planner,
            seed: None,
            graph: None,
            samples: None,
            k: None,
            radius: None,
            turning_radius: None,
            sampler: None,
            space: None,
            request: None,
        }
    }

    /// The roadmap fields this problem sets, by name (each applies to some graphs only).
    pub(super) fn roadmap_fields(&self) -> Vec<&'static str> {
        [
            ("graph", self.graph.is_some()),
            ("samples", self.samples.is_some()),
            ("k", self.k.is_some()),
            ("radius", self.radius.is_some()),
            ("turning_radius", self.turning_radius.is_some()),
            ("sampler", self.sampler.is_some()),
        ]
        .into_iter()
        .filter_map(|(name, set)| set.then_some(name))
        .collect()
    }
}

/// The roadmap a polygon world is searched on.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum GraphKind {
    /// The visibility graph of the grown obstacles: shortest paths for a disc robot.
    Visibility,
    /// The trapezoidal (vertical) cell decomposition: cell centroids and portal midpoints.
    Trapezoid,
    /// A probabilistic roadmap of straight segments.
    Prm,
    /// A probabilistic roadmap of poses joined by Dubins curves (a car that turns no tighter
    /// than `turning_radius`).
    DubinsPrm,
    /// A probabilistic roadmap of poses joined by Reeds-Shepp curves (the same car, driving in
    /// reverse too).
    ReedsSheppPrm,
}

impl GraphKind {
    /// The name used in problem documents.
    pub fn name(self) -> &'static str {
        match self {
            GraphKind::Visibility => "visibility",
            GraphKind::Trapezoid => "trapezoid",
            GraphKind::Prm => "prm",
            GraphKind::DubinsPrm => "dubins_prm",
            GraphKind::ReedsSheppPrm => "reeds_shepp_prm",
        }
    }
}

/// How a sampled roadmap draws its samples.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum SamplerKind {
    /// Uniform random samples from the problem's seed (default 0).
    Uniform,
    /// The deterministic Halton sequence (bases 2, 3 and 5).
    Halton,
}

/// The state space of a sampling planner: over a polygon world, `r2`, `dubins` or
/// `reeds_shepp`; over a box world, `rn`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum SpaceKind {
    /// Points `[x, y]` joined by straight motions.
    R2,
    /// Poses `[x, y, θ]` of a car joined by shortest Dubins curves of the problem's
    /// `turning_radius`.
    Dubins,
    /// Points of a box world's dimension, joined by straight motions.
    Rn,
    /// Poses `[x, y, θ]` of a car that also drives in reverse, joined by shortest Reeds-Shepp
    /// curves of the problem's `turning_radius`.
    ReedsShepp,
}

impl SpaceKind {
    /// The name used in problem documents.
    pub fn name(self) -> &'static str {
        match self {
            SpaceKind::R2 => "r2",
            SpaceKind::Dubins => "dubins",
            SpaceKind::Rn => "rn",
            SpaceKind::ReedsShepp => "reeds_shepp",
        }
    }
}

/// The world of a problem. In JSON, an object with one key naming the kind of world; a robot
/// world has the robot and, beside it, its scene.
#[derive(Debug, Clone, PartialEq)]
pub enum WorldSpec {
    /// A grid: `{"grid": {...}}`.
    Grid(GridSpec),
    /// Polygonal obstacles for a disc robot: `{"polygons": {"bounds": [xmin, ymin, xmax, ymax],
    /// "obstacles": [[[x, y], ...], ...], "robot_radius": r}}`, checked as it is read.
    Polygons(PolygonWorld),
    /// Axis-aligned boxes in any dimension, for the sampling planners in `"space": "rn"`:
    /// `{"boxes": {"bounds": [[lo, hi], ...], "obstacles": [[[lo, ...], [hi, ...]], ...]}}`.
    Boxes(BoxesSpec),
    /// A ROS map (map_server's YAML and image) made into a Nav2-style costmap around the robot:
    /// `{"ros_map": {"yaml": "PATH.yaml", "robot_radius": 0.2, "inflation_radius": 0.55,
    /// "cost_scaling_factor": 10, "unknown": "lethal"}}`; start and goal in metres.
    RosMap(RosMapSpec),
    /// A robot arm among the obstacles of a MoveIt planning scene, planned in a group's joint
    /// space: `{"robot": {"urdf": "PATH.urdf", "srdf": "PATH.srdf", "group": "arm"}, "scene":
    /// "PATH.yaml"}` (without a scene, the robot only has itself to avoid).
    Robot(RobotWorldSpec),
}

/// A robot world: the robot's files and the scene around it.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct RobotWorldSpec {
    /// The robot.
    pub robot: RobotSpec,
    /// The MoveIt planning scene (YAML), relative to the document's folder unless absolute.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub scene: Option<PathBuf>,
}

/// A robot: its URDF and SRDF (relative to the document's folder unless absolute), the group
/// to plan for and the collision checker to plan with.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RobotSpec {
    /// The robot's URDF: its links, joints, limits and collision geometry (spheres from a
    /// spherized URDF, or primitives each covered by one sphere).
    pub urdf: PathBuf,
    /// The robot's SRDF: its planning groups and the link pairs never in contact.
    pub srdf: PathBuf,
    /// The planning group (one of the SRDF's): required unless the problem's `request` names
    /// it, and then the same.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub group: Option<String>,
    /// The collision checker planned with (default `batch`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub checker: Option<ArmCheckerKind>,
}

/// The collision checker a robot world is planned with; both answer the same questions, and
/// both are conservative (see `trailmark_robot::checker`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ArmCheckerKind {
    /// Eight configurations at once in SIMD lanes (`trailmark_robot::BatchChecker`).
    #[default]
    Batch,
    /// One configuration at a time in `f64` (`trailmark_robot::ArmChecker`).
    Scalar,
}

/// The keys of a world object.
#[derive(Deserialize)]
#[serde(field_identifier, rename_all = "snake_case")]
enum WorldKey {
    Grid,
    Polygons,
    Boxes,
    RosMap,
    Robot,
    Scene,
}

impl Serialize for WorldSpec {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeMap;
        let scene = match self {
            WorldSpec::Robot(world) => world.scene.as_ref(),
            _ => None,
        };
        let mut map = serializer.serialize_map(Some(1 + usize::from(scene.is_some())))?;
        match self {
            WorldSpec::Grid(grid) => map.serialize_entry("grid", grid)?,
            WorldSpec::Polygons(world) => map.serialize_entry("polygons", world)?,
            WorldSpec::Boxes(world) => map.serialize_entry("boxes", world)?,
            WorldSpec::RosMap(world) => map.serialize_entry("ros_map", world)?,
            WorldSpec::Robot(world) => map.serialize_entry("robot", &world.robot)?,
        }
        if let Some(scene) = scene {
            map.serialize_entry("scene", scene)?;
        }
        map.end()
    }
}

impl<'de> Deserialize<'de> for WorldSpec {
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        deserializer.deserialize_map(WorldVisitor)
    }
}

/// Why a world with two kinds is refused.
const ONE_KIND: &str =
    "a world has one kind: give one of \"grid\", \"polygons\", \"boxes\", \"ros_map\" and \"robot\"";

struct WorldVisitor;

impl<'de> serde::de::Visitor<'de> for WorldVisitor {
    type Value = WorldSpec;

    fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        f.write_str("a world: an object with one key, \"grid\", \"polygons\", \"boxes\" or \"ros_map\"; or \"robot\" with an optional \"scene\" beside it")
    }

    fn visit_map<A: serde::de::MapAccess<'de>>(self, mut map: A) -> Result<WorldSpec, A::Error> {
        use serde::de::Error;
        let (mut world, mut robot, mut scene) = (None, None, None);
        while let Some(key) = map.next_key::<WorldKey>()? {
            let kind = match key {
                WorldKey::Grid => WorldSpec::Grid(map.next_value()?),
                WorldKey::Polygons => WorldSpec::Polygons(map.next_value()?),
                WorldKey::Boxes => WorldSpec::Boxes(map.next_value()?),
                WorldKey::RosMap => WorldSpec::RosMap(map.next_value()?),
                WorldKey::Robot if robot.is_none() => {
                    robot = Some(map.next_value::<RobotSpec>()?);
                    continue;
                }
                WorldKey::Scene if scene.is_none() => {
                    scene = Some(map.next_value::<PathBuf>()?);
                    continue;
                }
                WorldKey::Robot => return Err(A::Error::duplicate_field("robot")),
                WorldKey::Scene => return Err(A::Error::duplicate_field("scene")),
            };
            if world.is_some() {
                return Err(A::Error::custom(ONE_KIND));
            }
            world = Some(kind);
        }
        match (world, robot) {
            (Some(_), Some(_)) => Err(A::Error::custom(ONE_KIND)),
            (Some(_), None) if scene.is_some() => {
                Err(A::Error::custom("\"scene\" is the world of a \"robot\", beside it"))
            }
            (Some(world), None) => Ok(world),
            (None, Some(robot)) => Ok(WorldSpec::Robot(RobotWorldSpec { robot, scene })),
            (None, None) => Err(A::Error::custom(
                "a world needs one of \"grid\", \"polygons\", \"boxes\", \"ros_map\" and \"robot\"",
            )),
        }
    }
}

/// A ROS map world: the map's YAML file and the costmap's settings, each with Nav2's default.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RosMapSpec {
    /// The map's YAML file (map_server's format), relative to the document's folder unless
    /// absolute.
    pub yaml: PathBuf,
    /// The robot's radius in metres, its inscribed radius (default 0.1, Nav2's
    /// `robot_radius`); or give `footprint`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub robot_radius: Option<f64>,
    /// The robot's footprint, a polygon `[[x, y], ...]` in metres about its centre (its
    /// inscribed radius is the smallest distance from the centre to an edge).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub footprint: Option<Vec<[f64; 2]>>,
    /// How far costs spread from obstacles, in metres (default 0.55).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub inflation_radius: Option<f64>,
    /// How fast the cost falls off beyond the inscribed radius, per metre (default 10).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub cost_scaling_factor: Option<f64>,
    /// What unknown cells are: `"lethal"` (default), `"free"`, `"no_information"` (blocked,
    /// not inflated) or `{"cost": c}` with c in 0..=252.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub unknown: Option<Unknown>,
    /// How much a cell's cost adds to the price of crossing it: a move costs its length times
    /// `1 + cost_factor * cost / 252` (default 2, Smac's `cost_travel_multiplier`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub cost_factor: Option<f64>,
}

/// A world of axis-aligned boxes: the region, one `[lo, hi]` per axis, and the obstacles, each
/// its low and high corners. The dimensions and sides are checked when it is solved.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BoxesSpec {
    /// `[lo, hi]` per axis.
    pub bounds: Vec<[f64; 2]>,
    /// `[[lo, ...], [hi, ...]]` per box.
    #[serde(default)]
    pub obstacles: Vec<[Vec<f64>; 2]>,
}

/// A grid world: a MovingAI map file or inline rows, with its connectivity and optional costs.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct GridSpec {
    /// A MovingAI `.map` file (relative paths are relative to the problem file). Exactly one of
    /// `map` and `rows` is given.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub map: Option<PathBuf>,
    /// The rows of the grid in MovingAI characters (`.` passable, `@` blocked, ...).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub rows: Option<Vec<String>>,
    /// Optional per-cell costs, one row of numbers per grid row, each positive; a blocked cell
    /// stays blocked whatever its cost.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub costs: Option<Vec<Vec<f64>>>,
    /// 4 or 8 (default 8).
    #[serde(default)]
    pub connectivity: Connectivity,
    /// Whether a diagonal move may pass a blocked orthogonal neighbour (default false, the
    /// MovingAI rule).
    #[serde(default)]
    pub corner_cutting: bool,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unknown_planner_and_fields_are_errors() {
        let base = |planner: &str| {
            format!(
                r#"{{"world": {{"grid": {{"rows": [".."]}}}}, "start": [0,0], "goal": [1,0], "planner": {planner}}}"#
            )
        };
        assert!(serde_json::from_str::<ProblemSpec>(&base(r#"{"name": "astar"}"#)).is_ok());
        let err =
            serde_json::from_str::<ProblemSpec>(&base(r#"{"name": "teleport"}"#)).unwrap_err().to_string();
        assert!(err.contains("unknown variant `teleport`"), "{err}");
        let err = serde_json::from_str::<ProblemSpec>(&base(r#"{"name": "weighted_astar", "wieght": 2}"#))
            .unwrap_err()
            .to_string();
        assert!(err.contains("wieght") || err.contains("weight"), "{err}");
        let err = serde_json::from_str::<ProblemSpec>(&base(r#"{"name": "dijkstra", "weight": 2}"#));
        assert!(err.is_err(), "a parameter the planner does not take is an error");
        let err = serde_json::from_str::<ProblemSpec>(r#"{"world": {"grid": {}}, "start": [0,0]}"#);
        assert!(err.unwrap_err().to_string().contains("missing field"));
    }

    #[test]
    fn connectivity_is_4_or_8() {
        let w: GridSpec = serde_json::from_str(r#"{"rows": ["."], "connectivity": 4}"#).unwrap();
        assert_eq!(w.connectivity, Connectivity::Four);
        assert!(serde_json::from_str::<GridSpec>(r#"{"connectivity": 6}"#).is_err());
    }
}
