//! The trace as an SVG picture, drawn with plotters.
//!
//! Top to bottom: the title, a legend (each numeric variable's colour, path and unit), the
//! numeric panels, a lane per BOOL (a step line labelled with its path), and the time axis in
//! seconds from the trigger (a dashed line labelled "trigger" at 0) or from the first row.
//! STRINGs are not drawn; LTIMEs are drawn in seconds.
//!
//! Numeric variables share a y axis while it shows each of them: a variable joins a panel only
//! if the panel's span stays within [`SHARED_SPAN`] times the range of each varying variable
//! in it, and otherwise starts a panel of its own below. One axis for all would flatten a
//! 0.5 mm position under a 50 kN force; a panel per variable would be 64 panels; grouping by
//! range gives one panel in the common case and a few, each readable, otherwise. A panel's
//! axis names the units of its own variables ("kN, mm"); variables without a unit (counters,
//! plain numbers) share panels only with each other, whose axis says "value".
//!
//! Each line keeps at most two points per pixel of width (the lowest and the highest), so
//! peaks survive and a minute at 4 kHz of four variables makes a file of some 65 kB.

mod chart;
mod data;
mod decimate;
#[cfg(test)]
mod tests;

use super::{Column, Row};
use chart::Chart;
use data::{label, number, padded, panels, shorten, unit};
use decimate::min_max;
use plc_core::{IecType, TypeFamily};
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// How many times its own range a variable's panel may span: at 20, a variable still fills at
/// least a twentieth of the panel's height, some 15 pixels.
const SHARED_SPAN: f64 = 20.0;
const WIDTH: u32 = 1200;
/// Left of every chart, the same so their time axes line up: y labels or lane labels.
const MIN_LEFT: u32 = 90;
const MAX_LEFT: u32 = 380;
const RIGHT: u32 = 30;
const TITLE_H: u32 = 40;
const ONE_PANEL_H: u32 = 400;
const PANEL_H: u32 = 240;
const LANE_H: u32 = 26;
/// Under the bottom chart: the time labels and the axis title.
const AXIS_H: u32 = 46;
const LEGEND_ROW_H: u32 = 18;
const FONT: &str = "sans-serif";
/// Plotters writes sizes divided by 1.24: 15 is 12 px in the SVG.
const FONT_SIZE: u32 = 15;
/// A 12 px sans-serif character's width, to lay labels out (SVG has no text metrics).
const CHAR_W: u32 = 7;
/// Lane labels longer than this keep their end, where paths differ.
const MAX_LABEL_CHARS: usize = 50;
/// Distinct on white (the d3 "category10" colours); the 11th variable reuses the first.
const PALETTE: [RGBColor; 10] = [
    RGBColor(0x1f, 0x77, 0xb4),
    RGBColor(0xff, 0x7f, 0x0e),
    RGBColor(0x2c, 0xa0, 0x2c),
    RGBColor(0xd6, 0x27, 0x28),
    RGBColor(0x94, 0x67, 0xbd),
    RGBColor(0x8c, 0x56, 0x4b),
    RGBColor(0xe3, 0x77, 0xc2),
    RGBColor(0x7f, 0x7f, 0x7f),
    RGBColor(0xbc, 0xbd, 0x22),
    RGBColor(0x17, 0xbe, 0xcf),
];
const BOOL_COLOR: RGBColor = RGBColor(0x2f, 0x4b, 0x7c);
const LANE_LINE: RGBColor = RGBColor(0xbb, 0xbb, 0xbb);
const GRID: RGBColor = RGBColor(0xe4, 0xe4, 0xe4);

/// One variable's line, decimated, non-finite values skipped.
struct Series {
    label: String,
    unit: Option<String>,
    color: RGBColor,
    points: Vec<(f64, f64)>,
}

/// The rows a picture is drawn from, kept as numbers column by column: 8 bytes a value, where
/// a [`Row`]'s values take the size of the largest (a STRING's 255 bytes), so a 4 kHz trace of
/// 64 values for a minute is 120 MB and not 4 GB.
#[derive(Clone, Debug, Default)]
pub struct Samples {
    times_ns: Vec<u64>,
    /// One list per column; NaN where a row has no number (a STRING, a missing value).
    columns: Vec<Vec<f64>>,
}

impl Samples {
    /// No rows yet, for `columns` columns.
    pub fn new(columns: usize) -> Samples {
        Samples {
            times_ns: Vec::new(),
            columns: vec![Vec::new(); columns],
        }
    }

    /// `rows`, for `columns` columns.
    #[cfg(test)]
    pub fn from_rows(columns: usize, rows: &[Row]) -> Samples {
        let mut s = Samples::new(columns);
        for r in rows {
            s.push(r);
        }
        s
    }

    /// Adds a row.
    pub fn push(&mut self, row: &Row) {
        self.times_ns.push(row.time_ns);
        for (i, column) in self.columns.iter_mut().enumerate() {
            column.push(row.values.get(i).and_then(number).unwrap_or(f64::NAN));
        }
    }
}

