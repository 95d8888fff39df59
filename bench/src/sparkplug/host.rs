//! The measuring host: an MQTT client in this process (rumqttc, the client the edge node is
//! built on, but none of the node's code) that subscribes to the group, says its STATE online
//! on every connection (so the node's births wait for it, after a broker restart too), decodes
//! every payload and hands over what the figures need.

use plc_sparkplug::node::REBIRTH;
use plc_sparkplug::proto::{Metric, MetricValue, Payload};
use plc_sparkplug::topic::{MessageType, Topic};
use prost::Message;
use rumqttc::{Client, Event, MqttOptions, NetworkOptions, Packet, QoS};
use std::sync::mpsc::{Receiver, RecvTimeoutError, channel};
use std::time::{Duration, Instant, SystemTime, UNIX_EPOCH};

/// One message the host received, as the figures use it.
pub(super) enum Seen {
    /// A birth (NBIRTH or DBIRTH).
    Birth(MessageType, Birth),
    /// A DDATA: its live values' latencies (ms from the value's cycle time to its decoding
    /// here), how many values were historical, and its size on the wire.
    Data {
        latencies_ms: Vec<f64>,
        historical: usize,
        bytes: usize,
        at: Instant,
    },
    /// Any other message (deaths, commands, STATE).
    Other,
}

/// A birth as the host received it.
pub(super) struct Birth {
    /// Its size on the wire.
    pub(super) bytes: usize,
    /// Its metrics.
    pub(super) metrics: usize,
    /// When it was decoded.
    pub(super) at: Instant,
}

/// The host's connection; its thread ends when the host is dropped.
pub(super) struct Host {
    client: Client,
    seen: Receiver<Seen>,
    group: String,
    node: String,
}

/// The largest message the host takes: a birth of 10,000 metrics is about 0.5 MB.
const MAX_MESSAGE: usize = 64 << 20;

impl Host {
    /// Connects to the broker on loopback `port` as primary host `id` of `group`, and
    /// subscribes to the group's topics; returns at once (the connection is made by its
    /// thread, again after every loss).
    pub(super) fn connect(port: u16, group: &str, node: &str, id: &str) -> Host {
        let mut options = MqttOptions::new(format!("plc-bench-host-{id}"), "127.0.0.1", port);
        options
            .set_keep_alive(Duration::from_secs(15))
            .set_clean_session(true)
            .set_max_packet_size(MAX_MESSAGE, MAX_MESSAGE);
        let (client, mut connection) = Client::new(options, 64);
        // Its rebirth requests go out at once (Nagle's algorithm would hold them).
        let mut network = NetworkOptions::new();
        network.set_tcp_nodelay(true);
        connection.eventloop.set_network_options(network);
        let (tx, seen) = channel();
        let (subscriber, filter) = (client.clone(), format!("spBv1.0/{group}/#"));
        let state = format!("spBv1.0/STATE/{id}");
        std::thread::spawn(move || {
            for event in connection.iter() {
                let sent = match event {
                    Ok(Event::Incoming(Packet::ConnAck(_))) => {
                        // Subscribed before the STATE goes out: no birth it lets through is
                        // missed.
                        let _ = subscriber.try_subscribe(&filter, QoS::AtMostOnce);
                        let online = format!(r#"{{"online": true, "timestamp": {}}}"#, utc_ms());
                        let _ = subscriber.try_publish(&state, QoS::AtLeastOnce, true, online);
                        Ok(())
                    }
                    Ok(Event::Incoming(Packet::Publish(p))) => {
                        tx.send(seen_of(&p.topic, &p.payload))
                    }
                    Ok(_) => Ok(()),
                    Err(_) => {
                        std::thread::sleep(Duration::from_millis(50));
                        Ok(())
                    }
                };
                if sent.is_err() {
                    return;
                }
            }
        });
        Host {
            client,
            seen,
            group: group.to_string(),
            node: node.to_string(),
        }
    }

    /// The next message within `timeout`.
    pub(super) fn next(&self, timeout: Duration) -> Result<Seen, String> {
        self.seen.recv_timeout(timeout).map_err(|e| match e {
            RecvTimeoutError::Timeout => format!("nothing from the broker in {timeout:?}"),
            RecvTimeoutError::Disconnected => "the host's connection ended".into(),
        })
    }

    /// Waits for a birth of `kind`; every message before it is dropped.
    pub(super) fn birth(&self, kind: MessageType, within: Duration) -> Result<Birth, String> {
        let end = Instant::now() + within;
        loop {
            let left = end.saturating_duration_since(Instant::now());
            match self
                .next(left)
                .map_err(|e| format!("no {}: {e}", kind.name()))?
            {
                Seen::Birth(k, birth) if k == kind => return Ok(birth),
                _ => {}
            }
        }
    }

    /// Asks the node for its births again (NCMD `Node Control/Rebirth` = true).
    pub(super) fn rebirth(&self) -> Result<(), String> {
        let metric = Metric {
            name: Some(REBIRTH.into()),
            timestamp: Some(utc_ms()),
            datatype: Some(11),
            value: Some(MetricValue::BooleanValue(true)),
            ..Metric::default()
        };
        let payload = Payload {
            timestamp: Some(utc_ms()),
            metrics: vec![metric],
            ..Payload::default()
        };
        let topic = Topic::node(&self.group, MessageType::NCmd, &self.node, None);
        self.client
            .try_publish(
                topic.to_string(),
                QoS::AtLeastOnce,
                false,
                payload.encode_to_vec(),
            )
            .map_err(|e| format!("NCMD: {e}"))
    }

    /// Drops what arrived so far.
    pub(super) fn drain(&self) {
        while self.seen.try_recv().is_ok() {}
    }
}

impl Drop for Host {
    fn drop(&mut self) {
        let _ = self.client.try_disconnect();
    }
}

/// Milliseconds since the Unix epoch, now.
fn utc_ms() -> u64 {
    SystemTime::now()
        .duration_since(UNIX_EPOCH)
        .map_or(0, |d| d.as_millis() as u64)
}

/// What the figures need of one message.
fn seen_of(topic: &str, bytes: &[u8]) -> Seen {
    let at = Instant::now();
    let Some(Topic::Node { kind, .. }) = Topic::parse(topic) else {
        return Seen::Other;
    };
    let Ok(payload) = Payload::decode(bytes) else {
        return Seen::Other;
    };
    match kind {
        MessageType::NBirth | MessageType::DBirth => Seen::Birth(
            kind,
            Birth {
                bytes: bytes.len(),
                metrics: payload.metrics.len(),
                at,
            },
        ),
        MessageType::DData => {
            let now_ms = SystemTime::now()
                .duration_since(UNIX_EPOCH)
                .map_or(0.0, |d| d.as_secs_f64() * 1e3);
            let historical = payload
                .metrics
                .iter()
                .filter(|m| m.is_historical == Some(true))
                .count();
            let latencies_ms = payload
                .metrics
                .iter()
                .filter(|m| m.is_historical != Some(true))
                .filter_map(|m| m.timestamp)
                .map(|t| now_ms - t as f64)
                .collect();
            Seen::Data {
                latencies_ms,
                historical,
                bytes: bytes.len(),
                at,
            }
        }
        _ => Seen::Other,
    }
}
