//! `plc opcua serve` against the running main example, checked by an independent OPC UA
//! client: python asyncua, which `scripts/test.sh` installs into a virtual environment under
//! `target/` and names in `PLC_OPCUA_PYTHON`. The client's script is
//! `plc-opcua/tests/client/opcua_client.py`; what it checks is listed at its top.

use std::fs::File;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use plc_test_support::{ChildGuard, SpawnGuarded};

/// A program's alarms as OPC UA conditions.
#[path = "opcua/alarms.rs"]
mod alarms;

/// The venv's python, which has asyncua.
fn python() -> PathBuf {
    match std::env::var_os("PLC_OPCUA_PYTHON") {
        Some(p) if !p.is_empty() => PathBuf::from(p),
        _ => panic!(
            "PLC_OPCUA_PYTHON is not set: run the tests with scripts/test.sh, which installs the \
             OPC UA test client (python asyncua) into target/opcua-venv and sets it"
        ),
    }
}

/// The main example's binary, built beside `plc` by `cargo test --workspace`.
fn tensile_tester() -> PathBuf {
    let path = Path::new(env!("CARGO_BIN_EXE_plc")).with_file_name("tensile_tester");
    assert!(
        path.is_file(),
        "{} is missing: run the tests with scripts/test.sh (or `cargo build -p examples --bin \
         tensile_tester` first)",
        path.display()
    );
    path
}

fn start_program(dir: &Path, segment: &str, n: usize) -> ChildGuard {
    let log = File::create(dir.join(format!("tensile_tester-{n}.log"))).expect("log file");
    let child = Command::new(tensile_tester())
        .args(["--segment", segment])
        .arg("--retain")
        .arg(dir.join("retain"))
        .stdout(log.try_clone().expect("log file"))
        .stderr(log)
        .spawn_guarded()
        .expect("tensile_tester starts");
    wait_for(&format!("segment {segment}"), || {
        Command::new(env!("CARGO_BIN_EXE_plc"))
            .args(["get", segment, "state_cycles"])
            .output_guarded()
            .is_ok_and(|o| o.status.success())
    });
    child
}

fn wait_for(what: &str, mut ready: impl FnMut() -> bool) {
    // Generous: a debug build on a busy machine makes its RSA key and brings its bus up slowly.
    let deadline = Instant::now() + Duration::from_secs(120);
    while !ready() {
        assert!(Instant::now() < deadline, "{what} never came up");
        std::thread::sleep(Duration::from_millis(100));
    }
}

/// Runs the client script; panics with its output unless it succeeds.
fn client(dir: &Path, args: &[&str]) {
    script(dir, "opcua_client.py", args);
}

/// Runs the client script `name` (in `plc-opcua/tests/client/`); panics with its output and
/// the tails of the logs in `dir` unless it succeeds.
fn script(dir: &Path, name: &str, args: &[&str]) {
    let script = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../plc-opcua/tests/client")
        .join(name);
    let out = Command::new(python())
        .arg(script)
        .args(args)
        .output_guarded()
        .expect("python starts");
    let stdout = String::from_utf8_lossy(&out.stdout);
    print!("{stdout}");
    if !out.status.success() {
        let logs: String = std::fs::read_dir(dir)
            .into_iter()
            .flatten()
            .flatten()
            .filter(|e| e.path().extension().is_some_and(|x| x == "log"))
            .map(|e| {
                let text = std::fs::read_to_string(e.path()).unwrap_or_default();
                let tail: Vec<&str> = text.lines().rev().take(30).collect();
                format!(
                    "--- {}\n{}\n",
                    e.path().display(),
                    tail.into_iter().rev().collect::<Vec<_>>().join("\n")
                )
            })
            .collect();
        panic!(
            "the OPC UA client failed:\n{stdout}\n{}\n{logs}",
            String::from_utf8_lossy(&out.stderr)
        );
    }
}

