//! One MQTT session: a connection to the broker with its own bdSeq in its Will, driven by a
//! thread that hands what arrives to the edge node's loop. A session that ends for any reason
//! is not resumed: the node starts a new one with the next bdSeq, as the specification wants
//! for every new MQTT session.

use rumqttc::{
    Client, Connection, Event, LastWill, MqttOptions, NetworkOptions, Packet, QoS,
    TlsConfiguration, Transport,
};
use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::mpsc::{Receiver, SyncSender, TrySendError, sync_channel};
use std::time::Duration;

/// Messages received and not yet handled at most: beyond, they are dropped and counted (a
/// flood of commands cannot grow the node's memory, nor stop the connection).
const QUEUED: usize = 1024;
/// Requests (publishes) waiting for the connection thread at most.
const REQUESTS: usize = 4096;
/// The largest packet taken from the broker: commands larger are refused by the node with a
/// log line (up to this size) or end the session (beyond).
pub const MAX_INCOMING: usize = 16 << 20;
/// The largest packet sent: a birth of [`MAX_METRICS`](crate::device::MAX_METRICS) metrics.
const MAX_OUTGOING: usize = 256 << 20;

/// Where and how to connect.
#[derive(Clone, Debug)]
pub struct Broker {
    /// Host name or address.
    pub host: String,
    /// TCP port.
    pub port: u16,
    /// MQTT client id.
    pub client_id: String,
    /// User and password, when the broker asks for them.
    pub login: Option<(String, String)>,
    /// TLS, for an `mqtts://` broker.
    pub tls: Option<std::sync::Arc<rustls::ClientConfig>>,
}

/// What the connection thread reports.
#[derive(Debug)]
pub enum Incoming {
    /// The broker accepted the connection.
    Connected,
    /// A message on a subscribed topic.
    Message {
        /// Its topic.
        topic: String,
        /// Its payload.
        payload: Vec<u8>,
    },
    /// The session ended (why).
    Lost(String),
}

/// A session in progress.
pub struct Session {
    client: Client,
    events: Receiver<Incoming>,
    /// Messages dropped because the node was behind.
    pub dropped: Arc<AtomicU64>,
    /// The bdSeq of this session's NBIRTH and Will.
    pub bd_seq: u8,
}

impl Session {
    /// Starts connecting with the Will `will` (the NDEATH) on topic `will_topic`.
    pub fn start(broker: &Broker, will_topic: &str, will: Vec<u8>, bd_seq: u8) -> Session {
        let mut options = MqttOptions::new(&broker.client_id, &broker.host, broker.port);
        options
            .set_keep_alive(Duration::from_secs(15))
            // Sparkplug B with MQTT 3.1.1: a clean session, so no command queued for an old
            // session is applied to a new one.
            .set_clean_session(true)
            .set_max_packet_size(MAX_INCOMING, MAX_OUTGOING)
            .set_last_will(LastWill::new(will_topic, will, QoS::AtLeastOnce, false));
        if let Some(config) = &broker.tls {
            options.set_transport(Transport::tls_with_config(TlsConfiguration::Rustls(
                config.clone(),
            )));
        }
        if let Some((user, password)) = &broker.login {
            options.set_credentials(user, password);
        }
        let (client, mut connection) = Client::new(options, REQUESTS);
        // Each look's DDATA is one small write: with Nagle's algorithm (rumqttc's default) it
        // waits until the broker acknowledges the previous one, which a delayed
        // acknowledgement makes tens of milliseconds.
        let mut network = NetworkOptions::new();
        network.set_tcp_nodelay(true);
        connection.eventloop.set_network_options(network);
        let (tx, events) = sync_channel(QUEUED);
        let dropped = Arc::new(AtomicU64::new(0));
        let counter = dropped.clone();
        std::thread::Builder::new()
            .name("mqtt".into())
            .spawn(move || run(connection, tx, counter))
            .map_or_else(
                |e| log::error!(target: "plc_sparkplug", "cannot start the MQTT thread: {e}"),
                drop,
            );
        Session {
            client,
            events,
            dropped,
            bd_seq,
        }
    }

