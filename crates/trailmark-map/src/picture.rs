//! Pictures of costmaps: the map and its inflation as an image (one pixel per cell, in an SVG
//! as an embedded PNG, so a large map stays a small file), the path, start and goal drawn over
//! it in metres.
//!
//! Colours: free cells white, inflated cells from pale to deep violet as their cost rises,
//! the inscribed band (253) light red, lethal cells (254) near black, unknown cells (255) grey.
//!
//! ```
//! use trailmark_core::geometry::Point;
//! use trailmark_map::{Costmap, CostmapSvg, MapFrame};
//!
//! let costmap = Costmap::new(MapFrame::new(3, 2, 0.5, [0.0; 3])?, vec![0, 120, 254, 0, 253, 255])?;
//! let svg = CostmapSvg::new(&costmap).path(&[Point::new(0.25, 0.25), Point::new(0.25, 0.75)]).to_svg()?;
//! assert!(svg.starts_with("<svg") && svg.contains("data:image/png;base64,") && svg.contains("<polyline"));
//! # Ok::<(), trailmark_map::MapError>(())
//! ```

use std::fmt::Write as _;

use base64::Engine as _;
use image::ImageEncoder;
use image::codecs::png::{CompressionType, FilterType, PngEncoder};
use trailmark_core::geometry::Point;

use crate::costmap::Costmap;
use crate::error::MapError;
use crate::values::{INSCRIBED, LETHAL, MAX_NON_OBSTACLE, NO_INFORMATION};

/// The colour of a cost.
pub fn cost_colour(cost: u8) -> [u8; 3] {
    match cost {
        0 => [255, 255, 255],
        NO_INFORMATION => [190, 190, 196],
        LETHAL => [30, 32, 40],
        INSCRIBED => [236, 112, 99],
        c => {
            let t = f64::from(c) / f64::from(MAX_NON_OBSTACLE);
            let mix = |from: f64, to: f64| (from + (to - from) * t).round() as u8;
            [mix(238.0, 108.0), mix(232.0, 52.0), mix(250.0, 131.0)]
        }
    }
}

/// A picture of a costmap and a path over it.
#[derive(Debug, Clone)]
pub struct CostmapSvg<'a> {
    costmap: &'a Costmap,
    pixels_per_cell: f64,
    paths: Vec<Vec<Point>>,
    outlines: Vec<Vec<Point>>,
    marks: Vec<Point>,
    start: Option<Point>,
    goal: Option<Point>,
    title: Option<String>,
}

impl<'a> CostmapSvg<'a> {
    /// A picture of `costmap`, at most 1000 pixels on its longer side (and at least one pixel
    /// per cell).
    pub fn new(costmap: &'a Costmap) -> Self {
        let side = f64::from(costmap.frame().width().max(costmap.frame().height()));
        CostmapSvg {
            costmap,
            pixels_per_cell: (1000.0 / side).clamp(1.0, 24.0),
            paths: Vec::new(),
            outlines: Vec::new(),
            marks: Vec::new(),
            start: None,
            goal: None,
            title: None,
        }
    }

    /// Pixels per cell on screen.
    pub fn pixels_per_cell(mut self, pixels: f64) -> Self {
        self.pixels_per_cell = pixels;
        self
    }

    // The marks below are `WorldSvg`'s too; they are drawn here in cell units on an image and
    // in its own styles, so only their builders look alike.

    /// A path to draw, in metres (several may be drawn, in turn's colours).
    pub fn path(mut self, points: &[Point]) -> Self {
        self.paths.push(points.to_vec());
        self
    }

    /// A closed outline to draw under the paths, in metres: the robot's footprint at a pose.
    pub fn outline(mut self, corners: &[Point]) -> Self {
        self.outlines.push(corners.to_vec());
        self
    }

    /// A point to mark in red, in metres: where a car changes gear.
    pub fn mark(mut self, p: Point) -> Self {
        self.marks.push(p);
        self
    }

    /// The start, in metres.
    pub fn start(mut self, p: Point) -> Self {
        self.start = Some(p);
        self
    }

    /// The goal, in metres.
    pub fn goal(mut self, p: Point) -> Self {
        self.goal = Some(p);
        self
    }

    /// A title (shown as the SVG's `<title>`).
    pub fn title(mut self, title: impl Into<String>) -> Self {
        self.title = Some(title.into());
        self
    }

