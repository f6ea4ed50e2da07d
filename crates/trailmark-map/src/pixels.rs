//! Pixels to occupancy and back, exactly as ROS 2's map_server (Nav2's `map_io`) does.
//!
//! Reading: a pixel's shade is the mean of its red, green and blue samples on a 0..1 scale (and,
//! in trinary mode, of its alpha too when the image has an alpha channel, as map_server keeps
//! for compatibility); its occupancy is `1 - shade` (`shade` with `negate`). Trinary: occupied
//! when `occupied_thresh < occupancy`, free when `occupancy < free_thresh`, unknown otherwise;
//! the comparisons are strict in map_server's code, while its documentation says `>=` and
//! `<=` (the saver is the one that compares with `<=` / `>=`). Scale: a pixel that is not fully
//! opaque is unknown, the thresholds as in trinary, and in between
//! `rint((occupancy - free) / (occupied - free) * 100)`. Raw: `round(shade * 255)` when it is
//! in 0..=100, unknown otherwise (negate does not apply).
//!
//! Writing, as map_saver: trinary pixels are 254 (value <= free percent), 0 (value >= occupied
//! percent) or 205 (unknown and in between), in an 8-bit PGM (where the thresholds would read
//! one of these shades back as another kind of cell, the nearest shade that reads back right); scale pixels are gray
//! `(100 - value) / 100` with unknown transparent, in an RGBA PNG; raw pixels are the value,
//! unknown 255, in an 8-bit PGM.

use std::io::Cursor;
use std::path::Path;

use image::codecs::png::PngEncoder;
use image::codecs::pnm::{PnmEncoder, PnmSubtype, SampleEncoding};
use image::{DynamicImage, ImageEncoder, ImageFormat, ImageReader, Limits};
use trailmark_core::grid::Grid;

use crate::error::MapError;
use crate::metadata::{MapMetadata, MapMode};
use crate::occupancy::UNKNOWN;

/// The largest side of a map image accepted, in pixels.
pub const MAX_IMAGE_SIDE: u32 = 1 << 16;

/// A decoded image's size and its occupancy values, row 0 at the top.
pub(crate) struct Decoded {
    pub width: usize,
    pub height: usize,
    pub values: Vec<i8>,
}

/// The formats map images are read in. map_server reads whatever SDL_image reads; maps are
/// PGM or PNG, and only these are documented and read.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Format {
    /// A graymap, ASCII (P2) or binary (P5).
    Pgm,
    /// PNG.
    Png,
}

/// The first eight bytes of every PNG file.
const PNG_SIGNATURE: &[u8] = b"\x89PNG\r\n\x1a\n";

/// The format of an image from its first bytes, or [`MapError::ImageFormat`] naming what it is
/// instead: the other Netpbm formats by name, others as the image crate recognises them (from
/// their first bytes, whichever formats it was built to decode), anything else by its first
/// bytes.
fn format_of(bytes: &[u8], path: &Path) -> Result<Format, MapError> {
    let netpbm = |name: &str, digit: u8| format!("{name} (P{})", char::from(digit));
    let format = match bytes {
        [b'P', b'2' | b'5', ..] => return Ok(Format::Pgm),
        _ if bytes.starts_with(PNG_SIGNATURE) => return Ok(Format::Png),
        [b'P', d @ (b'1' | b'4'), ..] => netpbm("PBM", *d),
        [b'P', d @ (b'3' | b'6'), ..] => netpbm("PPM", *d),
        [b'P', d @ b'7', ..] => netpbm("PAM", *d),
        [] => "empty".to_string(),
        _ => match image::guess_format(bytes) {
            Ok(format) => format!("{format:?}").to_uppercase(),
            Err(_) => {
                let start: Vec<String> = bytes.iter().take(8).map(|b| format!("{b:02x}")).collect();
                format!("of no known image format (its first bytes are {})", start.join(" "))
            }
        },
    };
    Err(MapError::ImageFormat { path: path.to_path_buf(), format })
}

/// Decodes `bytes` (PGM P2/P5, PNG) into occupancy values by `meta`'s mode, thresholds and
/// negate. `path` names the image in errors.
pub(crate) fn decode(bytes: &[u8], meta: &MapMetadata, path: &Path) -> Result<Decoded, MapError> {
    let image_error =
        |e: image::ImageError| MapError::Image { path: path.to_path_buf(), reason: e.to_string() };
    let format = match format_of(bytes, path)? {
        Format::Pgm => ImageFormat::Pnm,
        Format::Png => ImageFormat::Png,
    };
    let (w, h) =
        ImageReader::with_format(Cursor::new(bytes), format).into_dimensions().map_err(image_error)?;
    if w > MAX_IMAGE_SIDE || h > MAX_IMAGE_SIDE {
        return Err(MapError::TooLarge { width: u64::from(w), height: u64::from(h) });
    }
    // An empty image, or more cells than a grid may have.
    Grid::cell_count(w as usize, h as usize)?;
    let mut limits = Limits::default();
    limits.max_image_width = Some(MAX_IMAGE_SIDE);
    limits.max_image_height = Some(MAX_IMAGE_SIDE);
    // An RGBA image of 16-bit samples of the largest grid, with room for the decoder's buffers.
    limits.max_alloc = Some((Grid::MAX_CELLS as u64) * 8 + (64 << 20));
    let mut reader = ImageReader::with_format(Cursor::new(bytes), format);
    reader.limits(limits);
    let image = reader.decode().map_err(image_error)?;
    let values = occupancy(&image, meta);
    Ok(Decoded { width: w as usize, height: h as usize, values })
}

