//! Inflation against distances measured here cell by cell: whatever the inflation radius, every
//! cell whose centre lies within the robot's inscribed radius of a lethal cell's centre is
//! inscribed (or lethal), and no cell beyond both radii gets a cost.

use proptest::prelude::*;
use trailmark_map::{Costmap, INSCRIBED, Inflation, LETHAL, MapFrame};

proptest! {
    #![proptest_config(ProptestConfig::with_cases(96))]

    #[test]
    fn the_inscribed_band_holds_whatever_the_inflation_radius(
        w in 1usize..24,
        h in 1usize..24,
        lethal in prop::collection::vec(any::<bool>(), 576),
        share in 1u8..12,
        cells in (1u32..40, 0u32..60, 1u32..8),
    ) {
        let (resolution, inscribed_cells, inflation_cells) = (0.05 * f64::from(cells.2), cells.0, cells.1);
        let inscribed_radius = f64::from(inscribed_cells) * 0.0137;
        let inflation_radius = f64::from(inflation_cells) * 0.0137;
        // About one cell in `share` lethal.
        let costs: Vec<u8> = (0..w * h)
            .map(|i| if lethal[i] && i % usize::from(share) == 0 { LETHAL } else { 0 })
            .collect();
        let mut costmap = Costmap::new(MapFrame::new(w, h, resolution, [0.0; 3]).unwrap(), costs.clone()).unwrap();
        let inflation = Inflation { inscribed_radius, inflation_radius, cost_scaling_factor: 10.0 };
        costmap.inflate(&inflation).unwrap();
        let reach = inscribed_radius.max(inflation_radius);
        for i in 0..w * h {
            let (x, y) = ((i % w) as f64, (i / w) as f64);
            let nearest = (0..w * h)
                .filter(|&j| costs[j] == LETHAL)
                .map(|j| ((j % w) as f64 - x).hypot((j / w) as f64 - y) * resolution)
                .fold(f64::INFINITY, f64::min);
            let cost = costmap.costs()[i];
            if nearest <= inscribed_radius * (1.0 - 1e-9) {
                prop_assert!(cost >= INSCRIBED, "cell {i} {nearest} m from a wall with a robot of {inscribed_radius} m: {cost}");
            }
            if nearest > reach + resolution {
                prop_assert_eq!(cost, 0, "cell {} is {} m from a wall, beyond {} m", i, nearest, reach);
            }
        }
    }
}
