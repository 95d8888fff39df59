//! Loading real modules (the `counter` and `foreign` test modules, built by `scripts/test.sh`)
//! through the whole path: file checks, ELF checks, sealed copy, trial child, entry checks;
//! then running one over its image, and every refusal with its message.

use plc_module::abi::CycleFacts;
use plc_module::trial::Trial;
use plc_module::{Module, ModuleError, ModuleFault};
use std::os::unix::fs::PermissionsExt;
use std::path::{Path, PathBuf};

fn built(name: &str) -> PathBuf {
    let lib = Path::new(env!("CARGO_BIN_EXE_plc-module-trial")).with_file_name(name);
    assert!(
        lib.is_file(),
        "{} is missing: run the tests with scripts/test.sh (or `cargo build -p \
         plc-test-module-counter -p plc-test-module-foreign` first)",
        lib.display()
    );
    lib
}

fn trial() -> Trial {
    Trial::with_program(env!("CARGO_BIN_EXE_plc-module-trial"))
}

/// A copy of `source` in a fresh directory, mode 0644 (as `cargo build` leaves it, minus x).
fn copy_of(source: &Path, dir: &Path, name: &str) -> PathBuf {
    let to = dir.join(name);
    std::fs::write(&to, std::fs::read(source).unwrap()).unwrap();
    std::fs::set_permissions(&to, std::fs::Permissions::from_mode(0o644)).unwrap();
    to
}

fn tempdir() -> tempfile::TempDir {
    tempfile::tempdir().unwrap()
}

fn counter(dir: &Path) -> PathBuf {
    copy_of(&built("libcounter.so"), dir, "libcounter.so")
}

/// The offset of variable `name` in the module's image.
fn at(m: &Module, name: &str) -> usize {
    let d = m.descriptor();
    d.variables[d.index_of(name).unwrap()].offset
}

fn u32_at(image: &[u8], at: usize) -> u32 {
    u32::from_le_bytes(image[at..at + 4].try_into().unwrap())
}

#[test]
fn a_module_runs_over_its_image() {
    let dir = tempdir();
    let m = Module::load(counter(dir.path()), &trial()).unwrap();
    assert_eq!(m.name(), "plc-test-module-counter");
    assert_eq!(m.descriptor().variables.len(), 8);
    assert_eq!(m.layout_hash(), m.descriptor().computed_hash());
    assert_eq!(m.bus(), None);

    let mut image = m.initial_image().unwrap();
    assert_eq!(image.len(), m.image_size());
    assert_eq!(u32_at(&image, at(&m, "count")), 100, "the initial value");

    image[at(&m, "inputs")] = 0b100;
    m.unpack_bits(&mut image).unwrap();
    assert_eq!(image[at(&m, "start")], 1, "bit 2 of inputs unpacked");
    let facts = CycleFacts {
        cycle: 7,
        now_ns: 1_500_000,
        inputs_valid: 1,
        ..CycleFacts::default()
    };
    m.tick(&mut image, &facts).unwrap();
    assert_eq!(u32_at(&image, at(&m, "count")), 101);
    assert_eq!(image[at(&m, "last_cycle")], 7);
    assert_eq!(image[at(&m, "last_now_us")..][..2], 1500u16.to_le_bytes());
    assert_eq!(image[at(&m, "motor_on")], 1);
    assert_eq!(image[at(&m, "outputs")], 0, "not packed before pack_bits");
    m.pack_bits(&mut image).unwrap();
    assert_eq!(image[at(&m, "outputs")], 1);
}

#[test]
fn a_panic_is_caught_with_its_message_and_leaves_the_image_as_it_was() {
    let dir = tempdir();
    let m = Module::load(counter(dir.path()), &trial()).unwrap();
    let mut image = m.initial_image().unwrap();
    image[at(&m, "panic_at_cycle")] = 3;
    for cycle in 1..=2 {
        let facts = CycleFacts {
            cycle,
            ..CycleFacts::default()
        };
        m.tick(&mut image, &facts).unwrap();
    }
    let before = image.clone();
    let facts = CycleFacts {
        cycle: 3,
        ..CycleFacts::default()
    };
    assert_eq!(
        m.tick(&mut image, &facts),
        Err(ModuleFault::Panicked(
            "counter: asked to panic in cycle 3".into()
        ))
    );
    assert_eq!(image, before, "the tick zeroed `count` before it panicked");
    let facts = CycleFacts {
        cycle: 4,
        ..CycleFacts::default()
    };
    m.tick(&mut image, &facts).unwrap();
    assert_eq!(
        u32_at(&image, at(&m, "count")),
        103,
        "it runs on after a panic"
    );
}

