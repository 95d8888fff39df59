//! The program the `plc` command's tests run against, and the handle that starts it in another
//! process (the test binary runs itself as the program, `PLC_TEST_ROLE=owner`) and stops it
//! cleanly when dropped. Each test binary that uses it has a test `owner_role` calling [`run`].
#![allow(dead_code)] // each test file uses its part

use plc_core::{FixedString, GlobalMemory, Time};
use plc_io::Runtime;
use std::process::{Command, Stdio};
use std::time::Duration;

use crate::common::{ChildGuard, SpawnGuarded, plc, terminate, wait_until};

#[derive(GlobalMemory, Debug, Clone)]
pub struct Gm {
    /// Digital inputs
    #[plc(link = "ethercat.io.inputs", direction = "input")]
    pub inputs: u16,
    #[plc(source = "inputs", bit = 2)]
    pub door_closed: bool,
    #[plc(direction = "command", initial = 100)]
    pub speed_setpoint: u16,
    /// Follows the setpoint; its own reporting deadband and an overspeed alarm (the Sparkplug
    /// tests).
    #[plc(
        direction = "status",
        unit = "rpm",
        deadband = 50,
        alarm(text = "Overspeed", high = 1000.0, severity = 700)
    )]
    pub speed_actual: u16,
    #[plc(read_only, initial = 7)]
    pub serial: u32,
    #[plc(direction = "command", initial = "none")]
    pub recipe: FixedString<16>,
    pub counter: u64,
    pub table: [i16; 3],
    #[plc(direction = "command", initial = "T#1.5s")]
    pub dwell: Time,
}

/// Runs as the control program when `PLC_TEST_ROLE=owner`: a counter and the setpoint copied to
/// the actual speed, every 5 ms.
pub fn run() {
    let segment = std::env::var("SEGMENT").unwrap();
    Runtime::<Gm>::builder()
        .period(Duration::from_millis(5))
        .segment(segment)
        .build()
        .expect("the runtime's settings are valid")
        .run(|ctx| {
            ctx.gm.counter += 1;
            ctx.gm.speed_actual = ctx.gm.speed_setpoint;
        })
        .unwrap();
}

pub struct Owner {
    pub child: ChildGuard,
    pub segment: String,
}

impl Owner {
    pub fn start(test: &str) -> Owner {
        Owner::start_as(test, "owner")
    }

    /// Starts the program of `<role>_role`.
    pub fn start_as(test: &str, role: &str) -> Owner {
        let segment = format!("cli_{test}_{}", std::process::id());
        let child = Command::new(std::env::current_exe().unwrap())
            .args([&format!("{role}_role"), "--exact", "--nocapture"])
            .env("PLC_TEST_ROLE", role)
            .env("SEGMENT", &segment)
            .stdout(Stdio::null())
            .spawn_guarded()
            .unwrap();
        let owner = Owner { child, segment };
        wait_until("the owner to start", || {
            plc(&["get", &owner.segment, "counter"]).status.success()
        });
        owner
    }
}

impl Drop for Owner {
    fn drop(&mut self) {
        terminate(&mut self.child);
    }
}
