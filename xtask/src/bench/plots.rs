//! The harness's distribution plots (plotters, SVG backend, no fonts needed): horizontal box
//! plots of per-query times on a log axis, and success rates as the share of queries solved by
//! each time.

use plotters::coord::types::RangedCoordf64;
use plotters::prelude::*;

use crate::bench::stats::quantile;

/// Colours of the series, in order.
pub const COLOURS: [RGBColor; 5] = [
    RGBColor(225, 48, 108),
    RGBColor(22, 160, 133),
    RGBColor(41, 128, 185),
    RGBColor(243, 156, 18),
    RGBColor(142, 68, 173),
];

/// One series of a box plot: a name, a colour, and the values of each category (one box each;
/// an empty list draws none).
pub struct BoxSeries {
    pub name: String,
    pub colour: RGBColor,
    pub values: Vec<Vec<f64>>,
}

/// Tukey's box: quartiles, whiskers at the most extreme values within 1.5 interquartile ranges,
/// and the values beyond them. `None` without a positive finite value (the axis is logarithmic).
#[derive(Debug, Clone, PartialEq)]
pub struct Box5 {
    pub low: f64,
    pub q1: f64,
    pub median: f64,
    pub q3: f64,
    pub high: f64,
    pub outliers: Vec<f64>,
}

impl Box5 {
    pub fn of(values: &[f64]) -> Option<Box5> {
        let mut v: Vec<f64> = values.iter().copied().filter(|x| x.is_finite() && *x > 0.0).collect();
        if v.is_empty() {
            return None;
        }
        v.sort_by(f64::total_cmp);
        let (q1, median, q3) = (quantile(&v, 0.25), quantile(&v, 0.5), quantile(&v, 0.75));
        let (lo_fence, hi_fence) = (q1 - 1.5 * (q3 - q1), q3 + 1.5 * (q3 - q1));
        let inside = v.iter().copied().filter(|x| (lo_fence..=hi_fence).contains(x));
        let (low, high) = inside.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| (a.min(x), b.max(x)));
        let outliers = v.iter().copied().filter(|x| !(lo_fence..=hi_fence).contains(x)).collect();
        Some(Box5 { low, q1, median, q3, high, outliers })
    }
}

fn err(e: impl std::fmt::Display) -> String {
    e.to_string()
}

/// A chart of the module: a logarithmic x axis, a linear y axis.
type Chart<'a, 'b> = ChartContext<'a, SVGBackend<'b>, Cartesian2d<LogCoord<f64>, RangedCoordf64>>;

/// Draws the chart's legend at `position`.
fn legend<'b>(chart: &mut Chart<'b, 'b>, position: SeriesLabelPosition) -> Result<(), String> {
    chart
        .configure_series_labels()
        .label_font(("sans-serif", 13))
        .position(position)
        .border_style(BLACK)
        .background_style(WHITE.mix(0.9))
        .draw()
        .map_err(err)
}

/// A horizontal box plot: one row per category (top to bottom), one box per series in each row,
/// values on a logarithmic axis described by `x_desc`.
pub fn box_plot_svg(
    caption: &str,
    x_desc: &str,
    categories: &[String],
    series: &[BoxSeries],
) -> Result<String, String> {
    let boxes: Vec<Vec<Option<Box5>>> =
        series.iter().map(|s| s.values.iter().map(|v| Box5::of(v)).collect()).collect();
    let all = boxes.iter().flatten().flatten();
    let (lo, hi) = all
        .flat_map(|b| b.outliers.iter().copied().chain([b.low, b.high]))
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| (a.min(x), b.max(x)));
    if !lo.is_finite() {
        return Err("no positive values to plot".into());
    }
    let (lo, hi) = (lo / 1.5, hi * 1.5);
    let n = categories.len();
    let height = 90 + 26 * n as u32 * series.len().max(1) as u32;
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (760, height)).into_drawing_area();
        root.fill(&WHITE).map_err(err)?;
        let label_width = 12 + 7 * categories.iter().map(|c| c.chars().count()).max().unwrap_or(4) as u32;
        let mut chart = ChartBuilder::on(&root)
            .caption(caption, ("sans-serif", 15))
            .margin(12)
            .x_label_area_size(36)
            .y_label_area_size(label_width)
            .build_cartesian_2d((lo..hi).log_scale(), -0.5..n as f64 - 0.5)
            .map_err(err)?;
        // Category i is drawn at y = n - 1 - i, so the first is at the top.
        let name_at = |y: &f64| {
            let i = n as f64 - 1.0 - y.round();
            if (y - y.round()).abs() < 1e-6 && i >= 0.0 { categories.get(i as usize).cloned() } else { None }
        };
        chart
            .configure_mesh()
            .label_style(("sans-serif", 13))
            .axis_desc_style(("sans-serif", 14))
            .x_desc(x_desc)
            .y_labels(n.max(1))
            .y_label_formatter(&|y| name_at(y).unwrap_or_default())
            .disable_y_mesh()
            .draw()
            .map_err(err)?;
        let band = 0.8 / series.len().max(1) as f64;
        for (k, (s, boxes)) in series.iter().zip(&boxes).enumerate() {
            let colour = s.colour;
            let offset = 0.4 - band * (k as f64 + 0.5);
            let mut first = true;
            for (i, b) in boxes.iter().enumerate() {
                let Some(b) = b else { continue };
                let y = (n - 1 - i) as f64 + offset;
                let half = band * 0.35;
                let stroke = colour.stroke_width(1);
                let mut shapes: Vec<DynElement<'static, SVGBackend, (f64, f64)>> = vec![
                    Rectangle::new([(b.q1, y - half), (b.q3, y + half)], colour.mix(0.25).filled())
                        .into_dyn(),
                    Rectangle::new([(b.q1, y - half), (b.q3, y + half)], stroke).into_dyn(),
                    PathElement::new(
                        vec![(b.median, y - half), (b.median, y + half)],
                        colour.stroke_width(3),
                    )
                    .into_dyn(),
                    PathElement::new(vec![(b.low, y), (b.q1, y)], stroke).into_dyn(),
                    PathElement::new(vec![(b.q3, y), (b.high, y)], stroke).into_dyn(),
                    PathElement::new(vec![(b.low, y - half / 2.0), (b.low, y + half / 2.0)], stroke)
                        .into_dyn(),
                    PathElement::new(vec![(b.high, y - half / 2.0), (b.high, y + half / 2.0)], stroke)
                        .into_dyn(),
                ];
                shapes.extend(
                    b.outliers.iter().map(|&x| Circle::new((x, y), 2, colour.stroke_width(1)).into_dyn()),
                );
                let drawn = chart.draw_series(shapes).map_err(err)?;
                if first {
                    first = false;
                    drawn.label(s.name.clone()).legend(move |(x, y)| {
                        Rectangle::new([(x, y - 5), (x + 16, y + 5)], colour.mix(0.5).filled())
                    });
                }
            }
        }
        legend(&mut chart, SeriesLabelPosition::UpperRight)?;
        root.present().map_err(err)?;
    }
    Ok(svg)
}

