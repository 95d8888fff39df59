//! Which CPUs the group's processes run on: the owner on one of its own, the server and the
//! clients on the others.

use crate::place;
use std::process::Command;

/// Where the group's processes run: the owner on a CPU of its own (the last this process may
/// use), the server and the clients on the others, as a machine builder isolates the
/// program's core. With one CPU all share it.
pub(super) struct Placement {
    all: Vec<usize>,
    owner: Option<usize>,
    others: Vec<usize>,
}

impl Placement {
    pub(super) fn split() -> Placement {
        let all = place::allowed_cpus();
        match all.split_last() {
            Some((&owner, others)) if !others.is_empty() => Placement {
                owner: Some(owner),
                others: others.to_vec(),
                all,
            },
            _ => Placement {
                owner: None,
                others: all.clone(),
                all,
            },
        }
    }

    pub(super) fn describe(&self) -> String {
        match self.owner {
            Some(cpu) => format!(
                "owner on CPU {cpu}, server and clients on CPUs {:?}",
                self.others
            ),
            None => "all on one CPU (no CPU to give the owner alone)".into(),
        }
    }

    /// `command` set to start on the owner's CPU.
    pub(super) fn owner<'c>(&self, command: &'c mut Command) -> Result<&'c mut Command, String> {
        if let Some(cpu) = self.owner {
            place::pin_command(command, &[cpu])?;
        }
        Ok(command)
    }

    /// `command` set to start on the others' CPUs.
    pub(super) fn others<'c>(&self, command: &'c mut Command) -> Result<&'c mut Command, String> {
        place::pin_command(command, &self.others)?;
        Ok(command)
    }

    /// The calling thread (and the threads it starts) on the others' CPUs.
    pub(super) fn others_here(&self) -> Result<(), String> {
        place::pin_to(&self.others)
    }

    /// The calling thread back on every CPU it had.
    pub(super) fn restore(&self) -> Result<(), String> {
        place::pin_to(&self.all)
    }
}
