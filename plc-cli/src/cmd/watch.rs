//! `plc watch <segment>`: a live watch window (ratatui). Keys: `/` filter, arrows and
//! PgUp/PgDn select, Enter write a value to the selected variable (checked as `plc set`
//! checks), `q` or Esc quit. Bit-mapped bools are shown under their source word; values that
//! changed in the last second are highlighted.

use super::{Error, period_of, set, show, type_text};
use plc_io::shm::DynSegment;
use ratatui::crossterm::event::{self, Event, KeyCode, KeyEventKind};
use ratatui::layout::{Constraint, Layout};
use ratatui::style::{Modifier, Style, Stylize};
use ratatui::text::Line;
use ratatui::widgets::{Block, Paragraph, Row, Table, TableState};
use std::time::{Duration, Instant};

enum Mode {
    Browse,
    Filter,
    Edit(String),
}

struct Watch {
    seg: DynSegment,
    /// Variable indices in display order: each word followed by its bit-mapped bools.
    order: Vec<usize>,
    filter: String,
    mode: Mode,
    table: TableState,
    values: Vec<String>,
    changed: Vec<Option<Instant>>,
    message: String,
}

impl Watch {
    fn new(seg: DynSegment, filter: Option<String>) -> Watch {
        let vars = &seg.descriptor().variables;
        let mut order = Vec::with_capacity(vars.len());
        for (i, v) in vars.iter().enumerate() {
            if v.bit.is_none() {
                order.push(i);
                order.extend(
                    vars.iter()
                        .enumerate()
                        .filter(|(_, b)| b.bit.is_some_and(|m| m.source == i))
                        .map(|(j, _)| j),
                );
            }
        }
        let n = vars.len();
        Watch {
            seg,
            order,
            filter: filter.unwrap_or_default(),
            mode: Mode::Browse,
            table: TableState::default().with_selected(Some(0)),
            values: vec![String::new(); n],
            changed: vec![None; n],
            message: String::new(),
        }
    }

    fn visible(&self) -> Vec<usize> {
        let f = self.filter.to_ascii_lowercase();
        self.order
            .iter()
            .copied()
            .filter(|&i| {
                self.seg.descriptor().variables[i]
                    .name
                    .to_ascii_lowercase()
                    .contains(&f)
            })
            .collect()
    }

    fn refresh(&mut self) -> Result<(), Error> {
        let image = self.seg.snapshot_bytes()?;
        for i in 0..self.values.len() {
            let v = show(&self.seg, &image, i, None);
            if v != self.values[i] {
                if !self.values[i].is_empty() {
                    self.changed[i] = Some(Instant::now());
                }
                self.values[i] = v;
            }
        }
        Ok(())
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
        f.render_widget(
            Paragraph::new(header).block(Block::bordered().title(" plc watch ")),
            head,
        );
        let vars = &self.seg.descriptor().variables;
        let visible = self.visible();
        let rows = visible.iter().map(|&i| {
            let v = &vars[i];
            let name = if v.bit.is_some() {
                format!("  └ {}", v.name)
            } else {
                v.name.clone()
            };
            let mut value = ratatui::text::Span::raw(self.values[i].clone());
            if self.changed[i].is_some_and(|t| t.elapsed() < Duration::from_secs(1)) {
                value = value.black().on_yellow();
            }
            Row::new(vec![
                ratatui::widgets::Cell::from(name),
                type_text(v).into(),
                v.direction.name().into(),
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
            vars.len(),
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
                let name = self.selected().map_or("", |i| vars[i].name.as_str());
                format!("{name} = {input}_   (Enter write, Esc cancel)")
            }
            Mode::Browse if !self.message.is_empty() => self.message.clone(),
            Mode::Browse => "q quit | / filter | up/down select | Enter write value".into(),
        };
        f.render_widget(Line::from(foot_text), foot);
    }

    fn selected(&self) -> Option<usize> {
        let visible = self.visible();
        self.table.selected().and_then(|s| visible.get(s).copied())
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
                    if let Some(i) = self.selected() {
                        let name = self.seg.descriptor().variables[i].name.clone();
                        let result =
                            set::check(&self.seg, &format!("{name}={input}")).and_then(|t| {
                                t.post(&self.seg)?;
                                Ok(t.value)
                            });
                        self.message = match result {
                            Ok(v) => format!("wrote {name} = {v}"),
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
                    KeyCode::Down => self.table.select(Some((sel + 1).min(n.saturating_sub(1)))),
                    KeyCode::Up => self.table.select(Some(sel.saturating_sub(1))),
                    KeyCode::PageDown => {
                        self.table.select(Some((sel + 20).min(n.saturating_sub(1))))
                    }
                    KeyCode::PageUp => self.table.select(Some(sel.saturating_sub(20))),
                    KeyCode::Enter if self.selected().is_some() => {
                        self.mode = Mode::Edit(String::new())
                    }
                    _ => {}
                }
            }
        }
        true
    }
}

pub fn run(segment: &str, filter: Option<String>, rate: f64) -> Result<(), Error> {
    let period = period_of(rate, 1000.0, "refreshes")?;
    let seg = DynSegment::attach(segment)?;
    let mut w = Watch::new(seg, filter);
    w.refresh()?;
    let mut terminal = ratatui::init();
    let outcome = (|| -> Result<Option<String>, Error> {
        let mut next = Instant::now();
        loop {
            if let Err(e) = w.refresh() {
                return Ok(Some(format!("plc watch: {e}")));
            }
            terminal.draw(|f| w.draw(f))?;
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
