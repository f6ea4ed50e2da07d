//! Robot arms in 3-D, from their own files: a URDF (links, joints, limits, collision geometry)
//! and an SRDF (planning groups, link pairs never in contact), among the obstacles of a MoveIt
//! planning scene, planned in a group's joint space by every planner of `trailmark-sample`.
//!
//! - [`urdf`] and [`srdf`]: the files read into typed models, every value checked;
//! - [`Robot`]: the links and joints checked as one tree, forward kinematics, planning groups
//!   resolved as MoveIt resolves them;
//! - [`scene`] and [`request`]: MoveIt's `PlanningScene` and `MotionPlanRequest` as YAML;
//! - [`SphereModel`] and [`ArmChecker`]: the robot as spheres (a spherized URDF's, or one sphere
//!   containing each primitive), checked against the scene and against each other; states
//!   exactly for the spheres, motions covered by checked states that miss nothing between them
//!   (see [`checker`]). It is the planners' `Validity` over the group's joint space
//!   ([`ArmChecker::space`]);
//! - [`BatchChecker`]: the same checks for eight configurations at once in SIMD lanes, the fast
//!   path (see [`batch`]);
//! - [`ExactChecker`]: the exact tier, the URDF's own shapes (meshes from OBJ and STL files,
//!   [`mesh`]) checked by parry3d: the reference a path planned with spheres is checked against
//!   (see [`exact`]).
//!
//! ```
//! use trailmark_core::termination::Termination;
//! use trailmark_robot::{ArmChecker, Robot, DEFAULT_STEP};
//! use trailmark_robot::{scene::Scene, srdf::Srdf, urdf::Urdf};
//! use trailmark_sample::{KdNearest, Planner, Problem, Rn, RrtConnect};
//!
//! // Two links on a post, turning about z, and a wall beside the post.
//! let urdf = Urdf::parse(r#"
//!   <robot name="arm">
//!     <link name="base"/>
//!     <link name="upper"><collision><origin xyz="0.25 0 0"/><geometry><sphere radius="0.05"/></geometry></collision>
//!                        <collision><origin xyz="0.5 0 0"/><geometry><sphere radius="0.05"/></geometry></collision></link>
//!     <link name="fore"><collision><origin xyz="0.2 0 0"/><geometry><sphere radius="0.05"/></geometry></collision>
//!                       <collision><origin xyz="0.4 0 0"/><geometry><sphere radius="0.05"/></geometry></collision></link>
//!     <joint name="shoulder" type="revolute"><parent link="base"/><child link="upper"/>
//!       <origin xyz="0 0 0.5"/><axis xyz="0 0 1"/><limit lower="-3" upper="3"/></joint>
//!     <joint name="elbow" type="revolute"><parent link="upper"/><child link="fore"/>
//!       <origin xyz="0.5 0 0"/><axis xyz="0 0 1"/><limit lower="-2.5" upper="2.5"/></joint>
//!   </robot>"#)?;
//! let srdf = Srdf::parse(r#"<robot name="arm"><group name="arm"><chain base_link="base" tip_link="fore"/></group></robot>"#)?;
//! let scene = Scene::parse("
//! world:
//!   collision_objects:
//!     - id: wall
//!       primitives: [{type: box, dimensions: [0.1, 0.6, 1.0]}]
//!       primitive_poses: [{position: [0.8, 0.0, 0.5], orientation: [0, 0, 0, 1]}]
//! ")?;
//! let robot = Robot::new(urdf)?;
//! let group = robot.group(&srdf, "arm")?;
//! let checker = ArmChecker::new(robot, &srdf, group, &scene, vec![0.0; 2], DEFAULT_STEP)?;
//! let space = checker.space::<2>()?;
//! // From pointing up the y axis to pointing down it: the shoulder cannot turn through the
//! // back (its limits are ±3), so the elbow folds to pass the wall in front.
//! let (start, goal) = ([1.57, 0.0].into(), [-1.57, 0.0].into());
//! let problem = Problem::new(&space, &checker, start, goal);
//! let mut planner = RrtConnect::new(KdNearest::<Rn<2>, 2>::new(&space)?).with_seed(1);
//! let plan = planner.solve(&problem, &Termination::iterations(10_000))?;
//! let path = plan.path().expect("a way past the wall");
//! assert!(path.windows(2).all(|m| checker.motion_is_free(m[0].as_slice(), m[1].as_slice())));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

#![deny(missing_docs)]

pub mod batch;
pub mod checker;
pub mod cloud;
pub mod cover;
mod error;
pub mod exact;
pub mod mesh;
mod motion;
pub mod request;
mod robot;
pub mod scene;
mod spheres;
pub mod srdf;
pub mod urdf;

pub use batch::{BatchChecker, Simd};
pub use checker::{ArmChecker, Contact, DEFAULT_STEP};
pub use error::RobotError;
pub use exact::ExactChecker;
/// nalgebra (0.35), whose poses, vectors and axes the robot's model is written in, so a user names
/// them without a version-matched dependency of their own.
pub use nalgebra;
pub use robot::{Group, Robot};
pub use spheres::{LinkSphere, SphereModel};