/// The picture of `samples` of `columns`, titled `title`; time zero is `trigger_time_ns`
/// (marked) if given, else the first row.
pub fn svg(
    title: &str,
    columns: &[Column],
    samples: &Samples,
    trigger_time_ns: Option<u64>,
) -> Result<String, String> {
    let origin = trigger_time_ns
        .or(samples.times_ns.first().copied())
        .unwrap_or(0);
    let times: Vec<f64> = samples
        .times_ns
        .iter()
        .map(|&t| (t as i128 - origin as i128) as f64 / 1e9)
        .collect();
    let x = padded(times.iter().copied());
    let bool_labels: Vec<String> = columns
        .iter()
        .filter(|c| c.iec_type == IecType::Bool)
        .map(|c| shorten(&label(c)))
        .collect();
    let longest = bool_labels.iter().map(|l| l.chars().count()).max();
    let left = (longest.unwrap_or(0) as u32 * CHAR_W + 16).clamp(MIN_LEFT, MAX_LEFT);
    let buckets = (WIDTH - left - RIGHT) as usize;

    let (mut numeric, mut bools) = (Vec::new(), Vec::new());
    for (i, c) in columns.iter().enumerate() {
        let points = || {
            let values = samples.columns.get(i).map_or(&[][..], |c| &c[..]);
            let finite = times
                .iter()
                .zip(values)
                .filter(|(_, v)| v.is_finite())
                .map(|(t, v)| (*t, *v));
            min_max(&finite.collect::<Vec<_>>(), x.clone(), buckets)
        };
        match c.iec_type.family() {
            TypeFamily::String => {}
            TypeFamily::Bool => bools.push(points()),
            _ => numeric.push(Series {
                label: label(c),
                unit: unit(c).map(str::to_string),
                color: PALETTE[numeric.len() % PALETTE.len()],
                points: points(),
            }),
        }
    }
    let mut panels = panels(&numeric);
    if panels.is_empty() && bools.is_empty() {
        // Nothing to draw is still a chart with axes.
        panels.push(Vec::new());
    }

    let per_row = ((WIDTH - left) / legend_entry_width(&numeric)).max(1) as usize;
    let legend_h = numeric.len().div_ceil(per_row) as u32 * LEGEND_ROW_H + 8;
    let panel_h = if panels.len() == 1 {
        ONE_PANEL_H
    } else {
        PANEL_H
    };
    let lanes_h = if bools.is_empty() {
        0
    } else {
        bools.len() as u32 * LANE_H + 10
    };
    let height = TITLE_H + legend_h + panels.len() as u32 * panel_h + lanes_h + AXIS_H + 10;

    let mut out = String::new();
    {
        let root = SVGBackend::with_string(&mut out, (WIDTH, height)).into_drawing_area();
        root.fill(&WHITE).map_err(fail)?;
        let (top, rest) = root.split_vertically(TITLE_H);
        top.draw(&Text::new(
            title.to_string(),
            (WIDTH as i32 / 2, TITLE_H as i32 / 2 + 4),
            style(20).pos(Pos::new(HPos::Center, VPos::Center)),
        ))
        .map_err(fail)?;
        let (legend_area, mut rest) = rest.split_vertically(legend_h);
        legend(&legend_area, &numeric, left, per_row)?;
        let axis = if trigger_time_ns.is_some() {
            "time from trigger (s)"
        } else {
            "time from first row (s)"
        };
        let trigger = trigger_time_ns
            .is_some()
            .then_some(0.0)
            .filter(|t| x.contains(t));
        for (k, members) in panels.iter().enumerate() {
            let last = k + 1 == panels.len() && bools.is_empty();
            let (area, below) = rest.split_vertically(panel_h + if last { AXIS_H } else { 0 });
            let series: Vec<&Series> = members.iter().map(|&i| &numeric[i]).collect();
            let chart = Chart {
                x: x.clone(),
                left,
                axis: last.then_some(axis),
                trigger,
                trigger_label: k == 0,
            };
            chart.panel(&area, &series, samples.times_ns.is_empty())?;
            rest = below;
        }
        if !bools.is_empty() {
            let chart = Chart {
                x: x.clone(),
                left,
                axis: Some(axis),
                trigger,
                trigger_label: panels.is_empty(),
            };
            chart.lanes(&root, &rest, &bool_labels, &bools)?;
        }
        root.present().map_err(fail)?;
    }
    Ok(out)
}

/// The legend: a colour sample and `path (unit)` per numeric variable, `per_row` to a row,
/// aligned with the charts' left edge.
fn legend(
    area: &DrawingArea<SVGBackend<'_>, Shift>,
    series: &[Series],
    left: u32,
    per_row: usize,
) -> Result<(), String> {
    let entry = legend_entry_width(series) as i32;
    for (k, s) in series.iter().enumerate() {
        let x = left as i32 + (k % per_row) as i32 * entry;
        let y = (k / per_row) as i32 * LEGEND_ROW_H as i32 + LEGEND_ROW_H as i32 / 2 + 4;
        area.draw(&PathElement::new(
            [(x, y), (x + 20, y)],
            s.color.stroke_width(3),
        ))
        .map_err(fail)?;
        let text = style(FONT_SIZE).pos(Pos::new(HPos::Left, VPos::Center));
        area.draw(&Text::new(s.label.clone(), (x + 26, y), text))
            .map_err(fail)?;
    }
    Ok(())
}

/// The width of a legend entry: the longest label, its sample and a gap.
fn legend_entry_width(series: &[Series]) -> u32 {
    let longest = series.iter().map(|s| s.label.chars().count()).max();
    longest.unwrap_or(0) as u32 * CHAR_W + 44
}

/// Black text of `size` in the one font family.
fn style(size: u32) -> TextStyle<'static> {
    TextStyle::from((FONT, size).into_font()).color(&BLACK)
}

/// A plotters error as the user's message.
fn fail(e: impl std::fmt::Display) -> String {
    format!("cannot draw the trace: {e}")
}
