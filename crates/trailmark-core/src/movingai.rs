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

/// What is wrong with a line of a map or scenario file.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum ParseErrorKind {
    /// A header line is not `type ...`, `height N`, `width N` or `map`.
    #[error("unknown header line {0:?} (expected type, height, width or map)")]
    UnknownHeader(String),
    /// A header value is not a number where one is needed.
    #[error("the {key} must be a whole number, got {value:?}")]
    BadHeaderValue {
        /// `height` or `width`.
        key: &'static str,
        /// The text found.
        value: String,
    },
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
    /// A map row holds a character that is no MovingAI cell.
    #[error("column {column}: unknown cell character {character:?} (passable: . G S, blocked: @ O T W)")]
    UnknownCell {
        /// The column, from 0.
        column: usize,
        /// The character.
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
    /// The declared size is not a valid grid.
    #[error(transparent)]
    Grid(GridError),
    /// The scenario version is not 1 or 1.0.
    #[error("unsupported scenario version {0:?} (supported: 1, 1.0)")]
    Version(String),
    /// A scenario line does not have nine fields.
    #[error("a scenario line has 9 fields (bucket, map, width, height, sx, sy, gx, gy, optimal), found {0}")]
    FieldCount(usize),
    /// A scenario field is not a valid number.
    #[error("field {field}: {value:?} is not a valid {expected}")]
    BadField {
        /// The field name.
        field: &'static str,
        /// The text found.
        value: String,
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

/// An error reading a MovingAI file from disk.
#[derive(Debug, Error)]
pub enum ReadError {
    /// The file could not be read.
    #[error("cannot read {}: {source}", path.display())]
    Io {
        /// The file.
        path: PathBuf,
        /// The I/O error.
        source: std::io::Error,
    },
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

/// Lines without their terminators (`\n` or `\r\n`), numbered from 1.
fn numbered_lines(text: &str) -> impl Iterator<Item = (usize, &str)> {
    text.split('\n').map(|l| l.strip_suffix('\r').unwrap_or(l)).enumerate().map(|(i, l)| (i + 1, l))
}

/// Parses the text of a MovingAI `.map` file.
pub fn parse_map(text: &str) -> Result<Grid, ParseError> {
    let mut lines = numbered_lines(text);
    let mut width = None;
    let mut height = None;
    let mut last_line = 0;
    // Header: key/value lines up to `map`.
    loop {
        let Some((n, line)) = lines.next() else {
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
        let value = parts.collect::<Vec<_>>().join(" ");
        match key {
            "map" if value.is_empty() => break,
            "type" => {}
            "height" | "width" => {
                let key: &'static str = if key == "height" { "height" } else { "width" };
                let v = value
                    .parse::<usize>()
                    .map_err(|_| err(n, ParseErrorKind::BadHeaderValue { key, value: value.clone() }))?;
                if key == "height" { height = Some(v) } else { width = Some(v) }
            }
            _ => return Err(err(n, ParseErrorKind::UnknownHeader(line.to_string()))),
        }
    }
    let height = height.ok_or_else(|| err(last_line, ParseErrorKind::MissingHeader("height")))?;
    let width = width.ok_or_else(|| err(last_line, ParseErrorKind::MissingHeader("width")))?;
    let mut grid = Grid::new(width, height).map_err(|e| err(last_line, ParseErrorKind::Grid(e)))?;
    // Blank lines at the end of the file are not rows.
    let mut rest: Vec<(usize, &str)> = lines.collect();
    while rest.last().is_some_and(|(_, l)| l.trim().is_empty()) {
        rest.pop();
    }
    let mut row = 0;
    for (n, line) in rest {
        last_line = n;
        if row == height {
            return Err(err(n, ParseErrorKind::TrailingText));
        }
        let mut found = 0;
        for (column, character) in line.chars().enumerate() {
            found += 1;
            if column >= width {
                continue;
            }
            match is_passable_char(character) {
                Some(true) => {}
                Some(false) => {
                    let cell = Cell::new(column as u32, row as u32);
                    grid.set_blocked(cell, true).map_err(|e| err(n, ParseErrorKind::Grid(e)))?;
                }
                None => return Err(err(n, ParseErrorKind::UnknownCell { column, character })),
            }
        }
        if found != width {
            return Err(err(n, ParseErrorKind::RowLength { expected: width, found }));
        }
        row += 1;
    }
    if row < height {
        return Err(err(last_line, ParseErrorKind::MissingRows { expected: height, found: row }));
    }
    Ok(grid)
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
    value
        .parse()
        .map_err(|_| err(line, ParseErrorKind::BadField { field, value: value.to_string(), expected }))
}

/// Parses the text of a MovingAI `.map.scen` scenario file.
///
/// The `version` line may be absent (the oldest files), `version 1` or `version 1.0`; blank
/// lines are skipped. Start and goal must lie inside the map size each line declares.
pub fn parse_scenarios(text: &str) -> Result<Vec<Scenario>, ParseError> {
    let mut out = Vec::new();
    for (n, line) in numbered_lines(text) {
        let trimmed = line.trim();
        if trimmed.is_empty() {
            continue;
        }
        if let Some(version) = trimmed.strip_prefix("version") {
            let version = version.trim();
            if out.is_empty() && matches!(version, "1" | "1.0") {
                continue;
            }
            return Err(err(n, ParseErrorKind::Version(version.to_string())));
        }
        // Tabs separate fields when present (so a map name could hold a space); else whitespace.
        let fields: Vec<&str> = if trimmed.contains('\t') {
            trimmed.split('\t').map(str::trim).collect()
        } else {
            trimmed.split_whitespace().collect()
        };
        if fields.len() != 9 {
            return Err(err(n, ParseErrorKind::FieldCount(fields.len())));
        }
        const WHOLE: &str = "whole number";
        let bucket = field(n, "bucket", fields[0], WHOLE)?;
        let map_width: u32 = field(n, "width", fields[2], WHOLE)?;
        let map_height: u32 = field(n, "height", fields[3], WHOLE)?;
        let start = Cell::new(field(n, "start x", fields[4], WHOLE)?, field(n, "start y", fields[5], WHOLE)?);
        let goal = Cell::new(field(n, "goal x", fields[6], WHOLE)?, field(n, "goal y", fields[7], WHOLE)?);
        let optimal_length: f64 = field(n, "optimal length", fields[8], "non-negative number")?;
        if !(optimal_length.is_finite() && optimal_length >= 0.0) {
            return Err(err(
                n,
                ParseErrorKind::BadField {
                    field: "optimal length",
                    value: fields[8].to_string(),
                    expected: "non-negative number",
                },
            ));
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
            map: fields[1].to_string(),
            map_width,
            map_height,
            start,
            goal,
            optimal_length,
        });
    }
    Ok(out)
}

fn read(path: &Path) -> Result<String, ReadError> {
    std::fs::read_to_string(path).map_err(|source| ReadError::Io { path: path.to_path_buf(), source })
}

/// Reads and parses a `.map` file.
pub fn read_map(path: impl AsRef<Path>) -> Result<Grid, ReadError> {
    let path = path.as_ref();
    parse_map(&read(path)?).map_err(|source| ReadError::Parse { path: path.to_path_buf(), source })
}

/// Reads and parses a `.map.scen` file.
pub fn read_scenarios(path: impl AsRef<Path>) -> Result<Vec<Scenario>, ReadError> {
    let path = path.as_ref();
    parse_scenarios(&read(path)?).map_err(|source| ReadError::Parse { path: path.to_path_buf(), source })
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
            ("height x\n", 1, ParseErrorKind::BadHeaderValue { key: "height", value: "x".into() }),
            ("hight 2\n", 1, ParseErrorKind::UnknownHeader("hight 2".into())),
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
        assert_eq!(e("version 2\n").kind, ParseErrorKind::Version("2".into()));
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
