//! Loading and saving maps as map_server and map_saver do: a YAML file naming an image.
//!
//! ```no_run
//! use trailmark_map::{SaveOptions, load_map, save_map};
//!
//! let map = load_map("maps/warehouse.yaml")?;
//! let yaml = save_map(&map, "/tmp/warehouse_copy", &SaveOptions::default())?;
//! assert_eq!(load_map(&yaml)?.values(), map.values());
//! # Ok::<(), trailmark_map::MapError>(())
//! ```

use std::path::{Path, PathBuf};

use trailmark_core::read::{read_capped, read_to_string_capped};

use crate::error::MapError;
use crate::frame::MapFrame;
use crate::metadata::{MapMetadata, MapMode, check_thresholds};
use crate::occupancy::OccupancyGrid;
use crate::pixels;

/// The largest map YAML file read: 1 MiB (map_server's files are a few hundred bytes).
pub const MAX_YAML_BYTES: u64 = 1 << 20;
/// The largest map image file read: 1 GiB.
pub const MAX_IMAGE_BYTES: u64 = 1 << 30;

/// A map's YAML fields with the occupancy grid its image gives.
#[derive(Debug, Clone, PartialEq)]
pub struct LoadedMap {
    /// The YAML file's fields.
    pub metadata: MapMetadata,
    /// Where the image was read from.
    pub image_path: PathBuf,
    /// The occupancy grid.
    pub occupancy: OccupancyGrid,
}

/// Loads the map a map_server YAML file describes: its occupancy values, resolution and
/// origin. See [`load_map_file`] for the YAML fields and the image path too.
pub fn load_map(yaml: impl AsRef<Path>) -> Result<OccupancyGrid, MapError> {
    load_map_file(yaml).map(|loaded| loaded.occupancy)
}

/// Loads a map_server YAML file and the image it names (relative to the YAML file's folder
/// unless absolute): PGM (P2 or P5, comments allowed, 8 or 16 bits) or PNG (gray, gray with
/// alpha, RGB, RGBA, palette). Any other image is refused ([`MapError::ImageFormat`]), PBM,
/// PPM and PAM too, though map_server reads whatever SDL_image reads. A map has at most
/// [`crate::MAX_MAP_CELLS`] cells, checked from the image's header before any pixel is
/// decoded; the memory loading takes per cell is stated there.
pub fn load_map_file(yaml: impl AsRef<Path>) -> Result<LoadedMap, MapError> {
    let yaml = yaml.as_ref();
    let metadata = MapMetadata::parse(&read_to_string_capped(yaml, MAX_YAML_BYTES)?)?;
    let image_path = match Path::new(&metadata.image) {
        p if p.is_absolute() => p.to_path_buf(),
        p => yaml.parent().unwrap_or(Path::new("")).join(p),
    };
    let bytes = read_capped(&image_path, MAX_IMAGE_BYTES)?;
    let occupancy = decode_map(&metadata, &bytes, &image_path)?;
    Ok(LoadedMap { metadata, image_path, occupancy })
}

/// The occupancy grid of an image already in memory, read by `metadata`'s rules (its `image`
/// field is not used); `name` names the image in errors.
pub fn decode_map(metadata: &MapMetadata, image: &[u8], name: &Path) -> Result<OccupancyGrid, MapError> {
    metadata.check()?;
    let image = pixels::Image::open(image, name)?;
    // The frame is checked from the header's size, before any pixel is decoded.
    let frame = MapFrame::new(image.width(), image.height(), metadata.resolution, metadata.origin)?;
    OccupancyGrid::new(frame, image.occupancy(metadata)?)
}

/// How a map is saved: map_saver's mode and thresholds.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SaveOptions {
    /// Trinary and raw write an 8-bit PGM, scale an RGBA PNG.
    pub mode: MapMode,
    /// Values at or below this fraction (times 100) are written free in trinary mode.
    pub free_thresh: f64,
    /// Values at or above this fraction (times 100) are written occupied in trinary mode.
    pub occupied_thresh: f64,
}

impl Default for SaveOptions {
    /// Trinary, free 0.196, occupied 0.65: ROS 1 map_saver's thresholds, which read the
    /// unknown shade it writes (205, occupancy 0.196) back as unknown. (Nav2's map_saver
    /// defaults to free 0.25, which reads that shade back as free.)
    fn default() -> Self {
        SaveOptions { mode: MapMode::Trinary, free_thresh: 0.196, occupied_thresh: 0.65 }
    }
}

/// The image bytes and the YAML fields map_saver writes for `map`, the YAML naming the image
/// `image_name`.
///
/// What loads back the same: a map of free, occupied and unknown cells in trinary mode; any
/// map in raw mode; any map in scale mode saved with thresholds 0 and 1 (other thresholds
/// rescale the values in between, as map_server does).
pub fn encode_map(
    map: &OccupancyGrid,
    image_name: &str,
    options: &SaveOptions,
) -> Result<(MapMetadata, Vec<u8>), MapError> {
    check_thresholds(options.free_thresh, options.occupied_thresh)?;
    let frame = map.frame();
    let bytes = pixels::encode(
        frame.width(),
        frame.height(),
        map.values(),
        options.mode,
        options.free_thresh,
        options.occupied_thresh,
    )
    .map_err(|reason| MapError::Save { reason })?;
    let metadata = MapMetadata {
        image: image_name.to_string(),
        resolution: frame.resolution(),
        origin: frame.origin(),
        negate: false,
        occupied_thresh: options.occupied_thresh,
        free_thresh: options.free_thresh,
        mode: options.mode,
    };
    Ok((metadata, bytes))
}

/// Saves `map` as `STEM.yaml` and `STEM.pgm` (trinary, raw) or `STEM.png` (scale), as
/// map_saver does; returns the YAML file's path.
pub fn save_map(
    map: &OccupancyGrid,
    stem: impl AsRef<Path>,
    options: &SaveOptions,
) -> Result<PathBuf, MapError> {
    let stem = stem.as_ref();
    let extension = if options.mode == MapMode::Scale { "png" } else { "pgm" };
    let image_path = stem.with_extension(extension);
    let yaml_path = stem.with_extension("yaml");
    let image_name = image_path.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
    let (metadata, bytes) = encode_map(map, &image_name, options)?;
    let write = |path: &Path, data: &[u8]| {
        std::fs::write(path, data).map_err(|source| MapError::Write { path: path.to_path_buf(), source })
    };
    write(&image_path, &bytes)?;
    write(&yaml_path, metadata.to_yaml().as_bytes())?;
    Ok(yaml_path)
}