/// `plc opcua serve SEGMENT` on localhost, its certificates in `dir/pki`, its output in
/// `dir/server.log`; returns once it accepts connections.
fn serve(dir: &Path, segment: &str, users: Option<&Path>) -> (ChildGuard, u16) {
    let port = free_port();
    let log = File::create(dir.join("server.log")).expect("log file");
    let mut command = Command::new(env!("CARGO_BIN_EXE_plc"));
    command
        .args(["opcua", "serve", segment, "--host", "127.0.0.1", "--port"])
        .arg(port.to_string())
        .arg("--pki")
        .arg(dir.join("pki"))
        .stdout(log.try_clone().expect("log file"))
        .stderr(log);
    if let Some(users) = users {
        command.arg("--users").arg(users);
    }
    let server = command.spawn_guarded().expect("plc opcua serve starts");
    wait_for("the OPC UA server", || {
        std::net::TcpStream::connect(("127.0.0.1", port)).is_ok()
    });
    (server, port)
}

/// A users file in `dir` with the user `operator` (password `pw of the operator`), made by
/// `plc opcua user add` with the password on standard input.
fn add_user(dir: &Path) -> PathBuf {
    let users = dir.join("users");
    let mut add = Command::new(env!("CARGO_BIN_EXE_plc"))
        .args(["opcua", "user", "add"])
        .arg(&users)
        .arg("operator")
        .stdin(Stdio::piped())
        .spawn_guarded()
        .expect("plc opcua user add starts");
    use std::io::Write;
    add.stdin
        .take()
        .expect("stdin")
        .write_all(b"pw of the operator\n")
        .expect("password written");
    assert!(add.wait().expect("user add ends").success());
    let text = std::fs::read_to_string(&users).expect("users file");
    assert!(text.contains("operator:$argon2id$") && !text.contains("pw of the operator"));
    users
}

