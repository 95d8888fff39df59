//! `plc force`, `plc unforce` and `plc forces`: values the running program holds at both of
//! its cycle's boundaries (after the inputs are read and before its logic; after its logic,
//! before the outputs go out) until they are released or the program stops, as TwinCAT and
//! CODESYS force. Any basic value may be forced, inputs and outputs included; who may force is
//! who may write.

use super::Error;
use crate::display::{self, Format};
use plc_core::Value;
use plc_core::write::{Checked, Write};
use plc_shm::limits::MAX_WRITES;
use plc_shm::{DynSegment, PathLocation};

/// `path=value`, checked as the program checks a force.
fn check(seg: &DynSegment, assignment: &str) -> Result<(PathLocation, Checked), Error> {
    let (spec, text) = assignment
        .split_once('=')
        .ok_or_else(|| format!("`{assignment}`: write `path=value`"))?;
    let at = seg.locate(spec.trim())?;
    let value = Value::parse(text, at.var.iec_type).map_err(|e| format!("`{}`: {e}", at.path))?;
    let checked = seg.check_force(Write {
        index: at.index,
        leaf: at.leaf,
        value,
    })?;
    Ok((at, checked))
}

/// Forces every assignment: all are checked first, then sent in requests of at most
/// [`MAX_WRITES`] (one request for as many as the owner holds), each held whole or refused whole.
pub fn force(segment: &str, assignments: &[String]) -> Result<(), Error> {
    let seg = DynSegment::attach(segment)?;
    let checked: Vec<(PathLocation, Checked)> = assignments
        .iter()
        .map(|a| check(&seg, a))
        .collect::<Result<_, _>>()?;
    for (n, part) in checked.chunks(MAX_WRITES).enumerate() {
        let forces: Vec<Checked> = part.iter().map(|(_, c)| *c).collect();
        if let Err(e) = seg.force(&forces) {
            return Err(match n * MAX_WRITES {
                0 => e.to_string(),
                done => format!("{e}\nthe first {done} forces are held"),
            }
            .into());
        }
        for (at, c) in part {
            println!(
                "{} forced to {}",
                at.path,
                display::value(&c.write().value, at.var.iec_type, &Format::default())
            );
        }
    }
    Ok(())
}

/// Releases the forces of `paths`, or all of them; with `restore`, each value goes back to what
/// it was before its force.
pub fn unforce(segment: &str, paths: &[String], all: bool, restore: bool) -> Result<(), Error> {
    let seg = DynSegment::attach(segment)?;
    if all {
        let held = seg.forces()?.len();
        seg.release_all(restore)?;
        let what = if held == 1 { "force" } else { "forces" };
        println!("{held} {what} released{}", restored(restore));
        return Ok(());
    }
    if paths.is_empty() {
        return Err("name the values to release, or give --all".into());
    }
    let found: Vec<PathLocation> = paths
        .iter()
        .map(|p| seg.locate(p.trim()))
        .collect::<Result<_, _>>()?;
    for part in found.chunks(MAX_WRITES) {
        let values: Vec<(usize, usize)> = part.iter().map(|at| (at.index, at.leaf)).collect();
        seg.release(&values, restore)?;
        for at in part {
            println!("{} released{}", at.path, restored(restore));
        }
    }
    Ok(())
}

fn restored(restore: bool) -> &'static str {
    if restore {
        " (restored to the value before the force)"
    } else {
        ""
    }
}

/// Lists the forces held: path, value, who, since when.
pub fn list(segment: &str, format: &Format) -> Result<(), Error> {
    let seg = DynSegment::attach(segment)?;
    let held = seg.forces()?;
    let image = seg.snapshot_bytes()?;
    if held.is_empty() {
        println!("no forces held in `{}`", seg.name());
        return Ok(());
    }
    println!("{:<32} {:<20} {:<16} SINCE", "PATH", "VALUE", "BY");
    for f in held {
        let path = plc_shm::path_of(&seg.descriptor().variables, f.index, f.leaf);
        let value = seg
            .locate(&path)
            .ok()
            .and_then(|at| {
                let v = at.var.value_in(&image, 0)?;
                Some(display::value(&v, at.var.iec_type, format))
            })
            .unwrap_or_else(|| "?".into());
        println!(
            "{:<32} {:<20} {:<16} {}",
            display::escape_text(&path),
            value,
            user(f.uid),
            plc_shm::utc_text(f.since_utc_ns)
        );
    }
    Ok(())
}

/// `uid 1000 (ada)`, or the uid alone when it has no name here.
pub fn user(uid: u32) -> String {
    match plc_shm::user_name(uid) {
        Some(name) => format!("uid {uid} ({})", display::escape_text(&name)),
        None => format!("uid {uid}"),
    }
}
