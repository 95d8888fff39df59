//! `plc watch <segment>`: a live watch window (ratatui). Keys: `/` filter, arrows and
//! PgUp/PgDn select, Enter write a value to the selected variable (checked as `plc set`
//! checks), `p` toggle reals between 6 significant digits (or `--digits`) and full precision,
//! `q` or Esc quit. Bit-mapped bools are shown under their source word; values that
//! changed in the last second are highlighted; forced values (`plc force`) are marked `F`, values an alarm watches `!` (red while it is
//! active or unacknowledged; the header counts them). Structures and arrays of structures are a tree:
//! Right (or Enter) opens the selected one, Left closes it. `PLC_WATCH_FRAME_LOG=FILE` appends
//! each refresh's time to FILE (see [`frame_log`]).

use super::watch_marks::{self, Mark, Marks};
use super::{Error, period_of, set, show, type_text};
use crate::display::{self, Format};
use plc_shm::{DynSegment, PathLocation, PathTarget};
use ratatui::crossterm::event::{self, Event, KeyCode, KeyEventKind};
use ratatui::layout::{Constraint, Layout};
use ratatui::style::{Modifier, Style, Stylize};
use ratatui::text::Line;
use ratatui::widgets::{Block, Paragraph, Row, Table, TableState};
use std::collections::{HashMap, HashSet};
use std::io::Write;
use std::time::{Duration, Instant};

/// Significant digits of reals unless `--digits` says otherwise: enough to read a measurement,
/// few enough that the last digits of a computed value do not flicker.
const DIGITS: u8 = 6;

enum Mode {
    Browse,
    Filter,
    Edit(String),
}

/// One line of the window.
enum Entry {
    /// A top-level basic variable (an array shown whole).
    Var(usize),
    /// A structure, an array of structures or one of its elements, at `depth` in the tree.
    Group {
        path: String,
        depth: usize,
        open: bool,
        type_text: String,
    },
    /// A basic value inside a structure.
    Leaf { at: Box<PathLocation>, depth: usize },
}

impl Entry {
    /// The key its value is kept under: the variable's name or the path.
    fn key<'a>(&'a self, w: &'a Watch) -> &'a str {
        match self {
            Entry::Var(i) => &w.seg.descriptor().variables[*i].name,
            Entry::Group { path, .. } => path,
            Entry::Leaf { at, .. } => &at.path,
        }
    }
}

struct Watch {
    seg: DynSegment,
    /// Variable indices in display order: each word followed by its bit-mapped bools.
    order: Vec<usize>,
    /// The lines as the tree is open now.
    entries: Vec<Entry>,
    /// The groups open, by lower-case path.
    open: HashSet<String>,
    filter: String,
    mode: Mode,
    table: TableState,
    values: HashMap<String, String>,
    changed: HashMap<String, Instant>,
    message: String,
    /// How values are shown now.
    format: Format,
    /// The digits reals are rounded to when not at full precision.
    digits: u8,
    /// What is forced, and what alarms watch.
    marks: Marks,
}

impl Watch {
    fn new(seg: DynSegment, filter: Option<String>, format: Format) -> Watch {
        let digits = format.digits.unwrap_or(DIGITS);
        let marks = Marks::new(&seg);
        let vars = &seg.descriptor().variables;
        // Each word's bools in one pass: a scan of all variables per word is quadratic, and
        // a program of 4,000 variables would wait for it at every start.
        let mut bits: Vec<Vec<usize>> = vec![Vec::new(); vars.len()];
        for (j, b) in vars.iter().enumerate() {
            if let Some(m) = b.bit
                && let Some(under) = bits.get_mut(m.source)
            {
                under.push(j);
            }
        }
        let mut order = Vec::with_capacity(vars.len());
        for (i, v) in vars.iter().enumerate() {
            if v.bit.is_none() {
                order.push(i);
                order.extend(&bits[i]);
            }
        }
        let mut w = Watch {
            seg,
            order,
            entries: Vec::new(),
            open: HashSet::new(),
            filter: filter.unwrap_or_default(),
            mode: Mode::Browse,
            table: TableState::default().with_selected(Some(0)),
            values: HashMap::new(),
            changed: HashMap::new(),
            message: String::new(),
            format: Format {
                digits: Some(digits),
                ..format
            },
            digits,
            marks,
        };
        w.rebuild();
        w
    }

    /// The lines, from the variables and the groups open.
    fn rebuild(&mut self) {
        let mut entries = Vec::new();
        for &i in &self.order {
            let v = &self.seg.descriptor().variables[i];
            if v.members.is_empty() {
                entries.push(Entry::Var(i));
            } else {
                self.group(v.name.clone(), 0, &mut entries);
            }
        }
        self.entries = entries;
    }

