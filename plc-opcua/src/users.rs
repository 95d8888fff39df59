//! The users file: who may write through the OPC UA server. One user a line, `name:hash`, the
//! hash an argon2id PHC string (salted, slow); `#` starts a comment line. The file holds no
//! password, and it is never followed through a symbolic link.

use argon2::Argon2;
use argon2::password_hash::{PasswordHash, PasswordHasher, PasswordVerifier, SaltString};
use std::collections::BTreeMap;
use std::fmt;
use std::io::Read;
use std::os::unix::fs::OpenOptionsExt;
use std::path::{Path, PathBuf};

/// A users file larger than this is refused (a few thousand users fit).
const MAX_FILE_BYTES: u64 = 1 << 20;

/// Why the users file could not be read or written.
#[derive(Debug)]
pub struct UsersError {
    /// The file.
    pub path: PathBuf,
    /// What is wrong and what to do.
    pub problem: String,
}

impl fmt::Display for UsersError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "users file {}: {}", self.path.display(), self.problem)
    }
}

impl std::error::Error for UsersError {}

/// The users who may write, by name, with their password hashes.
#[derive(Clone, Debug, Default)]
pub struct Users {
    hashes: BTreeMap<String, String>,
}

/// A hash with the parameters of every user's (argon2's defaults), of a password nobody
/// knows, made once: what a name the file does not hold is checked against.
fn stand_in_hash() -> &'static str {
    static HASH: std::sync::OnceLock<String> = std::sync::OnceLock::new();
    HASH.get_or_init(|| {
        let salt = SaltString::generate(&mut argon2::password_hash::rand_core::OsRng);
        let mut secret = [0u8; 32];
        argon2::password_hash::rand_core::RngCore::fill_bytes(
            &mut argon2::password_hash::rand_core::OsRng,
            &mut secret,
        );
        Argon2::default()
            .hash_password(&secret, &salt)
            .map(|h| h.to_string())
            .unwrap_or_default()
    })
}

/// Whether `name` is a user name the file can hold: 1 to 64 ASCII letters, digits, `_`, `-`,
/// `.` or `@` (no `:`, which separates the hash, and nothing a log line could be forged with).
pub fn valid_name(name: &str) -> bool {
    (1..=64).contains(&name.len())
        && name
            .bytes()
            .all(|b| b.is_ascii_alphanumeric() || b"_-.@".contains(&b))
}

impl Users {
    /// Reads a users file.
    pub fn load(path: &Path) -> Result<Users, UsersError> {
        let err = |problem: String| UsersError {
            path: path.to_path_buf(),
            problem,
        };
        let file = std::fs::OpenOptions::new()
            .read(true)
            .custom_flags(libc::O_NOFOLLOW)
            .open(path)
            .map_err(|e| {
                err(format!(
                    "cannot open it: {e} (a symbolic link is not followed)"
                ))
            })?;
        // Whoever may change the file may make himself a user: only its owner may write it.
        use std::os::unix::fs::MetadataExt;
        let meta = file
            .metadata()
            .map_err(|e| err(format!("cannot look at it: {e}")))?;
        if !meta.is_file() {
            return Err(err("it is not a regular file".into()));
        }
        // Whoever may read it may try the hashes offline: the server's user's alone.
        let me = plc_shm::euid();
        if meta.uid() != me {
            return Err(err(format!(
                "it belongs to uid {}, not to the server's user (uid {me}): \
                 `chown {me} {}`, or run the server as its owner",
                meta.uid(),
                path.display()
            )));
        }
        if meta.mode() & 0o077 != 0 {
            return Err(err(format!(
                "other users may read or write it (mode {:o}): `chmod 600 {}`",
                meta.mode() & 0o777,
                path.display()
            )));
        }
        let mut text = String::new();
        file.take(MAX_FILE_BYTES + 1)
            .read_to_string(&mut text)
            .map_err(|e| err(format!("cannot read it as UTF-8 text: {e}")))?;
        if text.len() as u64 > MAX_FILE_BYTES {
            return Err(err(format!("it is larger than {MAX_FILE_BYTES} bytes")));
        }
        Users::parse(&text).map_err(err)
    }

