//! Which CPUs a group's processes run on: the owner (the program measured) on one of its own,
//! the tools that load it (servers, edge nodes, clients, brokers) on the others.

use crate::place;
use std::process::Command;

/// Where a group's processes run: the owner on a CPU of its own (the last this process may
/// use), the tools on the others, as a machine builder isolates the program's core. With one
/// CPU all share it.
pub struct Placement {
    all: Vec<usize>,
    owner: Option<usize>,
    others: Vec<usize>,
}

impl Placement {
    /// The owner on the last CPU this process may use, the tools on the rest.
    pub fn split() -> Placement {
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

    /// Which CPUs run what, for the group's `*_placement` line.
    pub fn describe(&self) -> String {
        match self.owner {
            Some(cpu) => format!("owner on CPU {cpu}, the tools on CPUs {:?}", self.others),
            None => "all on one CPU (no CPU to give the owner alone)".into(),
        }
    }

    /// `command` set to start on the owner's CPU.
    pub fn owner<'c>(&self, command: &'c mut Command) -> Result<&'c mut Command, String> {
        if let Some(cpu) = self.owner {
            place::pin_command(command, &[cpu])?;
        }
        Ok(command)
    }

    /// `command` set to start on the others' CPUs.
    pub fn others<'c>(&self, command: &'c mut Command) -> Result<&'c mut Command, String> {
        place::pin_command(command, &self.others)?;
        Ok(command)
    }

    /// The calling thread (and the threads it starts) on the others' CPUs.
    pub fn others_here(&self) -> Result<(), String> {
        place::pin_to(&self.others)
    }

    /// The calling thread back on every CPU it had.
    pub fn restore(&self) -> Result<(), String> {
        place::pin_to(&self.all)
    }
}
