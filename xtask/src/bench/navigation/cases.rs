//! The cases of the navigation section: one map of each family, the sensor radii, and what the
//! robot knows before it starts (free space, a map with walls missing and phantom walls, or
//! free space with an obstacle that follows the robot).

use std::path::Path;

use rand::RngExt;
use rand_chacha::ChaCha8Rng;
use trailmark::core::generate;
use trailmark::movingai;
use trailmark::prelude::*;

use crate::bench::suite::Suite;
use crate::region::endpoints;

/// One navigation problem: a map, what the robot knows of it, a start and a goal, a sensor
/// radius, and an obstacle following the robot.
pub struct NavCase {
    /// The map's name, with the prior or the follower when they are not the default.
    pub name: String,
    pub grid: Grid,
    /// The robot's map at the start.
    pub prior: Grid,
    pub start: Cell,
    pub goal: Cell,
    pub radius: u32,
    /// An obstacle following the robot this many steps behind.
    pub follower_lag: Option<u32>,
}

/// The share of walls a partially known prior misses.
const MISSING_WALLS: f64 = 0.15;
/// The share of free cells a partially known prior blocks (phantom walls, gone when seen).
const PHANTOM_WALLS: f64 = 0.03;
/// How far behind the robot the follower of the follower cases goes.
const FOLLOWER_LAG: u32 = 3;

/// The truth with some walls missing and some phantom walls (never on the start or the goal):
/// the robot finds walls where it thought none, and free cells where it thought walls.
fn partial_prior(truth: &Grid, start: Cell, goal: Cell, seed: u64) -> Result<Grid, String> {
    let mut rng = <ChaCha8Rng as rand::SeedableRng>::seed_from_u64(seed ^ 0x7072_696f);
    let mut prior = truth.clone();
    for cell in truth.cells() {
        let draw: f64 = rng.random();
        let flip = if truth.is_passable(cell) {
            draw < PHANTOM_WALLS && cell != start && cell != goal
        } else {
            draw < MISSING_WALLS
        };
        if flip {
            prior.set_blocked(cell, truth.is_passable(cell)).map_err(|e| e.to_string())?;
        }
    }
    Ok(prior)
}

/// The MovingAI maps of the navigation section: two games (Dragon Age, Baldur's Gate) and a city.
const NAV_MOVINGAI: [(&str, &str); 3] =
    [("dao", "brc202d"), ("bg512", "AR0011SR"), ("cities", "Berlin_0_512")];

/// A map whose goal sits in a cup-shaped wall that opens away from the start: the robot sees
/// the wall only when it arrives next to the goal.
fn trap(size: usize) -> (Grid, Cell, Cell) {
    let mut grid = Grid::new(size, size).expect("a valid size");
    let (c, r) = (size as u32 * 3 / 4, size as u32 / 8);
    let goal = Cell::new(c, size as u32 / 2);
    for d in 0..=2 * r {
        for cell in [
            Cell::new(goal.x - r, goal.y - r + d), // the side facing the start
            Cell::new(goal.x - r + d, goal.y - r), // top
            Cell::new(goal.x - r + d, goal.y + r), // bottom
        ] {
            grid.set_blocked(cell, true).expect("inside");
        }
    }
    (grid, Cell::new(size as u32 / 16, size as u32 / 2), goal)
}

/// The navigation cases of a suite, one map of each family: generated random maps (10%, 25%
/// and 40% obstacles), rooms, mazes with corridors 1, 4 and 32 cells wide (3/8 of the size: a
/// robot in an unknown maze walks far), the trap, and the MovingAI maps when the folder is
/// there; each with sensor radius 1, 5 and 10 and a free-space prior. The random map with 25%
/// obstacles, the rooms and the maze with corridors 4 wide come again with a partially known
/// prior; the first two again with an obstacle following the robot. The maps of the first
/// version of the section (random 25% and 40%, the trap, the MovingAI maps) keep their start
/// and goal.
pub fn nav_cases(suite: Suite, seed: u64, movingai_dir: Option<&Path>) -> Result<Vec<NavCase>, String> {
    let size = match suite {
        Suite::Quick => 256,
        Suite::Full => 512,
    };
    let mut rng = <ChaCha8Rng as rand::SeedableRng>::seed_from_u64(seed ^ 0x6e61_7669);
    let mut later = <ChaCha8Rng as rand::SeedableRng>::seed_from_u64(seed ^ 0x6661_6d69);
    let mut maps: Vec<(String, Grid, Cell, Cell)> = Vec::new();
    let mut add = |name: String, grid: Result<Grid, generate::GenerateError>, rng: &mut ChaCha8Rng| {
        let grid = grid.map_err(|e| e.to_string())?;
        let (start, goal) = endpoints(&grid, rng).ok_or("an empty map")?;
        maps.push((name, grid, start, goal));
        Ok::<(), String>(())
    };
    for density in [10, 25, 40] {
        let grid = generate::random(size, size, f64::from(density) / 100.0, seed);
        let rng = if density == 10 { &mut later } else { &mut rng };
        add(format!("random{size}-{density}-s{seed}"), grid, rng)?;
    }
    add(format!("rooms{size}-16-s{seed}"), generate::rooms(size, size, 16, seed), &mut later)?;
    let small = size * 3 / 8;
    for corridor in [1, 4, 32] {
        let grid = generate::maze(small, small, corridor, seed);
        add(format!("maze{small}-{corridor}-s{seed}"), grid, &mut later)?;
    }
    let (grid, start, goal) = trap(size);
    maps.push((format!("trap{size}"), grid, start, goal));
    if let Some(dir) = movingai_dir {
        let chosen: &[(&str, &str)] = match suite {
            Suite::Quick => &NAV_MOVINGAI[..1],
            Suite::Full => &NAV_MOVINGAI,
        };
        for (set, name) in chosen {
            let path = dir.join("maps").join(set).join(format!("{name}.map"));
            let grid = movingai::read_map(&path).map_err(|e| e.to_string())?;
            let (start, goal) = endpoints(&grid, &mut rng).ok_or("an empty map")?;
            maps.push((name.to_string(), grid, start, goal));
        }
    }
    let mut cases = Vec::new();
    for (name, grid, start, goal) in maps {
        let free = Grid::new(grid.width() as usize, grid.height() as usize).map_err(|e| e.to_string())?;
        let family = |with: &str| name.starts_with(with);
        let mut settings = vec![(name.clone(), free.clone(), None)];
        if family(&format!("random{size}-25")) || family("rooms") || family(&format!("maze{small}-4-")) {
            settings.push((format!("{name} partial"), partial_prior(&grid, start, goal, seed)?, None));
        }
        if family(&format!("random{size}-25")) || family("rooms") {
            settings.push((format!("{name} follower"), free, Some(FOLLOWER_LAG)));
        }
        for (label, prior, follower_lag) in settings {
            for radius in [1, 5, 10] {
                cases.push(NavCase {
                    name: label.clone(),
                    grid: grid.clone(),
                    prior: prior.clone(),
                    start,
                    goal,
                    radius,
                    follower_lag,
                });
            }
        }
    }
    Ok(cases)
}
