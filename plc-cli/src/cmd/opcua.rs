//! `plc opcua serve SEGMENT...` runs the OPC UA server (plc-opcua) for running programs;
//! `plc opcua user add FILE NAME` adds a user who may write, the password read from standard
//! input (without echo at a terminal) and stored as a salted argon2 hash.

use super::Error;
use std::io::{BufRead, IsTerminal, Write};
use std::path::Path;

pub fn serve(options: &plc_opcua::ServeOptions) -> Result<(), Error> {
    plc_opcua::serve(options)?;
    Ok(())
}

pub fn add_user(file: &Path, name: &str) -> Result<(), Error> {
    let password = read_password(name)?;
    plc_opcua::add_user(file, name, &password)?;
    eprintln!(
        "user `{name}` may now write through the OPC UA server ({})",
        file.display()
    );
    Ok(())
}

/// One line of standard input, without its line end; at a terminal, asked for and not echoed.
fn read_password(name: &str) -> Result<String, Error> {
    let stdin = std::io::stdin();
    let echo_off = stdin.is_terminal().then(|| {
        eprint!("password for `{name}`: ");
        let _ = std::io::stderr().flush();
        EchoOff::new()
    });
    let mut line = String::new();
    let read = stdin.lock().read_line(&mut line);
    if echo_off.is_some() {
        eprintln!();
    }
    drop(echo_off);
    read.map_err(|e| format!("cannot read the password from standard input: {e}"))?;
    let password = line.strip_suffix('\n').unwrap_or(&line);
    let password = password.strip_suffix('\r').unwrap_or(password);
    if password.is_empty() {
        return Err("no password on standard input: give one line".into());
    }
    Ok(password.to_string())
}

/// The terminal's echo turned off until dropped.
struct EchoOff(Option<libc::termios>);

impl EchoOff {
    fn new() -> EchoOff {
        // SAFETY: tcgetattr/tcsetattr on fd 0 with a termios we own; failures leave echo on.
        unsafe {
            let mut t: libc::termios = std::mem::zeroed();
            if libc::tcgetattr(0, &mut t) != 0 {
                return EchoOff(None);
            }
            let saved = t;
            t.c_lflag &= !libc::ECHO;
            if libc::tcsetattr(0, libc::TCSANOW, &t) != 0 {
                return EchoOff(None);
            }
            EchoOff(Some(saved))
        }
    }
}

impl Drop for EchoOff {
    fn drop(&mut self) {
        if let Some(saved) = self.0 {
            // SAFETY: restores the settings read in `new`.
            unsafe { libc::tcsetattr(0, libc::TCSANOW, &saved) };
        }
    }
}
