//! The YAML file of a ROS map (map_server's format): which image, its resolution and origin,
//! and how pixels become occupancy.
//!
//! ```
//! use trailmark_map::{MapMetadata, MapMode};
//!
//! let meta = MapMetadata::parse("image: lab.pgm\nresolution: 0.05\norigin: [-10, -10.5, 0]\n\
//!     negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n")?;
//! assert_eq!(meta.mode, MapMode::Trinary); // no `mode`: the default
//! assert_eq!(meta.origin, [-10.0, -10.5, 0.0]);
//! assert_eq!(MapMetadata::parse(&meta.to_yaml())?, meta);
//! # Ok::<(), trailmark_map::MapError>(())
//! ```

use serde::{Deserialize, Serialize};
#[cfg(test)]
use trailmark_core::yaml::MAX_DEPTH as MAX_YAML_DEPTH;
use trailmark_core::yaml::{self, Yaml, number};

use crate::error::MapError;
use crate::frame::{check_origin, check_resolution};

/// How pixels become occupancy values (map_server's `mode`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum MapMode {
    /// Occupied (100), free (0) or unknown (-1) by the thresholds. The default.
    #[default]
    Trinary,
    /// Like trinary, but values between the thresholds are scaled to 0..=100, and a pixel that
    /// is not fully opaque is unknown.
    Scale,
    /// The pixel value is the occupancy (0..=100); any other value is unknown.
    Raw,
}

impl MapMode {
    /// The name in the YAML file: `trinary`, `scale` or `raw`.
    pub fn name(self) -> &'static str {
        match self {
            MapMode::Trinary => "trinary",
            MapMode::Scale => "scale",
            MapMode::Raw => "raw",
        }
    }
}

/// The fields of a map's YAML file.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct MapMetadata {
    /// The image file, relative to the YAML file's folder unless absolute.
    pub image: String,
    /// Metres per pixel.
    pub resolution: f64,
    /// `[x, y, yaw]` of the lower-left pixel's outer corner, metres and radians.
    pub origin: [f64; 3],
    /// Whether white is occupied and black free (the meaning of the thresholds is unchanged).
    pub negate: bool,
    /// Above this occupancy probability a pixel is occupied.
    pub occupied_thresh: f64,
    /// Below this occupancy probability a pixel is free.
    pub free_thresh: f64,
    /// How pixels become occupancy.
    pub mode: MapMode,
}

impl MapMetadata {
    /// Parses a map's YAML text. Every field map_server requires is required (`image`,
    /// `resolution`, `origin` with three numbers, `negate` as 0/1 or a boolean,
    /// `occupied_thresh`, `free_thresh`); `mode` defaults to trinary and is read without
    /// regard to case. Unknown fields are ignored, as map_server does. The values are checked
    /// ([`MapMetadata::check`]).
    ///
    /// YAML's anchors and aliases (`&name`, `*name`), which map_server's files never use, are
    /// refused ([`MapError::Yaml`]), as is nesting deeper than 16 lists and mappings: both are
    /// found by reading the text's events, before any document is built.
    pub fn parse(text: &str) -> Result<Self, MapError> {
        let doc = yaml::load(text, "map files").map_err(|reason| MapError::Yaml { reason })?;
        if doc.as_hash().is_none() {
            return Err(MapError::Yaml { reason: "the document is not a mapping of fields".into() });
        }
        let image = match field(&doc, "image")? {
            Yaml::String(s) if !s.is_empty() => s.clone(),
            Yaml::String(_) => return Err(invalid("image", "it is empty")),
            _ => return Err(invalid("image", "it is not a file name")),
        };
        let origin = match field(&doc, "origin")? {
            Yaml::Array(items) if items.len() == 3 => {
                let mut origin = [0.0; 3];
                for (slot, item) in origin.iter_mut().zip(items) {
                    *slot = number(item).ok_or_else(|| invalid("origin", "its items must be numbers"))?;
                }
                origin
            }
            Yaml::Array(items) => {
                return Err(invalid("origin", &format!("it must have 3 items, not {}", items.len())));
            }
            _ => return Err(invalid("origin", "it must be a list [x, y, yaw]")),
        };
        let negate = match field(&doc, "negate")? {
            Yaml::Integer(0) | Yaml::Boolean(false) => false,
            Yaml::Integer(1) | Yaml::Boolean(true) => true,
            _ => return Err(invalid("negate", "it must be 0, 1, true or false")),
        };
        let mode = match &doc["mode"] {
            Yaml::BadValue | Yaml::Null => MapMode::Trinary,
            Yaml::String(s) => match s.to_ascii_lowercase().as_str() {
                "trinary" => MapMode::Trinary,
                "scale" => MapMode::Scale,
                "raw" => MapMode::Raw,
                _ => return Err(invalid("mode", "it must be trinary, scale or raw")),
            },
            _ => return Err(invalid("mode", "it must be trinary, scale or raw")),
        };
        let meta = MapMetadata {
            image,
            resolution: number_field(&doc, "resolution")?,
            origin,
            negate,
            occupied_thresh: number_field(&doc, "occupied_thresh")?,
            free_thresh: number_field(&doc, "free_thresh")?,
            mode,
        };
        meta.check()?;
        Ok(meta)
    }

