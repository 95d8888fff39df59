//! TLS to the broker (`mqtts://`): the broker's certificate checked against the CA of `--ca`,
//! and a client certificate (`--cert`, `--key`) when the broker asks for one. Everything is
//! read and checked at start, so a wrong file is an error then, not a reconnection loop.

use rustls::ClientConfig;
use rustls::pki_types::pem::PemObject;
use rustls::pki_types::{CertificateDer, PrivateKeyDer};
use std::path::Path;
use std::sync::Arc;

/// The files of `--ca`, `--cert` and `--key`.
#[derive(Clone, Debug, Default)]
pub struct TlsFiles<'a> {
    /// The CA certificate(s) the broker's certificate must chain to (PEM).
    pub ca: Option<&'a Path>,
    /// The client certificate (PEM), with its chain.
    pub cert: Option<&'a Path>,
    /// The client certificate's private key (PEM).
    pub key: Option<&'a Path>,
}

/// The client configuration for `files`.
pub fn client_config(files: &TlsFiles<'_>) -> Result<Arc<ClientConfig>, String> {
    let Some(ca) = files.ca else {
        return Err(
            "an mqtts:// broker needs --ca FILE: the CA certificate (PEM) that signed the \
             broker's certificate"
                .into(),
        );
    };
    let mut roots = rustls::RootCertStore::empty();
    for cert in certificates(ca, "--ca")? {
        roots
            .add(cert)
            .map_err(|e| format!("--ca {}: not a usable CA certificate ({e})", ca.display()))?;
    }
    // ring, named here rather than left to the process default: the default fails when no
    // provider or two are built in. rustls deprecates ring's provider for lacking the
    // post-quantum key exchange that aws-lc-rs has; aws-lc-rs needs cmake and minutes of C
    // build, and a plant broker's TLS 1.2/1.3 works with either.
    #[allow(deprecated)]
    let provider = Arc::new(rustls::crypto::ring::default_provider());
    let builder = ClientConfig::builder_with_provider(provider)
        .with_safe_default_protocol_versions()
        .map_err(|e| format!("TLS cannot be set up: {e}"))?
        .with_root_certificates(roots);
    let config = match (files.cert, files.key) {
        (Some(cert), Some(key)) => {
            let chain = certificates(cert, "--cert")?;
            let key = PrivateKeyDer::from_pem_file(key).map_err(|e| {
                format!(
                    "--key {}: no PEM private key in it ({e}); give the client certificate's key",
                    key.display()
                )
            })?;
            builder
                .with_client_auth_cert(chain, key)
                .map_err(|e| format!("--cert and --key do not go together: {e}"))?
        }
        (None, None) => builder.with_no_client_auth(),
        _ => return Err("--cert and --key go together: give both, or neither".into()),
    };
    Ok(Arc::new(config))
}

/// The PEM certificates of `path` (at least one).
fn certificates(path: &Path, option: &str) -> Result<Vec<CertificateDer<'static>>, String> {
    let bad = |why: String| format!("{option} {}: {why}", path.display());
    let certs = CertificateDer::pem_file_iter(path)
        .map_err(|e| bad(format!("cannot be read ({e})")))?
        .collect::<Result<Vec<_>, _>>()
        .map_err(|e| bad(format!("not PEM certificates ({e})")))?;
    if certs.is_empty() {
        return Err(bad(
            "holds no certificate: give a PEM file (-----BEGIN CERTIFICATE-----)".into(),
        ));
    }
    Ok(certs)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn files_that_are_missing_empty_or_not_pem_are_errors_naming_the_option() {
        let dir = std::env::temp_dir().join(format!("plc-sparkplug-tls-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let e = client_config(&TlsFiles::default()).unwrap_err();
        assert!(e.contains("needs --ca"), "{e}");
        let missing = dir.join("missing.pem");
        let e = client_config(&TlsFiles {
            ca: Some(&missing),
            ..TlsFiles::default()
        })
        .unwrap_err();
        assert!(e.starts_with("--ca") && e.contains("cannot be read"), "{e}");
        let empty = dir.join("empty.pem");
        std::fs::write(&empty, "no pem here\n").unwrap();
        let e = client_config(&TlsFiles {
            ca: Some(&empty),
            ..TlsFiles::default()
        })
        .unwrap_err();
        assert!(e.contains("holds no certificate"), "{e}");
        let e = client_config(&TlsFiles {
            ca: Some(&empty),
            cert: Some(&empty),
            key: None,
        });
        assert!(e.is_err());
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