    /// A group's line, and its children's if it is open.
    fn group(&self, path: String, depth: usize, out: &mut Vec<Entry>) {
        let Ok(PathTarget::Group(children)) = self.seg.resolve_path(&path) else {
            return;
        };
        let open = self.open.contains(&path.to_ascii_lowercase());
        let type_text = group_type(&self.seg, &path);
        out.push(Entry::Group {
            path,
            depth,
            open,
            type_text,
        });
        if !open {
            return;
        }
        for child in children {
            match self.seg.resolve_path(&child) {
                Ok(PathTarget::Value(at)) => out.push(Entry::Leaf {
                    at,
                    depth: depth + 1,
                }),
                Ok(PathTarget::Group(_)) => self.group(child, depth + 1, out),
                Err(_) => {}
            }
        }
    }

    /// Indexes into `entries` of the lines the filter lets through.
    fn visible(&self) -> Vec<usize> {
        let f = self.filter.to_ascii_lowercase();
        (0..self.entries.len())
            .filter(|&e| self.entries[e].key(self).to_ascii_lowercase().contains(&f))
            .collect()
    }

    fn refresh(&mut self) -> Result<(), Error> {
        let image = self.seg.snapshot_bytes()?;
        self.marks.refresh(&self.seg, &self.seg.status())?;
        let now = Instant::now();
        let mut fresh = Vec::with_capacity(self.entries.len());
        for e in &self.entries {
            let value = match e {
                Entry::Var(i) => show(&self.seg, &image, *i, None, &self.format),
                Entry::Group { .. } => String::new(),
                Entry::Leaf { at, .. } => at.var.value_in(&image, 0).map_or("?".into(), |v| {
                    display::value(&v, at.var.iec_type, &self.format)
                }),
            };
            fresh.push((e.key(self).to_string(), value));
        }
        for (key, value) in fresh {
            match self.values.get(&key) {
                Some(old) if *old == value => {}
                Some(_) => {
                    self.changed.insert(key.clone(), now);
                    self.values.insert(key, value);
                }
                None => {
                    self.values.insert(key, value);
                }
            }
        }
        Ok(())
    }

    /// Opens or closes the selected group; `open` `None` toggles it.
    fn set_open(&mut self, open: Option<bool>) -> bool {
        let Some(Entry::Group {
            path, open: now, ..
        }) = self.selected_entry()
        else {
            return false;
        };
        let (key, now) = (path.to_ascii_lowercase(), *now);
        if open.unwrap_or(!now) {
            self.open.insert(key);
        } else {
            self.open.remove(&key);
        }
        self.rebuild();
        let _ = self.refresh();
        true
    }

    /// Switches reals between the rounded digits and full precision, and shows them so at
    /// once; nothing is highlighted as changed, since no value changed.
    fn toggle_precision(&mut self) {
        self.format.digits = match self.format.digits {
            Some(_) => None,
            None => Some(self.digits),
        };
        self.values.clear();
        let _ = self.refresh();
    }

    fn selected_entry(&self) -> Option<&Entry> {
        let visible = self.visible();
        self.table
            .selected()
            .and_then(|s| visible.get(s))
            .map(|&e| &self.entries[e])
    }

