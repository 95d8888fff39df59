//! What `plc change` and the program `plc run` hosts say to each other, over the host's change
//! socket `<runtime dir>/<segment>.change` (the runtime dir is the user's own): one JSON line
//! each way. And the report both print.

use plc_shm::change::ChangePlan;
use serde::{Deserialize, Serialize};
use std::path::{Path, PathBuf};

/// The most bytes of a request or an answer line.
pub const MAX_LINE: u64 = 1 << 20;

/// A change asked for.
#[derive(Debug, Serialize, Deserialize)]
pub struct Request {
    /// The new module (absolute), or none for `--back`.
    pub module: Option<PathBuf>,
    /// `--reset` paths.
    pub resets: Vec<String>,
    /// Report only.
    pub dry_run: bool,
    /// Only what runs: the module, its build time and the changes made (`plc list`).
    #[serde(default)]
    pub info: bool,
}

/// How it ended.
#[derive(Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum Outcome {
    /// Made (or, for a dry run, possible), and its probation passed.
    Done,
    /// Not made: the running program is untouched.
    Refused,
    /// Made, then it panicked on probation and the previous program came back.
    SwappedBack,
}

/// The host's answer.
#[derive(Debug, Serialize, Deserialize)]
pub struct Answer {
    /// How it ended.
    pub outcome: Outcome,
    /// The report, or why not.
    pub text: String,
}

/// What the host of segment `segment` runs (`plc list SEGMENT`), if `plc run` hosts it and it
/// answers.
pub fn hosted(segment: &str) -> Option<String> {
    let stream = std::os::unix::net::UnixStream::connect(socket_path(segment).ok()?).ok()?;
    let _ = stream.set_read_timeout(Some(std::time::Duration::from_secs(5)));
    let request = Request {
        module: None,
        resets: Vec::new(),
        dry_run: true,
        info: true,
    };
    let answer = ask(&stream, &request).ok()?;
    (answer.outcome == Outcome::Done).then_some(answer.text)
}

/// Sends `request` to the host at the other end of `stream` and reads its answer.
pub fn ask(
    mut stream: &std::os::unix::net::UnixStream,
    request: &Request,
) -> Result<Answer, String> {
    use std::io::{BufRead, BufReader, Read, Write};
    let mut line = serde_json::to_vec(request).map_err(|e| e.to_string())?;
    line.push(b'\n');
    let mut answer = String::new();
    stream
        .write_all(&line)
        .and_then(|()| BufReader::new(stream.take(MAX_LINE)).read_line(&mut answer))
        .map_err(|e| format!("the host did not answer: {e}"))?;
    serde_json::from_str(&answer)
        .map_err(|_| "the host ended without an answer: see its log".into())
}

/// Why a change to `module` is refused, each value its plan cannot carry on a line of its own.
pub fn refused_plan(module: &Path, refused: &[plc_shm::change::Refused]) -> String {
    let lines: Vec<String> = refused.iter().map(|r| format!("  {r}")).collect();
    format!(
        "the change to `{}` is refused, nothing changed:\n{}\nname a value with --reset PATH to \
         start it afresh from the new build's initial value",
        module.display(),
        lines.join("\n")
    )
}

/// Where the host of segment `segment` listens for changes.
pub fn socket_path(segment: &str) -> Result<PathBuf, plc_shm::ShmError> {
    let name = plc_shm::normalise_name(segment)?;
    Ok(plc_shm::runtime_dir().join(format!("{name}.change")))
}

/// The report: the change and each value in the list of what happens to it.
pub fn report(head: &str, plan: &ChangePlan) -> String {
    let mut out = format!("{head}\n");
    if plan.changes_nothing() {
        out.push_str("every value is kept as it is: the change swaps the code only\n");
    }
    let lists = [
        ("kept", &plan.kept),
        ("converted", &plan.widened),
        ("narrowed", &plan.narrowed),
        ("added", &plan.added),
        ("reset", &plan.reset),
        ("removed", &plan.removed),
    ];
    for (what, paths) in lists {
        if what == "narrowed" && paths.is_empty() {
            continue;
        }
        out.push_str(&format!("{what:<10} {:>5}", paths.len()));
        let mut width = 16;
        for (k, path) in paths.iter().enumerate() {
            let sep = if k == 0 { "  " } else { ", " };
            if k > 0 && width + sep.len() + path.len() > 100 {
                out.push_str(",\n                 ");
                width = 17;
            } else {
                out.push_str(sep);
                width += sep.len();
            }
            out.push_str(path);
            width += path.len();
        }
        out.push('\n');
    }
    out
}

/// The first line of a report: what runs where, and what built it.
pub fn head(segment: &str, name: &str, module: &Path, fingerprint: &str, dry_run: bool) -> String {
    let verb = if dry_run {
        "dry run, nothing changed: segment `{segment}` would run"
    } else {
        "segment `{segment}` runs"
    };
    format!(
        "{} `{name}` ({}), built by {fingerprint}",
        verb.replace("{segment}", segment),
        module.display()
    )
}
