//! An [`ArmChecker`] compiled for the batch kernel: the moving frames in order, each turning
//! about its own z axis (or sliding), the spheres in those frames, the obstacles as inverse
//! poses, all in `f32` and grown by a bound on the rounding of the `f32` arithmetic.
//!
//! A frame is a group joint's child link, or a joint mimicking one: every other joint keeps its
//! value (fixed, or the start state's) and is folded into constant transforms. A revolute joint
//! about any axis is a turn about z between two constant rotations (the one carrying z onto
//! the axis, and its inverse folded into what hangs below), so the kernel turns only about z.

use nalgebra::{Isometry3, Point3, Rotation3, Unit, UnitQuaternion, Vector3};

use crate::checker::{ArmChecker, chain_length, clearance};
use crate::motion;
use crate::scene::Shape;
use crate::urdf::JointKind;

/// A 3 x 4 rigid transform in `f32`: rotation rows, then the translation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Pose32 {
    pub(crate) rotation: [[f32; 3]; 3],
    pub(crate) translation: [f32; 3],
}

impl Pose32 {
    pub(crate) const IDENTITY: Pose32 =
        Pose32 { rotation: [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]], translation: [0.0; 3] };

    fn new(pose: &Isometry3<f64>) -> Pose32 {
        let r = pose.rotation.to_rotation_matrix();
        let t = pose.translation.vector;
        Pose32 {
            rotation: std::array::from_fn(|i| std::array::from_fn(|j| r[(i, j)] as f32)),
            translation: std::array::from_fn(|i| t[i] as f32),
        }
    }
}

/// How a frame moves with its joint value `multiplier * q[variable] + offset`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Motion {
    /// Turning about the frame's z axis.
    Turn,
    /// Sliding along this axis of the frame.
    Slide([f32; 3]),
}

/// One moving frame: `parent * constant * motion(value)`.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Frame {
    /// The frame above, or `None` for the world.
    pub(crate) parent: Option<usize>,
    pub(crate) constant: Pose32,
    pub(crate) motion: Motion,
    /// The group joint it follows, and how.
    pub(crate) variable: usize,
    pub(crate) multiplier: f32,
    pub(crate) offset: f32,
    /// Where its spheres start in the frames' spheres one after another.
    pub(crate) first: usize,
    /// Its spheres (centre, radius) in its own coordinates.
    pub(crate) spheres: Vec<([f32; 3], f32)>,
    /// One sphere containing them all.
    pub(crate) bound: ([f32; 3], f32),
    /// Per group joint, how far its spheres move per unit of the joint's value at most.
    pub(crate) reach: Vec<f64>,
}

/// An obstacle's shape in its own frame, and that frame's inverse.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Obstacle32 {
    pub(crate) inverse: Pose32,
    pub(crate) shape: Shape32,
}

/// [`Shape`] in `f32`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Shape32 {
    Box([f32; 3]),
    Cylinder { radius: f32, half_height: f32 },
    Sphere { centre: [f32; 3], radius: f32 },
}

/// A sphere: centre and radius.
pub(crate) type Ball = ([f32; 3], f32);

/// The spheres of a frame to test against an obstacle (those whose link may not touch it), a
/// group a link, each with a sphere containing it.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct WorldTest {
    pub(crate) obstacle: usize,
    pub(crate) groups: Vec<(Ball, Vec<u16>)>,
}

/// Sphere pairs of two frames (or of a frame and the robot's still part, `other: None`, whose
/// spheres are then given in world coordinates), grouped by their links.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct PairTest {
    pub(crate) frame: usize,
    pub(crate) other: Option<usize>,
    /// A sphere containing the `other` side's spheres of these pairs, when it is still.
    pub(crate) still_bound: Ball,
    pub(crate) links: Vec<LinkPair>,
    /// Per group joint, how much the distance of any of its pairs changes per unit of the
    /// joint's value at most.
    pub(crate) reach: Vec<f64>,
    /// The least gap of its pairs over every configuration (see [`Row`]).
    pub(crate) floor: f32,
}

/// The sphere pairs of two links: spheres containing each link's spheres (in their frames'
/// coordinates), and per sphere of the first, the spheres of the second it is checked with.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct LinkPair {
    pub(crate) links: (usize, usize),
    pub(crate) bound: Ball,
    pub(crate) other_bound: Ball,
    pub(crate) rows: Vec<Row>,
    /// The least gap of its pairs over every configuration.
    pub(crate) floor: f32,
}

