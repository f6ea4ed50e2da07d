//! Reading and writing MovingAI grid benchmarks: `.map` files and `.map.scen` scenario files.
//!
//! The format is that of Sturtevant's benchmark set (movingai.com/benchmarks): a map is a header
//! (`type`, `height`, `width`, in any order) then `map` and one line of characters per row;
//! `.`, `G`, `S` are passable and `@`, `O`, `T`, `W` blocked. A scenario file starts with
//! `version 1` (or `version 1.0`) and lists one query per line: bucket, map, map width, map
//! height, start x, start y, goal x, goal y and the optimal 8-connected length (no corner
//! cutting). Lines may end in CRLF and fields may be separated by tabs or spaces.
//!
//! ```
//! use trailmark_core::movingai::{parse_map, parse_scenarios};
//!
//! let grid = parse_map("type octile\r\nheight 2\r\nwidth 3\r\nmap\r\n..@\r\n...\r\n")?;
//! assert_eq!((grid.width(), grid.height(), grid.passable_count()), (3, 2, 5));
//!
//! let scen = parse_scenarios("version 1\n0\tmaps/x.map\t3\t2\t0\t0\t2\t1\t2.41421356\n")?;
//! assert_eq!(scen[0].goal.x, 2);
//! assert!((scen[0].optimal_length - 2.41421356).abs() < 1e-12);
//! # Ok::<(), trailmark_core::movingai::ParseError>(())
//! ```

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use serde::{Deserialize, Serialize};
use thiserror::Error;

use crate::grid::{Cell, Grid, GridError, is_passable_char};
use crate::read::{ReadFileError, read_to_string_capped};

/// One query of a scenario file.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Scenario {
    /// The difficulty bucket (optimal length / 4, rounded down, in most sets).
    pub bucket: u32,
    /// The map path as written in the scenario file.
    pub map: String,
    /// The width of the map the query was made for.
    pub map_width: u32,
    /// The height of the map the query was made for.
    pub map_height: u32,
    /// The start cell.
    pub start: Cell,
    /// The goal cell.
    pub goal: Cell,
    /// The published optimal path length (rounded as in the file).
    pub optimal_length: f64,
}

/// The largest `.map` file [`read_map`] reads: 1 GiB.
///
/// A map of [`Grid::MAX_CELLS`] cells takes at most `3 x 2^28` bytes with CRLF line ends (a map
/// one cell wide, a line end per cell) plus its header, which is below this cap; a larger file
/// cannot be a valid map.
pub const MAX_MAP_FILE_BYTES: u64 = 1 << 30;

/// The largest `.map.scen` file [`read_scenarios`] reads: 256 MiB.
///
/// The largest scenario files of the MovingAI sets are a few megabytes (some 100,000 queries of
/// under 100 bytes each); the parsed scenarios take a small multiple of the text's size.
pub const MAX_SCENARIO_FILE_BYTES: u64 = 1 << 28;

