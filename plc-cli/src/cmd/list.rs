//! `plc list [segment] [--json]`.

use super::{Error, type_text};
use plc_shm::{BusClocks, DynSegment, OwnerState, SegmentInfo, ShmError, list_segments};

/// The state column: the owner's, `gone` for a killed owner's leftover, or `damaged` for a
/// segment that cannot be read.
fn state(s: &SegmentInfo) -> &'static str {
    match &s.problem {
        Some(ShmError::OwnerGone(_)) => OwnerState::Gone.name(),
        Some(_) => "damaged",
        None => s.state.name(),
    }
}

pub fn run(segment: Option<&str>, json: bool) -> Result<(), Error> {
    let Some(segment) = segment else {
        let all = list_segments();
        if json {
            let rows: Vec<serde_json::Value> = all
                .iter()
                .map(|s| {
                    serde_json::json!({
                        "name": s.name, "pid": s.pid, "state": state(s),
                        "cycles": s.cycle_count, "variables": s.variables,
                        "retain_failures": s.retain_failures, "forces": s.forces,
                        "alarms_unacknowledged": s.alarms_unacknowledged,
                        "dc": s.clocks.as_ref().map(clocks_json),
                        "problem": s.problem.as_ref().map(|p| p.to_string()),
                    })
                })
                .collect();
            println!("{}", serde_json::to_string_pretty(&rows)?);
            return Ok(());
        }
        if all.is_empty() {
            println!("no running plc-vars programs");
        }
        println!(
            "{:<24} {:>8} {:<8} {:>12} {:>9} {:>14} {:>6} {:>7}",
            "SEGMENT", "PID", "STATE", "CYCLES", "VARIABLES", "FAILED SAVES", "FORCED", "UNACKED"
        );
        for s in &all {
            println!(
                "{:<24} {:>8} {:<8} {:>12} {:>9} {:>14} {:>6} {:>7}",
                s.name,
                s.pid,
                state(s),
                s.cycle_count,
                s.variables,
                s.retain_failures,
                s.forces,
                s.alarms_unacknowledged
            );
            if let Some(clocks) = &s.clocks {
                println!("  dc: {clocks}");
            }
            if let Some(problem) = &s.problem {
                println!("  {problem}");
            }
        }
        return Ok(());
    };
    let seg = DynSegment::attach(segment)?;
    if json {
        println!("{}", serde_json::to_string_pretty(seg.descriptor())?);
        return Ok(());
    }
    println!(
        "{:<28} {:<14} {:<9} {:<18} {:<36} DESCRIPTION",
        "NAME", "TYPE", "DIRECTION", "ACCESS", "LINK / ADDRESS"
    );
    print_level(&seg.descriptor().variables, 0, None);
    // A program `plc run` hosts says which module runs.
    if let Some(hosted) = super::change_wire::hosted(seg.name()) {
        println!("\n{hosted}");
    }
    let status = seg.status();
    if let Some(clocks) = &status.clocks {
        println!("\ndc: {clocks}");
    }
    if status.alarms_unacknowledged > 0 {
        // Returned-to-normal alarms wait for an acknowledgement too: both counts are shown.
        println!(
            "\nalarms: {} unacknowledged, {} active",
            status.alarms_unacknowledged, status.alarms_active
        );
    }
    let forces = status.forces;
    if forces > 0 {
        let what = if forces == 1 { "value" } else { "values" };
        println!(
            "\n{forces} {what} forced (`plc forces {}` lists them)",
            seg.name()
        );
    }
    Ok(())
}

/// The distributed clocks in `plc list --json`: the status block's figures, in ns (the
/// difference `null` when it was not read).
fn clocks_json(c: &BusClocks) -> serde_json::Value {
    serde_json::json!({
        "sync0_period_ns": c.sync0_period_ns,
        "max_time_difference_ns": c.max_time_difference_ns,
        "sync0_offset_ns": c.sync0_offset_ns,
    })
}

/// What a tool may do with `v`, as `plc set` decides it: `read-write`, or `read-only` with
/// why where more than `read_only` decides it (`read-only (input)`: the hardware writes it;
/// `read-only (status)`: the program reports it). A variable's direction decides; a
/// member's is the interface of its block (an IN parameter is written from outside), so only
/// its own `read_only` and its structure's access (`outer`, when tools may not write the
/// structure) do.
fn access(v: &plc_shm::VarDescriptor, member: bool, outer: Option<&'static str>) -> &'static str {
    use plc_core::{Access, Direction};
    if let Some(outer) = outer {
        return outer;
    }
    match (v.access, v.direction) {
        (Access::ReadOnly, _) => "read-only",
        _ if member => "read-write",
        (_, Direction::Input) => "read-only (input)",
        _ if !v.writable_from_outside() => "read-only (status)",
        _ => "read-write",
    }
}

/// One line per variable of a level, a structure's members indented under it (bit-mapped
/// bools under their source word, within the same level). `outer`: the access of a
/// structure tools may not write, which its members share.
fn print_level(vars: &[plc_shm::VarDescriptor], depth: usize, outer: Option<&'static str>) {
    let indent = "  ".repeat(depth);
    for v in vars {
        let (name, bit_of) = match v.bit {
            Some(b) => (
                format!("{indent}  └ {}", v.name),
                vars.get(b.source)
                    .map(|s| format!("bit {} of {}", b.bit, s.name)),
            ),
            None => (format!("{indent}{}", v.name), None),
        };
        let access = access(v, depth > 0, outer);
        let place = v
            .link
            .clone()
            .or_else(|| v.address.clone())
            .or(bit_of)
            .unwrap_or_default();
        println!(
            "{:<28} {:<14} {:<9} {:<18} {:<36} {}",
            name,
            type_text(v),
            v.direction.name(),
            access,
            place,
            v.description
        );
        let read_only = access != "read-write";
        print_level(&v.members, depth + 1, read_only.then_some(access));
    }
}
