//! Operators' actions on alarms, on the owner's side: checked by the socket server (the write
//! policy, alarm numbers the program declares), queued with the writes, and handed on the
//! cycle thread to whatever manages the program's alarms (plc-runtime's `Runtime`), which
//! answers whether it took them.

use crate::protocol::{AlarmAction, AlarmRequest};
use crate::sys::ids::user_name;

/// An operator's action on alarms, as the program's alarm manager gets it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct AlarmCommand {
    /// What to do.
    pub action: AlarmAction,
    /// Every alarm the action applies to (then `alarms` is empty).
    pub all: bool,
    /// The alarms' numbers in the descriptor's list (each below the program's count).
    pub alarms: Vec<usize>,
    /// The sender's uid, as the kernel gave it.
    pub uid: u32,
    /// Its user's name (or `uid N` when the system has none).
    pub user: String,
    /// The user the tool acts for, signed in elsewhere (the OPC UA server's user).
    pub on_behalf: Option<String>,
    /// What the operator wrote with it.
    pub comment: Option<String>,
}

impl AlarmCommand {
    /// The command of `request`, sent by `uid`: its user's name looked up here, off the
    /// cycle thread (the user database may read files or ask a directory server).
    pub(crate) fn new(request: AlarmRequest, uid: u32) -> AlarmCommand {
        let non_empty = |s: String| (!s.is_empty()).then_some(s);
        AlarmCommand {
            action: request.action,
            all: request.all,
            alarms: request.alarms,
            uid,
            user: user_name(uid).unwrap_or_else(|| format!("uid {uid}")),
            on_behalf: non_empty(request.on_behalf),
            comment: non_empty(request.comment),
        }
    }
}

/// Why the program's alarm manager refused a command: nothing of it was done.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct AlarmRefusal {
    /// The alarm of the command the reason is about (its place in `alarms`; 0 for `all`).
    pub which: usize,
    /// Why, in words the tool shows.
    pub why: String,
}

/// The answer of an owner whose program does not hand alarm actions to anyone (it drives its
/// own cycle with [`apply_requests`](super::ShmOwner::apply_requests)).
pub(crate) fn unmanaged(_: &AlarmCommand) -> Result<(), AlarmRefusal> {
    Err(AlarmRefusal {
        which: 0,
        why: "this program's alarms are not managed: it drives its own cycle without \
              plc-runtime's Runtime, which evaluates alarms and takes operators' actions"
            .into(),
    })
}

/// Checks `request`'s alarm numbers against the `count` the program declares: the refusal's
/// (which, why), if any.
pub(crate) fn check_numbers(request: &AlarmRequest, count: usize) -> Result<(), (usize, String)> {
    if count == 0 {
        return Err((0, "the program declares no alarms".into()));
    }
    match request.alarms.iter().position(|&a| a >= count) {
        Some(k) => Err((
            k,
            format!(
                "no alarm has number {} (the program declares {count}, numbered from 0)",
                request.alarms[k]
            ),
        )),
        None => Ok(()),
    }
}