    fn draw(&mut self, f: &mut ratatui::Frame) {
        let [head, body, foot] = Layout::vertical([
            Constraint::Length(3),
            Constraint::Min(3),
            Constraint::Length(1),
        ])
        .areas(f.area());
        let st = self.seg.status();
        let state = self.seg.owner_state();
        let header = format!(
            "{} | owner {} (pid {}) | cycle {} | cycle time last/min/mean/max {}/{}/{}/{} us | overruns {} | bus {}{}",
            self.seg.name(),
            state,
            st.pid,
            st.cycle_count,
            st.stats.last.as_micros(),
            st.stats.min.as_micros(),
            st.stats.mean.as_micros(),
            st.stats.max.as_micros(),
            st.stats.overruns,
            st.bus_state,
            if st.bus_fault { " FAULT" } else { "" },
        );
        let header = format!("{header}{}", watch_marks::header_counts(&st));
        f.render_widget(
            Paragraph::new(header).block(Block::bordered().title(" plc watch ")),
            head,
        );
        let vars = &self.seg.descriptor().variables;
        let visible = self.visible();
        let rows = visible.iter().map(|&e| {
            let entry = &self.entries[e];
            let (name, ty, direction) = match entry {
                Entry::Var(i) => {
                    let v = &vars[*i];
                    let name = if v.bit.is_some() {
                        format!("  └ {}", v.name)
                    } else {
                        v.name.clone()
                    };
                    (name, type_text(v), v.direction.name())
                }
                Entry::Group {
                    path,
                    depth,
                    open,
                    type_text,
                } => (
                    format!(
                        "{}{} {}",
                        "  ".repeat(*depth),
                        if *open { "▾" } else { "▸" },
                        tail(path)
                    ),
                    type_text.clone(),
                    "",
                ),
                Entry::Leaf { at, depth } => (
                    format!("{}{}", "  ".repeat(*depth), tail(&at.path)),
                    type_text(&at.var),
                    at.var.direction.name(),
                ),
            };
            let key = entry.key(self);
            let mark = match entry {
                Entry::Var(i) => self.marks.of(Some(*i), None),
                Entry::Leaf { at, .. } => self.marks.of(None, Some((at.index, at.leaf))),
                Entry::Group { .. } => Mark::default(),
            };
            let forced = mark.forced;
            let name = match (mark.alarm, mark.alarmed) {
                (true, true) => ratatui::text::Span::raw(format!("{name} !")).red().bold(),
                (true, false) => ratatui::text::Span::raw(format!("{name} !")),
                _ => ratatui::text::Span::raw(name),
            };
            let text = self.values.get(key).cloned().unwrap_or_default();
            let mut value = if forced {
                ratatui::text::Span::raw(format!("F {text}"))
                    .magenta()
                    .bold()
            } else {
                ratatui::text::Span::raw(text)
            };
            if self
                .changed
                .get(key)
                .is_some_and(|t| t.elapsed() < Duration::from_secs(1))
            {
                value = value.black().on_yellow();
            }
            Row::new(vec![
                ratatui::widgets::Cell::from(name),
                ty.into(),
                direction.into(),
                ratatui::widgets::Cell::from(value),
            ])
        });
        let table = Table::new(
            rows,
            [
                Constraint::Percentage(35),
                Constraint::Length(14),
                Constraint::Length(9),
                Constraint::Min(10),
            ],
        )
        .header(Row::new(["NAME", "TYPE", "DIRECTION", "VALUE"]).add_modifier(Modifier::BOLD))
        .row_highlight_style(Style::new().add_modifier(Modifier::REVERSED))
        .block(Block::bordered().title(format!(
            " {} of {} variables{} ",
            visible.len(),
            self.entries.len(),
            if self.filter.is_empty() {
                String::new()
            } else {
                format!(", filter `{}`", self.filter)
            }
        )));
        f.render_stateful_widget(table, body, &mut self.table);
        let foot_text = match &self.mode {
            Mode::Filter => format!("filter: {}_   (Enter done, Esc clear)", self.filter),
            Mode::Edit(input) => {
                let name = self.selected_entry().map_or("", |e| e.key(self));
                format!("{name} = {input}_   (Enter write, Esc cancel)")
            }
            Mode::Browse if !self.message.is_empty() => self.message.clone(),
            Mode::Browse => format!(
                "q quit | / filter | up/down select | right/left open/close | Enter write value | p {}",
                match self.format.digits {
                    Some(_) => "full precision".to_string(),
                    None => format!("{} digits", self.digits),
                }
            ),
        };
        f.render_widget(Line::from(foot_text), foot);
    }

