//! Occupancy grids as ROS keeps them: a value per cell, -1 unknown, 0 free to 100 occupied,
//! with the map frame that puts the cells in metres.

use trailmark_core::grid::{Cell, Grid};

use crate::error::MapError;
use crate::frame::MapFrame;

/// The value of an unknown cell.
pub const UNKNOWN: i8 = -1;
/// The value of a free cell.
pub const FREE: i8 = 0;
/// The value of an occupied cell.
pub const OCCUPIED: i8 = 100;

/// A map of occupancy values (-1 unknown, 0..=100 the probability of being occupied, in
/// percent) over a [`MapFrame`].
///
/// Cells are addressed as everywhere in trailmark, `(0, 0)` the top-left cell; the frame turns
/// them into metres. (A `nav_msgs/OccupancyGrid` message keeps its rows the other way up, from
/// the origin's row; [`OccupancyGrid::from_message_json`] and [`OccupancyGrid::to_message_json`]
/// convert.)
#[derive(Debug, Clone, PartialEq)]
pub struct OccupancyGrid {
    frame: MapFrame,
    /// Row-major values, row 0 at the top of the map.
    values: Vec<i8>,
}

/// How many cells of a map are free (0), occupied (100) and unknown (-1), and how many hold a
/// value in between.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct OccupancyCounts {
    /// Cells of value 0.
    pub free: usize,
    /// Cells of value 100.
    pub occupied: usize,
    /// Cells of value -1.
    pub unknown: usize,
    /// Cells of a value in 1..=99.
    pub between: usize,
}

impl OccupancyGrid {
    /// A map from its frame and its row-major values, row 0 at the top. Every value must be -1
    /// or in 0..=100 ([`MapError::Occupancy`]), and there must be one per cell
    /// ([`MapError::CellCount`]).
    pub fn new(frame: MapFrame, values: Vec<i8>) -> Result<Self, MapError> {
        frame.check_count(values.len())?;
        if let Some(index) = values.iter().position(|&v| !(-1..=100).contains(&v)) {
            return Err(MapError::Occupancy { index, value: i64::from(values[index]) });
        }
        Ok(OccupancyGrid { frame, values })
    }

    /// The frame: size, resolution, origin.
    pub fn frame(&self) -> &MapFrame {
        &self.frame
    }

    /// Row-major values, row 0 at the top of the map.
    pub fn values(&self) -> &[i8] {
        &self.values
    }

    /// The value of `cell`, or `None` outside the map.
    pub fn value(&self, cell: Cell) -> Option<i8> {
        self.frame.index_of(cell).map(|i| self.values[i])
    }

    /// How many cells are free, occupied, unknown and in between.
    pub fn counts(&self) -> OccupancyCounts {
        let mut counts = OccupancyCounts::default();
        for &v in &self.values {
            match v {
                FREE => counts.free += 1,
                OCCUPIED => counts.occupied += 1,
                UNKNOWN => counts.unknown += 1,
                _ => counts.between += 1,
            }
        }
        counts
    }

    /// An occupancy grid as a trailmark [`Grid`]: cells below `occupied_at` are passable (cost
    /// 1), the others blocked, and unknown cells passable when `unknown_free`.
    ///
    /// For costs that keep a robot clear of walls, make a [`crate::Costmap`] instead.
    pub fn to_grid(&self, occupied_at: i8, unknown_free: bool) -> Grid {
        let costs = self
            .values
            .iter()
            .map(|&v| {
                let free = if v == UNKNOWN { unknown_free } else { v < occupied_at };
                if free { 1.0 } else { f64::INFINITY }
            })
            .collect();
        let (w, h) = (self.frame.width() as usize, self.frame.height() as usize);
        Grid::from_costs(w, h, costs)
            .expect("a frame's size is a valid grid size, and 1 and inf are cell costs")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn values_are_checked() {
        let frame = MapFrame::new(2, 2, 0.1, [0.0; 3]).unwrap();
        assert!(matches!(OccupancyGrid::new(frame, vec![0; 3]), Err(MapError::CellCount { found: 3, .. })));
        assert!(matches!(
            OccupancyGrid::new(frame, vec![0, 101, 0, 0]),
            Err(MapError::Occupancy { index: 1, value: 101 })
        ));
        assert!(matches!(
            OccupancyGrid::new(frame, vec![0, 0, -2, 0]),
            Err(MapError::Occupancy { index: 2, .. })
        ));
        let map = OccupancyGrid::new(frame, vec![0, 100, -1, 50]).unwrap();
        let counts = map.counts();
        assert_eq!((counts.free, counts.occupied, counts.unknown, counts.between), (1, 1, 1, 1));
        assert_eq!(map.value(Cell::new(1, 1)), Some(50));
        assert_eq!(map.value(Cell::new(2, 0)), None);
        let grid = map.to_grid(50, true);
        assert_eq!(grid.passable_count(), 2);
    }
}
