//! The arm peer of the harness: OMPL's RRTConnect (or InformedRRTstar, BITstar, PRMstar's
//! roadmap) with FCL collision checking on a robot arm's
//! problems (MotionBenchMaker's, for the Panda). `benches/ompl/arm_driver.cpp` is built against
//! the system's OMPL, FCL, Eigen and nlohmann-json (found with pkg-config) and given the same
//! model trailmark's [`ArmChecker`](trailmark::robot::ArmChecker) checks: the robot's spheres
//! ([`SphereModel`]) moved by the URDF's forward kinematics, the link pairs checked against each
//! other, and the scene's boxes, cylinders and spheres. The input and output documents are
//! described at the top of the driver's source.

use std::io::Write;
use std::path::PathBuf;
use std::process::{Command, Stdio};

use serde::{Deserialize, Serialize};
use trailmark::robot::nalgebra::Isometry3;
use trailmark::robot::scene::{Scene, Shape};
use trailmark::robot::srdf::Srdf;
use trailmark::robot::urdf::JointKind;
use trailmark::robot::{Group, Robot, SphereModel};

use crate::bench::ompl::{compile, newer, pkg_config};

/// How to get what the driver needs, for the message shown when it is missing.
pub const INSTALL: &str = "install OMPL, FCL, Eigen and nlohmann-json with `sudo apt-get install \
                           libompl-dev libfcl-dev libeigen3-dev nlohmann-json3-dev` (Debian, \
                           Ubuntu) and run again";

/// MoveIt's default longest valid segment of a motion, as a fraction of the joint space's
/// extent (`longest_valid_segment_fraction`).
pub const MOVEIT_SEGMENT_FRACTION: f64 = 0.005;

/// The compiled driver.
pub struct OmplArmDriver {
    program: PathBuf,
    /// The OMPL version pkg-config reports.
    pub ompl_version: String,
    /// The FCL version pkg-config reports.
    pub fcl_version: String,
}

/// How the driver plans.
#[derive(Debug, Clone, Serialize)]
pub struct OmplArmSettings {
    /// The planner: `rrt_connect`, `informed_rrt_star` or `bit_star` (the optimizing ones
    /// minimise the path's length and run until the time limit), or `prm_star` (a roadmap of
    /// `roadmap_size` milestones built, no query).
    pub planner: &'static str,
    /// Runs per query.
    pub runs: usize,
    /// OMPL's global seed, set once per driver process.
    pub seed: u64,
    /// The time limit of each run, seconds (and of its simplification).
    pub time_limit_s: f64,
    /// The tree planners' range: the longest motion added at once, in joint-space units (0: OMPL's
    /// default, a fifth of the space's extent).
    pub range: f64,
    /// The longest motion checked without a state in between, in joint-space units (OMPL's
    /// longest valid segment).
    pub resolution: f64,
    /// Whether each path is also simplified (`SimpleSetup::simplifySolution`).
    pub simplify: bool,
    /// `prm_star`'s milestones: the roadmap each run builds (and nothing else).
    pub roadmap_size: usize,
}

impl OmplArmSettings {
    /// The settings for `group` with MoveIt's fraction: motions checked every
    /// [`MOVEIT_SEGMENT_FRACTION`] of the joint space's Euclidean extent (0.067 rad for the
    /// Panda's arm; MoveIt measures the extent as a sum over the joints, so its own step is
    /// coarser), a range of 1.0 (trailmark's `verify mbm` and VAMP's for the Panda), one run of
    /// at most 10 s, seed 1, no simplification.
    pub fn moveit(group: &Group) -> OmplArmSettings {
        let extent = group.bounds.iter().map(|(l, h)| (h - l) * (h - l)).sum::<f64>().sqrt();
        OmplArmSettings {
            planner: "rrt_connect",
            runs: 1,
            seed: 1,
            time_limit_s: 10.0,
            range: 1.0,
            resolution: MOVEIT_SEGMENT_FRACTION * extent,
            simplify: false,
            roadmap_size: 0,
        }
    }
}

/// The robot, its group and the scene a driver's input is written from.
pub struct ArmWorld<'a> {
    /// The robot (a spherized URDF, or primitives each covered by a sphere).
    pub robot: &'a Robot,
    /// Its semantic description: the group and the disabled link pairs.
    pub srdf: &'a Srdf,
    /// The planning group's name.
    pub group: &'a str,
    /// The obstacles and the allowed collision matrix.
    pub scene: &'a Scene,
    /// A value per joint of the robot: joints outside the group stay at theirs (the request's
    /// start state).
    pub template: &'a [f64],
}