/// A sphere of a link and the spheres of the other link it is checked with, each with the
/// least gap their surfaces can have over every configuration (`-inf` where not known): a
/// pair whose floor exceeds the growth of a test cannot touch in it and is passed over.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Row {
    pub(crate) sphere: u16,
    pub(crate) others: Vec<(u16, f32)>,
    pub(crate) floor: f32,
}

/// The whole compiled checker.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Program {
    pub(crate) frames: Vec<Frame>,
    /// How many spheres the frames have.
    pub(crate) sphere_count: usize,
    pub(crate) obstacles: Vec<Obstacle32>,
    /// Per frame, its tests against the world.
    pub(crate) world: Vec<Vec<WorldTest>>,
    pub(crate) pairs: Vec<PairTest>,
    /// Spheres that never move with the group, in world coordinates.
    pub(crate) still: Vec<([f32; 3], f32)>,
    /// A still sphere touches an obstacle, or two checked spheres whose distance never changes
    /// (both still, or both on one frame) touch: nothing is free. (Spheres that do not move
    /// are never grown for motions.)
    pub(crate) blocked: bool,
    /// Added to every radius: more than the `f32` arithmetic can be off by.
    pub(crate) slack: f32,
}

/// Relative size of [`Program::slack`] to the largest coordinate the arithmetic meets: about a
/// thousand times the `f32` rounding of a chain of a dozen transforms and a distance.
const SLACK_PER_METRE: f64 = 1e-4;

/// The largest joint value (radians or metres) the lanes take: beyond it a group's every state
/// is called colliding (the `ArmChecker` checks such groups).
pub(crate) const MAX_JOINT_VALUE: f64 = 1e4;

/// Where a link is: a frame (or the world) and its pose in it.
#[derive(Clone, Copy)]
struct Place {
    frame: Option<usize>,
    offset: Isometry3<f64>,
}

