//! A loaded module's variables as the runtime's [`Schema`]: its descriptor's lists made
//! `'static` by leaking them, once per load. A host never unloads a module, so this memory
//! would live as long anyway; it costs the descriptor's size for each change.

use plc_core::alarm::{AlarmDecl, AlarmKind, Condition, Limits, SuppressWhen};
use plc_core::memory::Schema;
use plc_core::{Access, BusSource, Time, VarInfo};
use plc_shm::{AlarmDescriptor, LayoutDescriptor, VarDescriptor};

fn leak(text: &str) -> &'static str {
    Box::leak(text.into())
}

fn leak_all<T>(items: Vec<T>) -> &'static [T] {
    Box::leak(items.into_boxed_slice())
}

/// The schema of a module whose descriptor is `desc` and bus description `bus`.
pub fn schema_of(desc: &LayoutDescriptor, bus: Option<&(String, String)>) -> Schema {
    Schema {
        variables: leak_all(desc.variables.iter().map(var_info).collect()),
        alarms: leak_all(desc.alarms.iter().map(alarm_decl).collect()),
        layout_hash: desc.layout_hash,
        image_size: desc.image_size,
        bus: bus.map(|(file, text)| BusSource {
            file: leak(file),
            text: leak(text),
        }),
    }
}

/// One variable or member, with its members.
fn var_info(d: &VarDescriptor) -> VarInfo {
    let mut v = plc_core::__private::var::<u8>(leak(&d.name), leak(&d.rust_type), d.offset, d.size)
        .iec(d.iec_type)
        .dims(leak_all(d.dims.clone()))
        .description(leak(&d.description))
        .direction(d.direction);
    if let Some(b) = d.bit {
        v = v.bit(b.source, b.bit);
    }
    if let Some(link) = &d.link {
        v = v.link(leak(link));
    }
    if let Some(address) = &d.address {
        v = v.address(leak(address));
    }
    if let Some(initial) = &d.initial {
        v = v.initial(leak(initial));
    }
    if d.nonvolatile {
        v = v.nonvolatile();
    }
    if d.access == Access::ReadOnly {
        v = v.read_only();
    }
    if d.ux {
        v = v.ux();
    }
    if let Some(q) = &d.quantity {
        v = v.quantity(leak(q));
    }
    if let Some(u) = &d.unit {
        v = v.unit(leak(u));
    }
    if let Some(db) = d.deadband {
        v = v.deadband(db);
    }
    if let Some(name) = &d.type_name {
        v = v.structure(
            leak(name),
            leak_all(d.members.iter().map(var_info).collect()),
        );
    }
    v
}

/// One alarm as the evaluator takes it.
fn alarm_decl(a: &AlarmDescriptor) -> AlarmDecl {
    let kind = match a.active_when {
        Some(active) => AlarmKind::Discrete { active },
        None => AlarmKind::Limit(Limits {
            low_low: a.low_low,
            low: a.low,
            high: a.high,
            high_high: a.high_high,
            deadband: a.deadband,
        }),
    };
    let condition = Condition {
        kind,
        delay: Time::from_nanos(a.delay_ns),
        latched: a.latched,
    };
    let suppress = match &a.suppress_when {
        Some(path) => SuppressWhen::Path(leak(path)),
        None => SuppressWhen::Never,
    };
    AlarmDecl::new(a.variable, a.leaf, leak(&a.text), condition)
        .with_severity(a.severity)
        .with_suppress(suppress)
}