    /// Parses the text of a users file (errors name the line).
    pub fn parse(text: &str) -> Result<Users, String> {
        let mut hashes = BTreeMap::new();
        for (n, line) in text.lines().enumerate() {
            let line = line.trim();
            if line.is_empty() || line.starts_with('#') {
                continue;
            }
            let at = n + 1;
            let (name, hash) = line.split_once(':').ok_or_else(|| {
                format!("line {at}: expected `name:hash` (add users with `plc opcua user add`)")
            })?;
            if !valid_name(name) {
                return Err(format!(
                    "line {at}: `{name}` is not a valid user name (1 to 64 letters, digits, `_`, \
                     `-`, `.`, `@`)"
                ));
            }
            PasswordHash::new(hash).map_err(|e| {
                format!(
                    "line {at}: the hash of `{name}` is not a PHC string ({e}); add the user again"
                )
            })?;
            if hashes.insert(name.to_string(), hash.to_string()).is_some() {
                return Err(format!("line {at}: user `{name}` appears twice"));
            }
        }
        Ok(Users { hashes })
    }

    /// Whether there is a user of this name.
    pub fn contains(&self, name: &str) -> bool {
        self.hashes.contains_key(name)
    }

    /// Number of users.
    pub fn len(&self) -> usize {
        self.hashes.len()
    }

    /// Whether there are none.
    pub fn is_empty(&self) -> bool {
        self.hashes.is_empty()
    }

    /// Whether `password` is `name`'s. Slow on purpose (argon2): call it off the async threads.
    ///
    /// A name the file does not hold costs the same: the password is checked against a hash
    /// of the same parameters, so the answer's time does not tell which names exist.
    pub fn verify(&self, name: &str, password: &str) -> bool {
        let (hash, known) = match self.hashes.get(name) {
            Some(hash) => (hash.as_str(), true),
            None => (stand_in_hash(), false),
        };
        let matches = PasswordHash::new(hash).is_ok_and(|h| {
            Argon2::default()
                .verify_password(password.as_bytes(), &h)
                .is_ok()
        });
        known && matches
    }

    /// Adds a user, or gives an existing one a new password: stores a fresh salted hash.
    pub fn set_password(&mut self, name: &str, password: &str) -> Result<(), String> {
        if !valid_name(name) {
            return Err(format!(
                "`{name}` is not a valid user name (1 to 64 letters, digits, `_`, `-`, `.`, `@`)"
            ));
        }
        if password.is_empty() {
            return Err("the password is empty".into());
        }
        let salt = SaltString::generate(&mut argon2::password_hash::rand_core::OsRng);
        let hash = Argon2::default()
            .hash_password(password.as_bytes(), &salt)
            .map_err(|e| format!("cannot hash the password: {e}"))?;
        self.hashes.insert(name.to_string(), hash.to_string());
        Ok(())
    }

    /// The file's text.
    pub fn to_text(&self) -> String {
        let mut text =
            String::from("# plc-vars OPC UA users: name:argon2 hash (`plc opcua user add`)\n");
        for (name, hash) in &self.hashes {
            text.push_str(&format!("{name}:{hash}\n"));
        }
        text
    }

    /// Writes the file whole, mode 0600: a new file created beside it (never through a
    /// symbolic link), then renamed over it.
    pub fn save(&self, path: &Path) -> Result<(), UsersError> {
        let err = |problem: String| UsersError {
            path: path.to_path_buf(),
            problem,
        };
        plc_files::write_atomically(path, self.to_text().as_bytes(), 0o600)
            .map_err(|e| err(format!("cannot write it: {e}")))
    }
}

