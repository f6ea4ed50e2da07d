//! Sphere covers that contain a robot's own collision geometry. A spherized URDF is an
//! approximation (the Panda's leaves centimetres of its meshes outside, between its spheres):
//! [`uncovered`] says how far, link by link, and [`cover`] adds spheres where the geometry
//! sticks out and grows them all by a tolerance, so that the spheres contain it and the sphere
//! checkers are conservative for the robot's own shapes too.
//!
//! The geometry is sampled finely enough to bound what lies between samples: each mesh
//! triangle is split until no edge is longer than `resolution` (every point of it is then
//! within `resolution / √3` of a corner of its piece, which is added to the growth); a box's
//! faces, a cylinder's and a capsule's surface likewise. A sphere of the geometry adds its own
//! radius to the distance of its centre.

use std::collections::HashMap;
use std::path::Path;

use nalgebra::{Isometry3, Matrix3, Point3, SymmetricEigen, Vector3};

use crate::error::RobotError;
use crate::mesh::{Mesh, resolve};
use crate::robot::Robot;
use crate::urdf::{Collision, Geometry, Link, Urdf};

/// The default resolution of [`uncovered`]: 2 mm (the growth then includes about 1.2 mm for
/// what lies between the samples).
pub const DEFAULT_COVER_RESOLUTION: f64 = 0.002;

/// The most sample points of one link's geometry (links are sampled one at a time), a bound
/// on the time and memory a hostile file can take (a resolution far below the geometry's size
/// asks for more): about 320 MB.
pub const MAX_COVER_SAMPLES: usize = 10_000_000;

/// For each link of `spheres` (a robot whose links are covered by spheres), how far the
/// collision geometry of the same link of `geometry` (the robot with its own meshes and
/// primitives; mesh files found from `urdf_dir`) lies outside that link's spheres, at most
/// (0 where it lies inside, or where the link has no geometry). Errors on a link with geometry
/// but no sphere, a link of `geometry` that `spheres` lacks, a mesh that cannot be read, a
/// resolution that is not positive and finite, and more than [`MAX_COVER_SAMPLES`] samples.
pub fn uncovered(
    spheres: &Robot,
    geometry: &Robot,
    urdf_dir: &Path,
    resolution: f64,
) -> Result<Vec<f64>, RobotError> {
    let mut growth = vec![0.0; spheres.urdf().links.len()];
    each_link(geometry, urdf_dir, resolution, |name, samples| {
        let index = sphere_link(spheres, name)?;
        let balls = balls(spheres.urdf(), index);
        growth[index] = samples.iter().map(|s| outside(&balls, s)).fold(0.0, f64::max);
        Ok(())
    })?;
    Ok(growth)
}

/// The most spheres [`cover`] adds to one link.
pub const MAX_ADDED_SPHERES: usize = 1000;

/// `spheres`' URDF with spheres added where the geometry of `geometry`'s links sticks out of
/// them by more than `tolerance` (each new sphere containing the samples of one such place),
/// then every sphere of a link with geometry grown by `tolerance`: every point of the geometry
/// then lies within a sphere of its link (up to the sampling's bound, included). The number of
/// spheres added to each link comes back too. Errors as [`uncovered`], on a tolerance that is
/// not positive and finite, and on a link needing more than [`MAX_ADDED_SPHERES`].
pub fn cover(
    spheres: &Robot,
    geometry: &Robot,
    urdf_dir: &Path,
    resolution: f64,
    tolerance: f64,
) -> Result<(Urdf, Vec<usize>), RobotError> {
    if !(tolerance.is_finite() && tolerance > 0.0) {
        return Err(invalid("tolerance", tolerance));
    }
    let mut urdf = spheres.urdf().clone();
    let mut added = vec![0; urdf.links.len()];
    each_link(geometry, urdf_dir, resolution, |name, samples| {
        let index = sphere_link(spheres, name)?;
        let balls = balls(&urdf, index);
        let axis: Vec<Vector3<f64>> = balls.iter().map(|b| b.0).collect();
        let (covering, count) = cover_link(&axis, balls, &samples, tolerance)?;
        added[index] = count;
        set_spheres(&mut urdf.links[index], covering, tolerance);
        Ok(())
    })?;
    Ok((urdf, added))
}

