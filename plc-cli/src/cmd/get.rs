//! `plc get <segment> [name...]`: one consistent snapshot, every name from it (every variable
//! without names), printed as the `--digits`, `--hex` and `--bin` flags ask (reals at full
//! precision without them; a TIME or LTIME as seconds).

use super::{Error, is_path, leaves_of, resolve, show};
use crate::display::{self, Format};
use plc_shm::DynSegment;

/// One name of the command line: a variable or array element as before, or the values a
/// path reaches inside structures.
enum Wanted {
    Flat(usize, Option<usize>),
    Paths(Vec<plc_shm::PathLocation>),
}

pub fn run(segment: &str, names: &[String], format: &Format) -> Result<(), Error> {
    let seg = DynSegment::attach(segment)?;
    // No names: every variable, as a newcomer who has not yet run `plc list` expects.
    let every: Vec<String>;
    let names = if names.is_empty() {
        every = seg
            .descriptor()
            .variables
            .iter()
            .map(|v| v.name.clone())
            .collect();
        &every[..]
    } else {
        names
    };
    let wanted: Vec<Wanted> = names
        .iter()
        .map(|n| {
            if is_path(&seg, n) {
                leaves_of(&seg, n).map(Wanted::Paths)
            } else {
                resolve(&seg, n).map(|(i, _, e)| Wanted::Flat(i, e))
            }
        })
        .collect::<Result<_, _>>()?;
    let image = seg.snapshot_bytes()?;
    for (spec, w) in names.iter().zip(wanted) {
        match w {
            Wanted::Flat(i, element) => {
                println!("{spec} = {}", show(&seg, &image, i, element, format))
            }
            Wanted::Paths(paths) => {
                for at in paths {
                    let value = at.var.value_in(&image, 0).map_or("?".to_string(), |v| {
                        display::value(&v, at.var.iec_type, format)
                    });
                    println!("{} = {value}", at.path);
                }
            }
        }
    }
    Ok(())
}
