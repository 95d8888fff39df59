//! What another process can do to a program's shared files, tried as an attacker or a buggy
//! tool would: plant symbolic links, leave or truncate files, write hostile numbers into the
//! shared words. The program neither crashes, stalls, nor writes where it should not.

mod common;

use common::{kill9, role, spawn_role, unique, wait_for};
use plc_core::{GlobalMemory, Value};
use plc_io::shm::{DynSegment, SharedGlobalMemory, ShmError, list_segments};
use std::os::unix::fs::{FileExt, PermissionsExt};
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

#[derive(GlobalMemory, Debug, Clone)]
pub struct Plain {
    count: u64,
    #[plc(direction = "command")]
    setpoint: u32,
    #[plc(direction = "output")]
    valve: bool,
}

fn shm(name: &str) -> PathBuf {
    PathBuf::from(format!("/dev/shm/plc.{name}"))
}

fn lock(name: &str) -> PathBuf {
    PathBuf::from(format!("/dev/shm/plc.{name}.lock"))
}

fn is_root() -> bool {
    // SAFETY: geteuid has no preconditions.
    unsafe { libc::geteuid() == 0 }
}

/// A scratch directory, removed on drop.
struct Scratch(PathBuf);

impl Scratch {
    fn new(what: &str) -> Scratch {
        let dir = std::env::temp_dir().join(format!("plc-harden-{what}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir(&dir).unwrap();
        std::fs::set_permissions(&dir, std::fs::Permissions::from_mode(0o700)).unwrap();
        Scratch(dir)
    }
    fn path(&self, name: &str) -> PathBuf {
        self.0.join(name)
    }
}

impl Drop for Scratch {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// Removes the files of segment `name` on drop (a test that fails must not leave them).
struct Cleanup(String);

impl Drop for Cleanup {
    fn drop(&mut self) {
        let _ = std::fs::remove_file(shm(&self.0));
        let _ = std::fs::remove_file(lock(&self.0));
    }
}

fn word(path: &Path, at: u64) -> u64 {
    let f = std::fs::File::open(path).unwrap();
    let mut b = [0u8; 8];
    f.read_exact_at(&mut b, at).unwrap();
    u64::from_le_bytes(b)
}

fn set_word(path: &Path, at: u64, v: u64) {
    let f = std::fs::OpenOptions::new().write(true).open(path).unwrap();
    f.write_all_at(&v.to_le_bytes(), at).unwrap();
}

#[test]
fn a_symlink_at_the_lock_or_segment_path_is_refused_and_its_target_untouched() {
    let dir = Scratch::new("link");
    let victim = dir.path("victim");
    std::fs::write(&victim, b"precious").unwrap();
    let paths: [fn(&str) -> PathBuf; 2] = [lock, shm];
    for (i, path_of) in paths.into_iter().enumerate() {
        let name = unique(&format!("link{i}"));
        let _c = Cleanup(name.clone());
        std::os::unix::fs::symlink(&victim, path_of(&name)).unwrap();
        let err = SharedGlobalMemory::<Plain>::create(&name)
            .err()
            .expect("refused");
        let text = err.to_string();
        assert!(matches!(err, ShmError::Unsafe { .. }), "{err:?}");
        assert!(
            text.contains("symbolic link") && text.contains(&path_of(&name).display().to_string()),
            "{text}"
        );
        assert_eq!(std::fs::read(&victim).unwrap(), b"precious");
    }
}

#[test]
fn a_lock_file_open_to_others_or_of_another_user_is_refused_with_the_fix() {
    let name = unique("lockmode");
    let _c = Cleanup(name.clone());
    std::fs::write(lock(&name), b"").unwrap();
    std::fs::set_permissions(lock(&name), std::fs::Permissions::from_mode(0o644)).unwrap();
    let err = SharedGlobalMemory::<Plain>::create(&name)
        .err()
        .expect("refused");
    assert!(
        err.to_string().contains("mode 0644") && err.to_string().contains("chmod 600"),
        "{err}"
    );
    if is_root() {
        std::fs::set_permissions(lock(&name), std::fs::Permissions::from_mode(0o600)).unwrap();
        std::os::unix::fs::chown(lock(&name), Some(65534), None).unwrap();
        let err = SharedGlobalMemory::<Plain>::create(&name)
            .err()
            .expect("refused");
        assert!(err.to_string().contains("belongs to uid 65534"), "{err}");
    }
}

#[test]
fn an_empty_leftover_segment_does_not_block_a_new_owner() {
    let name = unique("touched");
    let _c = Cleanup(name.clone());
    // What `touch /dev/shm/plc.<name>` leaves: an empty file of this user.
    let f = std::fs::OpenOptions::new()
        .write(true)
        .create_new(true)
        .open(shm(&name))
        .unwrap();
    f.set_permissions(std::fs::Permissions::from_mode(0o600))
        .unwrap();
    drop(f);
    let owner = SharedGlobalMemory::<Plain>::create(&name).expect("the leftover is replaced");
    owner.publish(&Plain::default()).unwrap();
    assert!(DynSegment::attach(&name).is_ok());
}

#[test]
fn a_segment_truncated_under_its_owner_neither_kills_it_nor_stops_the_tools() {
    if role().as_deref() == Some("truncated_owner") {
        let name = std::env::var("SEGMENT").unwrap();
        let mut owner = SharedGlobalMemory::<Plain>::create(&name).unwrap();
        let mut gm = Plain::default();
        let start = Instant::now();
        // Every publish and mailbox access after the truncation would be a SIGBUS without the
        // guard; the test's write of `setpoint` ends the loop.
        while gm.setpoint == 0 {
            gm.count += 1;
            owner.publish(&gm).unwrap();
            owner.apply_mailbox(&mut gm);
            assert!(
                start.elapsed() < Duration::from_secs(60),
                "never told to stop"
            );
            std::thread::sleep(Duration::from_millis(1));
        }
        return; // a clean stop: `owner` drops
    }
    if role().is_some() {
        return;
    }
    let name = unique("truncated");
    let _c = Cleanup(name.clone());
    let mut child = spawn_role(
        "a_segment_truncated_under_its_owner_neither_kills_it_nor_stops_the_tools",
        "truncated_owner",
        &[("SEGMENT", name.clone())],
    );
    let before = wait_for(Duration::from_secs(20), || DynSegment::attach(&name).ok());
    let first = before.status().generation;
    std::fs::OpenOptions::new()
        .write(true)
        .open(shm(&name))
        .unwrap()
        .set_len(0)
        .unwrap();
    // The owner replaces the segment at its next cycle: tools attach to the new one.
    let after = wait_for(Duration::from_secs(20), || {
        DynSegment::attach(&name)
            .ok()
            .filter(|s| s.status().generation != first)
    });
    let count = |s: &DynSegment| match s.read("count") {
        Ok(Value::UInt(n)) => n,
        other => panic!("{other:?}"),
    };
    let was = count(&after);
    wait_for(Duration::from_secs(20), || {
        (count(&after) > was).then_some(())
    });
    after.write("setpoint", Value::UInt(1)).unwrap();
    let status = child.wait().unwrap();
    assert!(status.success(), "the owner died: {status:?}");
    // It stopped cleanly: both files are gone, and the name is free at once.
    assert!(!shm(&name).exists() && !lock(&name).exists());
    assert!(SharedGlobalMemory::<Plain>::create(&name).is_ok());
}

#[test]
fn an_odd_or_huge_seqlock_word_written_from_outside_neither_stops_readers_nor_the_owner() {
    let name = unique("seqword");
    let owner = SharedGlobalMemory::<Plain>::create(&name).unwrap();
    let reader = DynSegment::attach(&name).unwrap();
    for hostile in [1, u64::MAX, u64::MAX - 1] {
        set_word(&shm(&name), 40, hostile);
        let gm = Plain {
            count: hostile,
            ..Default::default()
        };
        owner.publish(&gm).unwrap();
        assert_eq!(reader.read("count"), Ok(Value::UInt(hostile)));
    }
}

/// Byte offsets of the mailbox words of a `Plain` segment: head, tail, first slot.
fn mailbox_words() -> (u64, u64, u64) {
    let image = std::mem::size_of::<<Plain as GlobalMemory>::Image>() as u64;
    let mailbox = 192 + image.div_ceil(8) * 8;
    (mailbox, mailbox + 8, mailbox + 32)
}

#[test]
fn hostile_mailbox_words_neither_stall_a_writer_nor_panic_the_owner() {
    let name = unique("mbwords");
    let mut owner = SharedGlobalMemory::<Plain>::create(&name).unwrap();
    let (head, tail, slot0) = mailbox_words();
    let path = shm(&name);
    // A slot sequence far ahead of the head: a producer waits for a turn that never comes.
    set_word(&path, slot0, 1 << 40);
    let (tx, rx) = std::sync::mpsc::channel();
    let writer_name = name.clone();
    std::thread::spawn(move || {
        let seg = DynSegment::attach(&writer_name).unwrap();
        let _ = tx.send(seg.write("setpoint", Value::UInt(5)));
    });
    let result = rx
        .recv_timeout(Duration::from_secs(20))
        .expect("the writer returns");
    assert!(
        matches!(result, Err(ShmError::MailboxDamaged(_))),
        "{result:?}"
    );
    // Counters at the end of their range, where `+ 1` overflows.
    let mut gm = Plain::default();
    for (at, v) in [
        (tail, u64::MAX),
        (head, u64::MAX),
        (slot0, 0),
        (slot0, u64::MAX),
    ] {
        set_word(&path, at, v);
        owner.apply_mailbox(&mut gm);
        owner.publish(&gm).unwrap();
    }
    assert_eq!(gm.setpoint, 0, "nothing was applied from damaged words");
}

#[test]
fn a_huge_descriptor_length_is_refused_without_reading_it_and_listed_as_damaged() {
    let name = unique("hugedesc");
    let _owner = SharedGlobalMemory::<Plain>::create(&name).unwrap();
    let path = shm(&name);
    // Grown sparse to 1 GiB, with a header that says the descriptor fills it.
    let f = std::fs::OpenOptions::new().write(true).open(&path).unwrap();
    f.set_len(1 << 30).unwrap();
    let d_off = word(&path, 48);
    set_word(&path, 56, (1 << 30) - d_off);
    let start = Instant::now();
    let err = DynSegment::attach(&name).err().expect("refused");
    assert!(
        err.to_string().contains("more than"),
        "refused for its size, not after reading it: {err}"
    );
    assert!(start.elapsed() < Duration::from_secs(5));
    let listed = list_segments();
    let me = listed
        .iter()
        .find(|s| s.name == name)
        .expect("a damaged segment is listed, not dropped");
    assert!(
        me.problem
            .as_ref()
            .is_some_and(|p| p.to_string().contains("damaged")),
        "{me:?}"
    );
}

#[test]
fn a_tool_without_permission_is_told_so_not_that_there_is_no_segment() {
    if role().as_deref() == Some("stranger") {
        let name = std::env::var("SEGMENT").unwrap();
        if is_root() {
            // SAFETY: dropping privileges in this child process only.
            unsafe {
                assert_eq!(libc::setgid(65534), 0);
                assert_eq!(libc::setuid(65534), 0);
            }
        }
        let err = DynSegment::attach(&name).err().expect("refused");
        assert!(
            matches!(err, ShmError::PermissionDenied { .. })
                && err.to_string().contains("permission denied"),
            "{err:?}"
        );
        std::process::exit(0);
    }
    if role().is_some() {
        return;
    }
    let name = unique("stranger");
    let _owner = SharedGlobalMemory::<Plain>::create(&name).unwrap();
    if !is_root() {
        // The owner's own uid is refused only once the mode says so.
        std::fs::set_permissions(shm(&name), std::fs::Permissions::from_mode(0o000)).unwrap();
    }
    let mut child = spawn_role(
        "a_tool_without_permission_is_told_so_not_that_there_is_no_segment",
        "stranger",
        &[("SEGMENT", name.clone())],
    );
    assert!(child.wait().unwrap().success());
}

#[test]
fn a_clean_stop_leaves_no_file_and_a_killed_owners_files_are_removed_by_the_next_owner() {
    if role().as_deref() == Some("killed_owner") {
        let name = std::env::var("SEGMENT").unwrap();
        let owner = SharedGlobalMemory::<Plain>::create(&name).unwrap();
        loop {
            owner.publish(&Plain::default()).unwrap();
            std::thread::sleep(Duration::from_millis(2));
        }
    }
    if role().is_some() {
        return;
    }
    let clean = unique("cleanstop");
    drop(SharedGlobalMemory::<Plain>::create(&clean).unwrap());
    assert!(!shm(&clean).exists(), "segment removed");
    assert!(!lock(&clean).exists(), "lock file removed");

    let killed = unique("killedleft");
    let _c = Cleanup(killed.clone());
    let mut child = spawn_role(
        "a_clean_stop_leaves_no_file_and_a_killed_owners_files_are_removed_by_the_next_owner",
        "killed_owner",
        &[("SEGMENT", killed.clone())],
    );
    wait_for(Duration::from_secs(20), || DynSegment::attach(&killed).ok());
    let other = unique("sweeper");
    let alive = SharedGlobalMemory::<Plain>::create(&other).unwrap();
    assert!(
        shm(&killed).exists() && lock(&killed).exists(),
        "a live owner's files are left alone"
    );
    drop(alive);
    kill9(&mut child);
    assert!(shm(&killed).exists(), "a kill leaves the files");
    let _next = SharedGlobalMemory::<Plain>::create(&other).unwrap();
    assert!(
        !shm(&killed).exists() && !lock(&killed).exists(),
        "the next owner of any name removed them"
    );
}

#[test]
fn a_new_owner_after_a_clean_stop_has_a_later_generation() {
    let name = unique("generation");
    let first = SharedGlobalMemory::<Plain>::create(&name)
        .unwrap()
        .generation();
    let second = SharedGlobalMemory::<Plain>::create(&name)
        .unwrap()
        .generation();
    assert!(second > first, "{first} then {second}");
}

#[test]
fn planted_retain_links_and_open_modes_are_refused_and_nothing_outside_is_touched() {
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
    let temp = sub.join(format!("p.tmp.{}", std::process::id()));
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
    let runtime = std::thread::spawn(move || builder.build().run(|ctx| ctx.gm.count += 1));
    wait_for(Duration::from_secs(20), || {
        retain_dir.join("p.retain").exists().then_some(())
    });
    // The directory disappears (a full or failed disk does the same to the saves).
    std::fs::remove_dir_all(&retain_dir).unwrap();
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

#[test]
fn hostile_mailbox_words_while_the_runtime_cycles_do_not_stop_it() {
    let name = unique("rtwords");
    let builder = plc_io::Runtime::<Plain>::builder()
        .period(Duration::from_millis(1))
        .segment(&name)
        .max_cycles(400)
        .handle_signals(false);
    let hostile_name = name.clone();
    let attacker = std::thread::spawn(move || {
        wait_for(Duration::from_secs(20), || {
            DynSegment::attach(&hostile_name).ok()
        });
        let (head, tail, slot0) = mailbox_words();
        let path = shm(&hostile_name);
        for v in [u64::MAX, u64::MAX - 1, 0, 1 << 63] {
            for at in [head, tail, slot0, 40] {
                if path.exists() {
                    set_word(&path, at, v);
                }
            }
            std::thread::sleep(Duration::from_millis(20));
        }
    });
    let gm = builder
        .build()
        .run(|ctx| {
            ctx.gm.count += 1;
            ctx.gm.valve = ctx.gm.count % 2 == 0;
        })
        .expect("the runtime keeps cycling");
    attacker.join().unwrap();
    assert_eq!(gm.count, 400);
    assert_eq!(gm.setpoint, 0, "no write was made up from damaged words");
}

#[derive(GlobalMemory, Debug, Clone, PartialEq)]
pub struct Guarded {
    #[plc(direction = "input")]
    sensor: u16,
    #[plc(direction = "status")]
    state: u8,
    #[plc(read_only, initial = 7)]
    serial: u32,
    #[plc(direction = "command")]
    speed: u8,
    #[plc(direction = "command")]
    note: plc_core::FixedString<8>,
    table: [i16; 4],
}

/// One thing a misbehaving writer does to the mailbox.
#[derive(Clone, Debug)]
enum Message {
    /// A well-formed request with any index, element and value, past every writer check.
    Post(usize, usize, Box<Value>),
    /// A word anywhere in the mailbox (head, tail, counters, slots) set to anything.
    Word(u64, u64),
}

fn any_value() -> impl proptest::strategy::Strategy<Value = Value> {
    use proptest::prelude::*;
    prop_oneof![
        any::<bool>().prop_map(Value::Bool),
        any::<i64>().prop_map(Value::Int),
        any::<u64>().prop_map(Value::UInt),
        any::<f64>().prop_map(Value::Real),
        "[a-z\u{e9}]{0,12}".prop_map(|s| Value::Text(plc_core::FixedString::from_str_truncate(&s))),
    ]
}

fn any_message() -> impl proptest::strategy::Strategy<Value = Message> {
    use proptest::prelude::*;
    let mailbox_words = (32 + 64 * 288) / 8;
    prop_oneof![
        (0usize..10, 0usize..8, any_value()).prop_map(|(i, e, v)| Message::Post(i, e, Box::new(v))),
        (
            0u64..mailbox_words,
            prop_oneof![
                any::<u64>(),
                Just(0u64),
                Just(u64::MAX),
                Just(1u64 << 40),
                0u64..200
            ]
        )
            .prop_map(|(w, v)| Message::Word(w, v)),
    ]
}

proptest::proptest! {
    #![proptest_config(proptest::test_runner::Config::with_cases(64))]

    /// Whatever arrives, the owner neither panics nor loops, a writer returns, nothing that may
    /// not be written from outside changes, and what is applied is what `set` accepts.
    #[test]
    fn the_owner_survives_arbitrary_mailbox_messages(
        messages in proptest::collection::vec(any_message(), 1..40)
    ) {
        let name = unique("prop");
        let mut owner = SharedGlobalMemory::<Guarded>::create(&name).unwrap();
        let seg = DynSegment::attach(&name).unwrap();
        let path = shm(&name);
        let image = std::mem::size_of::<<Guarded as GlobalMemory>::Image>() as u64;
        let mailbox = 192 + image.div_ceil(8) * 8;
        let mut gm = Guarded::default();
        for m in &messages {
            match m {
                Message::Post(i, e, v) => {
                    let start = Instant::now();
                    let _ = seg.post_unchecked(*i, *e, **v);
                    proptest::prop_assert!(start.elapsed() < Duration::from_secs(5));
                }
                Message::Word(w, v) => set_word(&path, mailbox + w * 8, *v),
            }
            let mut applied = Vec::new();
            owner.apply_mailbox_with(&mut gm, |r, outcome| {
                if outcome.is_ok() {
                    applied.push(*r);
                }
            });
            for r in applied {
                let var = &Guarded::VARIABLES[r.index];
                proptest::prop_assert!(var.writable_from_outside(), "{} was written", var.name);
                proptest::prop_assert!(r.element < var.elements());
            }
            proptest::prop_assert_eq!((gm.sensor, gm.state, gm.serial), (0, 0, 7));
        }
        // After all that, a correct write still gets through once the ring is usable again, or
        // is refused with an error: never a hang.
        let start = Instant::now();
        let _ = seg.write("speed", Value::UInt(3));
        proptest::prop_assert!(start.elapsed() < Duration::from_secs(5));
        drop(seg);
        drop(owner);
        proptest::prop_assert!(!path.exists());
    }
}

#[derive(GlobalMemory, Debug, Clone)]
pub struct Attacked {
    #[plc(direction = "status")]
    count: u64,
    /// Always twice `count`: only the program writes either.
    #[plc(direction = "status")]
    doubled: u64,
    #[plc(direction = "command")]
    setpoint: u32,
    /// The last accepted `setpoint`.
    #[plc(direction = "status")]
    echo: u32,
}

/// A small deterministic generator: the attack needs noise, not statistics.
struct Noise(u64);

impl Noise {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }
    fn below(&mut self, n: u64) -> u64 {
        self.next() % n.max(1)
    }
}

/// Times `f`, which must answer within a few seconds whatever state the segment is in.
fn bounded<R>(what: &str, f: impl FnOnce() -> R) -> R {
    let start = Instant::now();
    let r = f();
    assert!(
        start.elapsed() < Duration::from_secs(5),
        "{what} took {:?}",
        start.elapsed()
    );
    r
}

#[test]
fn a_hostile_process_neither_stops_the_owner_nor_the_tools_for_longer_than_the_attack() {
    match role().as_deref() {
        Some("attacked_owner") => {
            let name = std::env::var("SEGMENT").unwrap();
            let _ = plc_io::Runtime::<Attacked>::builder()
                .period(Duration::from_millis(2))
                .segment(name)
                .handle_signals(false)
                .build()
                .run(|ctx| {
                    // Status variables come from the program alone: had a write from outside
                    // been applied to one, this panics, the run ends and the test sees the
                    // owner gone.
                    assert_eq!(ctx.gm.doubled, ctx.gm.count * 2, "a status was written");
                    ctx.gm.count += 1;
                    ctx.gm.doubled = ctx.gm.count * 2;
                    ctx.gm.echo = ctx.gm.setpoint;
                });
            return;
        }
        Some("attacker") => {
            let name = std::env::var("SEGMENT").unwrap();
            let mut noise = Noise(0x9E37_79B9_7F4A_7C15 ^ u64::from(std::process::id()));
            let start = Instant::now();
            while start.elapsed() < Duration::from_secs(3) {
                // Random bytes over the segment and the lock file, and resizes.
                for path in [shm(&name), lock(&name)] {
                    let Ok(f) = std::fs::OpenOptions::new().write(true).open(&path) else {
                        continue;
                    };
                    let len = f.metadata().map(|m| m.len()).unwrap_or(0).max(1);
                    for _ in 0..8 {
                        let bytes: Vec<u8> = (0..1 + noise.below(64))
                            .map(|_| noise.next() as u8)
                            .collect();
                        let _ = f.write_all_at(&bytes, noise.below(len));
                    }
                    match noise.below(50) {
                        0 => drop(f.set_len(noise.below(len))),
                        1 => drop(f.set_len(len + noise.below(1 << 16))),
                        _ => {}
                    }
                }
                // Flood the mailbox: requests of any kind past the writer's checks, and
                // valid-looking ones.
                if let Ok(seg) = DynSegment::attach(&name) {
                    for _ in 0..16 {
                        let value = match noise.below(4) {
                            0 => Value::UInt(noise.next()),
                            1 => Value::Int(noise.next() as i64),
                            2 => Value::Real(f64::from_bits(noise.next())),
                            _ => Value::Bool(noise.next() & 1 == 1),
                        };
                        let _ = seg.post_unchecked(
                            noise.below(6) as usize,
                            noise.below(3) as usize,
                            value,
                        );
                        let _ = seg.write("setpoint", Value::UInt(noise.below(1000)));
                    }
                }
            }
            return;
        }
        Some(_) => return,
        None => {}
    }
    let test = "a_hostile_process_neither_stops_the_owner_nor_the_tools_for_longer_than_the_attack";
    let name = unique("attacked");
    let _c = Cleanup(name.clone());
    let mut owner = spawn_role(test, "attacked_owner", &[("SEGMENT", name.clone())]);
    wait_for(Duration::from_secs(20), || DynSegment::attach(&name).ok());
    let mut attacker = spawn_role(test, "attacker", &[("SEGMENT", name.clone())]);
    // During the attack every tool call answers (rightly or with an error) in bounded time.
    let mut calls = 0;
    while attacker.try_wait().unwrap().is_none() {
        if let Ok(seg) = bounded("attach", || DynSegment::attach(&name)) {
            let _ = bounded("get", || seg.read("count"));
            let _ = bounded("set", || seg.write("setpoint", Value::UInt(1)));
        }
        bounded("list", list_segments);
        calls += 1;
    }
    assert!(attacker.wait().unwrap().success());
    assert!(calls > 0);
    // Within moments of the end, the tools read the program's own values and writes arrive.
    let attack_over = Instant::now();
    let seg = wait_for(Duration::from_secs(3), || {
        let seg = DynSegment::attach(&name).ok()?;
        let image = seg.snapshot_bytes().ok()?;
        let at = |i| seg.value_at(&image, i, 0);
        let (Some(Value::UInt(count)), Some(Value::UInt(doubled))) = (at(0), at(1)) else {
            return None;
        };
        (count > 0 && doubled == 2 * count).then_some(seg)
    });
    seg.write("setpoint", Value::UInt(4242)).unwrap();
    wait_for(Duration::from_secs(3), || {
        (seg.read("echo") == Ok(Value::UInt(4242))).then_some(())
    });
    let listed = list_segments();
    let me = listed.iter().find(|s| s.name == name).expect("listed");
    assert!(
        me.problem.is_none() && me.state == plc_io::shm::OwnerState::Running,
        "{me:?}"
    );
    let recovered = attack_over.elapsed();
    // The owner cycled through it all: it is still the one process that owns the segment.
    assert!(owner.try_wait().unwrap().is_none(), "the owner died");
    let before = seg.status().cycle_count;
    wait_for(Duration::from_secs(3), || {
        (seg.status().cycle_count > before).then_some(())
    });
    // Killed, it is replaced at once by a new owner.
    kill9(&mut owner);
    let next = SharedGlobalMemory::<Attacked>::create(&name).expect("a new owner starts at once");
    next.publish(&Attacked::default()).unwrap();
    assert!(SharedGlobalMemory::<Attacked>::attach(&name).is_ok());
    eprintln!("recovered {recovered:?} after the attack, {calls} tool rounds during it");
}
