//! `plc ack`, `plc reset`, `plc shelve`, `plc unshelve`: an operator's action on a running
//! program's alarms, sent over its socket as this user (who may is the write policy's, as for
//! `plc set`); the alarms named all or none, or with --all every one it applies to.

use super::Error;
use crate::display::escape_text;
use plc_shm::DynSegment;
use plc_shm::protocol::AlarmAction;

/// The alarms an action names, and what the operator writes with it.
#[derive(clap::Args)]
pub struct ActArgs {
    /// Segment name.
    pub segment: String,
    /// Alarms, by the path of the value each watches (`guard_door_open`,
    /// `stations[2].door`; `plc alarms SEGMENT --all` lists them).
    #[arg(required_unless_present = "all", conflicts_with = "all")]
    pub paths: Vec<String>,
    /// Every alarm the action applies to.
    #[arg(long)]
    pub all: bool,
    /// What the operator writes with it, kept in the alarm history (at most 255 bytes).
    #[arg(long)]
    pub comment: Option<String>,
}

/// `plc shelve`: alarms named, and for how long.
#[derive(clap::Args)]
pub struct ShelveArgs {
    /// Segment name.
    pub segment: String,
    /// Alarms, by path.
    #[arg(required = true)]
    pub paths: Vec<String>,
    /// How long (`30m`, `1h`, `T#2h30m`); at most 8 hours unless the program allows more.
    #[arg(long = "for")]
    pub duration: String,
    /// Why, kept in the alarm history (at most 255 bytes).
    #[arg(long)]
    pub comment: Option<String>,
}

/// Runs an action with its alarms named (or all).
pub fn run(action: AlarmAction, args: &ActArgs) -> Result<(), Error> {
    act(
        action,
        &args.segment,
        &args.paths,
        args.all,
        args.comment.as_deref(),
    )
}

/// Runs `plc shelve`.
pub fn shelve(args: &ShelveArgs) -> Result<(), Error> {
    let time = super::duration(&args.duration).map_err(|e| {
        format!(
            "--for {:?}: not a duration such as `30m`, `1h` or `T#2h30m`: {e}",
            args.duration
        )
    })?;
    if time.as_nanos() <= 0 {
        return Err(format!("--for {:?}: a shelf lasts longer than 0", args.duration).into());
    }
    let action = AlarmAction::Shelve {
        for_ns: time.as_nanos(),
    };
    act(
        action,
        &args.segment,
        &args.paths,
        false,
        args.comment.as_deref(),
    )
}

fn act(
    action: AlarmAction,
    segment: &str,
    paths: &[String],
    all: bool,
    comment: Option<&str>,
) -> Result<(), Error> {
    let seg = DynSegment::attach(segment)?;
    let comment = comment.unwrap_or("");
    if comment.len() > 255 {
        return Err(format!(
            "--comment takes at most 255 bytes, this one has {}: shorten it",
            comment.len()
        )
        .into());
    }
    if all {
        seg.act_on_all_alarms(action, comment, "")?;
        println!("{}: done to every alarm it applies to", past(action));
        return Ok(());
    }
    // Every path is checked before anything is sent.
    let numbers = paths
        .iter()
        .map(|p| seg.alarm_number(p))
        .collect::<Result<Vec<usize>, _>>()?;
    seg.act_on_alarms(action, &numbers, comment, "")?;
    for &n in &numbers {
        println!("{}: {}", past(action), escape_text(&seg.alarms()[n].path));
    }
    Ok(())
}

fn past(action: AlarmAction) -> &'static str {
    match action {
        AlarmAction::Acknowledge => "acknowledged",
        AlarmAction::Reset => "reset",
        AlarmAction::Shelve { .. } => "shelved",
        AlarmAction::Unshelve => "unshelved",
    }
}
