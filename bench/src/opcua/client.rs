//! The OPC UA clients on async-opcua's client crate: a session with the server (security
//! None, anonymous), the index of a namespace, and the monitoring parameters of every item the
//! group subscribes to.

use crate::owner::PERIOD;
use opcua::client::{ClientBuilder, IdentityToken, Session};
use opcua::types::{
    EndpointDescription, ExtensionObject, MessageSecurityMode, MonitoringParameters, NodeId,
    ReadValueId, TimestampsToReturn, UserTokenPolicy, VariableId, Variant,
};
use std::path::Path;
use std::sync::Arc;

/// One client session and its event loop.
pub(super) struct Client {
    pub(super) session: Arc<Session>,
    event_loop: tokio::task::JoinHandle<opcua::types::StatusCode>,
}

impl Client {
    pub(super) async fn connect(url: &str, work: &Path) -> Result<Client, String> {
        let mut client = ClientBuilder::new()
            .application_name("plc-bench")
            .application_uri("urn:plc-vars:plc-bench")
            .product_uri("urn:plc-vars:plc-bench")
            .pki_dir(work.join("client-pki"))
            .create_sample_keypair(true)
            .trust_server_certs(true)
            .session_retry_limit(0)
            // A response of 10,000 values: larger than async-opcua's defaults (arrays of
            // 1,000, messages of 5 x 64 KiB), as on the server.
            .max_array_length(100_000)
            .max_message_size(16 << 20)
            .max_chunk_count(256)
            .min_publish_interval(PERIOD)
            .client()
            .map_err(|e| format!("OPC UA client: {}", e.join("; ")))?;
        let endpoint: EndpointDescription = (
            url,
            "http://opcfoundation.org/UA/SecurityPolicy#None",
            MessageSecurityMode::None,
            UserTokenPolicy::anonymous(),
        )
            .into();
        let (session, event_loop) = client
            .connect_to_matching_endpoint(endpoint, IdentityToken::Anonymous)
            .await
            .map_err(|e| format!("connecting to {url}: {e}"))?;
        let event_loop = event_loop.spawn();
        if !session.wait_for_connection().await {
            return Err(format!("no session with {url}"));
        }
        Ok(Client {
            session,
            event_loop,
        })
    }

    pub(super) async fn close(self) {
        let _ = self.session.disconnect().await;
        self.event_loop.abort();
    }
}

/// The index of namespace `uri` on the server.
pub(super) async fn namespace(session: &Session, uri: &str) -> Result<u16, String> {
    let array: ReadValueId = NodeId::from(VariableId::Server_NamespaceArray).into();
    let values = session
        .read(&[array], TimestampsToReturn::Neither, 0.0)
        .await
        .map_err(|e| format!("reading the namespace array: {e}"))?;
    if let Some(Some(Variant::Array(a))) = values.first().map(|v| v.value.as_ref()) {
        for (i, v) in a.values.iter().enumerate() {
            if let Variant::String(s) = v
                && s.as_ref() == uri
            {
                return u16::try_from(i).map_err(|_| "namespace index out of range".into());
            }
        }
    }
    Err(format!("the server has no namespace {uri}"))
}

/// Monitoring at the owner's period, the newest value only.
pub(super) fn parameters(handle: u32) -> MonitoringParameters {
    MonitoringParameters {
        client_handle: handle,
        sampling_interval: PERIOD.as_secs_f64() * 1e3,
        filter: ExtensionObject::null(),
        queue_size: 1,
        discard_oldest: true,
    }
}