impl Program {
    pub(crate) fn new(checker: &ArmChecker) -> Program {
        let robot = &checker.robot;
        let joints = &robot.urdf().joints;
        let group = &checker.group;
        let values = &checker.template;
        let mut places = vec![Place { frame: None, offset: Isometry3::identity() }; robot.urdf().links.len()];
        let mut frames: Vec<Frame> = Vec::new();
        // Per frame, the joint that moves it.
        let mut frame_joints: Vec<usize> = Vec::new();
        // The frames' lengths, for the slack.
        let mut reach = 0.0f64;
        for &j in robot.joints_in_order() {
            let (parent, child) = robot.joint_links(j);
            let above = places[parent];
            let joint = &joints[j];
            reach += joint.origin.translation.vector.norm();
            if joint.kind == JointKind::Prismatic {
                reach += checker.extension[j];
            }
            let moving =
                matches!(joint.kind, JointKind::Revolute | JointKind::Continuous | JointKind::Prismatic);
            match robot.driver(group, j).filter(|_| moving) {
                Some((variable, multiplier, offset)) => {
                    let (turn, motion) = if joint.kind == JointKind::Prismatic {
                        let a = joint.axis.into_inner();
                        (UnitQuaternion::identity(), Motion::Slide([a.x as f32, a.y as f32, a.z as f32]))
                    } else {
                        (z_onto(&joint.axis), Motion::Turn)
                    };
                    frames.push(Frame {
                        parent: above.frame,
                        constant: Pose32::new(&(above.offset * joint.origin * turn)),
                        motion,
                        variable,
                        multiplier: multiplier as f32,
                        offset: offset as f32,
                        first: 0,
                        spheres: Vec::new(),
                        bound: ([0.0; 3], 0.0),
                        reach: vec![0.0; group.joints.len()],
                    });
                    frame_joints.push(j);
                    let offset = Isometry3::from_parts(Default::default(), turn.inverse());
                    places[child] = Place { frame: Some(frames.len() - 1), offset };
                }
                None => {
                    // Values outside the group stay the start state's (mimic joints included).
                    places[child] =
                        Place { frame: above.frame, offset: above.offset * robot.joint_transform(j, values) };
                }
            }
        }
        // Spheres into their frames; the still ones into the world.
        let spheres = &checker.model.spheres;
        let mut slot = Vec::with_capacity(spheres.len());
        let mut links = vec![Vec::new(); frames.len()];
        let mut frame_models = vec![Vec::new(); frames.len()];
        let mut still_models = Vec::new();
        let mut still64 = Vec::new();
        let mut still_clearance = f64::INFINITY;
        let mut radius = 0.0f64;
        for (k, s) in spheres.iter().enumerate() {
            let place = places[s.link];
            let centre = place.offset * Point3::from(s.centre);
            radius = radius.max(s.centre.norm() + s.radius);
            match place.frame {
                Some(f) => {
                    slot.push((Some(f), frames[f].spheres.len()));
                    frames[f].spheres.push((point32(&centre), s.radius as f32));
                    for (r, &v) in frames[f].reach.iter_mut().zip(&checker.reach[k]) {
                        *r = r.max(v);
                    }
                    links[f].push(s.link);
                    frame_models[f].push(k);
                }
                None => {
                    slot.push((None, still64.len()));
                    still64.push((centre, s.radius));
                    still_models.push(k);
                    for (o, allowed) in checker.obstacles.iter().zip(&checker.allowed_links) {
                        if !allowed.contains(&s.link) {
                            still_clearance = still_clearance.min(clearance(o, &centre) - s.radius);
                        }
                    }
                }
            }
        }
        let mut far = reach + radius;
        for o in &checker.obstacles {
            let extent = match o.shape {
                Shape::Box { half } => half.norm(),
                Shape::Cylinder { radius, half_height } => radius.hypot(half_height),
                Shape::Sphere { radius } => radius,
            };
            far = far.max(o.pose.translation.vector.norm() + extent);
        }
        // Joint values rounded to f32 (and their sines): an angle off by its magnitude times
        // 2^-22, and 4e-6 of the series, moves what hangs on it by that times its reach, once
        // per frame down the chain.
        let largest_value = frame_joints.iter().map(|&j| checker.extension[j]).fold(0.0, f64::max);
        let angle = largest_value * 2f64.powi(-22) + 4e-6;
        let far = far.max(1.0);
        let slack = (SLACK_PER_METRE * far + angle * far * frames.len() as f64) as f32;
        let mut sphere_count = 0;
        for f in &mut frames {
            f.bound = bounding(&f.spheres);
            f.first = sphere_count;
            sphere_count += f.spheres.len();
        }
        let obstacles = checker
            .obstacles
            .iter()
            .map(|o| Obstacle32 {
                inverse: Pose32::new(&o.pose.inverse()),
                shape: match o.shape {
                    Shape::Box { half } => Shape32::Box(std::array::from_fn(|i| half[i] as f32)),
                    Shape::Cylinder { radius, half_height } => {
                        Shape32::Cylinder { radius: radius as f32, half_height: half_height as f32 }
                    }
                    Shape::Sphere { radius } => Shape32::Sphere {
                        centre: point32(&o.pose.translation.vector.into()),
                        radius: radius as f32,
                    },
                },
            })
            .collect();
        // A frame's spheres a link at a time: runs of one link, as the model lists them.
        let link_bound = |f: usize, link: usize| -> Ball {
            let of: Vec<Ball> = (0..frames[f].spheres.len())
                .filter(|&i| links[f][i] == link)
                .map(|i| frames[f].spheres[i])
                .collect();
            bounding(&of)
        };
        // Where a frame can be: every frame descends from one moving about a fixed point (a
        // turning frame below the still part), its spheres within their chain's length of it;
        // obstacles beyond, by more than the largest growth, are never tested against it.
        let largest_growth = motion::COARSE * checker.step / 2.0 + 2.0 * f64::from(slack);
        let reachable = |f: usize, o: &crate::scene::Obstacle| -> bool {
            let mut root = f;
            while let Some(parent) = frames[root].parent {
                root = parent;
            }
            if frames[root].motion != Motion::Turn {
                return true;
            }
            let t = frames[root].constant.translation;
            let pivot = Point3::new(f64::from(t[0]), f64::from(t[1]), f64::from(t[2]));
            let below = robot.joint_links(frame_joints[root]).1;
            let far = frame_models[f]
                .iter()
                .map(|&k| {
                    let s = &spheres[k];
                    chain_length(robot, &checker.extension, below, s.link).unwrap_or(f64::INFINITY)
                        + s.centre.norm()
                        + s.radius
                })
                .fold(0.0, f64::max);
            clearance(o, &pivot) <= far + largest_growth + 1e-6 * far
        };
        let world = (0..frames.len())
            .map(|f| {
                (0..checker.obstacles.len())
                    .filter(|&o| reachable(f, &checker.obstacles[o]))
                    .filter_map(|o| {
                        let mut groups: Vec<(Ball, Vec<u16>)> = Vec::new();
                        let mut last = None;
                        for (i, &link) in links[f].iter().enumerate() {
                            if checker.allowed_links[o].contains(&link) {
                                continue;
                            }
                            if last != Some(link) {
                                groups.push((link_bound(f, link), Vec::new()));
                                last = Some(link);
                            }
                            if let Some(group) = groups.last_mut() {
                                group.1.push(i as u16);
                            }
                        }
                        (!groups.is_empty()).then_some(WorldTest { obstacle: o, groups })
                    })
                    .collect()
            })
            .collect();
        // Pairs grouped by their frames; pairs that never change measured now.
        let mut pairs: Vec<PairTest> = Vec::new();
        let mut fixed_gap = f64::INFINITY;
        // At the start state's values: only pairs whose distance never changes use these.
        let mut poses = Vec::new();
        robot.poses_into(&checker.template, &mut poses);
        let world_centre = |k: usize| poses[spheres[k].link] * Point3::from(spheres[k].centre);
        for (index, &(a, b)) in checker.pairs.iter().enumerate() {
            let (a, b) = (a as usize, b as usize);
            let ((fa, ia), (fb, ib)) = (slot[a], slot[b]);
            // The pair as (the later frame's sphere, the other's), and their links.
            let (frame, i, other, j, link, other_link) = match (fa, fb) {
                (Some(x), Some(y)) if x < y => (y, ib, Some(x), ia, spheres[b].link, spheres[a].link),
                (Some(x), other) if other != Some(x) => (x, ia, other, ib, spheres[a].link, spheres[b].link),
                (None, Some(y)) => (y, ib, None, ia, spheres[b].link, spheres[a].link),
                _ => {
                    let gap =
                        (world_centre(a) - world_centre(b)).norm() - spheres[a].radius - spheres[b].radius;
                    fixed_gap = fixed_gap.min(gap);
                    continue;
                }
            };
            let test = match pairs.iter().position(|p| p.frame == frame && p.other == other) {
                Some(t) => t,
                None => {
                    let reach = vec![0.0; group.joints.len()];
                    pairs.push(PairTest {
                        frame,
                        other,
                        still_bound: ([0.0; 3], 0.0),
                        links: Vec::new(),
                        reach,
                        floor: f32::NEG_INFINITY,
                    });
                    pairs.len() - 1
                }
            };
            for (r, &v) in pairs[test].reach.iter_mut().zip(&checker.pair_reach[index]) {
                *r = r.max(v);
            }
            let group = match pairs[test].links.iter().position(|g| g.links == (link, other_link)) {
                Some(g) => g,
                None => {
                    let bound = link_bound(frame, link);
                    let other_bound = match other {
                        Some(o) => link_bound(o, other_link),
                        None => ([0.0; 3], 0.0),
                    };
                    pairs[test].links.push(LinkPair {
                        links: (link, other_link),
                        bound,
                        other_bound,
                        rows: Vec::new(),
                        floor: f32::NEG_INFINITY,
                    });
                    pairs[test].links.len() - 1
                }
            };
            let rows = &mut pairs[test].links[group].rows;
            let pair = (j as u16, f32::NEG_INFINITY);
            match rows.iter_mut().find(|r| r.sphere == i as u16) {
                Some(row) => row.others.push(pair),
                None => rows.push(Row { sphere: i as u16, others: vec![pair], floor: f32::NEG_INFINITY }),
            }
        }
        // Floors: the least gap of each pair (pairs passed over in tests that cannot reach them).
        for test in &mut pairs {
            let model = |side: Option<usize>, i: u16| match side {
                Some(f) => frame_models[f][i as usize],
                None => still_models[i as usize],
            };
            let sides = (Some(test.frame), test.other);
            let floors = least_gaps(checker, &frames, test, sides, &model);
            for link in &mut test.links {
                for row in &mut link.rows {
                    for (j, floor) in &mut row.others {
                        if let Some(gap) = floors.get(&(model(sides.0, row.sphere), model(sides.1, *j))) {
                            // Rounded down into f32.
                            *floor = (gap - 1e-6 * (1.0 + gap.abs())) as f32;
                        }
                    }
                    row.floor = row.others.iter().map(|o| o.1).fold(f32::INFINITY, f32::min);
                }
                link.floor = link.rows.iter().map(|r| r.floor).fold(f32::INFINITY, f32::min);
            }
            test.floor = test.links.iter().map(|l| l.floor).fold(f32::INFINITY, f32::min);
        }
        let still: Vec<Ball> = still64.iter().map(|(c, r)| (point32(c), *r as f32)).collect();
        for p in pairs.iter_mut().filter(|p| p.other.is_none()) {
            let mut all = Vec::new();
            for g in &mut p.links {
                let used: Vec<Ball> =
                    g.rows.iter().flat_map(|r| r.others.iter().map(|&(j, _)| still[j as usize])).collect();
                g.other_bound = bounding(&used);
                all.extend(used);
            }
            p.still_bound = bounding(&all);
        }
        // Beyond MAX_JOINT_VALUE the lanes' turn counting is not exact: nothing is called free.
        let blocked = still_clearance <= f64::from(slack)
            || fixed_gap <= 2.0 * f64::from(slack)
            || largest_value > MAX_JOINT_VALUE;
        Program { frames, sphere_count, obstacles, world, pairs, still, blocked, slack }
    }
}