/// The occupancy of every pixel of `image`, row-major from the top.
fn occupancy(image: &DynamicImage, meta: &MapMetadata) -> Vec<i8> {
    let rule = Rule::new(meta);
    match image {
        // The common case, a gray PGM: red, green and blue are the one sample, no alpha.
        DynamicImage::ImageLuma8(gray) => {
            gray.as_raw().iter().map(|&v| rule.value(f64::from(v) * 257.0 / 65535.0, true)).collect()
        }
        _ => {
            let has_alpha = image.color().has_alpha();
            let rgba = image.to_rgba16();
            rgba.pixels()
                .map(|p| {
                    let [r, g, b, a] = p.0;
                    let mut sum = f64::from(r) + f64::from(g) + f64::from(b);
                    let mut n = 3.0;
                    if meta.mode == MapMode::Trinary && has_alpha {
                        sum += f64::from(a);
                        n = 4.0;
                    }
                    rule.value(sum / n / 65535.0, a == u16::MAX)
                })
                .collect()
        }
    }
}

/// map_server's rule from a pixel's shade to an occupancy value.
struct Rule {
    mode: MapMode,
    negate: bool,
    free: f64,
    occupied: f64,
}

impl Rule {
    fn new(meta: &MapMetadata) -> Self {
        Rule { mode: meta.mode, negate: meta.negate, free: meta.free_thresh, occupied: meta.occupied_thresh }
    }

    fn value(&self, shade: f64, opaque: bool) -> i8 {
        let occ = if self.negate { shade } else { 1.0 - shade };
        match self.mode {
            MapMode::Trinary => {
                if self.occupied < occ {
                    100
                } else if occ < self.free {
                    0
                } else {
                    UNKNOWN
                }
            }
            MapMode::Scale => {
                if !opaque {
                    UNKNOWN
                } else if self.occupied < occ {
                    100
                } else if occ < self.free {
                    0
                } else {
                    // free <= occ <= occupied, so the value is in 0..=100.
                    ((occ - self.free) / (self.occupied - self.free) * 100.0).round_ties_even() as i8
                }
            }
            MapMode::Raw => {
                let v = (shade * 255.0).round();
                if (0.0..=100.0).contains(&v) { v as i8 } else { UNKNOWN }
            }
        }
    }
}

/// The pixels of the three kinds of cell in a trinary or raw image.
struct Shades {
    free: u8,
    occupied: u8,
    unknown: u8,
}

impl Shades {
    /// map_saver's shades (254 free, 0 occupied, 205 unknown) where the thresholds read them
    /// back as what they were; otherwise the nearest shade that is read back so (map_saver's
    /// default `free_thresh` of 0.25 reads its own unknown shade 205, occupancy 0.196, as free).
    fn trinary(free: f64, occupied: f64) -> Result<Self, String> {
        let occ = |v: u8| 1.0 - f64::from(v) * 257.0 / 65535.0;
        let free_shade = [254u8, 255].into_iter().find(|&v| occ(v) < free);
        let occupied_shade = (occupied < occ(0)).then_some(0u8);
        let unknown_shade =
            std::iter::once(205u8).chain((0..=255u8).rev()).find(|&v| free <= occ(v) && occ(v) <= occupied);
        match (free_shade, occupied_shade, unknown_shade) {
            (Some(free), Some(occupied), Some(unknown)) => Ok(Shades { free, occupied, unknown }),
            _ => Err(format!(
                "with free_thresh {free} and occupied_thresh {occupied} no 8-bit shade reads back as free, occupied and unknown"
            )),
        }
    }
}

/// The image file map_saver writes for `values` (row-major from the top) in `mode`: PGM bytes
/// for trinary and raw, PNG bytes for scale.
pub(crate) fn encode(
    width: u32,
    height: u32,
    values: &[i8],
    mode: MapMode,
    free_thresh: f64,
    occupied_thresh: f64,
) -> Result<Vec<u8>, String> {
    let mut out = Vec::new();
    let failed = |e: image::ImageError| e.to_string();
    match mode {
        MapMode::Trinary | MapMode::Raw => {
            let free = (free_thresh * 100.0).round_ties_even() as i32;
            let occupied = (occupied_thresh * 100.0).round_ties_even() as i32;
            let shades = if mode == MapMode::Trinary {
                Shades::trinary(free_thresh, occupied_thresh)?
            } else {
                Shades { free: 0, occupied: 0, unknown: 0 }
            };
            let pixels: Vec<u8> = values
                .iter()
                .map(|&v| {
                    let v = i32::from(v);
                    match mode {
                        MapMode::Raw if (0..=100).contains(&v) => v as u8,
                        MapMode::Raw => 255,
                        _ if !(0..=100).contains(&v) => shades.unknown,
                        _ if v <= free => shades.free,
                        _ if occupied <= v => shades.occupied,
                        _ => shades.unknown,
                    }
                })
                .collect();
            PnmEncoder::new(&mut out)
                .with_subtype(PnmSubtype::Graymap(SampleEncoding::Binary))
                .write_image(&pixels, width, height, image::ExtendedColorType::L8)
                .map_err(failed)?;
        }
        MapMode::Scale => {
            let mut pixels = Vec::with_capacity(values.len() * 4);
            for &v in values {
                if (0..=100).contains(&v) {
                    let g = ((100.0 - f64::from(v)) / 100.0 * 255.0).round() as u8;
                    pixels.extend_from_slice(&[g, g, g, 255]);
                } else {
                    pixels.extend_from_slice(&[128, 128, 128, 0]);
                }
            }
            PngEncoder::new(&mut out)
                .write_image(&pixels, width, height, image::ExtendedColorType::Rgba8)
                .map_err(failed)?;
        }
    }
    Ok(out)
}