#[test]
fn an_image_of_another_size_is_refused_unchanged() {
    let dir = tempdir();
    let m = Module::load(counter(dir.path()), &trial()).unwrap();
    let mut short = vec![0u8; m.image_size() - 1];
    let got = m.tick(&mut short, &CycleFacts::default());
    assert_eq!(
        got,
        Err(ModuleFault::WrongImage {
            expected: m.image_size(),
            got: m.image_size() - 1
        })
    );
    assert!(short.iter().all(|&b| b == 0));
}

#[test]
fn a_rebuilt_module_at_the_same_path_is_the_new_code() {
    // glibc hands back the library it has for a path it loaded before: loading from the
    // sealed copy, never the path, is what makes the second load the new file.
    let dir = tempdir();
    let path = counter(dir.path());
    let first = Module::load(&path, &trial()).unwrap();
    std::fs::write(&path, std::fs::read(built("libforeign.so")).unwrap()).unwrap();
    let err = Module::load(&path, &trial()).unwrap_err();
    assert!(matches!(err, ModuleError::Fingerprint { .. }), "{err}");
    // The first stays loaded and runs.
    let mut image = first.initial_image().unwrap();
    first.tick(&mut image, &CycleFacts::default()).unwrap();
    // The same file twice gives two modules, each with its own code and statics.
    std::fs::write(&path, std::fs::read(built("libcounter.so")).unwrap()).unwrap();
    let second = Module::load(&path, &trial()).unwrap();
    assert_eq!(second.layout_hash(), first.layout_hash());
}

fn refusal(path: &Path) -> (ModuleError, String) {
    let err = Module::load(path, &trial()).unwrap_err();
    let text = err.to_string();
    eprintln!("refused: {text}");
    assert!(
        text.contains(&path.display().to_string()),
        "the message names the file: {text}"
    );
    (err, text)
}

#[test]
fn another_fingerprint_is_refused_naming_both() {
    let dir = tempdir();
    let path = copy_of(&built("libforeign.so"), dir.path(), "libforeign.so");
    let (err, text) = refusal(&path);
    assert!(matches!(err, ModuleError::Fingerprint { .. }), "{text}");
    assert!(text.contains("rustc 1.80.0"), "{text}");
    assert!(
        text.contains(plc_module::Fingerprint::host().text()),
        "{text}"
    );
}

#[test]
fn a_module_others_may_write_is_refused() {
    let dir = tempdir();
    let path = counter(dir.path());
    std::fs::set_permissions(&path, std::fs::Permissions::from_mode(0o664)).unwrap();
    let (err, text) = refusal(&path);
    assert!(matches!(err, ModuleError::Writable { .. }), "{text}");
    assert!(
        text.contains("writable by its group") && text.contains("chmod go-w"),
        "{text}"
    );
    std::fs::set_permissions(&path, std::fs::Permissions::from_mode(0o646)).unwrap();
    let (_, text) = refusal(&path);
    assert!(text.contains("writable by every user"), "{text}");
}

#[test]
fn a_link_to_a_module_is_refused() {
    let dir = tempdir();
    let path = counter(dir.path());
    let link = dir.path().join("libcurrent.so");
    std::os::unix::fs::symlink(&path, &link).unwrap();
    let (err, text) = refusal(&link);
    assert!(matches!(err, ModuleError::Link { .. }), "{text}");
    assert!(text.contains("symbolic link"), "{text}");
}

#[test]
fn a_module_of_another_user_is_refused() {
    let dir = tempdir();
    let path = counter(dir.path());
    // As root (CI) the copy is given to `nobody`; as another user, a file root owns stands in.
    let path = if plc_shm::euid() == 0 {
        std::os::unix::fs::chown(&path, Some(65534), Some(65534)).unwrap();
        path
    } else {
        PathBuf::from("/etc/hostname")
    };
    let (err, text) = refusal(&path);
    assert!(matches!(err, ModuleError::Owner { .. }), "{text}");
    assert!(text.contains("belongs to uid"), "{text}");
}

