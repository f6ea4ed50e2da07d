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
//! The images: PGM, ASCII (P2) or binary (P5), its header's three numbers separated by
//! whitespace and `#` comments, then one whitespace byte before the raster; samples of one byte,
//! or two (big-endian) when the maxval is above 255; a sample above the maxval is refused
//! ([`MapError::PixelAboveMaxval`]). PNG of any colour type and bit depth, decoded by the png
//! crate as the image crate decodes it; a palette index with no entry in the palette is
//! refused ([`MapError::PixelOutsidePalette`]). Other formats are refused by name.
//!
//! Writing, as map_saver: trinary pixels are 254 (value <= free percent), 0 (value >= occupied
//! percent) or 205 (unknown and in between), in an 8-bit PGM (where the thresholds would read
//! one of these shades back as another kind of cell, the nearest shade that reads back right); scale pixels are gray
//! `(100 - value) / 100` with unknown transparent, in an RGBA PNG; raw pixels are the value,
//! unknown 255, in an 8-bit PGM.

use std::io::Cursor;
use std::path::Path;

use image::ImageEncoder;
use image::codecs::png::PngEncoder;
use image::codecs::pnm::{PnmEncoder, PnmSubtype, SampleEncoding};

use crate::error::MapError;
use crate::metadata::{MapMetadata, MapMode};
use crate::occupancy::UNKNOWN;

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

/// A map image whose header has been read: its size is known, its pixels not yet decoded.
pub(crate) struct Image<'a> {
    bytes: &'a [u8],
    path: &'a Path,
    width: u32,
    height: u32,
    /// The PGM's header, `None` for a PNG.
    pgm: Option<PgmHeader>,
}

/// What a PGM's header says.
#[derive(Debug, Clone, Copy)]
struct PgmHeader {
    /// P2: samples written in decimal.
    ascii: bool,
    maxval: u32,
    /// Where the raster starts.
    raster: usize,
}

impl<'a> Image<'a> {
    /// Reads the header of a PGM or PNG image (any other format is refused), nothing more;
    /// `path` names the image in errors.
    pub(crate) fn open(bytes: &'a [u8], path: &'a Path) -> Result<Self, MapError> {
        let image = |width, height, pgm| Image { bytes, path, width, height, pgm };
        match format_of(bytes, path)? {
            Format::Pgm => {
                let (width, height, header) = pgm_header(bytes).map_err(|reason| bad(path, reason))?;
                Ok(image(width, height, Some(header)))
            }
            Format::Png => {
                let mut decoder = png_decoder(bytes);
                let info = decoder.read_header_info().map_err(|e| bad(path, e.to_string()))?;
                Ok(image(info.width, info.height, None))
            }
        }
    }

    /// The width in pixels.
    pub(crate) fn width(&self) -> usize {
        self.width as usize
    }

    /// The height in pixels.
    pub(crate) fn height(&self) -> usize {
        self.height as usize
    }

    /// The occupancy of every pixel by `meta`'s mode, thresholds and negate, row-major from the
    /// top. The caller has checked the size ([`crate::MapFrame::new`]): this allocates for it.
    pub(crate) fn occupancy(&self, meta: &MapMetadata) -> Result<Vec<i8>, MapError> {
        match self.pgm {
            Some(header) => self.pgm_occupancy(header, &Rule::new(meta)),
            None => self.png_occupancy(&Rule::new(meta)),
        }
    }

    /// A PGM's pixels. A sample's shade is its fraction of the maxval: a maxval below 255 is
    /// first scaled to 8 bits as SDL_image (map_server's reader) scales it, `v * 255 / maxval`
    /// truncated; map_server reads no maxval above 255, trailmark reads them as 16 bits.
    fn pgm_occupancy(&self, header: PgmHeader, rule: &Rule) -> Result<Vec<i8>, MapError> {
        let PgmHeader { ascii, maxval, raster } = header;
        let shade = |v: u32| {
            if maxval <= 255 {
                f64::from(v * 255 / maxval) * 257.0 / 65535.0
            } else {
                f64::from(v) / f64::from(maxval)
            }
        };
        // One value per possible sample, at most 65536 of them.
        let table: Vec<i8> = (0..=maxval).map(|v| rule.value(shade(v), true)).collect();
        let cells = self.width as usize * self.height as usize;
        let data = &self.bytes[raster..];
        // A binary sample takes one or two bytes, a decimal one at least two but the last: a
        // short raster is found without holding a cell for each pixel its header claims.
        let wide = usize::from(maxval > 255) + 1;
        let most = if ascii { data.len() / 2 + 1 } else { data.len() / wide };
        let mut values = Vec::with_capacity(cells.min(most));
        let mut push = |value: u32| -> Result<(), MapError> {
            let i = values.len();
            let v = table.get(value as usize).ok_or_else(|| MapError::PixelAboveMaxval {
                path: self.path.to_path_buf(),
                x: (i % self.width as usize) as u32,
                y: (i / self.width as usize) as u32,
                value,
                maxval,
            })?;
            values.push(*v);
            Ok(())
        };
        if ascii {
            let mut at = 0;
            for _ in 0..cells {
                at = skip_space(data, at);
                if at == data.len() {
                    break;
                }
                let (value, next) =
                    number(data, at).map_err(|what| bad(self.path, format!("a sample is {what}")))?;
                push(value)?;
                at = next;
            }
        } else {
            for sample in data.chunks_exact(wide).take(cells) {
                push(sample.iter().fold(0, |v, &b| v << 8 | u32::from(b)))?;
            }
        }
        if values.len() < cells {
            let reason = format!("the raster ends after {} of the {cells} samples", values.len());
            return Err(bad(self.path, reason));
        }
        Ok(values)
    }