    /// The next report, waiting at most `wait`; `Lost` once the thread ended.
    pub fn next(&self, wait: Duration) -> Option<Incoming> {
        use std::sync::mpsc::RecvTimeoutError;
        match self.events.recv_timeout(wait) {
            Ok(i) => Some(i),
            Err(RecvTimeoutError::Timeout) => None,
            Err(RecvTimeoutError::Disconnected) => {
                Some(Incoming::Lost("the MQTT connection thread ended".into()))
            }
        }
    }

    /// Sends a message (QoS 0, not retained, as the specification has edge nodes send all
    /// theirs); an error when the connection cannot keep up: the node then ends the session.
    pub fn publish(&self, topic: &str, payload: Vec<u8>) -> Result<(), String> {
        self.send(topic, QoS::AtMostOnce, payload)
    }

    /// Sends a message (QoS 0), waiting while the connection is behind: for the store's
    /// replay, which may be far more than the request queue holds. Ends with an error when the
    /// connection thread ended.
    pub fn publish_waiting(&self, topic: &str, payload: Vec<u8>) -> Result<(), String> {
        self.client
            .publish(topic, QoS::AtMostOnce, false, payload)
            .map_err(|_| "the connection to the broker is gone".into())
    }

    /// Sends a message with QoS 1 (the node's own death, before a clean disconnect).
    pub fn publish_reliably(&self, topic: &str, payload: Vec<u8>) -> Result<(), String> {
        self.send(topic, QoS::AtLeastOnce, payload)
    }

    fn send(&self, topic: &str, qos: QoS, payload: Vec<u8>) -> Result<(), String> {
        self.client
            .try_publish(topic, qos, false, payload)
            .map_err(|_| "the connection to the broker does not keep up (or is gone)".into())
    }

    /// Subscribes with QoS 1 (commands and STATE must not be lost on the way).
    pub fn subscribe(&self, filter: &str) -> Result<(), String> {
        self.client
            .try_subscribe(filter, QoS::AtLeastOnce)
            .map_err(|_| format!("cannot subscribe to {filter}: the connection is gone"))
    }

    /// Disconnects cleanly (the broker then drops the Will) and waits up to `wait` for what
    /// was sent before to leave.
    pub fn close(self, wait: Duration) {
        let _ = self.client.try_disconnect();
        let deadline = std::time::Instant::now() + wait;
        // Bounded by the deadline: the thread reports Lost once the disconnect went out.
        while let Some(left) = deadline.checked_duration_since(std::time::Instant::now()) {
            match self.next(left) {
                Some(Incoming::Lost(_)) | None => break,
                Some(_) => {}
            }
        }
    }
}

/// The connection thread: drives the connection until it fails or the session is dropped.
/// It never waits for the node: a message that finds the queue full (a flood of commands the
/// node cannot keep up with) is dropped and counted, so the connection keeps flowing and the
/// node's blocking sends (the replay of the store) always end.
fn run(mut connection: Connection, tx: SyncSender<Incoming>, dropped: Arc<AtomicU64>) {
    for event in connection.iter() {
        let report = match event {
            Ok(Event::Incoming(Packet::ConnAck(_))) => Incoming::Connected,
            Ok(Event::Incoming(Packet::Publish(p))) => Incoming::Message {
                topic: p.topic,
                payload: p.payload.to_vec(),
            },
            Ok(_) => continue,
            Err(e) => {
                // If the queue is full the node sees the thread end instead: the same.
                let _ = tx.try_send(Incoming::Lost(e.to_string()));
                return;
            }
        };
        match tx.try_send(report) {
            Ok(()) => {}
            Err(TrySendError::Full(_)) => {
                dropped.fetch_add(1, Ordering::Relaxed);
            }
            Err(TrySendError::Disconnected(_)) => return,
        }
    }
}