    /// The costmap alone as an RGB PNG, one pixel per cell, row 0 at the top.
    pub fn to_png(&self) -> Result<Vec<u8>, MapError> {
        let frame = self.costmap.frame();
        let rgb: Vec<u8> = self.costmap.costs().iter().flat_map(|&c| cost_colour(c)).collect();
        let mut png = Vec::new();
        // The default, fastest encoding hardly compresses: a 20 KB map became a 67 MB picture.
        PngEncoder::new_with_quality(&mut png, CompressionType::Best, FilterType::Adaptive)
            .write_image(&rgb, frame.width(), frame.height(), image::ExtendedColorType::Rgb8)
            .map_err(|e| MapError::Save { reason: e.to_string() })?;
        Ok(png)
    }

    /// The SVG document: the costmap image, then the paths, start and goal, in cell units.
    pub fn to_svg(&self) -> Result<String, MapError> {
        let frame = self.costmap.frame();
        let (w, h) = (frame.width(), frame.height());
        let png = base64::engine::general_purpose::STANDARD.encode(self.to_png()?);
        let mut out = String::new();
        let _ = writeln!(
            out,
            r#"<svg xmlns="http://www.w3.org/2000/svg" width="{}" height="{}" viewBox="0 0 {w} {h}">"#,
            (f64::from(w) * self.pixels_per_cell).round(),
            (f64::from(h) * self.pixels_per_cell).round(),
        );
        if let Some(title) = &self.title {
            let escaped = title.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;");
            let _ = writeln!(out, "<title>{escaped}</title>");
        }
        let _ = writeln!(
            out,
            r#"<image width="{w}" height="{h}" image-rendering="pixelated" style="image-rendering:pixelated" href="data:image/png;base64,{png}"/>"#
        );
        let stroke = (f64::from(w.max(h)) / 250.0).clamp(0.3, 3.0);
        let grid = |p: &Point| {
            let (x, y) = frame.point_to_grid(*p);
            format!("{x:.3},{y:.3}")
        };
        for outline in &self.outlines {
            let points: Vec<String> = outline.iter().map(grid).collect();
            let _ = writeln!(
                out,
                r##"<polygon points="{}" fill="#7f8c8d" fill-opacity="0.15" stroke="#555" stroke-width="{:.3}"/>"##,
                points.join(" "),
                stroke / 4.0
            );
        }
        const COLOURS: [&str; 4] = ["#0b62d6", "#f39c12", "#16a085", "#d6245f"];
        for (k, path) in self.paths.iter().enumerate() {
            let points: Vec<String> = path.iter().map(grid).collect();
            let _ = writeln!(
                out,
                r#"<polyline points="{}" fill="none" stroke="{}" stroke-width="{stroke:.3}" stroke-linejoin="round" stroke-linecap="round"/>"#,
                points.join(" "),
                COLOURS[k % COLOURS.len()],
            );
        }
        let r = stroke * 2.0;
        for p in &self.marks {
            let (x, y) = frame.point_to_grid(*p);
            let _ =
                writeln!(out, r##"<circle cx="{x:.3}" cy="{y:.3}" r="{:.3}" fill="#c0392b"/>"##, r * 0.75);
        }
        if let Some(p) = self.start {
            let (x, y) = frame.point_to_grid(p);
            let _ = writeln!(out, r##"<circle cx="{x:.3}" cy="{y:.3}" r="{r:.3}" fill="#27ae60"/>"##);
        }
        if let Some(p) = self.goal {
            let (x, y) = frame.point_to_grid(p);
            let _ = writeln!(
                out,
                r##"<circle cx="{x:.3}" cy="{y:.3}" r="{r:.3}" fill="none" stroke="#c0392b" stroke-width="{:.3}"/>"##,
                r / 2.0
            );
        }
        out.push_str("</svg>\n");
        Ok(out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::frame::MapFrame;

    #[test]
    fn a_plain_map_makes_a_small_picture() {
        // 4096 x 4096 cells, free but for a wall round the edge and a band of inflation.
        let n = 4096usize;
        let costs = (0..n * n)
            .map(|i| {
                let (x, y) = (i % n, i / n);
                let edge = x.min(y).min(n - 1 - x).min(n - 1 - y);
                match edge {
                    0 => LETHAL,
                    1..=4 => INSCRIBED,
                    5..=9 => 100,
                    _ => 0,
                }
            })
            .collect();
        let costmap = Costmap::new(MapFrame::new(n, n, 0.05, [0.0; 3]).unwrap(), costs).unwrap();
        let png = CostmapSvg::new(&costmap).to_png().unwrap();
        // 50 MB of pixels, nearly all alike: 59 KB compressed, 254 KB at the encoder's default.
        assert!(png.len() < 100_000, "{} bytes", png.len());
    }
}
