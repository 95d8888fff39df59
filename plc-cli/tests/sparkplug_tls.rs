//! `plc mqtt serve` to a broker that wants TLS with a client certificate, or a user and
//! password: mosquitto with three listeners (plain for the independent host, TLS requiring a
//! certificate from the test's CA, and one with a password file), certificates made by
//! `openssl`, the password file by `mosquitto_passwd`. Skipped, saying why, without them.

mod common;
mod owner;
mod spb;

use common::SpawnGuarded;
use owner::Owner;
use spb::{Host, broker_with, free_port, is, log_of, metric, parts, serve_url, test_dir, wait_log};
use std::path::Path;
use std::process::Command;
use std::time::Duration;

#[test]
fn owner_role() {
    if std::env::var("PLC_TEST_ROLE").as_deref() == Ok("owner") {
        owner::run();
    }
}

/// Runs a tool of the test's; false (with its output shown) when it fails.
fn run(dir: &Path, program: &str, args: &[&str]) -> bool {
    let out = Command::new(program)
        .current_dir(dir)
        .args(args)
        .output_guarded();
    match out {
        Ok(o) if o.status.success() => true,
        Ok(o) => {
            eprintln!("{program} {args:?}: {}", String::from_utf8_lossy(&o.stderr));
            false
        }
        Err(e) => {
            eprintln!("{program}: {e}");
            false
        }
    }
}

/// A CA `name` and a certificate `leaf` signed by it (EC P-256, a day), in `dir`.
fn certificates(dir: &Path, ca: &str, leaf: &str, san: &str) -> bool {
    let ec = [
        "-newkey",
        "ec",
        "-pkeyopt",
        "ec_paramgen_curve:prime256v1",
        "-nodes",
    ];
    let ca_key = format!("{ca}.key");
    let ca_pem = format!("{ca}.pem");
    let (key, csr, pem, ext) = (
        format!("{leaf}.key"),
        format!("{leaf}.csr"),
        format!("{leaf}.pem"),
        format!("{leaf}.ext"),
    );
    if !dir.join(&ca_pem).exists() {
        let mut args = vec!["req", "-x509", "-days", "1", "-subj"];
        let subj = format!("/CN={ca}");
        args.extend([subj.as_str(), "-keyout", &ca_key, "-out", &ca_pem]);
        args.extend(ec);
        if !run(dir, "openssl", &args) {
            return false;
        }
    }
    std::fs::write(dir.join(&ext), format!("subjectAltName={san}\n")).expect("ext file");
    let subj = format!("/CN={leaf}");
    let mut args = vec!["req", "-subj", &subj, "-keyout", &key, "-out", &csr];
    args.extend(ec);
    run(dir, "openssl", &args)
        && run(
            dir,
            "openssl",
            &[
                "x509",
                "-req",
                "-in",
                &csr,
                "-CA",
                &ca_pem,
                "-CAkey",
                &ca_key,
                "-CAcreateserial",
                "-days",
                "1",
                "-extfile",
                &ext,
                "-out",
                &pem,
            ],
        )
}

