//! Seeded generators: grids of random obstacles, mazes and rooms, in the styles of the MovingAI
//! `random`, `mazes` and `rooms` sets, and a lattice of unit blocks; polygon worlds of random convex obstacles, a bug trap,
//! and walls with narrow doors. The same arguments give the same world on every machine.
//!
//! Every size and count is checked before anything is allocated for it: grids against
//! [`Grid::MAX_CELLS`] (with checked multiplication), polygon worlds against
//! [`MAX_GENERATED_VERTICES`] and [`MAX_POLYGON_SIDES`]; an argument out of range is a
//! [`GenerateError`].
//!
//! ```
//! use trailmark_core::generate;
//!
//! let maze = generate::maze(64, 48, 3, 7)?;
//! assert_eq!((maze.width(), maze.height()), (64, 48));
//! assert_eq!(maze, generate::maze(64, 48, 3, 7)?); // reproducible
//! # Ok::<(), trailmark_core::generate::GenerateError>(())
//! ```

use rand::seq::SliceRandom;
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use thiserror::Error;

use crate::grid::{Cell, Grid, GridError};

/// The most vertices a generated polygon world may have in all: 65,536 (e.g. 10,000 hexagons).
///
/// The free space of a world unites its grown obstacles and roadmaps are built over every
/// vertex, so a world this large already takes seconds to build; the benchmarks use at most a
/// few thousand vertices.
pub const MAX_GENERATED_VERTICES: usize = 1 << 16;

/// The most sides a generated convex obstacle may have: 1024. (Validating a polygon costs time
/// quadratic in its vertices, and points at random angles on a circle come too close to tell
/// apart from collinear more often the more of them there are.)
pub const MAX_POLYGON_SIDES: usize = 1024;

/// How many times a random convex obstacle is drawn again when its angles come too close
/// together, before [`convex_obstacles`] gives up with [`GenerateError::Degenerate`].
const MAX_DRAWS: usize = 1000;