    /// Checks the values: a positive resolution of at most [`crate::MAX_RESOLUTION`], a finite
    /// origin whose x and y are within
    /// [`MAX_COORDINATE`](trailmark_core::world::MAX_COORDINATE), and
    /// `0 <= free_thresh < occupied_thresh <= 1`. (The map's corners are checked against the
    /// same bound once its size is known, [`crate::MapFrame::new`].)
    pub fn check(&self) -> Result<(), MapError> {
        check_resolution(self.resolution)?;
        check_origin(self.origin)?;
        check_thresholds(self.free_thresh, self.occupied_thresh)
    }

    /// The YAML text map_server reads back to these fields, numbers written in full (the
    /// shortest text that reads back to the same `f64`).
    pub fn to_yaml(&self) -> String {
        let [x, y, yaw] = self.origin;
        format!(
            "image: {}\nmode: {}\nresolution: {}\norigin: [{}, {}, {}]\nnegate: {}\noccupied_thresh: {}\nfree_thresh: {}\n",
            quote(&self.image),
            self.mode.name(),
            real(self.resolution),
            real(x),
            real(y),
            real(yaw),
            u8::from(self.negate),
            real(self.occupied_thresh),
            real(self.free_thresh),
        )
    }
}

pub(crate) fn check_thresholds(free: f64, occupied: f64) -> Result<(), MapError> {
    if (0.0..=1.0).contains(&free) && (0.0..=1.0).contains(&occupied) && free < occupied {
        Ok(())
    } else {
        Err(MapError::Thresholds { free, occupied })
    }
}

fn field<'a>(doc: &'a Yaml, name: &'static str) -> Result<&'a Yaml, MapError> {
    match &doc[name] {
        Yaml::BadValue => Err(MapError::MissingField { field: name }),
        value => Ok(value),
    }
}

fn number_field(doc: &Yaml, name: &'static str) -> Result<f64, MapError> {
    number(field(doc, name)?).ok_or_else(|| invalid(name, "it is not a number"))
}

fn invalid(field: &'static str, reason: &str) -> MapError {
    MapError::InvalidField { field, reason: reason.to_string() }
}

/// `v` as YAML reads it back as a float (`1` would read as an integer, which map_server also
/// takes; `1.0` says what it is).
fn real(v: f64) -> String {
    if v.fract() == 0.0 && v.abs() < 1e15 { format!("{v:.1}") } else { format!("{v}") }
}

