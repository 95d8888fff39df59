//! An HMI in another process: attaches to a running program's segment by name, writes values
//! over its socket, and prints live values, without the program's Rust types.
//!
//! ```sh
//! cargo run --release -p examples --bin tensile_tester &        # the control program
//! cargo run --release -p examples --bin hmi_reader -- tensile_tester \
//!     test_speed_mm_s=3.5 info_specimen_name="S235 bar"
//! ```
//!
//! Usage: `hmi_reader [SEGMENT] [NAME=VALUE]... [--seconds N]` (default segment
//! `tensile_tester`, 3 seconds of live values).

use plc_core::Value;
use plc_io::shm::DynSegment;
use std::process::ExitCode;
use std::time::Duration;

fn main() -> ExitCode {
    match run() {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("hmi_reader: {e}");
            ExitCode::FAILURE
        }
    }
}

fn run() -> Result<(), Box<dyn std::error::Error>> {
    let mut segment = "tensile_tester".to_string();
    let mut writes = Vec::new();
    let mut seconds = 3u64;
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        if a == "--seconds" {
            seconds = args.next().ok_or("--seconds needs a value")?.parse()?;
        } else if let Some((name, value)) = a.split_once('=') {
            writes.push((name.to_string(), value.to_string()));
        } else {
            segment = a;
        }
    }
    let seg = DynSegment::attach(&segment)?;
    println!(
        "attached to `{}`: {} variables, owner pid {} is {}",
        seg.name(),
        seg.descriptor().variables.len(),
        seg.status().pid,
        seg.owner_state()
    );
    for (name, text) in &writes {
        let i = seg
            .descriptor()
            .index_of(name)
            .ok_or_else(|| format!("`{segment}` has no variable `{name}`"))?;
        let value = Value::parse(text, seg.descriptor().variables[i].iec_type)
            .map_err(|e| format!("{name}: {e}"))?;
        seg.write(name, value)?;
        println!("wrote {name} = {value}");
    }
    for _ in 0..seconds {
        std::thread::sleep(Duration::from_secs(1));
        let image = seg.snapshot_bytes()?;
        let status = seg.status();
        let shown: Vec<String> = seg
            .descriptor()
            .variables
            .iter()
            .filter(|v| v.dims.is_empty())
            .map(|v| {
                let value = v.value_in(&image, 0).map_or("?".into(), |x| x.to_string());
                format!("{}={value}", v.name)
            })
            .collect();
        println!("cycle {}: {}", status.cycle_count, shown.join(" "));
    }
    Ok(())
}