/// A fresh directory for one test's files.
fn test_dir(what: &str) -> PathBuf {
    let nanos = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.subsec_nanos());
    let dir = std::env::temp_dir().join(format!("plc-opcua-{what}-{}_{nanos}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("test directory");
    dir
}

/// Runs the client script's check `what` as the user `operator`, with the server's
/// certificate store (`dir/pki`) and `dir` to make the client's certificate in.
fn user_client(dir: &Path, what: &str, url: &str, segment: &str) {
    let (pki, work) = (dir.join("pki"), dir);
    let utf8 = |p: &Path| p.to_str().expect("a UTF-8 temp dir").to_string();
    let (pki, work) = (utf8(&pki), utf8(work));
    client(
        dir,
        &[
            what,
            url,
            segment,
            "operator",
            "pw of the operator",
            &pki,
            &work,
        ],
    );
}

/// A TCP port free just now.
fn free_port() -> u16 {
    let listener = std::net::TcpListener::bind("127.0.0.1:0").expect("a free port");
    listener.local_addr().expect("its address").port()
}

#[test]
fn an_independent_opcua_client_browses_reads_subscribes_writes_and_follows_a_restart() {
    // Fails at once, saying how to install the client, when it is not there.
    python();
    let dir = test_dir("example");
    let segment = format!("opcua_test_{}", std::process::id());
    let mut program = start_program(&dir, &segment, 1);

    let users = add_user(&dir);
    let pki = dir.join("pki");
    let (_server, port) = serve(&dir, &segment, Some(&users));
    assert!(
        pki.join("own/cert.der").is_file() && pki.join("private/private.pem").is_file(),
        "the server made its certificate in --pki"
    );
    let url = format!("opc.tcp://127.0.0.1:{port}/");
    let plc = env!("CARGO_BIN_EXE_plc");
    let work = dir.to_str().expect("a UTF-8 temp dir");
    let pki_text = pki.to_str().expect("a UTF-8 temp dir");
    client(
        &dir,
        &[
            "check",
            &url,
            &segment,
            plc,
            pki_text,
            work,
            "operator",
            "pw of the operator",
        ],
    );

    // The program killed: values Bad; started again (a takeover of its segment): Good again.
    let _ = program.kill();
    let _ = program.wait();
    client(&dir, &["values", &url, &segment, "bad"]);
    program = start_program(&dir, &segment, 2);
    client(&dir, &["values", &url, &segment, "good"]);
    drop(program);
    let server_log = std::fs::read_to_string(dir.join("server.log")).unwrap_or_default();
    assert!(
        server_log.contains("OPC UA write by `operator`: ")
            && server_log.contains("test_speed_mm_s: "),
        "every write is logged with its user and old and new value:\n{server_log}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// The first declaration of a program whose declaration changes.
#[derive(plc_core::GlobalMemory, Debug, Clone)]
pub struct Before {
    #[plc(direction = "status")]
    count: u32,
    #[plc(direction = "command")]
    speed: f64,
    #[plc(alarm = "Door open")]
    door: bool,
}

/// Its next declaration: `speed` and the door's alarm gone, `grid` and the lid's alarm new.
#[derive(plc_core::GlobalMemory, Debug, Clone)]
pub struct After {
    #[plc(direction = "status")]
    count: u32,
    grid: [i16; 6],
    #[plc(alarm = "Lid open")]
    lid: bool,
}

/// Runs an owner of `T` on `segment`, applying writes and publishing every millisecond, until
/// `stop`.
fn run_owner<T: plc_core::GlobalMemory + Default + Clone + Send + 'static>(
    segment: String,
    stop: std::sync::Arc<std::sync::atomic::AtomicBool>,
) -> std::thread::JoinHandle<()> {
    std::thread::spawn(move || {
        let mut owner = plc_io::shm::SharedGlobalMemory::<T>::create(&segment).expect("owner");
        let mut gm = T::default();
        while !stop.load(std::sync::atomic::Ordering::Relaxed) {
            owner.apply_requests(&mut gm);
            owner.publish(&gm).expect("publish");
            std::thread::sleep(Duration::from_millis(1));
        }
    })
}

#[test]
fn a_changed_declaration_rebuilds_the_namespace() {
    python();
    let dir = test_dir("layout");
    let segment = format!("opcua_layout_{}", std::process::id());
    let stop = std::sync::Arc::new(std::sync::atomic::AtomicBool::new(false));
    let owner = run_owner::<Before>(segment.clone(), stop.clone());
    wait_for("the first owner", || {
        plc_io::shm::DynSegment::attach(&segment).is_ok()
    });
    let (_server, port) = serve(&dir, &segment, None);
    let url = format!("opc.tcp://127.0.0.1:{port}/");
    client(&dir, &["names", &url, &segment, "count,door,speed"]);
    script(
        &dir,
        "opcua_alarms.py",
        &["conditions", &url, &segment, "door"],
    );
    stop.store(true, std::sync::atomic::Ordering::Relaxed);
    owner.join().expect("the first owner stops");
    let stop = std::sync::Arc::new(std::sync::atomic::AtomicBool::new(false));
    let owner = run_owner::<After>(segment.clone(), stop.clone());
    client(&dir, &["names", &url, &segment, "count,grid,lid"]);
    script(
        &dir,
        "opcua_alarms.py",
        &["conditions", &url, &segment, "lid"],
    );
    stop.store(true, std::sync::atomic::Ordering::Relaxed);
    owner.join().expect("the second owner stops");
    let _ = std::fs::remove_dir_all(&dir);
}

/// Arrays a tool writes in parts.
#[derive(plc_core::GlobalMemory, Debug, Clone)]
pub struct Arrays {
    #[plc(direction = "command")]
    row: [i16; 6],
    #[plc(direction = "command")]
    plane: [[i16; 3]; 2],
    /// Larger than one request held before (64 writes): written whole, it lands in one cycle.
    #[plc(direction = "command")]
    table: [i32; 1000],
    /// Larger than one cycle's request: refused whole, written in parts.
    #[plc(direction = "command")]
    huge: [i16; 1100],
}

#[test]
fn writes_with_an_index_range_set_exactly_the_selected_elements() {
    python();
    let dir = test_dir("ranges");
    let segment = format!("opcua_ranges_{}", std::process::id());
    let stop = std::sync::Arc::new(std::sync::atomic::AtomicBool::new(false));
    let owner = run_owner::<Arrays>(segment.clone(), stop.clone());
    wait_for("the owner", || {
        plc_io::shm::DynSegment::attach(&segment).is_ok()
    });
    let users = add_user(&dir);
    let (_server, port) = serve(&dir, &segment, Some(&users));
    let url = format!("opc.tcp://127.0.0.1:{port}/");
    user_client(&dir, "ranges", &url, &segment);
    stop.store(true, std::sync::atomic::Ordering::Relaxed);
    owner.join().expect("the owner stops");
    let _ = std::fs::remove_dir_all(&dir);
}

/// A program whose values a tool forces: a setpoint, a feed beside it, a row of speeds.
#[derive(plc_core::GlobalMemory, Debug, Clone)]
pub struct Forceable {
    #[plc(direction = "command")]
    setpoint: f64,
    #[plc(direction = "command")]
    feed: f64,
    #[plc(direction = "command")]
    row: [i16; 4],
    #[plc(direction = "status")]
    cycles: u64,
}

#[test]
fn a_forced_value_is_served_and_writes_to_it_are_refused_as_locked_until_released() {
    use plc_core::{Value, write::Write};
    python();
    let dir = test_dir("force");
    let segment = format!("opcua_force_{}", std::process::id());
    let rt = plc_io::Runtime::<Forceable>::builder()
        .period(Duration::from_millis(1))
        .segment(&segment)
        .handle_signals(false)
        .build()
        .expect("the program starts");
    let stop = rt.stop_handle();
    let program = std::thread::spawn(move || rt.run(|ctx| ctx.gm.cycles += 1));
    let mut seg = None;
    wait_for("the program", || {
        seg = plc_io::shm::DynSegment::attach(&segment).ok();
        seg.is_some()
    });
    let seg = seg.expect("attached");
    let users = add_user(&dir);
    let (_server, port) = serve(&dir, &segment, Some(&users));
    let url = format!("opc.tcp://127.0.0.1:{port}/");

    // Forced by a tool (as `plc force` does): setpoint = 2.5, row[2] = 40.
    let setpoint = seg.index_of("setpoint").expect("declared");
    let row = seg.index_of("row").expect("declared");
    let forces = [
        Write {
            index: setpoint,
            leaf: 0,
            value: Value::Real(2.5),
        },
        Write {
            index: row,
            leaf: 2,
            value: Value::Int(40),
        },
    ]
    .map(|f| seg.check_force(f).expect("a valid force"));
    seg.force(&forces).expect("forced");
    user_client(&dir, "forced", &url, &segment);
    assert_eq!(seg.read("setpoint").expect("read"), Value::Real(2.5));

    seg.release(&[(setpoint, 0), (row, 2)], false)
        .expect("released");
    assert_eq!(seg.status().forces, 0);
    user_client(&dir, "released", &url, &segment);
    assert_eq!(seg.read("setpoint").expect("read"), Value::Real(7.0));

    stop.stop();
    program
        .join()
        .expect("the program thread")
        .expect("the program stops");
    let server_log = std::fs::read_to_string(dir.join("server.log")).unwrap_or_default();
    let refusal = server_log
        .lines()
        .find(|l| l.contains("OPC UA write by `operator` refused: ") && l.contains("setpoint"));
    assert!(
        refusal.is_some_and(|l| l.contains("`setpoint` is forced (by uid ")
            && l.contains("release it first")
            && l.contains("(BadLocked)")),
        "the refused write is logged as forced, naming who forced it:\n{server_log}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn attackers_on_loopback_cannot_lock_out_an_operator_or_exhaust_the_server() {
    python();
    let dir = test_dir("attack");
    let segment = format!("opcua_attack_{}", std::process::id());
    let _program = start_program(&dir, &segment, 1);
    let users = add_user(&dir);
    let (server, port) = serve(&dir, &segment, Some(&users));
    let url = format!("opc.tcp://127.0.0.1:{port}/");
    let (pki, work) = (dir.join("pki"), dir.to_str().expect("a UTF-8 temp dir"));
    let pid = server.id().to_string();
    client(
        &dir,
        &[
            "attack",
            &url,
            &segment,
            "operator",
            "pw of the operator",
            pki.to_str().expect("a UTF-8 temp dir"),
            work,
            &pid,
        ],
    );
    let log = std::fs::read_to_string(dir.join("server.log")).unwrap_or_default();
    let refusals = log.lines().filter(|l| l.contains("refused")).count();
    // 220 refusals (20 sessions, 200 sign-ins) over about 40 s: ten lines per ten seconds
    // for each kind of refusal, not one line each.
    assert!(
        refusals < 100,
        "refusals are logged at a bounded rate, not one line each ({refusals} lines):\n{log}"
    );
    assert!(
        log.contains("more like it were not logged"),
        "the log says how many refusals it did not log:\n{log}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}