#[test]
fn tls_with_a_client_certificate_and_a_password_file_are_honoured_and_strangers_refused() {
    let Some((python, mosquitto)) = parts() else {
        return;
    };
    let dir = test_dir("tls");
    if !(certificates(&dir, "ca", "server", "IP:127.0.0.1")
        && certificates(&dir, "ca", "edge", "DNS:edge")
        && certificates(&dir, "rogue", "stranger", "DNS:edge")
        && run(
            &dir,
            "mosquitto_passwd",
            &["-b", "-c", "passwd", "edge", "right password"],
        ))
    {
        eprintln!("skipped: openssl or mosquitto_passwd is missing or failed (see above)");
        return;
    }
    let (plain, tls, login) = (free_port(), free_port(), free_port());
    let conf = format!(
        "per_listener_settings true\n\
         listener {plain} 127.0.0.1\nallow_anonymous true\n\
         listener {tls} 127.0.0.1\nallow_anonymous true\ncafile ca.pem\ncertfile server.pem\n\
         keyfile server.key\nrequire_certificate true\n\
         listener {login} 127.0.0.1\nallow_anonymous false\npassword_file passwd\n"
    );
    // mosquitto reads the files relative to where it runs: the configuration names them
    // as in `dir`.
    let conf = conf.replace(" ca.pem", &format!(" {}", dir.join("ca.pem").display()));
    let conf = conf.replace(
        " server.pem",
        &format!(" {}", dir.join("server.pem").display()),
    );
    let conf = conf.replace(
        " server.key",
        &format!(" {}", dir.join("server.key").display()),
    );
    let conf = conf.replace(" passwd", &format!(" {}", dir.join("passwd").display()));
    let _broker = broker_with(&mosquitto, &dir, &conf, &[plain, tls, login]);
    let program = Owner::start("spb_tls");
    let seg = program.segment.clone();
    let mut host = Host::start(&python, plain, "plant", "scada");
    let file = |name: &str| dir.join(name).display().to_string();
    let mqtts = format!("mqtts://127.0.0.1:{tls}");

    // The CA's client certificate: connected, born.
    let ca = file("ca.pem");
    let (cert, key) = (file("edge.pem"), file("edge.key"));
    let tls_args = ["--ca", &ca, "--cert", &cert, "--key", &key];
    let mut edge = serve_url(&dir, 1, &mqtts, &seg, &tls_args);
    let nbirth = host.expect("NBIRTH over TLS", is("NBIRTH"));
    assert_eq!(metric(&nbirth, "bdSeq")["datatype"], "INT64");
    host.expect("DBIRTH over TLS", is("DBIRTH"));
    assert!(
        edge.terminate().is_ok_and(|s| s.success()),
        "{}",
        log_of(&dir, 1)
    );
    host.expect("NDEATH", is("NDEATH"));

    // A certificate of another CA, or none: the broker refuses, nothing is born.
    let (cert, key) = (file("stranger.pem"), file("stranger.key"));
    let _edge = serve_url(
        &dir,
        2,
        &mqtts,
        &seg,
        &["--ca", &ca, "--cert", &cert, "--key", &key],
    );
    wait_log(&dir, 2, "the MQTT session ended");
    let _edge = serve_url(&dir, 3, &mqtts, &seg, &["--ca", &ca]);
    wait_log(&dir, 3, "the MQTT session ended");
    // A broker whose certificate the node's CA did not sign: the node refuses it.
    let rogue = file("rogue.pem");
    let _edge = serve_url(
        &dir,
        4,
        &mqtts,
        &seg,
        &["--ca", &rogue, "--cert", &cert, "--key", &key],
    );
    wait_log(&dir, 4, "the MQTT session ended");
    assert!(
        host.within("no birth", Duration::from_secs(2), is("NBIRTH"))
            .is_none(),
        "a node the broker should have refused was born"
    );
    drop(_edge);

    // User and password: a wrong one is refused, the right one connects.
    std::fs::write(dir.join("wrong"), "wrong password\n").expect("password file");
    std::fs::write(dir.join("right"), "right password\n").expect("password file");
    let plain_login = format!("mqtt://127.0.0.1:{login}");
    let wrong = file("wrong");
    let _edge = serve_url(
        &dir,
        5,
        &plain_login,
        &seg,
        &["--user", "edge", "--password-file", &wrong],
    );
    wait_log(&dir, 5, "the MQTT session ended");
    assert!(
        host.within("no birth", Duration::from_secs(1), is("NBIRTH"))
            .is_none()
    );
    drop(_edge);
    let right = file("right");
    let mut edge = serve_url(
        &dir,
        6,
        &plain_login,
        &seg,
        &["--user", "edge", "--password-file", &right],
    );
    host.expect("NBIRTH with the right password", is("NBIRTH"));
    assert!(edge.terminate().is_ok_and(|s| s.success()));
    drop(program);
    let _ = std::fs::remove_dir_all(&dir);
}