/// What the driver is asked to run (see the top of `benches/ompl/arm_driver.cpp`).
#[derive(Debug, Clone, Serialize)]
pub struct ArmInput {
    /// `[lower, upper]` per group joint.
    pub bounds: Vec<[f64; 2]>,
    /// The robot's links in tree order, the root first.
    pub frames: Vec<ArmFrame>,
    /// Every sphere of the robot.
    pub spheres: Vec<ArmSphere>,
    /// The frame pairs whose spheres are tested against each other.
    pub self_pairs: Vec<[usize; 2]>,
    /// The scene's primitives.
    pub obstacles: Vec<ArmObstacle>,
    /// The queries planned.
    pub queries: Vec<ArmQuery>,
    /// How they are planned.
    #[serde(flatten)]
    pub settings: OmplArmSettings,
    /// States only to check, answered in [`ArmOutput::valid`].
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub states: Vec<Vec<f64>>,
}

/// A link's frame and the joint above it.
#[derive(Debug, Clone, Serialize)]
pub struct ArmFrame {
    /// The parent link's frame (-1 for the root).
    pub parent: i64,
    /// The joint's origin in the parent's frame: `[x, y, z, qx, qy, qz, qw]`.
    pub origin: [f64; 7],
    /// `fixed`, `revolute` or `prismatic`.
    pub joint: &'static str,
    /// The joint's axis, in the joint's frame.
    pub axis: [f64; 3],
    /// The group variable that drives the joint (-1: none, the joint stays at `value`).
    pub variable: i64,
    /// The joint's value is `multiplier × variable + offset` (a mimic's; 1 and 0 otherwise).
    pub multiplier: f64,
    /// See `multiplier`.
    pub offset: f64,
    /// The joint's value when no variable drives it.
    pub value: f64,
}

/// One sphere of the robot.
#[derive(Debug, Clone, Serialize)]
pub struct ArmSphere {
    /// The frame it moves with.
    pub frame: usize,
    /// Its centre in that frame.
    pub centre: [f64; 3],
    /// Its radius.
    pub radius: f64,
}

/// One primitive of the scene.
#[derive(Debug, Clone, Serialize)]
pub struct ArmObstacle {
    /// Its shape and size.
    #[serde(flatten)]
    pub shape: ArmShape,
    /// Its centre in the world frame.
    pub position: [f64; 3],
    /// Its orientation in the world frame, `[x, y, z, w]`.
    pub orientation: [f64; 4],
    /// The frames allowed to touch it (the scene's allowed collision matrix).
    pub allowed_frames: Vec<usize>,
}

/// An obstacle's shape, as the driver reads it.
#[derive(Debug, Clone, Serialize)]
#[serde(tag = "shape", rename_all = "lowercase")]
pub enum ArmShape {
    /// A box of these half side lengths.
    Box {
        /// Half its sides along x, y and z.
        half: [f64; 3],
    },
    /// A cylinder along z.
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

/// A start and a goal, a value per group joint each.
#[derive(Debug, Clone, Serialize)]
pub struct ArmQuery {
    /// The start.
    pub start: Vec<f64>,
    /// The goal.
    pub goal: Vec<f64>,
}

/// What the driver answers (its versions of OMPL and FCL are those of [`OmplArmDriver`]).
#[derive(Debug, Clone, Deserialize)]
pub struct ArmOutput {
    /// The runs, query by query.
    pub runs: Vec<OmplArmRun>,
    /// Per state of [`ArmInput::states`], whether it is valid (what the agreement test reads).
    #[serde(default)]
    #[cfg_attr(not(test), allow(dead_code))]
    pub valid: Vec<bool>,
}

/// One run of the driver's planner.
#[derive(Debug, Clone, Deserialize, Serialize)]
pub struct OmplArmRun {
    /// The index of the query.
    pub query: usize,
    /// The run of that query.
    pub run: usize,
    /// `exact`, `approximate` or `none`.
    pub status: String,
    /// The wall time of `SimpleSetup::solve`, seconds.
    pub time_s: f64,
    /// State validity checks while solving (motions count as the states they were checked at).
    pub checks: u64,
    /// The vertices of the planner's trees (PRMstar's milestones).
    pub vertices: u64,
    /// The path's length in joint space (`None` without a path).
    #[serde(default)]
    pub length: Option<f64>,
    /// The path's states.
    pub path: Vec<Vec<f64>>,
    /// The time of simplifying it, seconds (when asked).
    #[serde(default)]
    pub simplify_time_s: Option<f64>,
    /// State validity checks while simplifying.
    #[serde(default)]
    pub simplify_checks: Option<u64>,
    /// The simplified path's length.
    #[serde(default)]
    pub simplified_length: Option<f64>,
    /// The simplified path's states.
    #[serde(default)]
    pub simplified: Vec<Vec<f64>>,
}

impl OmplArmRun {
    /// Whether a `prm_star` run built its whole roadmap of `size` milestones (false for the
    /// other planners, which build none: `size` is 0).
    pub fn planner_built(&self, size: usize) -> bool {
        size > 0 && self.vertices >= size as u64
    }

