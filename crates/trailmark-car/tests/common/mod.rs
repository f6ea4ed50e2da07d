//! What the tests on the Nav2 maps share: where the maps are, the car, a check of its footprint
//! that shares nothing with the planner's, and seeded start and goal poses.

#![allow(dead_code)]

use std::path::PathBuf;

use rand::RngExt;
use rand_chacha::ChaCha8Rng;
use trailmark_car::HybridAStar;
use trailmark_core::footprint::Footprint;
use trailmark_core::geometry::{Point, Pose};
use trailmark_core::world::Polygon;
use trailmark_map::{Costmap, LETHAL};

#[path = "../../../../tests/support/shared_data.rs"]
mod shared_data;

/// The Nav2 example maps, or `None` (with a message) when they are absent.
pub fn data() -> Option<PathBuf> {
    shared_data::shared_data("rosmaps", "the Nav2 example maps")
}

/// A 0.6 m x 0.4 m car, its reference point (the rear axle) 0.15 m from the back.
pub const CAR: [[f64; 2]; 4] = [[-0.15, -0.2], [0.45, -0.2], [0.45, 0.2], [-0.15, 0.2]];
pub const TURNING_RADIUS: f64 = 0.5;

pub fn footprint() -> Footprint {
    Footprint::Polygon(Polygon::new(CAR.iter().map(|p| Point::new(p[0], p[1])).collect()).unwrap())
}

/// Whether the rectangle `CAR` at `pose` (world frame) overlaps no lethal or unknown cell and
/// stays on the map: every cell near the pose tested by the separating axis theorem (the cell's
/// two axes and the rectangle's two).
pub fn independently_free(costmap: &Costmap, pose: &Pose) -> bool {
    let frame = costmap.frame();
    let res = frame.resolution();
    let corners: Vec<Point> = CAR.iter().map(|p| pose * Point::new(p[0], p[1])).collect();
    // Corners in grid units (x right, y down from the top-left), where cells are unit squares.
    let g: Vec<(f64, f64)> = corners.iter().map(|&p| frame.point_to_grid(p)).collect();
    let (w, h) = (f64::from(frame.width()), f64::from(frame.height()));
    if g.iter().any(|&(x, y)| x < 0.0 || y < 0.0 || x > w || y > h) {
        return false;
    }
    let (x0, x1) = g.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| (a.min(p.0), b.max(p.0)));
    let (y0, y1) = g.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| (a.min(p.1), b.max(p.1)));
    let _ = res;
    let axes = [(g[1].0 - g[0].0, g[1].1 - g[0].1), (g[3].0 - g[0].0, g[3].1 - g[0].1)];
    for cy in y0.floor() as i64..=y1.floor() as i64 {
        for cx in x0.floor() as i64..=x1.floor() as i64 {
            if cx < 0 || cy < 0 || cx as f64 >= w || cy as f64 >= h {
                continue;
            }
            let square = [
                (cx as f64, cy as f64),
                (cx as f64 + 1.0, cy as f64),
                (cx as f64 + 1.0, cy as f64 + 1.0),
                (cx as f64, cy as f64 + 1.0),
            ];
            let separated = |axis: (f64, f64)| {
                let proj = |p: &(f64, f64)| p.0 * axis.0 + p.1 * axis.1;
                let (a0, a1) = g
                    .iter()
                    .map(proj)
                    .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| (a.min(v), b.max(v)));
                let (b0, b1) = square
                    .iter()
                    .map(proj)
                    .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| (a.min(v), b.max(v)));
                a1 <= b0 || b1 <= a0
            };
            let overlaps = ![(1.0, 0.0), (0.0, 1.0), axes[0], axes[1]].into_iter().any(separated);
            if overlaps {
                let cell = trailmark_core::grid::Cell::new(cx as u32, cy as u32);
                if costmap.cost(cell).is_none_or(|c| c >= LETHAL) {
                    return false;
                }
            }
        }
    }
    true
}

/// A random pose on the map whose footprint is free: in the open (no lethal cell within
/// [`NEAR_WALL`] of its reference point, any heading), or parked (a lethal cell that near, the
/// car facing along the wall: across the line to the nearest lethal cell, either way).
pub fn random_pose(costmap: &Costmap, planner: &HybridAStar, rng: &mut ChaCha8Rng, parked: bool) -> Pose {
    let frame = costmap.frame();
    let (w, h) = (frame.width(), frame.height());
    let reach = (NEAR_WALL / frame.resolution()).ceil() as i64;
    for _ in 0..1_000_000 {
        let (gx, gy) = (rng.random::<f64>() * f64::from(w), rng.random::<f64>() * f64::from(h));
        let cell = trailmark_core::grid::Cell::new(gx as u32, gy as u32);
        if costmap.cost(cell).is_none_or(|c| c >= LETHAL) {
            continue;
        }
        let p = frame.point_from_grid(gx, gy);
        let mut nearest: Option<(f64, Point)> = None;
        for dy in -reach..=reach {
            for dx in -reach..=reach {
                let (x, y) = (i64::from(cell.x) + dx, i64::from(cell.y) + dy);
                if x < 0 || y < 0 || x >= i64::from(w) || y >= i64::from(h) {
                    continue;
                }
                let c = trailmark_core::grid::Cell::new(x as u32, y as u32);
                if costmap.cost(c).is_some_and(|v| v >= LETHAL) {
                    let q = frame.centre(c);
                    let d = (q - p).norm();
                    if d <= NEAR_WALL && nearest.is_none_or(|(best, _)| d < best) {
                        nearest = Some((d, q));
                    }
                }
            }
        }
        let heading = match (nearest, parked) {
            (Some((_, q)), true) => {
                let to_wall = q - p;
                let along = to_wall.y.atan2(to_wall.x) + std::f64::consts::FRAC_PI_2;
                if rng.random::<bool>() { along } else { along + std::f64::consts::PI }
            }
            (None, false) => rng.random::<f64>() * std::f64::consts::TAU,
            _ => continue,
        };
        let pose = Pose::new(p.coords, heading);
        if planner.is_free(&pose) && independently_free(costmap, &pose) {
            return pose;
        }
    }
    panic!("no {} pose found", if parked { "parked" } else { "open" });
}

/// How near a wall a parked car's reference point is, in metres.
pub const NEAR_WALL: f64 = 0.5;
