//! Who may read and who may write a program's variables.
//!
//! Reading is the file system's decision: the segment's socket and its directory are the
//! owner's, mode 0700 (0750 and 0660 with a read group), so only the owner's user, the read
//! group's members and root can connect. Writing is the owner's decision, per connection,
//! from the credentials the kernel gives for its peer (`SO_PEERCRED`, `SO_PEERGROUPS`): the
//! owner's own uid writes, and so does every member of the write group, if there is one.

use crate::error::ShmError;
use crate::sys::ids::{Group, group, group_name};
use crate::sys::unix::Peer;

/// The groups a program shares its variables with, by name (resolved when the segment is
/// created). Without either, only the program's own user reads and writes.
///
/// ```
/// let sharing = plc_shm::Sharing::new().read_group("plc-viewers").write_group("plc-operators");
/// assert_eq!(sharing.write_group_name(), Some("plc-operators"));
/// ```
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Sharing {
    read_group: Option<String>,
    write_group: Option<String>,
    alarm_history: Option<(std::path::PathBuf, usize)>,
}

impl Sharing {
    /// Only the program's own user.
    pub fn new() -> Sharing {
        Sharing::default()
    }

    /// Members of `group` may read the variables (connect to the socket, map the segment).
    pub fn read_group(mut self, group: impl Into<String>) -> Sharing {
        self.read_group = Some(group.into());
        self
    }

    /// Members of `group` may write the variables from outside. They must also be able to
    /// connect: without a read group this group reads too; with one, they must be in both.
    pub fn write_group(mut self, group: impl Into<String>) -> Sharing {
        self.write_group = Some(group.into());
        self
    }

    /// Tells tools where the program keeps its alarm history, and how many records it keeps
    /// (`plc alarms --history` reads it there; the file keeps its own owner and mode, so only
    /// those who may read it do).
    pub fn alarm_history(mut self, path: impl Into<std::path::PathBuf>, records: usize) -> Sharing {
        self.alarm_history = Some((path.into(), records));
        self
    }

    /// Where the alarm history is and how many records it keeps, if the program said.
    pub fn alarm_history_file(&self) -> Option<(&std::path::Path, usize)> {
        self.alarm_history.as_ref().map(|(p, n)| (p.as_path(), *n))
    }

    /// The read group's name, if any.
    pub fn read_group_name(&self) -> Option<&str> {
        self.read_group.as_deref()
    }

    /// The write group's name, if any.
    pub fn write_group_name(&self) -> Option<&str> {
        self.write_group.as_deref()
    }

    /// Checks that both groups exist on this machine, as the owner of segment `segment` will
    /// resolve them when it creates the segment: an unknown group is an error naming it and
    /// the fix.
    pub fn check(&self, segment: &str) -> Result<(), ShmError> {
        Policy::resolve(segment, self).map(drop)
    }
}

/// A program's policy, resolved.
#[derive(Clone, Debug)]
pub struct Policy {
    /// The owner's uid: it always writes.
    pub owner_uid: u32,
    /// The group whose members connect (the directory's and socket's group).
    pub read: Option<Group>,
    /// The group whose members write.
    pub write: Option<Group>,
}

impl Policy {
    /// Resolves `sharing` for segment `segment`, owned by this process's user.
    pub fn resolve(segment: &str, sharing: &Sharing) -> Result<Policy, ShmError> {
        let read = sharing
            .read_group
            .as_deref()
            .map(|g| group(segment, g, "read"))
            .transpose()?;
        let write = sharing
            .write_group
            .as_deref()
            .map(|g| group(segment, g, "write"))
            .transpose()?;
        Ok(Policy {
            owner_uid: crate::sys::ids::euid(),
            read,
            write,
        })
    }

    /// The group the directory and the socket give access to: the read group, else the write
    /// group (whose members must connect to write).
    pub fn access_group(&self) -> Option<&Group> {
        self.read.as_ref().or(self.write.as_ref())
    }

    /// Whether `peer` may write.
    pub fn may_write(&self, peer: &Peer) -> bool {
        peer.uid == self.owner_uid
            || self
                .write
                .as_ref()
                .is_some_and(|g| peer.gid == g.gid || peer.groups.contains(&g.gid))
    }

    /// The refusal a writer who may not write gets, naming the rule.
    pub fn refusal(&self, peer: &Peer, segment: &str) -> String {
        let who = match &self.write {
            Some(g) => format!("uid {} and group {}", self.owner_uid, g.name),
            None => format!("uid {}", self.owner_uid),
        };
        format!(
            "uid {} (group {}) may not write `{segment}`: only {who} may; see \
             RuntimeBuilder::write_group",
            peer.uid,
            group_name(peer.gid)
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn peer(uid: u32, gid: u32, groups: &[u32]) -> Peer {
        Peer {
            pid: 1,
            uid,
            gid,
            groups: groups.to_vec(),
        }
    }

    #[test]
    fn the_owner_and_the_write_groups_members_write_and_nobody_else() {
        let only_owner = Policy {
            owner_uid: 1000,
            read: None,
            write: None,
        };
        assert!(only_owner.may_write(&peer(1000, 5, &[])));
        assert!(!only_owner.may_write(&peer(1001, 5, &[])));
        let text = only_owner.refusal(&peer(1001, 5, &[]), "press");
        assert!(
            text.starts_with("uid 1001 (group ")
                && text.contains(
                    "may not write `press`: only uid 1000 may; see RuntimeBuilder::write_group"
                ),
            "{text}"
        );
        let with_group = Policy {
            write: Some(Group {
                name: "plc-operators".into(),
                gid: 2000,
            }),
            ..only_owner
        };
        assert!(with_group.may_write(&peer(1001, 2000, &[])));
        assert!(with_group.may_write(&peer(1001, 5, &[7, 2000])));
        assert!(!with_group.may_write(&peer(1001, 5, &[7])));
        assert!(
            with_group
                .refusal(&peer(1001, 5, &[7]), "press")
                .contains("only uid 1000 and group plc-operators may")
        );
    }

    #[test]
    fn an_unknown_group_is_refused_with_the_fix() {
        let err = Policy::resolve("press", &Sharing::new().write_group("no-such-group-xyz"))
            .unwrap_err()
            .to_string();
        assert!(
            err.contains("`no-such-group-xyz`") && err.contains("groupadd"),
            "{err}"
        );
    }
}
