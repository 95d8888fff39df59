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
            "{:<24} {:>8} {:<8} {:>12} {:>9} {:>14} {:>6}",
            "SEGMENT", "PID", "STATE", "CYCLES", "VARIABLES", "FAILED SAVES", "FORCED"
        );
        for s in &all {
            println!(
                "{:<24} {:>8} {:<8} {:>12} {:>9} {:>14} {:>6}",
                s.name,
                s.pid,
                state(s),
                s.cycle_count,
                s.variables,
                s.retain_failures,
                s.forces
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
        "{:<28} {:<14} {:<9} {:<10} {:<36} DESCRIPTION",
        "NAME", "TYPE", "DIRECTION", "ACCESS", "LINK / ADDRESS"
    );
    print_level(&seg.descriptor().variables, 0);
    let status = seg.status();
    if let Some(clocks) = &status.clocks {
        println!("\ndc: {clocks}");
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

/// One line per variable of a level, a structure's members indented under it (bit-mapped
/// bools under their source word, within the same level).
fn print_level(vars: &[plc_shm::VarDescriptor], depth: usize) {
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
        let access = match v.access {
            plc_core::Access::ReadOnly => "read-only",
            plc_core::Access::ReadWrite => "read-write",
        };
        let place = v
            .link
            .clone()
            .or_else(|| v.address.clone())
            .or(bit_of)
            .unwrap_or_default();
        println!(
            "{:<28} {:<14} {:<9} {:<10} {:<36} {}",
            name,
            type_text(v),
            v.direction.name(),
            access,
            place,
            v.description
        );
        print_level(&v.members, depth + 1);
    }
}