/// `plc opcua user add FILE NAME`: reads the users file if it exists, sets `name`'s password
/// and writes the file back.
pub fn add_user(path: &Path, name: &str, password: &str) -> Result<(), UsersError> {
    let mut users = match std::fs::symlink_metadata(path) {
        Ok(_) => Users::load(path)?,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => Users::default(),
        Err(e) => {
            return Err(UsersError {
                path: path.to_path_buf(),
                problem: format!("cannot look at it: {e}"),
            });
        }
    };
    users
        .set_password(name, password)
        .map_err(|problem| UsersError {
            path: path.to_path_buf(),
            problem,
        })?;
    users.save(path)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_users_file_others_may_read_or_another_user_owns_is_refused_and_a_saved_one_is_private() {
        use std::os::unix::fs::PermissionsExt;
        let dir = std::env::temp_dir().join(format!("plc-opcua-users-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("users");
        add_user(&path, "operator", "pw").unwrap();
        let mode = std::fs::metadata(&path).unwrap().permissions().mode() & 0o777;
        assert_eq!(mode, 0o600);
        assert!(Users::load(&path).unwrap().verify("operator", "pw"));
        for mode in [0o666, 0o644, 0o640, 0o604] {
            std::fs::set_permissions(&path, std::fs::Permissions::from_mode(mode)).unwrap();
            let e = Users::load(&path).unwrap_err().to_string();
            assert!(
                e.contains("other users may read or write it") && e.contains("chmod 600"),
                "mode {mode:o}: {e}"
            );
        }
        std::fs::set_permissions(&path, std::fs::Permissions::from_mode(0o600)).unwrap();
        // Owned by another user (root may give it away; others cannot, and skip this).
        if plc_shm::euid() == 0 {
            std::os::unix::fs::chown(&path, Some(4242), None).unwrap();
            let e = Users::load(&path).unwrap_err().to_string();
            assert!(
                e.contains("belongs to uid 4242") && e.contains("chown 0"),
                "{e}"
            );
            std::os::unix::fs::chown(&path, Some(0), None).unwrap();
        }
        assert!(Users::load(&path).is_ok());
        let link = dir.join("link");
        let _ = std::fs::remove_file(&link);
        std::os::unix::fs::symlink(&path, &link).unwrap();
        assert!(
            Users::load(&link).is_err(),
            "a symbolic link is not followed"
        );
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn a_set_password_verifies_and_no_other_does() {
        let mut users = Users::default();
        users.set_password("operator", "s3cret").unwrap();
        assert!(users.verify("operator", "s3cret"));
        assert!(!users.verify("operator", "s3cret "));
        assert!(!users.verify("nobody", "s3cret"));
    }

    #[test]
    fn the_file_holds_a_salted_hash_not_the_password() {
        let mut a = Users::default();
        a.set_password("operator", "s3cret").unwrap();
        let mut b = Users::default();
        b.set_password("operator", "s3cret").unwrap();
        let text = a.to_text();
        assert!(!text.contains("s3cret"));
        assert!(text.contains("operator:$argon2id$"));
        assert_ne!(
            text,
            b.to_text(),
            "two hashes of one password differ by their salt"
        );
        assert!(Users::parse(&text).unwrap().verify("operator", "s3cret"));
    }

    #[test]
    fn bad_lines_are_refused_naming_the_line() {
        let e = Users::parse("# users\n\nbob\n").unwrap_err();
        assert!(e.starts_with("line 3:"), "{e}");
        let e = Users::parse("bob:plain-password\n").unwrap_err();
        assert!(e.contains("not a PHC string"), "{e}");
        let e =
            Users::parse("bo b:$argon2id$v=19$m=19456,t=2,p=1$c2FsdHNhbHQ$aGFzaA\n").unwrap_err();
        assert!(e.contains("not a valid user name"), "{e}");
    }

    #[test]
    fn names_that_could_break_the_file_or_a_log_line_are_refused() {
        for bad in ["", "a:b", "a b", "a\nb", &"x".repeat(65)] {
            assert!(!valid_name(bad), "{bad:?}");
        }
        assert!(valid_name("op.erator-1@plant"));
    }
}
