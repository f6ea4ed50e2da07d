//! Seeded terrains with rivers, bridges, fords and forests.
//!
//! Rivers run from the top edge to the bottom edge, meandering; each has bridges (choke points,
//! each with its own probability of being closed) and, optionally, a ford far from the bridges
//! that is always open but slow. Forests are patches of slow terrain; a road may run through a
//! forest (a choke point: a fallen tree closes it, and the way around is through the trees).
//! The start is near the left edge, the goal near the right edge, so every route crosses every
//! river. The same seed gives the same terrain.
//!
//! ```
//! use trailmark_contingency::generate::{RiverOptions, river_terrain};
//!
//! let terrain = river_terrain(7, &RiverOptions::default())?;
//! assert_eq!(terrain.choke_points().len(), 2 * 3 + 1); // two rivers of three bridges, one road
//! assert_eq!(terrain.grid().width(), 64);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use serde::{Deserialize, Serialize};

use trailmark_core::cost::Cost;
use trailmark_core::grid::{Cell, Connectivity, Grid, is_cell_cost};

use crate::terrain::{ChokePoint, MAX_CHOKE_POINTS, Terrain, TerrainError};

/// The most forest patches a generated terrain may have: 64. Each patch costs time in
/// proportion to its area, up to a quarter of the grid; more patches than this only cover the
/// same ground again.
pub const MAX_FORESTS: u32 = 64;

/// The shape of a generated terrain.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct RiverOptions {
    /// Columns.
    pub width: u32,
    /// Rows.
    pub height: u32,
    /// Rivers, from the top edge to the bottom edge.
    pub rivers: u32,
    /// Width of a river, in cells.
    pub river_width: u32,
    /// Bridges per river (choke points).
    pub bridges: u32,
    /// Whether each river has a ford: always open, costing `ford_cost` per unit length.
    pub fords: bool,
    /// The cost of wading through a ford.
    pub ford_cost: Cost,
    /// Forest patches.
    pub forests: u32,
    /// The cost of driving through forest.
    pub forest_cost: Cost,
    /// Forests with a road through them (a choke point), at most `forests`.
    pub roads: u32,
    /// The range the probability of each choke point being blocked is drawn from.
    pub probability: (f64, f64),
}

impl Default for RiverOptions {
    fn default() -> Self {
        RiverOptions {
            width: 64,
            height: 48,
            rivers: 2,
            river_width: 3,
            bridges: 3,
            fords: true,
            ford_cost: 6.0,
            forests: 3,
            forest_cost: 3.0,
            roads: 1,
            probability: (0.1, 0.6),
        }
    }
}

