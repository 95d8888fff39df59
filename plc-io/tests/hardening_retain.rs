//! Retained values under attack: links and open modes planted where the retain file goes are
//! refused without touching anything outside, and a final save that is lost is an error from
//! `run`, with failed saves counted in the status. (The segment's files: `hardening.rs`.)

mod common;

use common::{Scratch, alone, is_root, unique, wait_for};
use plc_core::GlobalMemory;
use plc_io::shm::DynSegment;
use std::os::unix::fs::PermissionsExt;
use std::path::Path;
use std::time::Duration;

#[test]
fn planted_retain_links_and_open_modes_are_refused_and_nothing_outside_is_touched() {
    let _alone = alone();
    use plc_io::retain::{RetainError, RetainStore};
    #[derive(GlobalMemory, Debug, Clone)]
    pub struct Kept {
        #[plc(nonvolatile, initial = 5)]
        kept: u32,
    }
    let dir = Scratch::new("retain");
    let victim = dir.path("victim");
    std::fs::write(&victim, b"precious").unwrap();
    let sub = dir.path("r");
    let store = RetainStore::new(sub.join("p.retain"));
    // The directory is created private at load; the file is private.
    store.load(&mut Kept::default()).unwrap();
    store.save(&Kept::default()).unwrap();
    let mode = |p: &Path| std::fs::metadata(p).unwrap().permissions().mode() & 0o777;
    assert_eq!(mode(&sub), 0o700);
    assert_eq!(mode(&sub.join("p.retain")), 0o600);

    // A link where the next save's temporary file goes: replaced, never written through.
    let temp = sub.join(format!(".p.retain.tmp.{}", std::process::id()));
    std::os::unix::fs::symlink(&victim, &temp).unwrap();
    store.save(&Kept::default()).unwrap();
    assert_eq!(std::fs::read(&victim).unwrap(), b"precious");
    assert!(!temp.exists());

    fn unsafe_err<R: std::fmt::Debug>(r: Result<R, RetainError>) -> String {
        match r {
            Err(e @ RetainError::Unsafe { .. }) => e.to_string(),
            other => panic!("not refused: {other:?}"),
        }
    }
    // The retain file a link.
    let linked = RetainStore::new(sub.join("linked.retain"));
    std::os::unix::fs::symlink(&victim, sub.join("linked.retain")).unwrap();
    let text = unsafe_err(linked.load(&mut Kept::default()));
    assert!(text.contains("symbolic link"), "{text}");
    // A file others may read.
    std::fs::set_permissions(sub.join("p.retain"), std::fs::Permissions::from_mode(0o644)).unwrap();
    let text = unsafe_err(store.load(&mut Kept::default()));
    assert!(
        text.contains("mode 0644") && text.contains("chmod 600"),
        "{text}"
    );
    std::fs::set_permissions(sub.join("p.retain"), std::fs::Permissions::from_mode(0o600)).unwrap();
    // A directory anyone may write.
    std::fs::set_permissions(&sub, std::fs::Permissions::from_mode(0o777)).unwrap();
    let text = unsafe_err(store.save(&Kept::default()));
    assert!(text.contains("chmod 700"), "{text}");
    std::fs::set_permissions(&sub, std::fs::Permissions::from_mode(0o700)).unwrap();
    // A directory of another user.
    if is_root() {
        std::os::unix::fs::chown(&sub, Some(65534), None).unwrap();
        let text = unsafe_err(store.load(&mut Kept::default()));
        assert!(text.contains("belongs to uid 65534"), "{text}");
        std::os::unix::fs::chown(&sub, Some(0), None).unwrap();
    }
    // A directory that is a link.
    std::os::unix::fs::symlink(&sub, dir.path("dirlink")).unwrap();
    let via_link = RetainStore::new(dir.path("dirlink").join("p.retain"));
    let text = unsafe_err(via_link.save(&Kept::default()));
    assert!(text.contains("not a directory"), "{text}");
    assert_eq!(std::fs::read(&victim).unwrap(), b"precious");
}

#[derive(GlobalMemory, Debug, Clone)]
pub struct Saved {
    #[plc(nonvolatile)]
    count: u64,
    #[plc(direction = "command")]
    setpoint: u32,
    #[plc(direction = "output")]
    valve: bool,
}

#[test]
fn a_lost_final_retain_save_is_an_error_from_run_and_failed_saves_are_in_the_status() {
    let _alone = alone();
    let dir = Scratch::new("lostsave");
    let retain_dir = dir.path("r");
    let name = unique("lostsave");
    let builder = plc_io::Runtime::<Saved>::builder()
        .period(Duration::from_millis(2))
        .segment(&name)
        .retain(retain_dir.join("p.retain"))
        .retain_interval(Duration::from_millis(20))
        .handle_signals(false);
    let stop = builder.stop_handle();
    let runtime = std::thread::spawn(move || {
        builder
            .build()
            .expect("the runtime's settings are valid")
            .run(|ctx| ctx.gm.count += 1)
    });
    wait_for(Duration::from_secs(20), || {
        retain_dir.join("p.retain").exists().then_some(())
    });
    // The directory disappears (a full or failed disk does the same to the saves). A save
    // running meanwhile can add or rename a file inside it: try again until it is gone.
    wait_for(Duration::from_secs(20), || {
        std::fs::remove_dir_all(&retain_dir).ok()
    });
    let seg = wait_for(Duration::from_secs(20), || DynSegment::attach(&name).ok());
    wait_for(Duration::from_secs(20), || {
        (seg.status().retain_failures > 0).then_some(())
    });
    stop.stop();
    let err = runtime
        .join()
        .unwrap()
        .expect_err("the lost save is an error");
    assert!(
        matches!(err, plc_io::RuntimeError::RetainNotSaved(_)),
        "{err:?}"
    );
    assert!(err.to_string().contains("not saved"), "{err}");
}