    /// A PNG's pixels, decoded by the png crate as the image crate decodes them (samples below
    /// 8 bits and tRNS expanded); a palette image's indices are read before they become colours,
    /// each checked against the palette.
    fn png_occupancy(&self, rule: &Rule) -> Result<Vec<i8>, MapError> {
        let png_error = |e: png::DecodingError| bad(self.path, e.to_string());
        let mut decoder = png_decoder(self.bytes);
        let indexed = decoder.read_header_info().map_err(png_error)?.color_type == png::ColorType::Indexed;
        decoder.set_transformations(if indexed {
            png::Transformations::IDENTITY
        } else {
            png::Transformations::EXPAND
        });
        let mut reader = decoder.read_info().map_err(png_error)?;
        let (colour, depth) = reader.output_color_type();
        let info = reader.info();
        // A palette's entries as occupancy values, alpha from tRNS as the png crate takes it
        // (ignored when it has more values than the palette has entries).
        let palette: Vec<i8> = match (&info.palette, indexed) {
            (Some(rgb), true) => {
                let trns = info.trns.as_deref().filter(|t| t.len() <= rgb.len() / 3).unwrap_or(&[]);
                rgb.chunks_exact(3)
                    .enumerate()
                    .map(|(i, c)| {
                        let alpha = trns.get(i).copied().unwrap_or(u8::MAX);
                        rule.pixel([c[0], c[1], c[2], alpha].map(|s| u16::from(s) * 257), info.trns.is_some())
                    })
                    .collect()
            }
            _ => Vec::new(),
        };
        let bits = depth as usize;
        let samples = colour.samples();
        let has_alpha = matches!(colour, png::ColorType::GrayscaleAlpha | png::ColorType::Rgba);
        let width = self.width as usize;
        let mut values = Vec::with_capacity(width * self.height as usize);
        // The bytes of a row as the header's size gives it: the decoder checks that an
        // animated PNG's first frame is the whole image, and a row is checked again here.
        let row_bytes = (width * samples * bits).div_ceil(8);
        let mut convert = |y: usize, row: &[u8]| -> Result<(), MapError> {
            if row.len() < row_bytes {
                return Err(bad(self.path, format!("row {y} has {} of its {row_bytes} bytes", row.len())));
            }
            for x in 0..width {
                if indexed {
                    // Indices packed from the high bits of each byte.
                    let bit = x * bits;
                    let index = (row[bit / 8] >> (8 - bits - bit % 8)) & ((1u16 << bits) - 1) as u8;
                    let value =
                        palette.get(usize::from(index)).ok_or_else(|| MapError::PixelOutsidePalette {
                            path: self.path.to_path_buf(),
                            x: x as u32,
                            y: y as u32,
                            index: u32::from(index),
                            entries: palette.len() as u32,
                        })?;
                    values.push(*value);
                } else {
                    let sample = |k: usize| match bits {
                        16 => u16::from_be_bytes([row[2 * k], row[2 * k + 1]]),
                        _ => u16::from(row[k]) * 257,
                    };
                    let at = x * samples;
                    let rgba = match samples {
                        1 => [sample(at), sample(at), sample(at), u16::MAX],
                        2 => [sample(at), sample(at), sample(at), sample(at + 1)],
                        3 => [sample(at), sample(at + 1), sample(at + 2), u16::MAX],
                        _ => [sample(at), sample(at + 1), sample(at + 2), sample(at + 3)],
                    };
                    values.push(rule.pixel(rgba, has_alpha));
                }
            }
            Ok(())
        };
        if reader.info().interlaced {
            // The passes are gathered into a whole frame before any row is complete.
            let size =
                reader.output_buffer_size().ok_or_else(|| bad(self.path, "too large to decode".into()))?;
            let mut frame = vec![0; size];
            let out = reader.next_frame(&mut frame).map_err(png_error)?;
            for (y, row) in frame.chunks_exact(out.line_size).enumerate() {
                convert(y, row)?;
            }
        } else {
            let mut y = 0;
            while let Some(row) = reader.next_row().map_err(png_error)? {
                convert(y, row.data())?;
                y += 1;
            }
        }
        if values.len() != width * self.height as usize {
            return Err(bad(self.path, "the image data ends early".into()));
        }
        Ok(values)
    }
}

