//! The inflation layer, with Nav2's conventions: the robot's inscribed radius around every
//! lethal cell is `253` (the robot's centre there means a collision), and beyond it the cost
//! falls off as `252 * exp(-cost_scaling_factor * (d - inscribed_radius))` up to the
//! inflation radius.
//!
//! Distances are between cell centres, to the nearest lethal cell, exact (a Euclidean distance
//! transform, [`crate::squared_distances`]); Nav2 finds them with a brushfire from the
//! obstacles, which is exact in most cells and an estimate in some.

use serde::{Deserialize, Serialize};
use trailmark_core::footprint::{Footprint, FootprintError};

use crate::error::MapError;
use crate::values::{INSCRIBED, LETHAL, MAX_NON_OBSTACLE};

/// How far costs spread from lethal cells.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Inflation {
    /// Metres from a lethal cell within which the robot's centre means a collision (cost 253).
    pub inscribed_radius: f64,
    /// Metres from a lethal cell up to which cells get a cost (Nav2's `inflation_radius`).
    /// Cells within the inscribed radius are inscribed whatever this says: an inflation
    /// radius smaller than the inscribed radius inflates to the inscribed radius.
    pub inflation_radius: f64,
    /// How fast the cost falls off beyond the inscribed radius, per metre (Nav2's
    /// `cost_scaling_factor`).
    pub cost_scaling_factor: f64,
}

impl Inflation {
    /// Nav2's defaults around a robot: inflation radius 0.55 m, cost scaling factor 10.
    pub fn around(footprint: &Footprint) -> Result<Self, MapError> {
        let inflation = Inflation {
            inscribed_radius: footprint.inscribed_radius().map_err(|e| match e {
                FootprintError::Radius(r) => MapError::Setting {
                    setting: "robot_radius",
                    expected: "finite and not negative",
                    value: r,
                },
                // A polygon's radius is a distance, never refused.
                other => MapError::Footprint(other),
            })?,
            inflation_radius: 0.55,
            cost_scaling_factor: 10.0,
        };
        inflation.check()?;
        Ok(inflation)
    }

    /// Checks that the radii and the factor are finite and not negative.
    pub fn check(&self) -> Result<(), MapError> {
        non_negative("inscribed_radius", self.inscribed_radius)?;
        non_negative("inflation_radius", self.inflation_radius)?;
        non_negative("cost_scaling_factor", self.cost_scaling_factor)?;
        Ok(())
    }

    /// The cost of a cell `cells` cell-lengths (centre to centre) from the nearest lethal cell
    /// on a map of `resolution` metres per cell: Nav2's `computeCost`. 254 at distance 0, 253
    /// within the inscribed radius, `252 * exp(-k (d - r))` truncated beyond it, 0 beyond
    /// [`Inflation::cell_radius`].
    pub fn cost(&self, cells: f64, resolution: f64) -> u8 {
        if cells == 0.0 {
            return LETHAL;
        }
        if cells > self.cell_radius(resolution) {
            return 0;
        }
        let metres = cells * resolution;
        if metres <= self.inscribed_radius {
            INSCRIBED
        } else {
            let factor = (-self.cost_scaling_factor * (metres - self.inscribed_radius)).exp();
            // In [0, 252]: factor is in (0, 1].
            (f64::from(MAX_NON_OBSTACLE) * factor) as u8
        }
    }

    /// How far costs spread in cells, as Nav2 rounds it: `ceil(radius / resolution)`, the
    /// radius the inflation radius or, when that is smaller, the inscribed radius. Nav2 stops
    /// at the inflation radius and warns; cells within the inscribed radius left free let a
    /// planner pass a gap narrower than the robot.
    pub fn cell_radius(&self, resolution: f64) -> f64 {
        (self.inflation_radius.max(self.inscribed_radius) / resolution).ceil().max(0.0)
    }
}

fn non_negative(setting: &'static str, value: f64) -> Result<f64, MapError> {
    if value.is_finite() && value >= 0.0 {
        Ok(value)
    } else {
        Err(MapError::Setting { setting, expected: "a finite number of at least 0", value })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nav2_cost_curve() {
        let inflation =
            Inflation { inscribed_radius: 0.2, inflation_radius: 0.55, cost_scaling_factor: 10.0 };
        let res = 0.05;
        assert_eq!(inflation.cost(0.0, res), 254);
        assert_eq!(inflation.cost(4.0, res), 253); // 0.2 m: on the inscribed radius
        // 0.25 m: 252 * exp(-10 * 0.05) = 152.8..., truncated.
        assert_eq!(inflation.cost(5.0, res), 152);
        assert_eq!(inflation.cost(inflation.cell_radius(res) + 0.01, res), 0);
    }

    #[test]
    fn cells_within_the_inscribed_radius_are_inscribed_whatever_the_inflation_radius() {
        let res = 0.05;
        for inflation_radius in [0.0, 0.05, 0.1, 0.19] {
            let inflation = Inflation { inscribed_radius: 0.2, inflation_radius, cost_scaling_factor: 10.0 };
            for cells in 1..=4 {
                assert_eq!(inflation.cost(f64::from(cells), res), INSCRIBED, "{inflation_radius} at {cells}");
            }
            assert_eq!(inflation.cost(5.0, res), 0, "{inflation_radius}: nothing beyond both radii");
        }
    }

    #[test]
    fn inscribed_radius_of_a_footprint() {
        let corners = [[-0.3, -0.2], [0.5, -0.2], [0.5, 0.2], [-0.3, 0.2]];
        let corners = corners.iter().map(|p| trailmark_core::geometry::Point::new(p[0], p[1])).collect();
        let rectangle = Footprint::Polygon(trailmark_core::world::Polygon::new(corners).unwrap());
        assert!((rectangle.inscribed_radius().unwrap() - 0.2).abs() < 1e-12);
        assert_eq!(Footprint::Radius(0.22).inscribed_radius().unwrap(), 0.22);
        assert!(Footprint::Radius(-1.0).inscribed_radius().is_err());
    }
}
