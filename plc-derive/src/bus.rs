//! `#[plc(bus = "bus/machine.toml")]`: the bus description read while compiling, and every
//! `link` of the struct checked against it by the bus description's own rules
//! (`plc_rules::bus::links`, which plc-io applies again before the bus starts). A bad link is
//! an error under the link; a file that cannot be read or does not parse is an error under the
//! `bus` attribute. The expansion includes the file's bytes, so an edit of it recompiles the
//! struct.

use crate::ast::{At, Container};
use crate::ctxt::Ctxt;
use plc_rules::bus::{BusConfig, BusLayout, LinkedVar, resolve_links};
use plc_rules::link::Link;
use proc_macro2::TokenStream;
use quote::quote;
use std::path::PathBuf;

/// Where relative bus paths start: the crate's directory. A test harness that compiles code
/// elsewhere (trybuild) names the directory the paths are relative to in
/// `PLC_VARS_MANIFEST_DIR`.
fn base_dir() -> PathBuf {
    std::env::var_os("PLC_VARS_MANIFEST_DIR")
        .or_else(|| std::env::var_os("CARGO_MANIFEST_DIR"))
        .map(PathBuf::from)
        .unwrap_or_default()
}

/// Reads the bus description and checks the struct's links against it; returns the file's
/// absolute path, for the expansion to include, when it could be read.
pub fn check(c: &Container, cx: &mut Ctxt) -> Option<PathBuf> {
    let bus = c.bus.as_ref()?;
    let path = base_dir().join(&bus.value);
    let text = match std::fs::read_to_string(&path) {
        Ok(t) => t,
        Err(e) => {
            cx.error(
                bus.at.span(),
                format!(
                    "cannot read the bus description `{}` ({e}): the path is relative to the \
                     crate's directory, where its Cargo.toml is",
                    bus.value
                ),
            );
            return None;
        }
    };
    let json = bus.value.to_ascii_lowercase().ends_with(".json");
    let parsed = if json {
        BusConfig::from_json_str(&text)
    } else {
        BusConfig::from_toml_str(&text)
    };
    match parsed {
        Ok(config) => check_links(c, &config, bus, cx),
        Err(e) => cx.error(
            bus.at.span(),
            format!(
                "the bus description `{}` is not valid: {}",
                bus.value,
                e.problems.join("; ")
            ),
        ),
    }
    Some(path)
}

fn check_links(c: &Container, config: &BusConfig, bus: &At<String>, cx: &mut Ctxt) {
    let layout = BusLayout::new(config);
    let linked: Vec<Option<LinkedVar>> = c
        .fields()
        .map(|(v, m)| {
            let link = m.link.as_ref()?;
            // A malformed link has its own error already.
            Link::parse(&link.value).ok()?;
            let known = m.ty.value.known();
            Some(LinkedVar {
                name: &m.name.value,
                link: &link.value,
                iec_type: known.map(|k| m.iec_type.as_ref().map_or(k.iec, |t| t.value)),
                array: known.map(|k| !k.is_scalar()),
                direction: v.effective_direction,
            })
        })
        .collect();
    let (_, issues) = resolve_links(&linked, &layout);
    for issue in issues {
        let at = c.decl.vars[issue.var]
            .link
            .as_ref()
            .map_or(bus.at.span(), |l| l.at.span());
        cx.error(at, format!("{} (in `{}`)", issue.message, bus.value));
    }
}

/// `const _: &[u8] = include_bytes!("...");`: cargo then rebuilds the struct when the file
/// changes.
pub fn track(path: Option<&PathBuf>) -> TokenStream {
    match path.and_then(|p| p.to_str()) {
        Some(p) => quote!(
            const _: &[u8] = ::core::include_bytes!(#p);
        ),
        None => TokenStream::new(),
    }
}

/// `const BUS = Some(("bus/machine.toml", include_str!("...")))` in the impl: the description
/// as written and its text, which a program built as a module hands its host, so the host
/// runs the bus it was compiled against.
pub fn constant(c: &Container, path: Option<&PathBuf>) -> TokenStream {
    match (c.bus.as_ref(), path.and_then(|p| p.to_str())) {
        (Some(bus), Some(p)) => {
            let written = &bus.value;
            let krate = &c.krate;
            quote!(
                const BUS: ::core::option::Option<#krate::BusSource> =
                    ::core::option::Option::Some(#krate::BusSource {
                        file: #written,
                        text: ::core::include_str!(#p),
                    });
            )
        }
        _ => TokenStream::new(),
    }
}