/// The least gap of each sphere pair (model indices) of `test` over every configuration, where
/// at most two group joints move the pair's spheres relative to each other: on a grid of those
/// joints' values, each pair's smallest gap, less how much it can shrink between grid points
/// (its relative speed bound times half a cell). Empty for tests with more such joints.
fn least_gaps(
    checker: &ArmChecker,
    frames: &[Frame],
    test: &PairTest,
    sides: (Option<usize>, Option<usize>),
    model: &dyn Fn(Option<usize>, u16) -> usize,
) -> std::collections::HashMap<(usize, usize), f64> {
    let ancestors = |mut at: Option<usize>| {
        let mut all = Vec::new();
        while let Some(f) = at {
            all.push(f);
            at = frames[f].parent;
        }
        all
    };
    let (a, b) = (ancestors(sides.0), ancestors(sides.1));
    let mut variables: Vec<usize> = a
        .iter()
        .filter(|f| !b.contains(f))
        .chain(b.iter().filter(|f| !a.contains(f)))
        .map(|&f| frames[f].variable)
        .collect();
    variables.sort_unstable();
    variables.dedup();
    let cells = match variables.len() {
        1 => 1024,
        2 => 32,
        _ => return Default::default(),
    };
    let bounds = &checker.group.bounds;
    let width = |k: usize| (bounds[variables[k]].1 - bounds[variables[k]].0) / cells as f64;
    // How much a pair's gap can shrink from the nearest grid point (half a cell each way).
    let shrink: f64 = (0..variables.len()).map(|k| test.reach[variables[k]] * width(k) / 2.0).sum();
    let pairs: Vec<(usize, usize)> = test
        .links
        .iter()
        .flat_map(|l| {
            l.rows
                .iter()
                .flat_map(|r| r.others.iter().map(|&(j, _)| (model(sides.0, r.sphere), model(sides.1, j))))
        })
        .collect();
    let mut smallest = vec![f64::INFINITY; pairs.len()];
    let mut values = checker.template.clone();
    let mut poses = Vec::new();
    let spheres = &checker.model.spheres;
    let points = if variables.len() == 1 { cells } else { cells * cells };
    for n in 0..points {
        for (k, &v) in variables.iter().enumerate() {
            let cell = if k == 0 { n % cells } else { n / cells };
            values[checker.group.joints[v]] = bounds[v].0 + (cell as f64 + 0.5) * width(k);
        }
        checker.robot.poses_into(&values, &mut poses);
        for (gap, &(x, y)) in smallest.iter_mut().zip(&pairs) {
            let (sx, sy) = (&spheres[x], &spheres[y]);
            let d =
                (poses[sx.link] * Point3::from(sx.centre) - poses[sy.link] * Point3::from(sy.centre)).norm();
            *gap = gap.min(d - sx.radius - sy.radius);
        }
    }
    pairs.into_iter().zip(smallest.into_iter().map(|gap| gap - shrink)).collect()
}