/// The bytes the PNG decoder may allocate for itself: a row or two, and the ancillary chunks
/// it keeps (text and ICC profiles are skipped). The pixels go to buffers of ours.
const PNG_DECODER_BYTES: usize = 16 << 20;

fn png_decoder(bytes: &[u8]) -> png::Decoder<Cursor<&[u8]>> {
    let mut decoder =
        png::Decoder::new_with_limits(Cursor::new(bytes), png::Limits { bytes: PNG_DECODER_BYTES });
    decoder.set_ignore_text_chunk(true);
    decoder.set_ignore_iccp_chunk(true);
    decoder
}

fn bad(path: &Path, reason: String) -> MapError {
    MapError::Image { path: path.to_path_buf(), reason }
}

/// Netpbm's whitespace.
fn is_space(b: u8) -> bool {
    matches!(b, b' ' | b'\t' | b'\n' | b'\r' | 0x0b | 0x0c)
}

/// The first byte at or after `at` that is neither whitespace nor in a comment (`#` to the end
/// of its line).
fn skip_space(data: &[u8], mut at: usize) -> usize {
    while let Some(&b) = data.get(at) {
        if b == b'#' {
            while data.get(at).is_some_and(|&b| b != b'\n' && b != b'\r') {
                at += 1;
            }
        } else if is_space(b) {
            at += 1;
        } else {
            break;
        }
    }
    at
}

/// The decimal number starting at `at` and where it ends, or what is there instead.
fn number(data: &[u8], at: usize) -> Result<(u32, usize), &'static str> {
    let digits = data[at..].iter().take_while(|b| b.is_ascii_digit()).count();
    match data.get(at + digits) {
        _ if digits == 0 => return Err("not a number"),
        Some(&b) if !is_space(b) && b != b'#' => return Err("not a number"),
        _ => {}
    }
    let value = data[at..at + digits]
        .iter()
        .try_fold(0u32, |v, &d| v.checked_mul(10)?.checked_add(u32::from(d - b'0')))
        .ok_or("larger than 4294967295")?;
    Ok((value, at + digits))
}

/// A PGM's width, height and header (P2 or P5 already seen): three decimal numbers after the
/// magic, whitespace and comments between them, then one whitespace byte (or a comment to the
/// end of its line) before the raster.
fn pgm_header(bytes: &[u8]) -> Result<(u32, u32, PgmHeader), String> {
    if !bytes.get(2).is_some_and(|&b| is_space(b) || b == b'#') {
        return Err("no whitespace after the magic number P2 or P5".into());
    }
    let mut at = 2;
    let mut fields = [0u32; 3];
    for (slot, name) in fields.iter_mut().zip(["width", "height", "maxval"]) {
        at = skip_space(bytes, at);
        if at == bytes.len() {
            return Err(format!("the header ends before the {name}"));
        }
        (*slot, at) = number(bytes, at).map_err(|what| format!("the {name} is {what}"))?;
    }
    let [width, height, maxval] = fields;
    if !(1..=65535).contains(&maxval) {
        return Err(format!("the maxval is {maxval}, not in 1..=65535"));
    }
    // The one whitespace byte, or a comment and its line end, before the raster.
    at = match bytes.get(at) {
        Some(b'#') => {
            bytes[at..].iter().position(|&b| b == b'\n' || b == b'\r').map_or(bytes.len(), |n| at + n + 1)
        }
        Some(_) => at + 1,
        None => at,
    };
    Ok((width, height, PgmHeader { ascii: bytes[1] == b'2', maxval, raster: at }))
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

    /// The value of a pixel of 16-bit samples: its shade the mean of red, green and blue, and
    /// of alpha too in trinary mode when the image has an alpha channel.
    fn pixel(&self, [r, g, b, a]: [u16; 4], has_alpha: bool) -> i8 {
        let mut sum = f64::from(r) + f64::from(g) + f64::from(b);
        let mut n = 3.0;
        if self.mode == MapMode::Trinary && has_alpha {
            sum += f64::from(a);
            n = 4.0;
        }
        self.value(sum / n / 65535.0, a == u16::MAX)
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