/// One line of a success plot: the times at which queries were solved, out of `total`.
pub struct SuccessLine {
    pub label: String,
    pub colour: RGBColor,
    pub dashed: bool,
    pub solved_at: Vec<f64>,
    pub total: usize,
}

/// The share of queries solved by each time (log axis): a step line per series, ending at the
/// series' success rate.
pub fn success_svg(caption: &str, x_desc: &str, lines: &[SuccessLine]) -> Result<String, String> {
    let times = lines.iter().flat_map(|l| l.solved_at.iter().copied()).filter(|t| *t > 0.0 && t.is_finite());
    let (lo, hi) = times.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| (a.min(x), b.max(x)));
    if !lo.is_finite() {
        return Err("no solved queries to plot".into());
    }
    let (lo, hi) = (lo / 1.5, hi * 1.5);
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (760, 440)).into_drawing_area();
        root.fill(&WHITE).map_err(err)?;
        let mut chart = ChartBuilder::on(&root)
            .caption(caption, ("sans-serif", 15))
            .margin(12)
            .x_label_area_size(36)
            .y_label_area_size(56)
            .build_cartesian_2d((lo..hi).log_scale(), 0.0..101.0)
            .map_err(err)?;
        chart
            .configure_mesh()
            .label_style(("sans-serif", 13))
            .axis_desc_style(("sans-serif", 14))
            .x_desc(x_desc)
            .y_desc("% of queries solved")
            .draw()
            .map_err(err)?;
        for line in lines {
            let mut at: Vec<f64> =
                line.solved_at.iter().copied().filter(|t| *t > 0.0 && t.is_finite()).collect();
            at.sort_by(f64::total_cmp);
            let share = |k: usize| 100.0 * k as f64 / line.total.max(1) as f64;
            let mut points = vec![(lo, 0.0)];
            for (k, &t) in at.iter().enumerate() {
                points.extend([(t, share(k)), (t, share(k + 1))]);
            }
            points.push((hi, share(at.len())));
            let (colour, style) = (line.colour, line.colour.stroke_width(2));
            let series = if line.dashed {
                chart.draw_series(DashedLineSeries::new(points, 6, 4, style))
            } else {
                chart.draw_series(LineSeries::new(points, style))
            };
            series
                .map_err(err)?
                .label(line.label.clone())
                .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 18, y)], colour.stroke_width(2)));
        }
        legend(&mut chart, SeriesLabelPosition::LowerRight)?;
        root.present().map_err(err)?;
    }
    Ok(svg)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tukey_boxes_by_hand() {
        // 1..=9 and 100: quartiles by linear interpolation 3.25, 5.5, 7.75; fences -3.5 and 14.5.
        let mut v: Vec<f64> = (1..=9).map(f64::from).collect();
        v.push(100.0);
        let b = Box5::of(&v).unwrap();
        assert_eq!((b.q1, b.median, b.q3), (3.25, 5.5, 7.75));
        assert_eq!((b.low, b.high), (1.0, 9.0));
        assert_eq!(b.outliers, vec![100.0]);
        assert_eq!(Box5::of(&[0.0, -1.0, f64::NAN]), None);
    }

    #[test]
    fn plots_draw_their_series() {
        let categories = vec!["a".to_string(), "b".to_string()];
        let series =
            [BoxSeries { name: "one".into(), colour: COLOURS[0], values: vec![vec![1.0, 2.0, 3.0], vec![]] }];
        let svg = box_plot_svg("t", "ms", &categories, &series).unwrap();
        // plotters writes each text on a line of its own.
        assert!(svg.contains("<svg") && svg.contains("\none\n") && svg.contains("\na\n"));
        let line = SuccessLine {
            label: "x".into(),
            colour: COLOURS[1],
            dashed: true,
            solved_at: vec![1.0, 2.0],
            total: 4,
        };
        let svg = success_svg("t", "ms", &[line]).unwrap();
        assert!(svg.contains("\nx\n"));
        assert!(box_plot_svg("t", "ms", &categories, &[]).is_err());
    }
}
