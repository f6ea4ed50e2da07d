//! What can be wrong with a map, its files, its frame or a costmap's settings.

use std::path::PathBuf;

use thiserror::Error;
use trailmark_core::grid::GridError;
use trailmark_core::read::ReadFileError;

/// What was wrong with a map or with what was asked of it.
#[derive(Debug, Error)]
pub enum MapError {
    /// A file could not be read (missing, not a regular file, too large, not UTF-8).
    #[error(transparent)]
    Read(#[from] ReadFileError),
    /// A file could not be written.
    #[error("cannot write {}: {source}", path.display())]
    Write {
        /// The file.
        path: PathBuf,
        /// The I/O error.
        source: std::io::Error,
    },
    /// The map's YAML file is not YAML, not a mapping, or uses what map files never do
    /// (anchors, aliases, deep nesting).
    #[error("the map YAML is malformed: {reason}")]
    Yaml {
        /// What the parser said.
        reason: String,
    },
    /// A field of the map's YAML file is missing.
    #[error("the map YAML has no `{field}`")]
    MissingField {
        /// The field.
        field: &'static str,
    },
    /// A field of the map's YAML file has the wrong type or an impossible value.
    #[error("the map YAML's `{field}` is invalid: {reason}")]
    InvalidField {
        /// The field.
        field: &'static str,
        /// Why.
        reason: String,
    },
    /// The thresholds are not `0 <= free_thresh < occupied_thresh <= 1`.
    #[error(
        "thresholds must satisfy 0 <= free_thresh < occupied_thresh <= 1, got free_thresh {free} and occupied_thresh {occupied}"
    )]
    Thresholds {
        /// `free_thresh`.
        free: f64,
        /// `occupied_thresh`.
        occupied: f64,
    },
    /// The resolution is not a positive finite number of metres per cell of at most
    /// [`crate::MAX_RESOLUTION`].
    #[error(
        "the map's `resolution` must be a positive number of metres per cell, at most 1e4, got {resolution:?}"
    )]
    Resolution {
        /// The resolution given.
        resolution: f64,
    },
    /// The origin is not finite, or its x or y is beyond
    /// [`MAX_COORDINATE`](trailmark_core::world::MAX_COORDINATE) in magnitude.
    #[error(
        "the map's `origin` must be finite metres and radians, x and y within +-{max:e} m, got [{x:?}, {y:?}, {yaw:?}]",
        max = trailmark_core::world::MAX_COORDINATE
    )]
    Origin {
        /// x in metres.
        x: f64,
        /// y in metres.
        y: f64,
        /// yaw in radians.
        yaw: f64,
    },
    /// A corner of the map lies beyond [`MAX_COORDINATE`](trailmark_core::world::MAX_COORDINATE)
    /// in x or y, or its cells are smaller than [`crate::MIN_RELATIVE_RESOLUTION`] times the
    /// largest coordinate it reaches (too fine for `f64` to tell points apart there).
    #[error(
        "a map of {width} x {height} cells of `resolution` {resolution:?} m at `origin` [{:?}, {:?}, {:?}] must have its corners within +-{max:e} m and cells of at least {rel:e} times its largest coordinate",
        origin[0], origin[1], origin[2], max = trailmark_core::world::MAX_COORDINATE, rel = 1e-9
    )]
    Extent {
        /// `[x, y, yaw]` of the lower-left corner.
        origin: [f64; 3],
        /// Width in cells.
        width: u32,
        /// Height in cells.
        height: u32,
        /// Metres per cell.
        resolution: f64,
    },
    /// The image could not be decoded (unknown format, truncated, corrupt).
    #[error("cannot decode the map image {}: {reason}", path.display())]
    Image {
        /// The image file (empty when decoded from memory).
        path: PathBuf,
        /// What the decoder said.
        reason: String,
    },
    /// The image is in a format map files are not read in: map images are PGM (P2, P5) or PNG.
    #[error("the map image {} is {format}, not PGM (P2, P5) or PNG", path.display())]
    ImageFormat {
        /// The image file (as named to [`crate::decode_map`] when decoded from memory).
        path: PathBuf,
        /// What it is instead: `"PPM (P6)"`, `"PBM (P1)"`, ... or what it starts with.
        format: String,
    },
    /// A pixel of a PGM image holds a sample above the maxval its header gives (which would
    /// read as white). Pixels are numbered as in the image, `(0, 0)` the top-left.
    #[error(
        "pixel ({x}, {y}) of the map image {} is {value}, above the maxval {maxval} its header gives",
        path.display()
    )]
    PixelAboveMaxval {
        /// The image file (as named to [`crate::decode_map`] when decoded from memory).
        path: PathBuf,
        /// The pixel's column, from the left.
        x: u32,
        /// The pixel's row, from the top.
        y: u32,
        /// Its sample.
        value: u32,
        /// The header's maxval.
        maxval: u32,
    },
    /// A pixel of a palette PNG holds an index past the last entry of the palette (which would
    /// read as black). Pixels are numbered as in the image, `(0, 0)` the top-left.
    #[error(
        "pixel ({x}, {y}) of the map image {} is palette index {index}, but the palette has {entries} entries",
        path.display()
    )]
    PixelOutsidePalette {
        /// The image file (as named to [`crate::decode_map`] when decoded from memory).
        path: PathBuf,
        /// The pixel's column, from the left.
        x: u32,
        /// The pixel's row, from the top.
        y: u32,
        /// Its index.
        index: u32,
        /// How many colours the palette has.
        entries: u32,
    },
    /// The map cannot be saved as asked (no shade reads back as each kind of cell under the
    /// thresholds, or the encoder failed).
    #[error("cannot save the map: {reason}")]
    Save {
        /// Why.
        reason: String,
    },
    /// The map has more than [`crate::MAX_MAP_CELLS`] cells or a side longer than
    /// [`crate::MAX_IMAGE_SIDE`] (a map file's image is refused from its header).
    #[error("a map of {width} x {height} cells is too large: at most 67108864 cells and 32768 a side")]
    TooLarge {
        /// Width in cells (the image's pixels).
        width: u64,
        /// Height in cells.
        height: u64,
    },
    /// The grid's size is wrong (empty, too large) or does not match its data.
    #[error(transparent)]
    Grid(#[from] GridError),
    /// The occupancy data has the wrong number of cells.
    #[error("expected {expected} cells ({width} x {height}), got {found}")]
    CellCount {
        /// The width.
        width: u64,
        /// The height.
        height: u64,
        /// `width x height`.
        expected: u64,
        /// The number of values given.
        found: usize,
    },
    /// An occupancy value is outside -1 (unknown) ..= 100 (occupied).
    #[error("occupancy value {value} at data index {index} is outside -1..=100")]
    Occupancy {
        /// The index in the data.
        index: usize,
        /// The value.
        value: i64,
    },
    /// An `nav_msgs/OccupancyGrid` message is malformed.
    #[error("the OccupancyGrid message is malformed: {reason}")]
    Message {
        /// What was wrong.
        reason: String,
    },
    /// The origin's orientation is not a rotation about z (the map is not level).
    #[error("the origin's orientation is not a rotation about the z axis: quaternion {quaternion:?}")]
    NotLevel {
        /// `[x, y, z, w]`.
        quaternion: [f64; 4],
    },
    /// A point in metres lies outside the map.
    #[error("the point ({x}, {y}) m lies outside the map")]
    OutsideMap {
        /// x in metres.
        x: f64,
        /// y in metres.
        y: f64,
    },
    /// A setting of the robot or of the inflation is not a finite, non-negative number (or is
    /// out of its range).
    #[error("{setting} must be {expected}, got {value}")]
    Setting {
        /// The setting.
        setting: &'static str,
        /// What it must be.
        expected: &'static str,
        /// The value given.
        value: f64,
    },
    /// The footprint cannot be used.
    #[error("the footprint: {0}")]
    Footprint(#[from] trailmark_core::footprint::FootprintError),
}