/// `balls` (a link's spheres: centre, radius) with spheres added until no sample lies more
/// than `tolerance` outside them, each new one centred on the link's axis, the segments between
/// the points of `axis`; how many were added.
fn cover_link(
    axis: &[Vector3<f64>],
    mut balls: Vec<Ball>,
    samples: &[Sample],
    tolerance: f64,
) -> Result<(Vec<Ball>, usize), RobotError> {
    let mut added = 0;
    // A new sphere centred on the axis stays within the link's width rather than bulging from
    // its surface.
    let centres = axis;
    let on_axis = |p: &Point3<f64>| {
        let Some(&(mut best)) = centres.first() else { return p.coords };
        for (i, a) in centres.iter().enumerate() {
            for b in &centres[i..] {
                let ab = b - a;
                let t = if ab.norm_squared() > 0.0 {
                    ((p.coords - a).dot(&ab) / ab.norm_squared()).clamp(0.0, 1.0)
                } else {
                    0.0
                };
                let q = a + ab * t;
                if (p.coords - q).norm() < (p.coords - best).norm() {
                    best = q;
                }
            }
        }
        best
    };
    let mut out: Vec<f64> = samples.iter().map(|s| outside(&balls, s)).collect();
    loop {
        let (worst, at) = out
            .iter()
            .enumerate()
            .fold((f64::NEG_INFINITY, 0), |m, (i, &o)| if o > m.0 { (o, i) } else { m });
        if worst <= tolerance {
            break;
        }
        if added == MAX_ADDED_SPHERES {
            return Err(RobotError::TooLarge {
                what: "the spheres a link's cover needs",
                count: added + 1,
                max: MAX_ADDED_SPHERES,
            });
        }
        let (p, slack) = samples[at];
        let centre = on_axis(&p);
        let radius = (p.coords - centre).norm() + slack;
        balls.push((centre, radius));
        added += 1;
        for (o, s) in out.iter_mut().zip(samples) {
            *o = o.min((s.0.coords - centre).norm() + s.1 - radius);
        }
    }
    Ok((balls, added))
}

/// Replaces `link`'s spheres by `balls`, each grown by `tolerance`; its other shapes stay.
fn set_spheres(link: &mut Link, balls: Vec<Ball>, tolerance: f64) {
    link.collisions.retain(|c| !matches!(c.geometry, Geometry::Sphere { .. }));
    for (centre, radius) in balls {
        link.collisions.push(Collision {
            origin: Isometry3::translation(centre.x, centre.y, centre.z),
            geometry: Geometry::Sphere { radius: radius + tolerance },
        });
    }
}

/// A robot's spheres made from its own geometry (meshes and primitives, mesh files found from
/// `urdf_dir`), for a robot without a spherized URDF: each link's geometry sampled (as
/// [`uncovered`] samples it), seeds placed along its longest principal axis, and spheres
/// centred on that axis added by [`cover`]'s rule until they contain every sample, then grown
/// by `tolerance`. The URDF comes back with every link's collision geometry replaced by its
/// spheres. Errors as [`cover`].
pub fn spherize(
    geometry: &Robot,
    urdf_dir: &Path,
    resolution: f64,
    tolerance: f64,
) -> Result<Urdf, RobotError> {
    if !(tolerance.is_finite() && tolerance > 0.0) {
        return Err(invalid("tolerance", tolerance));
    }
    let mut urdf = geometry.urdf().clone();
    each_link(geometry, urdf_dir, resolution, |name, samples| {
        // The seeds only shape the axis: they cover nothing.
        let seeds = axis_seeds(&samples, resolution);
        let (balls, _) = cover_link(&seeds, Vec::new(), &samples, tolerance)?;
        let link = urdf
            .links
            .iter_mut()
            .find(|l| l.name == name)
            .ok_or_else(|| RobotError::UnknownLink(name.into()))?;
        link.collisions.clear();
        set_spheres(link, balls, tolerance);
        Ok(())
    })?;
    Ok(urdf)
}

