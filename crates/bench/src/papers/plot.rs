//! SVG line plots (plotters' SVG backend), one series per algorithm.

use std::path::Path;

use plotters::prelude::*;

/// One plotted series: its name and its (x, y) points.
pub struct Series {
    /// Legend text.
    pub name: String,
    /// Points, drawn in the given order, joined by a line unless the plot is a scatter.
    pub points: Vec<(f64, f64)>,
}

/// Axis scale.
#[derive(Clone, Copy, PartialEq, Eq)]
pub enum Axis {
    /// Linear.
    Linear,
    /// Base-10 logarithmic (the values are plotted as log10; non-positive values are left out).
    Log,
}

/// A plot to write.
pub struct Plot<'a> {
    /// Title.
    pub title: &'a str,
    /// X axis label.
    pub x_label: &'a str,
    /// Y axis label.
    pub y_label: &'a str,
    /// X axis scale.
    pub x_axis: Axis,
    /// Y axis scale.
    pub y_axis: Axis,
    /// Points only, no lines.
    pub scatter: bool,
}

/// The plots of one report, written into one folder.
pub struct Gallery<'a> {
    out: &'a Path,
    /// (file name, title) of each plot written.
    pub written: Vec<(String, String)>,
}

impl<'a> Gallery<'a> {
    /// An empty gallery writing into `out`.
    pub fn new(out: &'a Path) -> Self {
        Self {
            out,
            written: Vec::new(),
        }
    }

    /// Writes `plot` as `file` (see [`write()`]) and lists it if anything was drawn.
    pub fn add(&mut self, file: &str, plot: &Plot, series: &[Series]) -> anyhow::Result<()> {
        if write(&self.out.join(file), plot, series)? {
            self.written
                .push((file.to_string(), plot.title.to_string()));
        }
        Ok(())
    }
}

/// The "Plots" section of a report: one link per plot written.
pub fn section(plots: &[(String, String)]) -> String {
    let mut md = String::from("\n## Plots\n\n");
    for (file, title) in plots {
        md += &format!("- [{title}]({file})\n");
    }
    md + "\n"
}

const COLOURS: [RGBColor; 6] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(148, 103, 189),
    RGBColor(255, 127, 14),
    RGBColor(0, 0, 0),
];

fn transform(axis: Axis, v: f64) -> Option<f64> {
    match axis {
        Axis::Linear => v.is_finite().then_some(v),
        Axis::Log => (v > 0.0 && v.is_finite()).then(|| v.log10()),
    }
}

/// Writes `series` to `path` as an 800 x 500 SVG. Returns whether anything was drawn (a plot
/// without a single finite point is not written).
pub fn write(path: &Path, plot: &Plot, series: &[Series]) -> anyhow::Result<bool> {
    let data: Vec<(String, Vec<(f64, f64)>)> = series
        .iter()
        .map(|s| {
            let pts = s
                .points
                .iter()
                .filter_map(|&(x, y)| {
                    Some((transform(plot.x_axis, x)?, transform(plot.y_axis, y)?))
                })
                .collect();
            (s.name.clone(), pts)
        })
        .filter(|(_, p): &(String, Vec<(f64, f64)>)| !p.is_empty())
        .collect();
    let all: Vec<(f64, f64)> = data.iter().flat_map(|(_, p)| p.iter().copied()).collect();
    if all.is_empty() {
        return Ok(false);
    }
    let range = |f: fn(&(f64, f64)) -> f64| {
        let lo = all.iter().map(f).fold(f64::INFINITY, f64::min);
        let hi = all.iter().map(f).fold(f64::NEG_INFINITY, f64::max);
        let pad = ((hi - lo) * 0.05).max(1e-9 + lo.abs() * 0.05);
        (lo - pad)..(hi + pad)
    };
    let label = |text: &str, axis: Axis| match axis {
        Axis::Linear => text.to_string(),
        Axis::Log => format!("log10 {text}"),
    };
    let root = SVGBackend::new(path, (800, 500)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| anyhow::anyhow!("{e}"))?;
    let mut chart = ChartBuilder::on(&root)
        .caption(plot.title, ("sans-serif", 20))
        .margin(10)
        .x_label_area_size(40)
        .y_label_area_size(60)
        .build_cartesian_2d(range(|p| p.0), range(|p| p.1))
        .map_err(|e| anyhow::anyhow!("{e}"))?;
    chart
        .configure_mesh()
        .x_desc(label(plot.x_label, plot.x_axis))
        .y_desc(label(plot.y_label, plot.y_axis))
        .draw()
        .map_err(|e| anyhow::anyhow!("{e}"))?;
    for (i, (name, points)) in data.iter().enumerate() {
        let colour = COLOURS[i % COLOURS.len()];
        if !plot.scatter {
            chart
                .draw_series(LineSeries::new(points.iter().copied(), colour))
                .map_err(|e| anyhow::anyhow!("{e}"))?;
        }
        chart
            .draw_series(points.iter().map(|&p| Circle::new(p, 3, colour.filled())))
            .map_err(|e| anyhow::anyhow!("{e}"))?
            .label(name.as_str())
            .legend(move |(x, y)| Circle::new((x + 10, y), 4, colour.filled()));
    }
    chart
        .configure_series_labels()
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .draw()
        .map_err(|e| anyhow::anyhow!("{e}"))?;
    root.present().map_err(|e| anyhow::anyhow!("{e}"))?;
    Ok(true)
}
