//! One chart of the picture: a numeric panel or the BOOL lanes, with the grid, the labels and
//! the trigger line every chart shares.

use super::data::{padded, steps};
use super::{AXIS_H, BOOL_COLOR, FONT_SIZE, GRID, LANE_LINE, RIGHT, Series, fail, style};
use plotters::coord::Shift;
use plotters::coord::types::RangedCoordf64;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use std::ops::Range;

/// What one chart shares with the others.
pub struct Chart<'a> {
    pub x: Range<f64>,
    pub left: u32,
    /// The time axis title, for the bottom chart: the others draw no time labels.
    pub axis: Option<&'a str>,
    /// Where the trigger line goes, if it is drawn.
    pub trigger: Option<f64>,
    /// Whether this chart, the top one, labels the trigger line.
    pub trigger_label: bool,
}

impl Chart<'_> {
    /// A numeric panel of `series` on one y axis.
    pub fn panel(
        &self,
        area: &DrawingArea<SVGBackend<'_>, Shift>,
        series: &[&Series],
        no_rows: bool,
    ) -> Result<(), String> {
        let y = padded(series.iter().flat_map(|s| s.points.iter().map(|p| p.1)));
        let mut chart = self
            .builder(area)
            .build_cartesian_2d(self.x.clone(), y.clone())
            .map_err(fail)?;
        let mut units: Vec<&str> = Vec::new();
        for u in series.iter().filter_map(|s| s.unit.as_deref()) {
            if !units.contains(&u) {
                units.push(u);
            }
        }
        let y_desc = if units.is_empty() {
            "value".to_string()
        } else {
            units.join(", ")
        };
        self.mesh(&mut chart, Some(&y_desc))?;
        for s in series {
            line(&mut chart, &s.points, s.color)?;
        }
        if no_rows {
            let middle = ((self.x.start + self.x.end) / 2.0, (y.start + y.end) / 2.0);
            let text = Text::new(
                "no rows recorded",
                middle,
                style(18).pos(Pos::new(HPos::Center, VPos::Center)),
            );
            chart.plotting_area().draw(&text).map_err(fail)?;
        }
        self.mark_trigger(&mut chart, y)
    }

    /// A lane per BOOL, top to bottom in column order, labelled left of the chart on `root`.
    pub fn lanes(
        &self,
        root: &DrawingArea<SVGBackend<'_>, Shift>,
        area: &DrawingArea<SVGBackend<'_>, Shift>,
        labels: &[String],
        bools: &[Vec<(f64, f64)>],
    ) -> Result<(), String> {
        let n = bools.len() as f64;
        let mut chart = self
            .builder(area)
            .build_cartesian_2d(self.x.clone(), 0.0..n)
            .map_err(fail)?;
        self.mesh(&mut chart, None)?;
        for (k, (points, text)) in bools.iter().zip(labels).enumerate() {
            // Lane k from the top spans base..base + 1; the step goes between 20% and 80%.
            let base = n - 1.0 - k as f64;
            let lane = |v: f64| base + 0.2 + 0.6 * v;
            let stepped: Vec<(f64, f64)> = steps(points)
                .into_iter()
                .map(|(t, v)| (t, lane(v)))
                .collect();
            line(&mut chart, &stepped, BOOL_COLOR)?;
            if k > 0 {
                let edge = [(self.x.start, base + 1.0), (self.x.end, base + 1.0)];
                chart
                    .draw_series(LineSeries::new(edge, LANE_LINE))
                    .map_err(fail)?;
            }
            let (px, py) = chart.backend_coord(&(self.x.start, base + 0.5));
            root.draw(&Text::new(
                text.clone(),
                (px - 8, py),
                style(FONT_SIZE).pos(Pos::new(HPos::Right, VPos::Center)),
            ))
            .map_err(fail)?;
        }
        self.mark_trigger(&mut chart, 0.0..n)
    }

    /// A chart on `area` with the margins and label areas every chart shares, so their time
    /// axes line up.
    fn builder<'a, 'b>(
        &self,
        area: &'a DrawingArea<SVGBackend<'b>, Shift>,
    ) -> ChartBuilder<'a, 'b, SVGBackend<'b>> {
        let mut b = ChartBuilder::on(area);
        b.margin_top(10)
            .margin_right(RIGHT)
            .y_label_area_size(self.left)
            .x_label_area_size(if self.axis.is_some() { AXIS_H } else { 0 });
        b
    }

    /// The grid and labels every chart has, the time labels on the bottom one only; a y axis
    /// titled `y_desc`, or none for the lanes.
    fn mesh(&self, chart: &mut Plot<'_>, y_desc: Option<&str>) -> Result<(), String> {
        let (x, y) = (chart.x_range(), chart.y_range());
        let x_tick = |v: &f64| tick(*v, x.end - x.start);
        let y_tick = |v: &f64| tick(*v, y.end - y.start);
        let mut mesh = chart.configure_mesh();
        // Only the grid at the labels, light: the minor lines made the curves hard to follow.
        mesh.label_style(style(FONT_SIZE))
            .axis_desc_style(style(16))
            .bold_line_style(GRID)
            .light_line_style(TRANSPARENT)
            .x_labels(12)
            .y_label_formatter(&y_tick);
        match self.axis {
            Some(axis) => mesh.x_desc(axis).x_label_formatter(&x_tick),
            None => mesh.x_label_formatter(&|_| String::new()),
        };
        match y_desc {
            Some(desc) => mesh.y_desc(desc),
            None => mesh.disable_y_mesh().disable_y_axis(),
        };
        mesh.draw().map_err(fail)
    }

    /// The dashed trigger line at its time, labelled on the top chart.
    fn mark_trigger(&self, chart: &mut Plot<'_>, y: Range<f64>) -> Result<(), String> {
        let Some(t) = self.trigger else {
            return Ok(());
        };
        let dash = BLACK.stroke_width(1);
        chart
            .draw_series(DashedLineSeries::new(
                [(t, y.start), (t, y.end)],
                6,
                4,
                dash,
            ))
            .map_err(fail)?;
        if self.trigger_label {
            let label = EmptyElement::at((t, y.end))
                + Text::new(
                    "trigger",
                    (5, 3),
                    style(FONT_SIZE).pos(Pos::new(HPos::Left, VPos::Top)),
                );
            chart.plotting_area().draw(&label).map_err(fail)?;
        }
        Ok(())
    }
}

/// A chart of seconds against values, as this file draws them.
type Plot<'a> = ChartContext<'a, SVGBackend<'a>, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

/// Draws `points` as a line; a lone point as a dot, which a line would not show.
fn line(chart: &mut Plot<'_>, points: &[(f64, f64)], color: RGBColor) -> Result<(), String> {
    if let [p] = points {
        chart
            .draw_series(std::iter::once(Circle::new(*p, 3, color.filled())))
            .map_err(fail)?;
    } else if !points.is_empty() {
        chart
            .draw_series(LineSeries::new(
                points.iter().copied(),
                color.stroke_width(2),
            ))
            .map_err(fail)?;
    }
    Ok(())
}

/// A tick label as plotters writes it, but `0.0` where rounding left `-0.0` (a tick at the
/// trigger is computed as -1e-17) and with an exponent for values too small for five decimals.
fn tick(v: f64, span: f64) -> String {
    if v.abs() < span * 1e-9 {
        return "0.0".to_string();
    }
    let printer = plotters::data::float::FloatPrettyPrinter {
        allow_scientific: true,
        min_decimal: 1,
        max_decimal: 5,
    };
    printer.print(v)
}