/// Points inside the geometry of `samples`: one for each radius (the samples' median distance
/// from the longest principal axis) along that axis (2 to 32), spread along it, then moved to
/// the middles of the samples nearest each.
fn axis_seeds(samples: &[Sample], resolution: f64) -> Vec<Vector3<f64>> {
    let n = samples.len().max(1) as f64;
    let mean = samples.iter().fold(Vector3::zeros(), |m, s| m + s.0.coords) / n;
    let covariance = samples.iter().fold(Matrix3::zeros(), |c, s| {
        let d = s.0.coords - mean;
        c + d * d.transpose()
    }) / n;
    let eigen = SymmetricEigen::new(covariance);
    let longest = eigen.eigenvalues.iamax();
    let axis = eigen.eigenvectors.column(longest).into_owned();
    let along: Vec<f64> = samples.iter().map(|s| (s.0.coords - mean).dot(&axis)).collect();
    let (low, high) =
        along.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), &t| (l.min(t), h.max(t)));
    let mut radial: Vec<f64> =
        samples.iter().zip(&along).map(|(s, t)| (s.0.coords - mean - axis * *t).norm()).collect();
    radial.sort_by(f64::total_cmp);
    let width = radial.get(radial.len() / 2).copied().unwrap_or(0.0).max(resolution);
    let length = if high > low { high - low } else { 0.0 };
    // Seeds about a radius apart: enough to follow a link that bends (the Panda's elbows; a
    // diameter apart, its fifth and seventh links' covers meet at its home pose).
    let count = ((length / width).ceil() as usize + 1).clamp(2, 32);
    // At most about 20,000 samples move the seeds.
    let stride = samples.len().div_ceil(20_000).max(1);
    let mut seeds: Vec<Vector3<f64>> = (0..count)
        .map(|k| {
            let t = if length > 0.0 { low + length * k as f64 / (count - 1) as f64 } else { 0.0 };
            mean + axis * t
        })
        .collect();
    // A few rounds of Lloyd's k-means: seeds move to the middles of the samples nearest them,
    // which follow a link that bends (an elbow) where its principal axis does not.
    for _ in 0..10 {
        let mut sums = vec![(Vector3::zeros(), 0usize); seeds.len()];
        for s in samples.iter().step_by(stride) {
            let nearest = (0..seeds.len())
                .min_by(|&a, &b| (s.0.coords - seeds[a]).norm().total_cmp(&(s.0.coords - seeds[b]).norm()))
                .unwrap_or(0);
            sums[nearest].0 += s.0.coords;
            sums[nearest].1 += 1;
        }
        for (seed, (sum, n)) in seeds.iter_mut().zip(sums) {
            if n > 0 {
                *seed = sum / n as f64;
            }
        }
    }
    seeds
}

/// A sphere of a link: its centre in the link's frame, and its radius.
type Ball = (Vector3<f64>, f64);

/// A point of a link's geometry (in the link's frame) and how far the geometry may reach
/// beyond it (the sampling's bound, or a sphere's radius).
type Sample = (Point3<f64>, f64);

/// The spheres of link `index` of `urdf`: centre and radius.
fn balls(urdf: &Urdf, index: usize) -> Vec<Ball> {
    urdf.links[index]
        .collisions
        .iter()
        .filter_map(|c| match c.geometry {
            Geometry::Sphere { radius } => Some((c.origin.translation.vector, radius)),
            _ => None,
        })
        .collect()
}

/// How far the geometry about `sample` reaches outside the nearest of `balls`.
fn outside(balls: &[Ball], sample: &Sample) -> f64 {
    balls.iter().map(|(c, r)| (sample.0.coords - c).norm() - r).fold(f64::INFINITY, f64::min) + sample.1
}

fn invalid(attribute: &'static str, value: f64) -> RobotError {
    RobotError::Invalid {
        element: "cover".into(),
        attribute,
        reason: "a positive finite length",
        value: value.to_string(),
    }
}

/// The index in `spheres` of the link `name`, which must have a sphere.
fn sphere_link(spheres: &Robot, name: &str) -> Result<usize, RobotError> {
    let index = spheres.link_index(name).ok_or_else(|| RobotError::UnknownLink(name.into()))?;
    if balls(spheres.urdf(), index).is_empty() {
        return Err(RobotError::NoSphereCover { link: name.into(), shape: "geometry without spheres" });
    }
    Ok(index)
}