/// What is wrong with a line of a map or scenario file.
///
/// The messages never quote the file: a path from a problem document may name any file, whose
/// content must not leak into an error message. They name the line (in [`ParseError`]), the
/// column, the field, and numbers the parser has already read as such.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum ParseErrorKind {
    /// A header line is not `type ...`, `height N`, `width N` or `map`.
    #[error("this is not a map header line (expected type, height, width or map)")]
    UnknownHeader,
    /// A header value is not a number where one is needed.
    #[error("the {key} must be a whole number")]
    BadHeaderValue {
        /// `height` or `width`.
        key: &'static str,
    },
    /// A header line appears twice.
    #[error("a second {0} line (the header has one of each)")]
    DuplicateHeader(&'static str),
    /// The header ended without the named entry.
    #[error("the header has no {0} line")]
    MissingHeader(&'static str),
    /// A map row has the wrong length.
    #[error("the row has {found} cells, but the map is {expected} wide")]
    RowLength {
        /// The declared width.
        expected: usize,
        /// The cells in this row.
        found: usize,
    },
    /// A map row holds a character that is no MovingAI cell. The message names the column but
    /// not the character.
    #[error("column {column}: not a MovingAI cell character (passable: . G S, blocked: @ O T W)")]
    UnknownCell {
        /// The column, from 0.
        column: usize,
        /// The character (for callers; the message does not show it).
        character: char,
    },
    /// The file ended before all rows were read.
    #[error("the map declares {expected} rows but has {found}")]
    MissingRows {
        /// The declared height.
        expected: usize,
        /// The rows found.
        found: usize,
    },
    /// There is text after the last row.
    #[error("unexpected text after the last map row")]
    TrailingText,
    /// The declared size is not a valid grid (a side of 0, or more than [`Grid::MAX_CELLS`]
    /// cells).
    #[error(transparent)]
    Grid(GridError),
    /// The scenario version is not 1 or 1.0, or a second version line.
    #[error("unsupported or repeated scenario version line (supported: one line of version 1 or 1.0, first)")]
    Version,
    /// A scenario line does not have nine fields.
    #[error("a scenario line has 9 fields (bucket, map, width, height, sx, sy, gx, gy, optimal), found {0}")]
    FieldCount(usize),
    /// A scenario field is not a valid number.
    #[error("field {field} is not a valid {expected}")]
    BadField {
        /// The field name.
        field: &'static str,
        /// What was expected there.
        expected: &'static str,
    },
    /// A scenario's start or goal lies outside the map size it declares.
    #[error("the {which} {cell} is outside the declared {width} x {height} map")]
    CellOutside {
        /// `start` or `goal`.
        which: &'static str,
        /// The cell.
        cell: Cell,
        /// The declared width.
        width: u32,
        /// The declared height.
        height: u32,
    },
}

/// A syntax error in a MovingAI file, with its 1-based line number.
#[derive(Debug, Clone, PartialEq, Error)]
#[error("line {line}: {kind}")]
pub struct ParseError {
    /// The line, counted from 1.
    pub line: usize,
    /// What is wrong with it.
    pub kind: ParseErrorKind,
}

/// An error reading a MovingAI file from disk. The messages name the path, never the content.
#[derive(Debug, Error)]
pub enum ReadError {
    /// The file could not be read: missing, not a regular file, larger than the cap
    /// ([`MAX_MAP_FILE_BYTES`], [`MAX_SCENARIO_FILE_BYTES`]), not UTF-8.
    #[error(transparent)]
    File(#[from] ReadFileError),
    /// The file is not a valid map or scenario file.
    #[error("{}: {source}", path.display())]
    Parse {
        /// The file.
        path: PathBuf,
        /// The syntax error.
        source: ParseError,
    },
}

fn err(line: usize, kind: ParseErrorKind) -> ParseError {
    ParseError { line, kind }
}

/// Lines without their terminators (`\n` or `\r\n`), numbered from 1, each with the number of
/// bytes of `text` up to and including its `\n`.
fn numbered_lines(text: &str) -> impl Iterator<Item = (usize, &str, usize)> {
    let mut consumed = 0;
    text.split('\n').enumerate().map(move |(i, raw)| {
        consumed += raw.len() + 1;
        (i + 1, raw.strip_suffix('\r').unwrap_or(raw), consumed)
    })
}

/// Parses the text of a MovingAI `.map` file.
///
/// The header (`type`, `height`, `width` in any order, each once, then `map`) is checked before
/// any row is read, and the size it claims against [`Grid::MAX_CELLS`]; memory for the cells is
/// then reserved for no more of them than the rest of the text can hold, so a short text
/// claiming a huge map costs nothing. Blank lines in the header and at the end are skipped.
pub fn parse_map(text: &str) -> Result<Grid, ParseError> {
    let mut lines = numbered_lines(text);
    let (mut width, mut height, mut kind) = (None, None, false);
    let mut last_line = 0;
    // Header: key/value lines up to `map`; then the bytes of the text it took.
    let consumed = loop {
        let Some((n, line, upto)) = lines.next() else {
            let missing = if height.is_none() {
                "height"
            } else if width.is_none() {
                "width"
            } else {
                "map"
            };
            return Err(err(last_line.max(1), ParseErrorKind::MissingHeader(missing)));
        };
        last_line = n;
        let line = line.trim();
        if line.is_empty() {
            continue;
        }
        let mut parts = line.split_whitespace();
        let key = parts.next().unwrap_or_default();
        let value = parts.next();
        let extra = parts.next().is_some();
        match key {
            "map" if value.is_none() => break upto,
            "type" => {
                if std::mem::replace(&mut kind, true) {
                    return Err(err(n, ParseErrorKind::DuplicateHeader("type")));
                }
            }
            "height" | "width" => {
                let (key, slot): (&'static str, _) =
                    if key == "height" { ("height", &mut height) } else { ("width", &mut width) };
                if slot.is_some() {
                    return Err(err(n, ParseErrorKind::DuplicateHeader(key)));
                }
                let v = value
                    .filter(|_| !extra)
                    .and_then(|v| v.parse::<usize>().ok())
                    .ok_or_else(|| err(n, ParseErrorKind::BadHeaderValue { key }))?;
                *slot = Some(v);
            }
            _ => return Err(err(n, ParseErrorKind::UnknownHeader)),
        }
    };
    let height = height.ok_or_else(|| err(last_line, ParseErrorKind::MissingHeader("height")))?;
    let width = width.ok_or_else(|| err(last_line, ParseErrorKind::MissingHeader("width")))?;
    let cells = Grid::cell_count(width, height).map_err(|e| err(last_line, ParseErrorKind::Grid(e)))?;
    // Each cell takes at least one byte of the text: never reserve for more than it holds.
    let mut costs = Vec::with_capacity(cells.min(text.len().saturating_sub(consumed)));
    let mut row = 0;
    // Blank lines at the end of the file are not rows; a blank line before another line is
    // (a row of the wrong length) or is text after the last row.
    let mut blank = None;
    for (n, line, _) in lines {
        if line.trim().is_empty() {
            blank.get_or_insert((n, line));
            continue;
        }
        for (n, line) in blank.take().into_iter().chain([(n, line)]) {
            if row == height {
                return Err(err(n, ParseErrorKind::TrailingText));
            }
            parse_row(n, line, width, &mut costs)?;
            (row, last_line) = (row + 1, n);
        }
    }
    if row < height {
        return Err(err(last_line, ParseErrorKind::MissingRows { expected: height, found: row }));
    }
    Grid::from_costs(width, height, costs).map_err(|e| err(last_line, ParseErrorKind::Grid(e)))
}

/// Appends the costs of one map row (at most `width` of them) to `costs`: an error unless the
/// row has exactly `width` cell characters.
fn parse_row(n: usize, line: &str, width: usize, costs: &mut Vec<f64>) -> Result<(), ParseError> {
    let mut found = 0;
    for (column, character) in line.chars().enumerate() {
        found += 1;
        if column >= width {
            continue;
        }
        match is_passable_char(character) {
            Some(true) => costs.push(1.0),
            Some(false) => costs.push(f64::INFINITY),
            None => return Err(err(n, ParseErrorKind::UnknownCell { column, character })),
        }
    }
    if found != width {
        return Err(err(n, ParseErrorKind::RowLength { expected: width, found }));
    }
    Ok(())
}

/// Writes `grid` in the MovingAI `.map` format (`.` passable, `@` blocked, `\n` line ends).
/// Cell costs other than passable/blocked are not represented.
pub fn write_map(grid: &Grid) -> String {
    let mut out = String::with_capacity(grid.len() + grid.height() as usize + 40);
    let _ = write!(out, "type octile\nheight {}\nwidth {}\nmap\n", grid.height(), grid.width());
    for row in grid.to_rows() {
        out.push_str(&row);
        out.push('\n');
    }
    out
}

fn field<T: std::str::FromStr>(
    line: usize,
    field: &'static str,
    value: &str,
    expected: &'static str,
) -> Result<T, ParseError> {
    value.parse().map_err(|_| err(line, ParseErrorKind::BadField { field, expected }))
}

/// Parses the text of a MovingAI `.map.scen` scenario file.
///
/// The `version` line may be absent (the oldest files), `version 1` or `version 1.0`, once,
/// before the first query; blank lines are skipped. Every number must be in range: the bucket,
/// sizes and cells `u32`, the declared map size a valid grid (at most [`Grid::MAX_CELLS`]
/// cells), start and goal inside it, and the optimal length finite and non-negative.
pub fn parse_scenarios(text: &str) -> Result<Vec<Scenario>, ParseError> {
    let mut out = Vec::new();
    let mut version = false;
    for (n, line, _) in numbered_lines(text) {
        let trimmed = line.trim();
        if trimmed.is_empty() {
            continue;
        }
        if let Some(v) = trimmed.strip_prefix("version") {
            if out.is_empty() && !version && matches!(v.trim(), "1" | "1.0") {
                version = true;
                continue;
            }
            return Err(err(n, ParseErrorKind::Version));
        }
        // Tabs separate fields when present (so a map name could hold a space); else whitespace.
        let fields: Vec<&str> = if trimmed.contains('\t') {
            trimmed.split('\t').map(str::trim).collect()
        } else {
            trimmed.split_whitespace().collect()
        };
        let [bucket, map, width, height, sx, sy, gx, gy, optimal] = fields[..] else {
            return Err(err(n, ParseErrorKind::FieldCount(fields.len())));
        };
        const WHOLE: &str = "whole number";
        let bucket = field(n, "bucket", bucket, WHOLE)?;
        let map_width: u32 = field(n, "width", width, WHOLE)?;
        let map_height: u32 = field(n, "height", height, WHOLE)?;
        Grid::cell_count(map_width as usize, map_height as usize)
            .map_err(|e| err(n, ParseErrorKind::Grid(e)))?;
        let start = Cell::new(field(n, "start x", sx, WHOLE)?, field(n, "start y", sy, WHOLE)?);
        let goal = Cell::new(field(n, "goal x", gx, WHOLE)?, field(n, "goal y", gy, WHOLE)?);
        const LENGTH: &str = "non-negative number";
        let optimal_length: f64 = field(n, "optimal length", optimal, LENGTH)?;
        if !(optimal_length.is_finite() && optimal_length >= 0.0) {
            return Err(err(n, ParseErrorKind::BadField { field: "optimal length", expected: LENGTH }));
        }
        for (which, cell) in [("start", start), ("goal", goal)] {
            if cell.x >= map_width || cell.y >= map_height {
                return Err(err(
                    n,
                    ParseErrorKind::CellOutside { which, cell, width: map_width, height: map_height },
                ));
            }
        }
        out.push(Scenario {
            bucket,
            map: map.to_string(),
            map_width,
            map_height,
            start,
            goal,
            optimal_length,
        });
    }
    Ok(out)
}

/// Reads and parses a `.map` file: a regular file of at most [`MAX_MAP_FILE_BYTES`] bytes
/// (read with [`read_to_string_capped`]).
pub fn read_map(path: impl AsRef<Path>) -> Result<Grid, ReadError> {
    let path = path.as_ref();
    let text = read_to_string_capped(path, MAX_MAP_FILE_BYTES)?;
    parse_map(&text).map_err(|source| ReadError::Parse { path: path.to_path_buf(), source })
}

/// Reads and parses a `.map.scen` file: a regular file of at most [`MAX_SCENARIO_FILE_BYTES`]
/// bytes (read with [`read_to_string_capped`]).
pub fn read_scenarios(path: impl AsRef<Path>) -> Result<Vec<Scenario>, ReadError> {
    let path = path.as_ref();
    let text = read_to_string_capped(path, MAX_SCENARIO_FILE_BYTES)?;
    parse_scenarios(&text).map_err(|source| ReadError::Parse { path: path.to_path_buf(), source })
}

#[cfg(test)]
mod tests {
    use super::*;

    const MAP: &str = "type octile\nheight 3\nwidth 4\nmap\n.@..\n.T.G\nSWO.\n";

    #[test]
    fn reads_every_cell_kind() {
        let grid = parse_map(MAP).unwrap();
        let rows = grid.to_rows();
        assert_eq!(rows, [".@..", ".@..", ".@@."]);
    }

    #[test]
    fn crlf_header_order_and_trailing_blank_lines() {
        let text = "type octile\r\nwidth 4\r\nheight 3\r\nmap\r\n.@..\r\n.T.G\r\nSWO.\r\n\r\n\r\n";
        assert_eq!(parse_map(text).unwrap(), parse_map(MAP).unwrap());
    }

    #[test]
    fn write_then_read_is_identity() {
        let grid = parse_map(MAP).unwrap();
        assert_eq!(parse_map(&write_map(&grid)).unwrap(), grid);
    }

    #[test]
    fn map_errors_name_the_line() {
        let cases: [(&str, usize, ParseErrorKind); 7] = [
            ("type octile\nheight 2\nmap\n..\n..\n", 3, ParseErrorKind::MissingHeader("width")),
            ("height x\n", 1, ParseErrorKind::BadHeaderValue { key: "height" }),
            ("hight 2\n", 1, ParseErrorKind::UnknownHeader),
            ("height 2\nwidth 2\nmap\n..\n...\n", 5, ParseErrorKind::RowLength { expected: 2, found: 3 }),
            (
                "height 2\nwidth 2\nmap\n..\n.x\n",
                5,
                ParseErrorKind::UnknownCell { column: 1, character: 'x' },
            ),
            ("height 3\nwidth 2\nmap\n..\n..\n", 5, ParseErrorKind::MissingRows { expected: 3, found: 2 }),
            ("height 1\nwidth 2\nmap\n..\n@@\n", 5, ParseErrorKind::TrailingText),
        ];
        for (text, line, kind) in cases {
            assert_eq!(parse_map(text), Err(ParseError { line, kind }), "{text:?}");
        }
        assert!(matches!(
            parse_map("height 0\nwidth 2\nmap\n"),
            Err(ParseError { line: 3, kind: ParseErrorKind::Grid(GridError::Empty { .. }) })
        ));
    }

    #[test]
    fn scenarios_with_tabs_spaces_and_versions() {
        let tabs = "version 1\n0\tmaps/dao/arena.map\t49\t49\t1\t11\t1\t12\t1\n";
        let spaces = "version 1.0\n61 maps/bgmaps/AR0011SR.map 512 512 210 395 87 201 244.95\r\n\n";
        let a = parse_scenarios(tabs).unwrap();
        assert_eq!(a[0].start, Cell::new(1, 11));
        assert_eq!(a[0].optimal_length, 1.0);
        let b = parse_scenarios(spaces).unwrap();
        assert_eq!(b[0].bucket, 61);
        assert_eq!(b[0].map, "maps/bgmaps/AR0011SR.map");
        assert_eq!(
            (b[0].start, b[0].goal, b[0].optimal_length),
            (Cell::new(210, 395), Cell::new(87, 201), 244.95)
        );
        assert_eq!(parse_scenarios("0 m 2 2 0 0 1 1 1.5\n").unwrap().len(), 1, "no version line");
    }

    #[test]
    fn scenario_errors_name_the_line() {
        let e = |t: &str| parse_scenarios(t).unwrap_err();
        assert_eq!(e("version 2\n").kind, ParseErrorKind::Version);
        assert_eq!(e("version 1\nversion 1\n"), ParseError { line: 2, kind: ParseErrorKind::Version });
        assert_eq!(
            e("version 1\n0 m 2 2 0 0 1\n"),
            ParseError { line: 2, kind: ParseErrorKind::FieldCount(7) }
        );
        assert!(matches!(
            e("0 m 2 2 0 0 1 1 -1\n").kind,
            ParseErrorKind::BadField { field: "optimal length", .. }
        ));
        assert!(matches!(
            e("0 m 2 2 0 0 1 1 NaN\n").kind,
            ParseErrorKind::BadField { field: "optimal length", .. }
        ));
        assert!(matches!(e("0 m 2 2 0 -1 1 1 1\n").kind, ParseErrorKind::BadField { field: "start y", .. }));
        assert!(matches!(e("0 m 2 2 0 0 2 1 1\n").kind, ParseErrorKind::CellOutside { which: "goal", .. }));
    }
}