/// Generates a terrain from `seed`. Options out of range give a [`TerrainError`], checked
/// before anything is allocated: a size beyond [`Grid::MAX_CELLS`] cells
/// ([`TerrainError::Grid`]), more choke points (bridges and roads) than [`MAX_CHOKE_POINTS`]
/// ([`TerrainError::TooManyChokePoints`]), more than [`MAX_FORESTS`] forests, no room for the
/// rivers or bridges, a probability range outside `[0, 1]`, a cost that is not a valid cell
/// cost (positive, at most [`trailmark_core::grid::MAX_CELL_COST`]).
pub fn river_terrain(seed: u64, options: &RiverOptions) -> Result<Terrain, TerrainError> {
    let o = options;
    let bad = |what: &str| Err(TerrainError::Spec(format!("river terrain: {what}")));
    let (lo, hi) = o.probability;
    if !(0.0..=1.0).contains(&lo) || !(lo..=1.0).contains(&hi) {
        return bad("the probability range must lie in [0, 1], low first");
    }
    let (w, h) = (o.width as usize, o.height as usize);
    let cells = Grid::cell_count(w, h)?;
    let chokes = u64::from(o.rivers) * u64::from(o.bridges) + u64::from(o.roads.min(o.forests));
    if chokes > MAX_CHOKE_POINTS as u64 {
        return Err(TerrainError::TooManyChokePoints {
            count: usize::try_from(chokes).unwrap_or(usize::MAX),
        });
    }
    if o.forests > MAX_FORESTS {
        return bad(&format!("more forests than the {MAX_FORESTS} supported"));
    }
    let spacing = w / (o.rivers as usize + 1);
    if o.river_width == 0 || spacing < (o.river_width as usize).saturating_mul(2).saturating_add(6) || h < 8 {
        return bad("too narrow for the rivers (or a river width of 0, or fewer than 8 rows)");
    }
    if u64::from(o.bridges) * 3 + 4 > h as u64 {
        return bad("too few rows for the bridges");
    }
    if !(is_cell_cost(o.ford_cost)
        && o.ford_cost.is_finite()
        && is_cell_cost(o.forest_cost)
        && o.forest_cost.is_finite())
    {
        return bad("ford and forest costs must be positive and at most 1e12");
    }
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut costs = vec![1.0; cells];
    let at = |x: usize, y: usize| y * w + x;
    let mut chokes = Vec::new();
    let draw = |rng: &mut ChaCha8Rng| if hi > lo { rng.random_range(lo..hi) } else { lo };

    // Forests first, so that rivers cut through them.
    let mut forest_centres = Vec::new();
    for _ in 0..o.forests {
        let (cx, cy) = (rng.random_range(0..w) as f64, rng.random_range(0..h) as f64);
        let (rx, ry) = (
            rng.random_range(3.0..(spacing as f64 / 2.0).max(3.5)),
            rng.random_range(3.0..(h as f64 / 4.0).max(3.5)),
        );
        // The cells of the ellipse lie in its bounding box (cx, cy are whole numbers).
        let (x0, x1) = ((cx - rx.ceil()).max(0.0) as usize, ((cx + rx.ceil()) as usize).min(w - 1));
        let (y0, y1) = ((cy - ry.ceil()).max(0.0) as usize, ((cy + ry.ceil()) as usize).min(h - 1));
        for y in y0..=y1 {
            for x in x0..=x1 {
                let (dx, dy) = ((x as f64 - cx) / rx, (y as f64 - cy) / ry);
                if dx * dx + dy * dy <= 1.0 {
                    costs[at(x, y)] = o.forest_cost;
                }
            }
        }
        forest_centres.push((cx as usize, cy as usize, rx as usize));
    }

    // Rivers: a meandering band of water from top to bottom.
    let mut banks = Vec::new();
    for r in 0..o.rivers as usize {
        let base = (r + 1) * spacing;
        let swing = (spacing / 4).max(1) as i64;
        let mut offset = 0i64;
        let mut left = Vec::with_capacity(h);
        for y in 0..h {
            if y > 0 && rng.random_bool(0.35) {
                offset = (offset + if rng.random_bool(0.5) { 1 } else { -1 }).clamp(-swing, swing);
            }
            let x0 = (base as i64 + offset) as usize;
            for x in x0..x0 + o.river_width as usize {
                costs[at(x, y)] = f64::INFINITY;
            }
            left.push(x0);
        }
        banks.push(left);
    }

    // Fords and bridges: rows across each river, spread out.
    for (r, left) in banks.iter().enumerate() {
        let mut rows: Vec<usize> = Vec::new();
        let ford = o.fords.then(|| if rng.random_bool(0.5) { 1 } else { h - 2 });
        let mut tries = 0;
        while rows.len() < o.bridges as usize && tries < 10_000 {
            tries += 1;
            let y = rng.random_range(2..h - 2);
            if rows.iter().chain(ford.as_ref()).all(|&other| other.abs_diff(y) >= 3) {
                rows.push(y);
            }
        }
        if rows.len() < o.bridges as usize {
            return bad("could not place the bridges");
        }
        rows.sort_unstable();
        if let Some(y) = ford {
            for x in left[y]..left[y] + o.river_width as usize {
                costs[at(x, y)] = o.ford_cost;
            }
        }
        for (b, &y) in rows.iter().enumerate() {
            let cells: Vec<Cell> =
                (left[y]..left[y] + o.river_width as usize).map(|x| Cell::new(x as u32, y as u32)).collect();
            for c in &cells {
                costs[at(c.x as usize, c.y as usize)] = 1.0;
            }
            chokes.push(ChokePoint {
                name: format!("river {} bridge {}", r + 1, b + 1),
                cells,
                probability: draw(&mut rng),
            });
        }
    }

    // Roads through forests: a short run of ordinary cells across the forest's middle row, clear of
    // water and of other choke points by one cell.
    let mut roads = 0;
    for &(cx, cy, rx) in &forest_centres {
        if roads == o.roads {
            break;
        }
        let (from, to) = (cx.saturating_sub(rx / 2).max(1), (cx + rx / 2).min(w - 2));
        let clear = |x: usize, y: usize| {
            (y.saturating_sub(1)..=(y + 1).min(h - 1))
                .all(|yy| (x - 1..=x + 1).all(|xx| costs[at(xx, yy)] == o.forest_cost))
        };
        if cy == 0 || cy >= h - 1 || to < from + 2 || !(from..=to).all(|x| clear(x, cy)) {
            continue;
        }
        let cells: Vec<Cell> = (from..=to).map(|x| Cell::new(x as u32, cy as u32)).collect();
        for c in &cells {
            costs[at(c.x as usize, c.y as usize)] = 1.0;
        }
        roads += 1;
        chokes.push(ChokePoint { name: format!("forest road {roads}"), cells, probability: draw(&mut rng) });
    }

    // Start and goal: passable cells near the left and right edges, outside every choke point.
    let in_choke = |c: &Cell| chokes.iter().any(|k: &ChokePoint| k.cells.contains(c));
    let open = |c: &Cell| costs[at(c.x as usize, c.y as usize)] == 1.0 && !in_choke(c);
    // A random open cell of the edge column; when a forest covers that column, the first open
    // cell of the columns further in (up to a quarter of the width), scanned.
    let pick = |rng: &mut ChaCha8Rng, x: usize, inward: isize| -> Option<Cell> {
        (0..100).map(|_| Cell::new(x as u32, rng.random_range(0..h) as u32)).find(|c| open(c)).or_else(|| {
            (0..=(w / 4) as isize)
                .map(|k| (x as isize + k * inward) as u32)
                .flat_map(|x| (0..h as u32).map(move |y| Cell::new(x, y)))
                .find(|c| open(c))
        })
    };
    let (Some(start), Some(goal)) = (pick(&mut rng, 1, 1), pick(&mut rng, w - 2, -1)) else {
        return bad("no open cell for the start or the goal");
    };
    let grid = Grid::from_costs(w, h, costs)?;
    Terrain::new(grid, Connectivity::Eight, start, goal, chokes)
}
