//! Robot maps: the maps ROS saves (map_server's YAML + PGM/PNG, `nav_msgs/OccupancyGrid`),
//! their frame in metres, and costmaps with Nav2's values and inflation, ready for every grid
//! planner of trailmark.
//!
//! ```
//! use trailmark_core::geometry::Point;
//! use trailmark_map::{Costmap, CostmapOptions, Footprint, Inflation, MapMetadata, TravelCost, decode_map};
//!
//! // A map as map_server saves it: the YAML fields and a PGM (254 free, 0 occupied, 205 unknown).
//! let meta = MapMetadata::parse("image: tiny.pgm\nresolution: 0.1\norigin: [-0.2, -0.1, 0]\n\
//!     negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n")?;
//! let pgm = b"P2\n# a comment\n4 2\n255\n254 254 0 205\n254 254 254 254\n";
//! let map = decode_map(&meta, pgm, "tiny.pgm".as_ref())?;
//! let counts = map.counts();
//! assert_eq!((counts.free, counts.occupied, counts.unknown), (6, 1, 1));
//!
//! // Metres to cells: the origin is the lower-left corner, y up.
//! let frame = map.frame();
//! let cell = frame.cell_at(Point::new(0.05, 0.05))?;
//! assert_eq!(map.value(cell), Some(100));
//!
//! // A costmap around a robot of radius 0.1 m, and the grid the planners search.
//! let settings = CostmapOptions {
//!     inflation: Some(Inflation::around(&Footprint::Radius(0.1))?),
//!     ..CostmapOptions::default()
//! };
//! let costmap = Costmap::from_occupancy(&map, &settings)?;
//! assert_eq!(costmap.cost(cell), Some(254));
//! let grid = costmap.to_grid(&TravelCost::default())?;
//! assert!(grid.passable_count() < 6);
//! # Ok::<(), trailmark_map::MapError>(())
//! ```

#![deny(missing_docs)]

// One documented path per item: everything is named from the crate root.
mod clearance;
mod costmap;
mod distance;
mod error;
mod files;
mod frame;
mod inflation;
mod message;
mod metadata;
mod occupancy;
mod picture;
mod pixels;
mod values;

pub use clearance::CostmapClearance;
pub use costmap::{Costmap, CostmapOptions, TravelCost, Unknown};
/// Old name of [`CostmapOptions`], kept for one release.
#[deprecated(since = "0.3.0", note = "use trailmark_map::CostmapOptions")]
pub type CostmapSettings = CostmapOptions;
pub use distance::{NO_SOURCE, squared_distances};
pub use error::MapError;
pub use files::{
    LoadedMap, MAX_IMAGE_BYTES, MAX_YAML_BYTES, SaveOptions, decode_map, encode_map, load_map, load_map_file,
    save_map,
};
pub use frame::{MAX_IMAGE_SIDE, MAX_MAP_CELLS, MAX_RESOLUTION, MIN_RELATIVE_RESOLUTION, MapFrame};
pub use inflation::Inflation;
pub use message::MAX_MESSAGE_BYTES;
pub use metadata::{MapMetadata, MapMode};
pub use occupancy::{FREE, OCCUPIED, OccupancyCounts, OccupancyGrid, UNKNOWN};
pub use picture::{CostmapSvg, cost_colour};
pub use trailmark_core::footprint::Footprint;
pub use values::{FREE_SPACE, INSCRIBED, LETHAL, MAX_NON_OBSTACLE, NO_INFORMATION};