/// A file name as a YAML scalar: plain when it is safe, double-quoted otherwise, with YAML's
/// escapes for the backslash, the quote, control characters and the characters YAML reads as
/// line breaks or a byte-order mark.
fn quote(s: &str) -> String {
    let plain = s.chars().all(|c| c.is_ascii_alphanumeric() || "._-/".contains(c))
        && s.chars().next().is_some_and(|c| c.is_ascii_alphanumeric() || c == '.' || c == '/');
    if plain {
        return s.to_string();
    }
    let mut out = String::from("\"");
    for c in s.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            c if (c as u32) < 0x20 || c == '\u{7f}' => out.push_str(&format!("\\x{:02x}", c as u32)),
            '\u{80}'..='\u{9f}' | '\u{2028}' | '\u{2029}' | '\u{feff}' => {
                out.push_str(&format!("\\u{:04x}", c as u32))
            }
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    const NAV2: &str = "image: warehouse.pgm\nmode: trinary\nresolution: 0.03\norigin: [-15.1, -25, 0]\n\
                        negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.1\n";

    #[test]
    fn nav2_files_parse() {
        let m = MapMetadata::parse(NAV2).unwrap();
        assert_eq!(m.image, "warehouse.pgm");
        assert_eq!((m.resolution, m.origin, m.negate), (0.03, [-15.1, -25.0, 0.0], false));
        assert_eq!((m.occupied_thresh, m.free_thresh, m.mode), (0.65, 0.1, MapMode::Trinary));
        let scale =
            MapMetadata::parse(&NAV2.replace("trinary", "Scale").replace("negate: 0", "negate: true"));
        assert_eq!(scale.as_ref().map(|m| (m.mode, m.negate)).unwrap(), (MapMode::Scale, true));
    }

    #[test]
    fn writing_reads_back() {
        let mut m = MapMetadata::parse(NAV2).unwrap();
        m.image = "my map #2.png".into();
        assert_eq!(MapMetadata::parse(&m.to_yaml()).unwrap(), m);
        // Control characters, quotes, backslashes and YAML's other line breaks, escaped.
        m.image = "a \"b\" \\ c\u{18}\t\u{85}\u{2028}é.pgm".into();
        m.origin = [0.1 + 0.2, -1e-9, 3.0];
        m.mode = MapMode::Raw;
        assert_eq!(MapMetadata::parse(&m.to_yaml()).unwrap(), m);
    }

    #[test]
    fn mistakes_are_named() {
        let bad = |from: &str, to: &str| MapMetadata::parse(&NAV2.replace(from, to)).unwrap_err();
        assert!(matches!(bad("image: warehouse.pgm\n", ""), MapError::MissingField { field: "image" }));
        assert!(matches!(bad("negate: 0\n", ""), MapError::MissingField { field: "negate" }));
        assert!(matches!(bad("negate: 0", "negate: 2"), MapError::InvalidField { field: "negate", .. }));
        assert!(matches!(bad("0.03", "-0.03"), MapError::Resolution { .. }));
        assert!(matches!(bad("0.03", ".nan"), MapError::Resolution { .. }));
        assert!(matches!(bad("0.03", "fast"), MapError::InvalidField { field: "resolution", .. }));
        assert!(matches!(bad("0.03", "1e300"), MapError::Resolution { .. }));
        assert!(matches!(bad("[-15.1", "[1e15"), MapError::Origin { x: 1e15, .. }));
        assert!(matches!(bad("-25, 0]", "-1e10, 0]"), MapError::Origin { y: -1e10, .. }));
        assert!(matches!(bad("-25, 0]", "-25]"), MapError::InvalidField { field: "origin", .. }));
        assert!(matches!(bad("0.65", "1.5"), MapError::Thresholds { .. }));
        assert!(matches!(bad("0.1\n", "0.7\n"), MapError::Thresholds { .. }));
        assert!(matches!(bad("0.1\n", "-0.1\n"), MapError::Thresholds { .. }));
        assert!(matches!(bad("trinary", "ternary"), MapError::InvalidField { field: "mode", .. }));
        assert!(matches!(bad("origin: [", "origin: [[["), MapError::Yaml { .. }));
        assert!(matches!(MapMetadata::parse(""), Err(MapError::Yaml { .. })));
        assert!(matches!(MapMetadata::parse("- 1\n- 2\n"), Err(MapError::Yaml { .. })));
    }

    /// The reason of a YAML error, or a panic naming what was returned instead.
    fn yaml_reason(text: &str) -> String {
        match MapMetadata::parse(text) {
            Err(MapError::Yaml { reason }) => reason,
            other => panic!("expected a YAML error, got {other:?}"),
        }
    }

    #[test]
    fn aliases_and_anchors_are_refused_before_they_are_expanded() {
        // Billion laughs, kept small enough to expand harmlessly were it not refused: each
        // level names the one before nine times, so the last names 9^6 scalars.
        let mut bomb = String::from(NAV2);
        bomb.push_str("l0: &l0 [x, x, x, x, x, x, x, x, x]\n");
        for level in 1..6 {
            let previous = format!("*l{}", level - 1);
            bomb.push_str(&format!("l{level}: &l{level} [{}]\n", [previous.as_str(); 9].join(", ")));
        }
        let reason = yaml_reason(&bomb);
        assert!(reason.contains("anchor") && reason.contains("line 8"), "{reason}");
        // An alias of a field's value, and an anchor alone.
        let aliased = NAV2.replace("free_thresh: 0.1", "free_thresh: *t").replace("0.65", "&t 0.65");
        assert!(yaml_reason(&aliased).contains("anchor"));
        assert!(yaml_reason(&NAV2.replace("[-15.1", "&o [-15.1")).contains("anchor"));
    }

    #[test]
    fn deep_nesting_is_refused_before_the_document_is_built() {
        // Block sequences two characters a level: a document this deep, once built, is
        // dropped by recursion deeper than a thread's stack.
        let deep = format!("{NAV2}laughs:\n  {}x\n", "- ".repeat(100_000));
        assert!(yaml_reason(&deep).contains("at most 16 deep"));
        let shallow = format!("{NAV2}extra:\n  {}x\n", "- ".repeat(MAX_YAML_DEPTH - 1));
        assert!(MapMetadata::parse(&shallow).is_ok());
    }
}