    /// Whether OMPL found an exact solution.
    pub fn exact(&self) -> bool {
        self.status == "exact"
    }

    /// State validity checks per second of solving.
    #[cfg_attr(not(test), allow(dead_code))]
    pub fn checks_per_second(&self) -> f64 {
        if self.time_s > 0.0 { self.checks as f64 / self.time_s } else { 0.0 }
    }
}

/// `[x, y, z, qx, qy, qz, qw]` of `pose`.
fn pose_array(pose: &Isometry3<f64>) -> [f64; 7] {
    let (t, q) = (pose.translation.vector, pose.rotation.coords);
    [t.x, t.y, t.z, q.x, q.y, q.z, q.w]
}

impl ArmInput {
    /// The input of `world` with no query yet: the group's bounds, the robot's frames and
    /// spheres, the frame pairs checked (those [`SphereModel::checks`] allows, with the scene's
    /// allowed pairs, of which at least one moves with the group, as
    /// [`ArmChecker`](trailmark::robot::ArmChecker) checks them: two links that never move
    /// relative to each other stay as they are) and the obstacles.
    pub fn new(world: &ArmWorld<'_>, settings: OmplArmSettings) -> Result<ArmInput, String> {
        let robot = world.robot;
        let group = robot.group(world.srdf, world.group).map_err(|e| e.to_string())?;
        let model = SphereModel::new(robot, world.srdf, &world.scene.allowed).map_err(|e| e.to_string())?;
        let urdf = robot.urdf();
        let (values, joints) = (world.template.len(), urdf.joints.len());
        if values != joints {
            return Err(format!("a start of {values} values for a robot of {joints} joints"));
        }
        if group.wraps.contains(&true) {
            return Err("the OMPL driver's space is a box: groups with continuous joints are not run".into());
        }
        let mut frame_of = vec![usize::MAX; urdf.links.len()];
        let mut moving = vec![false; urdf.links.len()];
        frame_of[robot.root()] = 0;
        let mut frames = vec![ArmFrame {
            parent: -1,
            origin: pose_array(&Isometry3::identity()),
            joint: "fixed",
            axis: [0.0, 0.0, 1.0],
            variable: -1,
            multiplier: 1.0,
            offset: 0.0,
            value: 0.0,
        }];
        for &j in robot.joints_in_order() {
            let joint = &urdf.joints[j];
            let (parent, child) = robot.joint_links(j);
            let kind = match joint.kind {
                JointKind::Revolute | JointKind::Continuous => "revolute",
                JointKind::Prismatic => "prismatic",
                JointKind::Fixed | JointKind::Floating | JointKind::Planar => "fixed",
            };
            let drive = robot.driver(&group, j).filter(|_| kind != "fixed");
            let value = match robot.mimic(j) {
                Some((followed, multiplier, offset)) => multiplier * world.template[followed] + offset,
                None => world.template[j],
            };
            let (variable, multiplier, offset) = drive.map_or((-1, 1.0, 0.0), |(v, m, o)| (v as i64, m, o));
            moving[child] =
                moving[parent] || (joint.kind != JointKind::Fixed && robot.driver(&group, j).is_some());
            frame_of[child] = frames.len();
            frames.push(ArmFrame {
                parent: frame_of[parent] as i64,
                origin: pose_array(&joint.origin),
                joint: kind,
                axis: [joint.axis.x, joint.axis.y, joint.axis.z],
                variable,
                multiplier,
                offset,
                value,
            });
        }
        let spheres = model
            .spheres
            .iter()
            .map(|s| ArmSphere { frame: frame_of[s.link], centre: s.centre.into(), radius: s.radius })
            .collect();
        let mut self_pairs = Vec::new();
        for a in 0..urdf.links.len() {
            for b in a + 1..urdf.links.len() {
                if (moving[a] || moving[b]) && model.checks(a, b) {
                    self_pairs.push([frame_of[a], frame_of[b]]);
                }
            }
        }
        let allowed = |id: &str| -> Vec<usize> {
            let pairs = world.scene.allowed.iter();
            let links = pairs.flat_map(|(a, b)| [(a == id).then_some(b), (b == id).then_some(a)]).flatten();
            let mut frames: Vec<usize> =
                links.filter_map(|l| robot.link_index(l)).map(|l| frame_of[l]).collect();
            frames.sort_unstable();
            frames.dedup();
            frames
        };
        let obstacles = world
            .scene
            .obstacles
            .iter()
            .map(|o| {
                let shape = match o.shape {
                    Shape::Box { half } => ArmShape::Box { half: half.into() },
                    Shape::Cylinder { radius, half_height } => ArmShape::Cylinder { radius, half_height },
                    Shape::Sphere { radius } => ArmShape::Sphere { radius },
                };
                let [x, y, z, qx, qy, qz, qw] = pose_array(&o.pose);
                ArmObstacle {
                    shape,
                    position: [x, y, z],
                    orientation: [qx, qy, qz, qw],
                    allowed_frames: allowed(&o.id),
                }
            })
            .collect();
        Ok(ArmInput {
            bounds: group.bounds.iter().map(|&(l, h)| [l, h]).collect(),
            frames,
            spheres,
            self_pairs,
            obstacles,
            queries: Vec::new(),
            settings,
            states: Vec::new(),
        })
    }
}

impl OmplArmDriver {
    /// Builds the driver into `target/ompl/` (when its source changed); an error that says what
    /// to install when OMPL, FCL, Eigen or nlohmann-json is missing.
    pub fn build() -> Result<OmplArmDriver, String> {
        let version = |package: &str, name: &str| {
            pkg_config(&["--modversion", package]).map_err(|_| format!("{name} not found: {INSTALL}"))
        };
        let ompl_version = version("ompl", "OMPL")?;
        let fcl_version = version("fcl", "FCL")?;
        version("eigen3", "Eigen")?;
        version("nlohmann_json", "nlohmann-json")?;
        let root = crate::workspace::root();
        let source = root.join("benches/ompl/arm_driver.cpp");
        let folder = root.join("target/ompl");
        let program = folder.join("ompl-arm-driver");
        if newer(&source, &program) {
            errln!("compiling the OMPL arm driver (OMPL {ompl_version}, FCL {fcl_version})...");
            compile(&source, &program, &["ompl", "fcl", "eigen3", "nlohmann_json"], &["ompl", "fcl"], &[])?;
        }
        Ok(OmplArmDriver { program, ompl_version, fcl_version })
    }