/// Samples the geometry of each link of `geometry` that has some, one link at a time, and
/// gives them to `f` with the link's name.
fn each_link(
    geometry: &Robot,
    urdf_dir: &Path,
    resolution: f64,
    mut f: impl FnMut(&str, Vec<Sample>) -> Result<(), RobotError>,
) -> Result<(), RobotError> {
    if !(resolution.is_finite() && resolution > 0.0) {
        return Err(invalid("resolution", resolution));
    }
    let mut meshes: HashMap<String, Mesh> = HashMap::new();
    for link in &geometry.urdf().links {
        if link.collisions.is_empty() {
            continue;
        }
        let mut samples: Vec<Sample> = Vec::new();
        for c in &link.collisions {
            let mut visit = |p: Point3<f64>, extra: f64| -> Result<(), RobotError> {
                if samples.len() == MAX_COVER_SAMPLES {
                    return Err(RobotError::TooLarge {
                        what: "a link's cover samples",
                        count: samples.len() + 1,
                        max: MAX_COVER_SAMPLES,
                    });
                }
                samples.push((c.origin * p, extra));
                Ok(())
            };
            match &c.geometry {
                Geometry::Mesh { filename, scale } => {
                    if !meshes.contains_key(filename) {
                        meshes.insert(filename.clone(), Mesh::from_file(resolve(filename, urdf_dir)?)?);
                    }
                    let mesh = &meshes[filename];
                    let at = |i: u32| Point3::from(mesh.vertices[i as usize].coords.component_mul(scale));
                    for t in &mesh.triangles {
                        triangle([at(t[0]), at(t[1]), at(t[2])], resolution, &mut visit)?;
                    }
                }
                Geometry::Sphere { radius } => visit(Point3::origin(), *radius)?,
                Geometry::Box { size } => {
                    let h = size / 2.0;
                    let corner = |x: f64, y: f64, z: f64| Point3::new(x * h.x, y * h.y, z * h.z);
                    // Each face as two triangles.
                    for axis in 0..3 {
                        for side in [-1.0, 1.0] {
                            let mut c = [Point3::origin(); 4];
                            for (k, (u, v)) in
                                [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)].iter().enumerate()
                            {
                                let mut w = [0.0; 3];
                                w[axis] = side;
                                w[(axis + 1) % 3] = *u;
                                w[(axis + 2) % 3] = *v;
                                c[k] = corner(w[0], w[1], w[2]);
                            }
                            triangle([c[0], c[1], c[2]], resolution, &mut visit)?;
                            triangle([c[0], c[2], c[3]], resolution, &mut visit)?;
                        }
                    }
                }
                Geometry::Cylinder { radius, length } => {
                    around_z(*radius, -length / 2.0, length / 2.0, 0.0, resolution, &mut visit)?;
                }
                Geometry::Capsule { radius, length } => {
                    // The axis sampled, each sample a ball of the capsule's radius.
                    let steps = (length / resolution).ceil().max(1.0) as usize;
                    for i in 0..=steps {
                        let z = -length / 2.0 + length * i as f64 / steps as f64;
                        visit(Point3::new(0.0, 0.0, z), radius + resolution / 2.0)?;
                    }
                }
            }
        }
        f(&link.name, samples)?;
    }
    Ok(())
}

/// Visits points of the triangle `t` (every point of it within `resolution / √3` of one, which
/// each visit adds): its corners, after splitting it until no edge is longer than `resolution`.
fn triangle(
    t: [Point3<f64>; 3],
    resolution: f64,
    visit: &mut dyn FnMut(Point3<f64>, f64) -> Result<(), RobotError>,
) -> Result<(), RobotError> {
    let slack = resolution / 3f64.sqrt();
    let longest = (t[0] - t[1]).norm().max((t[1] - t[2]).norm()).max((t[2] - t[0]).norm());
    let n = (longest / resolution).ceil().max(1.0) as usize;
    // A regular split into n² pieces: each edge of a piece is an edge of the triangle over n.
    for i in 0..=n {
        for j in 0..=n - i {
            let (a, b) = (i as f64 / n as f64, j as f64 / n as f64);
            let p = t[0] + (t[1] - t[0]) * a + (t[2] - t[0]) * b;
            visit(p, slack)?;
        }
    }
    Ok(())
}

/// Visits points of a cylinder's surface (side and caps) about z from `low` to `high`.
fn around_z(
    radius: f64,
    low: f64,
    high: f64,
    extra: f64,
    resolution: f64,
    visit: &mut dyn FnMut(Point3<f64>, f64) -> Result<(), RobotError>,
) -> Result<(), RobotError> {
    // A polygon of `sides` inscribed in the circle: the circle lies within the sagitta of it.
    let sides = ((std::f64::consts::TAU * radius / resolution).ceil() as usize).max(8);
    let sagitta = radius * (1.0 - (std::f64::consts::PI / sides as f64).cos());
    let rim = |k: usize, z: f64| {
        let a = std::f64::consts::TAU * k as f64 / sides as f64;
        Point3::new(radius * a.cos(), radius * a.sin(), z)
    };
    // The side: a grid of rim points, each cell a rectangle with sides of at most the
    // resolution, so every point of it within resolution / √2 of a corner.
    let steps = ((high - low) / resolution).ceil().max(1.0) as usize;
    for k in 0..sides {
        for j in 0..=steps {
            let z = low + (high - low) * j as f64 / steps as f64;
            visit(rim(k, z), resolution / 2f64.sqrt() + sagitta + extra)?;
        }
    }
    let mut with_sagitta = |p: Point3<f64>, slack: f64| visit(p, slack + sagitta + extra);
    for k in 0..sides {
        triangle([Point3::new(0.0, 0.0, low), rim(k, low), rim(k + 1, low)], resolution, &mut with_sagitta)?;
        triangle(
            [Point3::new(0.0, 0.0, high), rim(k, high), rim(k + 1, high)],
            resolution,
            &mut with_sagitta,
        )?;
    }
    Ok(())
}
