//! Pictures of contingency plans: the terrain shaded by cost, the choke points marked with their
//! probabilities, the preferred route solid and the contingent routes dashed.

use std::collections::HashSet;
use std::fmt::Write;

use trailmark_core::grid::Cell;

use crate::plan::{Action, PlanNode};
use crate::terrain::Terrain;

/// Draws `plan` over `terrain` as an SVG document, `cell` pixels per grid cell.
///
/// The preferred route (every choke point seen open) is a solid red line; the routes taken after
/// a blockage are dashed blue, and those beyond the nesting depth (naive replanning) dotted grey.
/// Choke points are orange, more opaque the likelier they are blocked, labelled with their name
/// and probability. Impassable cells are dark; passable cells darker green the slower they are.
pub fn plan_svg(terrain: &Terrain, plan: &PlanNode, cell: f64, title: &str) -> String {
    let grid = terrain.grid();
    let (w, h) = (grid.width(), grid.height());
    let legend = 18.0;
    let (width, height) = (w as f64 * cell, h as f64 * cell + legend);
    let mut svg = String::new();
    let _ = writeln!(
        svg,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" viewBox="0 0 {width} {height}" font-family="sans-serif">"#
    );
    let _ = writeln!(svg, r##"<rect width="{width}" height="{height}" fill="#ffffff"/>"##);

    // Terrain: runs of equal cost merged into one rectangle per row.
    let max_cost = grid.costs().iter().copied().filter(|c| c.is_finite()).fold(1.0, f64::max);
    let colour = |cost: f64| -> String {
        if !cost.is_finite() {
            return "#3b4a5a".into();
        }
        let t = if max_cost > 1.0 { ((cost - 1.0) / (max_cost - 1.0)).clamp(0.0, 1.0) } else { 0.0 };
        let mix = |a: f64, b: f64| (a + (b - a) * t).round() as u8;
        format!("#{:02x}{:02x}{:02x}", mix(244.0, 74.0), mix(241.0, 124.0), mix(232.0, 64.0))
    };
    for y in 0..h {
        let mut x = 0;
        while x < w {
            let cost = grid.cost(Cell::new(x, y)).unwrap_or(f64::INFINITY);
            let run = (x..w)
                .take_while(|&xx| grid.cost(Cell::new(xx, y)).unwrap_or(f64::INFINITY) == cost)
                .count() as u32;
            let _ = writeln!(
                svg,
                r#"<rect x="{}" y="{}" width="{}" height="{cell}" fill="{}"/>"#,
                x as f64 * cell,
                y as f64 * cell,
                run as f64 * cell,
                colour(cost)
            );
            x += run;
        }
    }

    // Choke points.
    for choke in terrain.choke_points() {
        let opacity = 0.25 + 0.75 * choke.probability;
        for c in &choke.cells {
            let _ = writeln!(
                svg,
                r##"<rect x="{}" y="{}" width="{cell}" height="{cell}" fill="#e67e22" fill-opacity="{opacity:.2}" stroke="#a04000" stroke-width="0.5"/>"##,
                c.x as f64 * cell,
                c.y as f64 * cell
            );
        }
    }

    // Routes: contingent ones first, so the preferred route is drawn on top.
    let preferred = plan.preferred_route();
    let mut seen = HashSet::new();
    let mut drives = Vec::new();
    collect_drives(plan, &mut drives);
    let centre = |c: &Cell| format!("{:.1},{:.1}", (c.x as f64 + 0.5) * cell, (c.y as f64 + 0.5) * cell);
    let polyline = |cells: &[Cell]| cells.iter().map(centre).collect::<Vec<_>>().join(" ");
    let stroke = (cell / 4.0).max(1.0);
    for (route, replan) in drives {
        if route.len() < 2 || !seen.insert(route.clone()) || is_part_of(&preferred, &route) {
            continue;
        }
        let style = if replan {
            format!(r##"stroke="#7f8c8d" stroke-dasharray="{:.1} {:.1}""##, stroke, stroke * 2.0)
        } else {
            format!(r##"stroke="#1f5fa8" stroke-dasharray="{:.1} {:.1}""##, stroke * 4.0, stroke * 2.5)
        };
        let _ = writeln!(
            svg,
            r#"<polyline points="{}" fill="none" {style} stroke-width="{stroke:.1}" stroke-linejoin="round"/>"#,
            polyline(&route)
        );
    }
    let _ = writeln!(
        svg,
        r##"<polyline points="{}" fill="none" stroke="#c0392b" stroke-width="{:.1}" stroke-linejoin="round"/>"##,
        polyline(&preferred),
        stroke * 1.5
    );

    // Start, goal, labels.
    for (c, fill) in [(terrain.start(), "#27ae60"), (terrain.goal(), "#111111")] {
        let _ = writeln!(
            svg,
            r##"<circle cx="{:.1}" cy="{:.1}" r="{:.1}" fill="{fill}" stroke="#ffffff" stroke-width="1"/>"##,
            (c.x as f64 + 0.5) * cell,
            (c.y as f64 + 0.5) * cell,
            cell * 0.8
        );
    }
    let font = (cell * 1.4).max(9.0);
    for choke in terrain.choke_points() {
        let n = choke.cells.len() as f64;
        let cx = choke.cells.iter().map(|c| c.x as f64 + 0.5).sum::<f64>() / n * cell;
        let cy = choke.cells.iter().map(|c| c.y as f64 + 0.5).sum::<f64>() / n * cell;
        let _ = writeln!(
            svg,
            r##"<text x="{cx:.1}" y="{:.1}" font-size="{font:.1}" text-anchor="middle" fill="#111111" stroke="#ffffff" stroke-width="3" paint-order="stroke">{} p={:.2}</text>"##,
            cy - cell,
            escape(&choke.name),
            choke.probability
        );
    }
    let _ = writeln!(
        svg,
        r##"<text x="4" y="{:.1}" font-size="12" fill="#111111">{}</text>"##,
        height - 5.0,
        escape(title)
    );
    svg.push_str("</svg>\n");
    svg
}

/// Every drive of the plan: its route and whether it is naive replanning.
fn collect_drives(node: &PlanNode, out: &mut Vec<(Vec<Cell>, bool)>) {
    if let Action::Drive(d) = &node.action {
        out.push((d.route.clone(), d.replan));
        for o in &d.outcomes {
            collect_drives(&o.next, out);
        }
    }
}

/// Whether `part` appears in `route` as consecutive cells.
fn is_part_of(route: &[Cell], part: &[Cell]) -> bool {
    route.windows(part.len()).any(|w| w == part)
}

fn escape(text: &str) -> String {
    text.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;")
}