    /// Handles a key; `false` quits.
    fn key(&mut self, code: KeyCode) -> bool {
        match &mut self.mode {
            Mode::Filter => match code {
                KeyCode::Enter => self.mode = Mode::Browse,
                KeyCode::Esc => {
                    self.filter.clear();
                    self.mode = Mode::Browse;
                }
                KeyCode::Backspace => {
                    self.filter.pop();
                }
                KeyCode::Char(c) => {
                    self.filter.push(c);
                    self.table.select(Some(0));
                }
                _ => {}
            },
            Mode::Edit(input) => match code {
                KeyCode::Esc => self.mode = Mode::Browse,
                KeyCode::Backspace => {
                    input.pop();
                }
                KeyCode::Char(c) => input.push(c),
                KeyCode::Enter => {
                    let input = input.clone();
                    self.mode = Mode::Browse;
                    let target = match self.selected_entry() {
                        Some(Entry::Var(i)) => {
                            let v = &self.seg.descriptor().variables[*i];
                            Some((v.name.clone(), v.iec_type))
                        }
                        Some(Entry::Leaf { at, .. }) => Some((at.path.clone(), at.var.iec_type)),
                        _ => None,
                    };
                    if let Some((name, iec_type)) = target {
                        let result =
                            set::check(&self.seg, &format!("{name}={input}")).and_then(|t| {
                                self.seg.write_checked(&[t.write])?;
                                Ok(t.write.write().value)
                            });
                        self.message = match result {
                            Ok(v) => format!(
                                "wrote {name} = {}",
                                display::value(&v, iec_type, &self.format)
                            ),
                            Err(e) => format!("not written: {e}"),
                        };
                    }
                }
                _ => {}
            },
            Mode::Browse => {
                self.message.clear();
                let n = self.visible().len();
                let sel = self.table.selected().unwrap_or(0);
                match code {
                    KeyCode::Char('q') | KeyCode::Esc => return false,
                    KeyCode::Char('/') => self.mode = Mode::Filter,
                    KeyCode::Char('p') => self.toggle_precision(),
                    KeyCode::Down => self.table.select(Some((sel + 1).min(n.saturating_sub(1)))),
                    KeyCode::Up => self.table.select(Some(sel.saturating_sub(1))),
                    KeyCode::PageDown => {
                        self.table.select(Some((sel + 20).min(n.saturating_sub(1))))
                    }
                    KeyCode::PageUp => self.table.select(Some(sel.saturating_sub(20))),
                    KeyCode::Right | KeyCode::Char('+') => {
                        self.set_open(Some(true));
                    }
                    KeyCode::Left | KeyCode::Char('-') => {
                        self.set_open(Some(false));
                    }
                    // Enter opens or closes a group, else edits the value.
                    KeyCode::Enter if !self.set_open(None) && self.selected_entry().is_some() => {
                        self.mode = Mode::Edit(String::new())
                    }
                    _ => {}
                }
            }
        }
        true
    }
}

pub fn run(segment: &str, filter: Option<String>, rate: f64, format: Format) -> Result<(), Error> {
    let period = period_of(rate, 1000.0, "refreshes")?;
    let seg = DynSegment::attach(segment)?;
    let mut w = Watch::new(seg, filter, format);
    w.refresh()?;
    let mut frame_log = frame_log()?;
    let mut terminal = ratatui::init();
    let outcome = (|| -> Result<Option<String>, Error> {
        let mut next = Instant::now();
        loop {
            let started = Instant::now();
            if let Err(e) = w.refresh() {
                return Ok(Some(format!("plc watch: {e}")));
            }
            terminal.draw(|f| w.draw(f))?;
            if let Some(log) = &mut frame_log {
                // One short line per frame, flushed so a reader sees every finished frame.
                let _ = writeln!(log, "{}", started.elapsed().as_micros());
                let _ = log.flush();
            }
            next += period;
            while event::poll(next.saturating_duration_since(Instant::now()))? {
                if let Event::Key(k) = event::read()?
                    && k.kind == KeyEventKind::Press
                    && !w.key(k.code)
                {
                    return Ok(None);
                }
                terminal.draw(|f| w.draw(f))?;
            }
            if next < Instant::now() {
                next = Instant::now();
            }
        }
    })();
    ratatui::restore();
    if let Ok(Some(message)) = &outcome {
        eprintln!("{message}");
    }
    outcome.map(|_| ())
}

/// `PLC_WATCH_FRAME_LOG=FILE`: each refresh's time (snapshot, values, drawing the window,
/// written to the terminal) in microseconds, one line per frame, appended to FILE (what
/// plc-bench's `watch_4000_frame_p99_ms` reads). Not set: nothing is timed or written.
fn frame_log() -> Result<Option<std::io::BufWriter<std::fs::File>>, Error> {
    let Some(path) = std::env::var_os("PLC_WATCH_FRAME_LOG") else {
        return Ok(None);
    };
    let file = std::fs::OpenOptions::new()
        .create(true)
        .append(true)
        .open(&path)
        .map_err(|e| format!("PLC_WATCH_FRAME_LOG {}: {e}", path.to_string_lossy()))?;
    Ok(Some(std::io::BufWriter::new(file)))
}

/// The last step of a path, as a tree line shows it under its parent: `pos`, `[1]`.
fn tail(path: &str) -> &str {
    match path.rfind(['.', '[']) {
        Some(i) if path.as_bytes()[i] == b'.' => &path[i + 1..],
        Some(i) if path.ends_with(']') => &path[i..],
        _ => path,
    }
}

/// A group's type as the window shows it: `Axis[3]` for an array of structures, `Axis` for
/// a structure or one element of the array.
fn group_type(seg: &DynSegment, path: &str) -> String {
    match seg.node_at(path) {
        Some(n) if path.trim_end().ends_with(']') => n.type_name().to_string(),
        Some(n) => type_text(n),
        None => String::new(),
    }
}