    /// Plans from `start` to `goal` (a value per group joint each) in `world` with `settings`:
    /// the runs, in order.
    pub fn plan(
        &self,
        world: &ArmWorld<'_>,
        start: &[f64],
        goal: &[f64],
        settings: OmplArmSettings,
    ) -> Result<Vec<OmplArmRun>, String> {
        let mut input = ArmInput::new(world, settings)?;
        input.queries.push(ArmQuery { start: start.to_vec(), goal: goal.to_vec() });
        Ok(self.run(&input)?.runs)
    }

    /// Runs `input`: its document on the driver's standard input, the answer read from its
    /// standard output.
    pub fn run(&self, input: &ArmInput) -> Result<ArmOutput, String> {
        let text = serde_json::to_vec(input).map_err(|e| e.to_string())?;
        let mut child = Command::new(&self.program)
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .map_err(|e| format!("cannot run the OMPL arm driver: {e}"))?;
        // The driver reads its whole input before it writes anything: no deadlock on the pipes.
        let written = child.stdin.take().map(|mut stdin| stdin.write_all(&text));
        let out = child.wait_with_output().map_err(|e| format!("the OMPL arm driver: {e}"))?;
        if !out.status.success() {
            return Err(format!("the OMPL arm driver failed:\n{}", String::from_utf8_lossy(&out.stderr)));
        }
        if let Some(Err(e)) = written {
            return Err(format!("cannot write the OMPL arm driver's input: {e}"));
        }
        serde_json::from_slice(&out.stdout).map_err(|e| format!("the OMPL arm driver's output: {e}"))
    }
}

pub mod problem;
#[cfg(test)]
mod tests;