#[test]
fn files_that_are_no_module_are_refused() {
    let dir = tempdir();
    let text_file = dir.path().join("libnotes.so");
    std::fs::write(&text_file, "a text file\n").unwrap();
    let (err, text) = refusal(&text_file);
    assert!(matches!(err, ModuleError::NotALibrary { .. }), "{text}");
    assert!(
        text.contains("not an ELF file") && text.contains("cdylib"),
        "{text}"
    );

    let full = std::fs::read(built("libcounter.so")).unwrap();
    // Cut inside its code (a cut in the debug information after the loaded parts is harmless,
    // and such a file loads).
    let truncated = dir.path().join("libtruncated.so");
    std::fs::write(&truncated, &full[..64 << 10]).unwrap();
    let (err, text) = refusal(&truncated);
    assert!(matches!(err, ModuleError::Damaged { .. }), "{text}");
    assert!(text.contains("lies beyond the file"), "{text}");

    // Whole in size but garbage in its symbols and relocations, after the headers: the trial
    // child loads it (and crashes or is refused), not the host.
    let mut damaged = full.clone();
    damaged[4096..256 << 10].fill(0xa5);
    let damaged_path = dir.path().join("libdamaged.so");
    std::fs::write(&damaged_path, &damaged).unwrap();
    let (err, text) = refusal(&damaged_path);
    assert!(
        matches!(
            err,
            ModuleError::Trial { .. } | ModuleError::NotALibrary { .. }
        ),
        "{text}"
    );
}

#[test]
fn another_shared_library_is_no_program() {
    let candidates = [
        "/lib/x86_64-linux-gnu/libm.so.6",
        "/usr/lib/x86_64-linux-gnu/libm.so.6",
        "/lib/aarch64-linux-gnu/libm.so.6",
        "/usr/lib/aarch64-linux-gnu/libm.so.6",
        "/lib64/libm.so.6",
    ];
    let libm = candidates
        .iter()
        .map(Path::new)
        .find(|p| p.is_file())
        .expect("the C library's libm.so.6, which every glibc system has");
    let dir = tempdir();
    let path = copy_of(libm, dir.path(), "libm.so");
    let (err, text) = refusal(&path);
    assert!(matches!(err, ModuleError::NotAProgram { .. }), "{text}");
    assert!(text.contains("exports no `plc_program_v1`"), "{text}");
    assert!(text.contains("plc_io::program!"), "{text}");
}

#[test]
fn a_trial_program_that_does_not_answer_is_a_refusal() {
    let dir = tempdir();
    let path = counter(dir.path());
    let err = Module::load(&path, &Trial::with_program("/bin/true")).unwrap_err();
    assert!(matches!(err, ModuleError::Trial { .. }), "{err}");
    assert!(err.to_string().contains("no answer"), "{err}");
    // A child that never answers, and floods its output meanwhile. (Written by `install`:
    // a script this process wrote itself could be busy when run, see plc-test-support.)
    let source = dir.path().join("flood.sh");
    std::fs::write(&source, "#!/bin/sh\nexec yes flood\n").unwrap();
    let bin = dir.path().join("bin");
    std::fs::create_dir(&bin).unwrap();
    let flood = plc_test_support::install_executable(&source, &bin).unwrap();
    let slow = Trial::with_program(flood).timeout(std::time::Duration::from_millis(300));
    let err = Module::load(&path, &slow).unwrap_err();
    assert!(err.to_string().contains("did not finish loading"), "{err}");
}

#[test]
fn inspecting_a_module_gives_what_loading_it_gives() {
    let dir = tempdir();
    let path = counter(dir.path());
    let info = Module::inspect(&path, &trial()).unwrap();
    assert_eq!(info, Module::load(&path, &trial()).unwrap().info());
    assert_eq!(info.fingerprint, plc_module::Fingerprint::host().text());
    // Its refusals are load's.
    let foreign = copy_of(&built("libforeign.so"), dir.path(), "libforeign.so");
    let err = Module::inspect(&foreign, &trial()).unwrap_err();
    assert!(matches!(err, ModuleError::Fingerprint { .. }), "{err}");
}