/// The rotation carrying z onto `axis`.
fn z_onto(axis: &Unit<Vector3<f64>>) -> UnitQuaternion<f64> {
    UnitQuaternion::rotation_between(&Vector3::z(), axis).unwrap_or_else(|| {
        // Opposite: half a turn about x.
        UnitQuaternion::from_rotation_matrix(&Rotation3::from_axis_angle(
            &Vector3::x_axis(),
            std::f64::consts::PI,
        ))
    })
}

fn point32(p: &Point3<f64>) -> [f32; 3] {
    [p.x as f32, p.y as f32, p.z as f32]
}

/// A sphere containing every one of `spheres` (about their centres' mean; not the smallest).
fn bounding(spheres: &[([f32; 3], f32)]) -> ([f32; 3], f32) {
    if spheres.is_empty() {
        return ([0.0; 3], 0.0);
    }
    let n = spheres.len() as f64;
    let mean: [f32; 3] =
        std::array::from_fn(|i| (spheres.iter().map(|(c, _)| c[i] as f64).sum::<f64>() / n) as f32);
    let radius = spheres
        .iter()
        .map(|(c, r)| (0..3).map(|i| (c[i] as f64 - mean[i] as f64).powi(2)).sum::<f64>().sqrt() + *r as f64)
        .fold(0.0, f64::max);
    // Rounded up: the bound must contain what it bounds.
    (mean, (radius * (1.0 + 1e-6)) as f32)
}