/// What was wrong with a generator's arguments.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum GenerateError {
    /// The size is not a valid grid.
    #[error(transparent)]
    Grid(#[from] GridError),
    /// The obstacle fraction is not within `[0, 1]`.
    #[error("the obstacle fraction {0} is not within [0, 1]")]
    Fraction(f64),
    /// A polygon world could not be made from the arguments.
    #[error(transparent)]
    World(#[from] crate::world::WorldError),
    /// A door width that is not positive or not below half the world's side.
    #[error("a door width of {door} must be positive and below half the side {size}")]
    Door {
        /// The door width given.
        door: f64,
        /// The world's side.
        size: f64,
    },
    /// A count beyond what a generator supports ([`MAX_GENERATED_VERTICES`],
    /// [`MAX_POLYGON_SIDES`]).
    #[error("{what} of {count} is more than the {max} supported")]
    TooMany {
        /// What was counted: `"obstacle sides"`, `"vertices (obstacles x sides)"`, `"walls"`.
        what: &'static str,
        /// The count given.
        count: usize,
        /// The most supported.
        max: usize,
    },
    /// No valid convex polygon came out of [`convex_obstacles`]'s draws (its sides too many
    /// for the random angles to stay apart).
    #[error("no convex polygon of {sides} sides came out of {draws} random draws")]
    Degenerate {
        /// The sides asked for.
        sides: usize,
        /// The draws made.
        draws: usize,
    },
    /// A corridor or room size of zero, or too large for the grid.
    #[error("a {what} of {size} does not fit a {width} x {height} grid")]
    Size {
        /// `"corridor width"` or `"room size"`.
        what: &'static str,
        /// The size given.
        size: u32,
        /// The grid width.
        width: usize,
        /// The grid height.
        height: usize,
    },
}

fn rng(seed: u64) -> ChaCha8Rng {
    ChaCha8Rng::seed_from_u64(seed)
}

/// A grid whose cells are blocked independently with probability `obstacle_fraction`.
pub fn random(width: usize, height: usize, obstacle_fraction: f64, seed: u64) -> Result<Grid, GenerateError> {
    if !(0.0..=1.0).contains(&obstacle_fraction) {
        return Err(GenerateError::Fraction(obstacle_fraction));
    }
    let cells = Grid::cell_count(width, height)?;
    let mut rng = rng(seed);
    let costs =
        (0..cells).map(|_| if rng.random_bool(obstacle_fraction) { f64::INFINITY } else { 1.0 }).collect();
    Ok(Grid::from_costs(width, height, costs)?)
}

/// A square grid of side `2k + 1` with a blocked cell at every cell whose column and row are both
/// odd: `k²` unit blocks, each alone, with one-cell corridors between them. Any-angle paths
/// there touch a block's corner at almost every step (`k = 50`: 2,500 blocks, 10,000 corners).
pub fn lattice(k: usize) -> Result<Grid, GenerateError> {
    // A side that saturates is refused as too large below.
    let side = k.saturating_mul(2).saturating_add(1);
    let cells = Grid::cell_count(side, side)?;
    let costs =
        (0..cells).map(|i| if (i % side) % 2 == 1 && (i / side) % 2 == 1 { f64::INFINITY } else { 1.0 });
    Ok(Grid::from_costs(side, side, costs.collect())?)
}

/// A perfect maze (one route between any two places) with corridors `corridor` cells wide and
/// walls one cell thick, carved by a seeded depth-first backtracker. Cells beyond the last
/// whole corridor on the right and bottom stay blocked.
pub fn maze(width: usize, height: usize, corridor: u32, seed: u64) -> Result<Grid, GenerateError> {
    let cells = Grid::cell_count(width, height)?;
    let mut grid = Grid::from_costs(width, height, vec![f64::INFINITY; cells])?;
    let pitch = corridor as usize + 1;
    let (cols, rows) = (width.saturating_sub(1) / pitch.max(1), height.saturating_sub(1) / pitch.max(1));
    if corridor == 0 || cols == 0 || rows == 0 {
        return Err(GenerateError::Size { what: "corridor width", size: corridor, width, height });
    }
    let mut rng = rng(seed);
    // Every cell opened lies inside the grid, whose sides fit a u32 (checked above).
    let open = |grid: &mut Grid, x0: usize, y0: usize, w: usize, h: usize| {
        for y in y0..y0 + h {
            for x in x0..x0 + w {
                let _ = grid.set_blocked(Cell::new(x as u32, y as u32), false);
            }
        }
    };
    let c = corridor as usize;
    let mut visited = vec![false; cols * rows];
    let mut stack = vec![(0usize, 0usize)];
    visited[0] = true;
    open(&mut grid, 1, 1, c, c);
    while let Some(&(cx, cy)) = stack.last() {
        let mut next = Vec::with_capacity(4);
        if cx > 0 && !visited[cy * cols + cx - 1] {
            next.push((cx - 1, cy));
        }
        if cx + 1 < cols && !visited[cy * cols + cx + 1] {
            next.push((cx + 1, cy));
        }
        if cy > 0 && !visited[(cy - 1) * cols + cx] {
            next.push((cx, cy - 1));
        }
        if cy + 1 < rows && !visited[(cy + 1) * cols + cx] {
            next.push((cx, cy + 1));
        }
        if next.is_empty() {
            stack.pop();
            continue;
        }
        let (nx, ny) = next[rng.random_range(0..next.len())];
        visited[ny * cols + nx] = true;
        open(&mut grid, 1 + nx * pitch, 1 + ny * pitch, c, c);
        // Knock down the wall between the two maze cells.
        let (x0, y0) = (1 + cx.min(nx) * pitch, 1 + cy.min(ny) * pitch);
        if nx != cx {
            open(&mut grid, x0 + c, y0, 1, c);
        } else {
            open(&mut grid, x0, y0 + c, c, 1);
        }
        stack.push((nx, ny));
    }
    Ok(grid)
}

/// Square rooms of `room` x `room` cells separated by one-cell walls. Every room is reachable:
/// the doors of a random spanning tree are always open, and each other wall gets a door with
/// probability one half. Doors are a random stretch of a quarter to a half of the wall.
pub fn rooms(width: usize, height: usize, room: u32, seed: u64) -> Result<Grid, GenerateError> {
    let mut grid = Grid::new(width, height)?;
    let pitch = room as usize + 1;
    let (cols, rows) = (width.div_ceil(pitch), height.div_ceil(pitch));
    if room < 2 || room as usize >= width.max(height) {
        return Err(GenerateError::Size { what: "room size", size: room, width, height });
    }
    let mut rng = rng(seed);
    // Inside the grid, whose sides fit a u32 (checked by `Grid::new`).
    let block = |grid: &mut Grid, x: usize, y: usize, blocked: bool| {
        if x < width && y < height {
            let _ = grid.set_blocked(Cell::new(x as u32, y as u32), blocked);
        }
    };
    // Walls on every multiple of the pitch (offset so that rooms start at 0).
    for y in 0..height {
        for x in 0..width {
            if x % pitch == room as usize || y % pitch == room as usize {
                block(&mut grid, x, y, true);
            }
        }
    }
    // Walls between rooms: (room index, vertical?) in a random order; a union-find spanning tree.
    let mut walls = Vec::new();
    for ry in 0..rows {
        for rx in 0..cols {
            if rx + 1 < cols {
                walls.push((rx, ry, true));
            }
            if ry + 1 < rows {
                walls.push((rx, ry, false));
            }
        }
    }
    walls.shuffle(&mut rng);
    let mut parent: Vec<usize> = (0..cols * rows).collect();
    fn find(parent: &mut [usize], mut i: usize) -> usize {
        while parent[i] != i {
            parent[i] = parent[parent[i]];
            i = parent[i];
        }
        i
    }
    for (rx, ry, vertical) in walls {
        let a = find(&mut parent, ry * cols + rx);
        let b = find(&mut parent, if vertical { ry * cols + rx + 1 } else { (ry + 1) * cols + rx });
        let tree = a != b;
        if tree {
            parent[a] = b;
        }
        if !tree && !rng.random_bool(0.5) {
            continue;
        }
        let r = room as usize;
        // The door runs along the part of the wall inside the grid (rooms on the far edges may
        // be cut short).
        let extent = if vertical { r.min(height - ry * pitch) } else { r.min(width - rx * pitch) };
        let len = rng.random_range((r / 4).max(1)..=(r / 2).max(1)).min(extent);
        let at = rng.random_range(0..=extent - len);
        for k in at..at + len {
            if vertical {
                block(&mut grid, rx * pitch + r, ry * pitch + k, false);
            } else {
                block(&mut grid, rx * pitch + k, ry * pitch + r, false);
            }
        }
    }
    Ok(grid)
}

/// A square world of side `size` with `count` random convex obstacles of `sides` vertices each
/// (at least 3), in the style of roadmap benchmarks: centres uniform in the square, radii
/// uniform in `[0.3, 1] x size / sqrt(count) / 2`, vertices at sorted random angles on that
/// circle. Obstacles may overlap; the free space merges them. The robot radius is
/// `robot_radius`.
///
/// At most [`MAX_POLYGON_SIDES`] sides and [`MAX_GENERATED_VERTICES`] vertices in all; an
/// obstacle whose angles come too close together is drawn again, up to 1000 times.
///
/// ```
/// use trailmark_core::generate;
///
/// let world = generate::convex_obstacles(100.0, 50, 6, 0.0, 7)?;
/// assert_eq!(world.obstacles().len(), 50);
/// assert!(world.obstacles().iter().all(|o| o.is_convex() && o.vertices().len() == 6));
/// assert_eq!(world, generate::convex_obstacles(100.0, 50, 6, 0.0, 7)?); // reproducible
/// # Ok::<(), trailmark_core::generate::GenerateError>(())
/// ```
pub fn convex_obstacles(
    size: f64,
    count: usize,
    sides: usize,
    robot_radius: f64,
    seed: u64,
) -> Result<crate::world::PolygonWorld, GenerateError> {
    use crate::geometry::Point;
    use crate::world::{Bounds, PolygonWorld};
    let bounds = Bounds::new(0.0, 0.0, size, size)?;
    if sides < 3 {
        return Err(GenerateError::Size {
            what: "polygon side count",
            size: sides as u32, // below 3
            width: 3,
            height: 3,
        });
    }
    if sides > MAX_POLYGON_SIDES {
        return Err(GenerateError::TooMany { what: "obstacle sides", count: sides, max: MAX_POLYGON_SIDES });
    }
    let vertices = count.saturating_mul(sides);
    if vertices > MAX_GENERATED_VERTICES {
        let what = "vertices (obstacles x sides)";
        return Err(GenerateError::TooMany { what, count: vertices, max: MAX_GENERATED_VERTICES });
    }
    let mut rng = rng(seed);
    let scale = size / (count.max(1) as f64).sqrt() / 2.0;
    let mut obstacles = Vec::with_capacity(count);
    let mut draws = 0;
    while obstacles.len() < count {
        if draws == MAX_DRAWS {
            return Err(GenerateError::Degenerate { sides, draws });
        }
        draws += 1;
        let centre = Point::new(rng.random_range(0.0..size), rng.random_range(0.0..size));
        let radius = scale * rng.random_range(0.3..1.0);
        let mut angles: Vec<f64> = (0..sides).map(|_| rng.random_range(0.0..std::f64::consts::TAU)).collect();
        angles.sort_by(f64::total_cmp);
        let polygon: Vec<Point> =
            angles.iter().map(|t| centre + radius * crate::geometry::Vector::new(t.cos(), t.sin())).collect();
        // Angles too close together give a degenerate polygon: draw again.
        if crate::world::Polygon::new(polygon.clone())
            .is_ok_and(|p| p.vertices().len() == sides && p.is_convex())
        {
            obstacles.push(polygon);
            draws = 0;
        }
    }
    Ok(PolygonWorld::new(bounds, obstacles, robot_radius)?)
}

/// The rectangle from `(x0, y0)` to `(x1, y1)`, counter-clockwise.
fn rectangle(x0: f64, y0: f64, x1: f64, y1: f64) -> Vec<crate::geometry::Point> {
    use crate::geometry::Point;
    vec![Point::new(x0, y0), Point::new(x1, y0), Point::new(x1, y1), Point::new(x0, y1)]
}

/// A square world of side `size` with a bug trap in the middle: a cup of three walls of
/// thickness `size / 40`, its inside `size / 2` wide and `size / 2` deep, open toward +x
/// through a mouth of width `size / 8` in the middle of its right wall, so a robot inside must
/// find the mouth (the classic trap of greedy and sampling planners). The trap's centre,
/// returned beside the world, is inside it.
///
/// ```
/// use trailmark_core::generate;
///
/// let (world, inside) = generate::bug_trap(40.0, 0.25)?;
/// let checker = world.checker();
/// assert!(checker.point_is_free(inside));
/// // The straight way out to the left is walled off.
/// assert!(!checker.segment_is_free(inside, trailmark_core::geometry::Point::new(2.0, 20.0)));
/// # Ok::<(), trailmark_core::generate::GenerateError>(())
/// ```
pub fn bug_trap(
    size: f64,
    robot_radius: f64,
) -> Result<(crate::world::PolygonWorld, crate::geometry::Point), GenerateError> {
    use crate::world::{Bounds, PolygonWorld};
    let bounds = Bounds::new(0.0, 0.0, size, size)?;
    let (t, c) = (size / 40.0, size / 2.0);
    let (lo, hi) = (c - size / 4.0, c + size / 4.0);
    let mouth = size / 16.0;
    let walls = vec![
        rectangle(lo - t, lo - t, hi + t, lo), // bottom
        rectangle(lo - t, hi, hi + t, hi + t), // top
        rectangle(lo - t, lo, lo, hi),         // left
        rectangle(hi, lo, hi + t, c - mouth),  // right, below the mouth
        rectangle(hi, c + mouth, hi + t, hi),  // right, above the mouth
    ];
    Ok((PolygonWorld::new(bounds, walls, robot_radius)?, crate::geometry::Point::new(c, c)))
}

/// A 30 x 30 world whose middle, a 10 x 10 square, is walled all round (walls 1 thick, no
/// door), for a robot of radius `robot_radius`; the point returned is its centre, which no path
/// from outside reaches: the problem a planner cannot solve, for tests of its limits.
///
/// ```
/// use trailmark_core::generate;
/// use trailmark_core::geometry::Point;
///
/// let (world, inside) = generate::walled_goal(0.2)?;
/// let checker = world.checker();
/// assert!(checker.point_is_free(inside) && checker.point_is_free(Point::new(2.0, 2.0)));
/// assert!(!checker.segment_is_free(inside, Point::new(2.0, 2.0)));
/// # Ok::<(), trailmark_core::generate::GenerateError>(())
/// ```
pub fn walled_goal(
    robot_radius: f64,
) -> Result<(crate::world::PolygonWorld, crate::geometry::Point), GenerateError> {
    use crate::world::{Bounds, PolygonWorld};
    let walls = vec![
        rectangle(10.0, 10.0, 20.0, 11.0),
        rectangle(10.0, 19.0, 20.0, 20.0),
        rectangle(10.0, 11.0, 11.0, 19.0),
        rectangle(19.0, 11.0, 20.0, 19.0),
    ];
    let world = PolygonWorld::new(Bounds::new(0.0, 0.0, 30.0, 30.0)?, walls, robot_radius)?;
    Ok((world, crate::geometry::Point::new(15.0, 15.0)))
}

/// A square world of side `size` cut by `walls` evenly spaced vertical walls (thickness
/// `size / 50`), each with one door of width `door` at a random height: every path from the
/// left edge to the right goes through every door. The robot radius is `robot_radius`, so the
/// free width of a door is `door - 2 robot_radius`. At most [`MAX_GENERATED_VERTICES`] / 8
/// walls (each is two rectangles).
///
/// ```
/// use trailmark_core::generate;
///
/// let world = generate::narrow_passages(40.0, 3, 1.0, 0.25, 7)?;
/// assert_eq!(world.obstacles().len(), 6); // two pieces per wall
/// assert_eq!(world, generate::narrow_passages(40.0, 3, 1.0, 0.25, 7)?); // reproducible
/// # Ok::<(), trailmark_core::generate::GenerateError>(())
/// ```
pub fn narrow_passages(
    size: f64,
    walls: usize,
    door: f64,
    robot_radius: f64,
    seed: u64,
) -> Result<crate::world::PolygonWorld, GenerateError> {
    use crate::world::{Bounds, PolygonWorld};
    let bounds = Bounds::new(0.0, 0.0, size, size)?;
    if !(door > 0.0 && door < size / 2.0) {
        return Err(GenerateError::Door { door, size });
    }
    if walls > MAX_GENERATED_VERTICES / 8 {
        return Err(GenerateError::TooMany { what: "walls", count: walls, max: MAX_GENERATED_VERTICES / 8 });
    }
    let mut rng = rng(seed);
    let t = size / 50.0;
    let mut obstacles = Vec::with_capacity(2 * walls);
    for i in 1..=walls {
        let x = size * i as f64 / (walls + 1) as f64 - t / 2.0;
        let y = rng.random_range(size / 8.0..size * 7.0 / 8.0 - door);
        obstacles.push(rectangle(x, 0.0, x + t, y));
        obstacles.push(rectangle(x, y + door, x + t, size));
    }
    Ok(PolygonWorld::new(bounds, obstacles, robot_radius)?)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The passable cells reachable from `from`, 4-connected, by flood fill.
    fn reachable(grid: &Grid, from: Cell) -> usize {
        let mut seen = vec![false; grid.len()];
        let mut stack = vec![from];
        let w = grid.width() as usize;
        let mut n = 0;
        while let Some(c) = stack.pop() {
            if !grid.is_passable(c) || std::mem::replace(&mut seen[c.y as usize * w + c.x as usize], true) {
                continue;
            }
            n += 1;
            for (dx, dy) in [(1i32, 0i32), (-1, 0), (0, 1), (0, -1)] {
                stack.push(Cell::new(c.x.wrapping_add_signed(dx), c.y.wrapping_add_signed(dy)));
            }
        }
        n
    }

    #[test]
    fn mazes_and_rooms_are_connected() {
        for seed in 0..5 {
            let m = maze(61, 40, 2, seed).unwrap();
            assert_eq!(reachable(&m, Cell::new(1, 1)), m.passable_count(), "maze seed {seed}");
            for (w, h) in [(70, 45), (72, 72), (73, 19), (9, 100)] {
                let r = rooms(w, h, 8, seed).unwrap();
                assert_eq!(reachable(&r, Cell::new(0, 0)), r.passable_count(), "rooms {w}x{h} seed {seed}");
            }
        }
    }

    #[test]
    fn a_lattice_is_its_rows() {
        let rows = [".....", ".@.@.", ".....", ".@.@.", "....."];
        assert_eq!(lattice(2).unwrap(), Grid::from_rows(&rows).unwrap());
        assert_eq!(lattice(50).unwrap().passable_count(), 101 * 101 - 2500);
        assert!(lattice(usize::MAX).is_err());
    }

    #[test]
    fn same_seed_same_grid() {
        assert_eq!(random(30, 20, 0.3, 9).unwrap(), random(30, 20, 0.3, 9).unwrap());
        assert_ne!(random(30, 20, 0.3, 9).unwrap(), random(30, 20, 0.3, 10).unwrap());
        let density = random(200, 200, 0.25, 1).unwrap().passable_count() as f64 / 40000.0;
        assert!((density - 0.75).abs() < 0.02, "{density}");
    }

    #[test]
    fn bad_arguments_are_errors() {
        assert_eq!(random(3, 3, 1.5, 0), Err(GenerateError::Fraction(1.5)));
        assert!(random(3, 3, f64::NAN, 0).is_err());
        assert!(matches!(maze(10, 10, 0, 0), Err(GenerateError::Size { .. })));
        assert!(matches!(maze(3, 3, 4, 0), Err(GenerateError::Size { .. })));
        assert!(matches!(rooms(10, 10, 1, 0), Err(GenerateError::Size { .. })));
        assert!(matches!(random(0, 3, 0.1, 0), Err(GenerateError::Grid(_))));
        assert!(matches!(
            random(usize::MAX, 2, 0.1, 0),
            Err(GenerateError::Grid(GridError::TooLarge { .. }))
        ));
        assert!(matches!(maze(1 << 15, 1 << 14, 3, 0), Err(GenerateError::Grid(GridError::TooLarge { .. }))));
        assert!(matches!(
            rooms(1 << 15, 1 << 14, 8, 0),
            Err(GenerateError::Grid(GridError::TooLarge { .. }))
        ));
        let too_many = |r| matches!(r, Err(GenerateError::TooMany { .. }));
        assert!(too_many(convex_obstacles(10.0, usize::MAX, 6, 0.0, 0)));
        assert!(too_many(convex_obstacles(10.0, 2, usize::MAX, 0.0, 0)));
        assert!(too_many(convex_obstacles(10.0, 1 << 14, 6, 0.0, 0)));
        assert!(too_many(narrow_passages(10.0, usize::MAX, 1.0, 0.0, 0)));
        assert!(matches!(narrow_passages(10.0, 2, 5.0, 0.0, 0), Err(GenerateError::Door { .. })));
    }
}
