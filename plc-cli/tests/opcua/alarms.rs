//! A program's alarms as OPC UA conditions, checked by the independent client (python
//! asyncua, `plc-opcua/tests/client/opcua_alarms.py`, which lists what it checks at its top):
//! events through a severity filter on raise, acknowledgement and return to normal, an
//! acknowledgement by a user over SignAndEncrypt that reaches the program (and its journal),
//! refused over None, and ConditionRefresh.

use super::{add_user, python, script, serve, test_dir, wait_for};
use std::time::Duration;

/// A program with a bool alarm above the client's severity filter, one below it, and a limit
/// alarm; a tool raises them by writing their values (`plc set`).
#[derive(plc_core::GlobalMemory, Debug, Clone)]
pub struct Alarmed {
    #[plc(direction = "command", alarm(text = "Door open", severity = 700))]
    door: bool,
    #[plc(
        direction = "command",
        alarm(
            text = "Oil temperature",
            high = 80.0,
            high_high = 95.0,
            severity = 600
        )
    )]
    oil: f32,
    #[plc(direction = "command", alarm(text = "Filter dirty", severity = 300))]
    filter: bool,
    #[plc(direction = "status")]
    cycles: u64,
}

#[test]
fn alarms_are_conditions_with_events_acknowledgement_and_refresh() {
    python();
    let dir = test_dir("alarms");
    let segment = format!("opcua_alarms_{}", std::process::id());
    // The program's alarm journal in a directory of its own, 0700 as it asks.
    let journal_dir = dir.join("journal");
    {
        use std::os::unix::fs::DirBuilderExt;
        std::fs::DirBuilder::new()
            .mode(0o700)
            .create(&journal_dir)
            .expect("journal directory");
    }
    let rt = plc_io::Runtime::<Alarmed>::builder()
        .period(Duration::from_millis(1))
        .segment(&segment)
        .handle_signals(false)
        .alarm_journal(journal_dir.join("alarms.journal"))
        .build()
        .expect("the program starts");
    let stop = rt.stop_handle();
    let program = std::thread::spawn(move || rt.run(|ctx| ctx.gm.cycles += 1));
    // The client checks the program's side itself: `plc alarms` shows the acknowledgement,
    // `plc alarms --history` the user and comment the journal recorded.
    wait_for("the program", || {
        plc_io::shm::DynSegment::attach(&segment).is_ok()
    });
    let users = add_user(&dir);
    let (_server, port) = serve(&dir, &segment, Some(&users));
    let url = format!("opc.tcp://127.0.0.1:{port}/");
    let utf8 = |p: &std::path::Path| p.to_str().expect("a UTF-8 temp dir").to_string();
    let (pki, work) = (utf8(&dir.join("pki")), utf8(&dir));
    script(
        &dir,
        "opcua_alarms.py",
        &[
            "check",
            &url,
            &segment,
            env!("CARGO_BIN_EXE_plc"),
            &pki,
            &work,
            "operator",
            "pw of the operator",
        ],
    );

    stop.stop();
    program
        .join()
        .expect("the program thread")
        .expect("the program stops");
    let server_log = std::fs::read_to_string(dir.join("server.log")).unwrap_or_default();
    assert!(
        server_log.contains("OPC UA acknowledgement by `operator`: ")
            && server_log.contains(".door: \"seen from the HMI\""),
        "the acknowledgement is logged with its user and comment:\n{server_log}"
    );
    assert!(
        server_log.contains("OPC UA acknowledgement by `anonymous` refused: ")
            && server_log.contains("(BadUserAccessDenied)"),
        "the anonymous acknowledgement's refusal is logged:\n{server_log}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// As many alarms as a plant's, raised and cleared at once by `raise_all`.
#[derive(plc_core::GlobalMemory, Debug, Clone)]
pub struct Flooded {
    #[plc(alarm(text = "Door open", severity = 700))]
    doors: [bool; FLOOD],
    #[plc(direction = "command")]
    raise_all: bool,
}

/// The alarms of [`Flooded`]: two polls' worth of events (256 a poll), all in one subscriber's
/// queue of 1,000 with a ConditionRefresh's two more.
const FLOOD: usize = 500;

#[test]
fn a_flood_of_alarms_reaches_a_subscriber_whole() {
    python();
    let dir = test_dir("alarm-flood");
    let segment = format!("opcua_flood_{}", std::process::id());
    let rt = plc_io::Runtime::<Flooded>::builder()
        .period(Duration::from_millis(1))
        .segment(&segment)
        .handle_signals(false)
        .build()
        .expect("the program starts");
    let stop = rt.stop_handle();
    let program = std::thread::spawn(move || {
        rt.run(|ctx| {
            let raise = ctx.gm.raise_all;
            ctx.gm.doors.iter_mut().for_each(|d| *d = raise);
        })
    });
    wait_for("the program", || {
        plc_io::shm::DynSegment::attach(&segment).is_ok()
    });
    let (_server, port) = serve(&dir, &segment, None);
    let url = format!("opc.tcp://127.0.0.1:{port}/");
    let count = FLOOD.to_string();
    script(
        &dir,
        "opcua_alarms.py",
        &["flood", &url, &segment, env!("CARGO_BIN_EXE_plc"), &count],
    );
    stop.stop();
    program
        .join()
        .expect("the program thread")
        .expect("the program stops");
    let _ = std::fs::remove_dir_all(&dir);
}
