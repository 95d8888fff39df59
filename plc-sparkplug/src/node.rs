//! The edge node's loop: one MQTT session at a time (each with the next bdSeq), births when the
//! broker and the primary host are there, data by exception from every device, commands.

use crate::ServeOptions;
use crate::device::{DataPolicy, Device, now_ms};
use crate::forward::Forward;
use crate::metric::{DataType, bool_property};
use crate::proto::{Metric, MetricValue, Payload};
use crate::session::{Broker, Incoming, Session};
use crate::store::Store;
use crate::topic::{MessageType, Topic};
use prost::Message;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

/// The name of the node's rebirth command metric.
pub const REBIRTH: &str = "Node Control/Rebirth";
/// Commands larger than this are refused unread.
pub const MAX_COMMAND: usize = 1 << 20;
/// How often devices are read for changes.
const TICK: Duration = Duration::from_millis(10);
/// How often a dead device's segment is looked for again.
const REATTACH: Duration = Duration::from_secs(1);
/// The longest wait between two connection attempts.
const MAX_BACKOFF: Duration = Duration::from_secs(30);
/// Reports handled per tick at most, so a flood of commands cannot stop the data.
const EVENTS_PER_TICK: usize = 256;

/// Warnings about commands, at a bounded rate.
static REFUSALS: plc_shm::LogLimit = plc_shm::LogLimit::new("plc_sparkplug");
/// Warnings about the store, which could fail every tick.
static STORE_FAILURES: plc_shm::LogLimit = plc_shm::LogLimit::new("plc_sparkplug");

struct Slot {
    name: String,
    device: Option<Device>,
    born: bool,
    next_try: Instant,
    said_missing: bool,
}

/// The edge node's state.
pub struct Node {
    opts: ServeOptions,
    broker: Broker,
    store: Store,
    forward: Forward,
    policy: DataPolicy,
    slots: Vec<Slot>,
    session: Option<Session>,
    connected: bool,
    host_online: bool,
    last_state: Option<u64>,
    births_sent: bool,
    seq: u8,
    reconnect_at: Instant,
    backoff: Duration,
    refused: u64,
}

impl Node {
    /// A node for `opts`, its bdSeq kept in `store`, data waiting for a birth in `forward`.
    pub fn new(opts: ServeOptions, broker: Broker, store: Store, forward: Forward) -> Node {
        let now = Instant::now();
        let policy = DataPolicy {
            deadband: opts.deadband,
            min_interval: opts
                .max_rate
                .map_or(Duration::ZERO, |r| Duration::from_secs_f64(1.0 / r)),
        };
        let slots = opts
            .segments
            .iter()
            .map(|s| Slot {
                name: s.clone(),
                device: None,
                born: false,
                next_try: now,
                said_missing: false,
            })
            .collect();
        Node {
            opts,
            broker,
            store,
            forward,
            policy,
            slots,
            session: None,
            connected: false,
            host_online: false,
            last_state: None,
            births_sent: false,
            seq: 0,
            reconnect_at: now,
            backoff: Duration::from_millis(500),
            refused: 0,
        }
    }

    fn topic(&self, kind: MessageType, device: Option<&str>) -> String {
        Topic::node(&self.opts.group, kind, &self.opts.node, device).to_string()
    }

    /// Runs until `stop` is set; then publishes the node's death and disconnects.
    pub fn run(mut self, stop: &Arc<AtomicBool>) -> Result<(), String> {
        while !stop.load(Ordering::Relaxed) {
            self.step()?;
        }
        if let Some(session) = self.session.take() {
            if self.connected {
                let death = self.death(session.bd_seq);
                let _ = session.publish_reliably(&self.topic(MessageType::NDeath, None), death);
            }
            session.close(Duration::from_secs(2));
        }
        log::info!(target: "plc_sparkplug", "stopped");
        Ok(())
    }

    fn step(&mut self) -> Result<(), String> {
        let now = Instant::now();
        if self.session.is_none() && now >= self.reconnect_at {
            let bd_seq = self.store.next_bd_seq()?;
            let will = self.death(bd_seq);
            let topic = self.topic(MessageType::NDeath, None);
            log::info!(target: "plc_sparkplug",
                "connecting to {}:{} (bdSeq {bd_seq})", self.broker.host, self.broker.port);
            self.session = Some(Session::start(&self.broker, &topic, will, bd_seq));
        }
        let mut wait = TICK;
        for _ in 0..EVENTS_PER_TICK {
            let Some(event) = self.session.as_ref().and_then(|s| s.next(wait)) else {
                break;
            };
            wait = Duration::ZERO;
            self.handle(event);
        }
        if self.session.is_none() {
            // Not connected: keep the devices' state current (deaths and returns are only
            // logged), at the same pace.
            std::thread::sleep(wait);
        }
        if let Some(s) = &self.session {
            let dropped = s.dropped.swap(0, Ordering::Relaxed);
            if dropped > 0 {
                self.refused += dropped;
                let n = self.refused;
                REFUSALS.warn(|| {
                    format!("{dropped} message(s) dropped unread: more arrived than the node takes ({n} refused so far)")
                });
            }
        }
        if self.connected && self.host_online && !self.births_sent {
            self.births();
        }
        self.poll_devices();
        Ok(())
    }

    fn handle(&mut self, event: Incoming) {
        match event {
            Incoming::Connected => {
                log::info!(target: "plc_sparkplug", "connected");
                self.connected = true;
                self.births_sent = false;
                self.backoff = Duration::from_millis(500);
                self.host_online = self.opts.primary_host.is_none();
                let mut filters = vec![
                    self.topic(MessageType::NCmd, None),
                    self.topic(MessageType::DCmd, Some("+")),
                ];
                if let Some(host) = &self.opts.primary_host {
                    filters.push(Topic::State { host: host.clone() }.to_string());
                }
                for f in filters {
                    if let Err(e) = self.session.as_ref().map_or(Ok(()), |s| s.subscribe(&f)) {
                        self.lose(&e);
                        return;
                    }
                }
            }
            Incoming::Lost(why) => self.lose(&why),
            Incoming::Message { topic, payload } => self.message(&topic, &payload),
        }
    }

    /// Ends the session (the broker publishes the Will if it was not closed cleanly) and
    /// plans the next with a growing wait.
    fn lose(&mut self, why: &str) {
        log::warn!(target: "plc_sparkplug",
            "the MQTT session ended ({why}); connecting again in {:?}", self.backoff);
        if let Some(s) = self.session.take() {
            s.close(Duration::ZERO);
        }
        self.connected = false;
        self.births_sent = false;
        for slot in &mut self.slots {
            slot.born = false;
        }
        self.reconnect_at = Instant::now() + self.backoff;
        self.backoff = (self.backoff * 2).min(MAX_BACKOFF);
    }

    /// The NDEATH payload: the session's bdSeq.
    fn death(&self, bd_seq: u8) -> Vec<u8> {
        Payload {
            timestamp: Some(now_ms()),
            metrics: vec![bd_seq_metric(bd_seq)],
            ..Payload::default()
        }
        .encode_to_vec()
    }

    fn next_seq(&mut self) -> u64 {
        self.seq = self.seq.wrapping_add(1);
        u64::from(self.seq)
    }

    fn send(&mut self, kind: MessageType, device: Option<&str>, mut payload: Payload) -> bool {
        payload.seq = Some(if kind == MessageType::NBirth {
            self.seq = 0;
            0
        } else {
            self.next_seq()
        });
        let topic = self.topic(kind, device);
        let sent = self
            .session
            .as_ref()
            .map_or(Err("no session".to_string()), |s| {
                s.publish(&topic, payload.encode_to_vec())
            });
        if let Err(e) = sent {
            self.lose(&e);
            return false;
        }
        true
    }

    /// NBIRTH (seq 0, bdSeq, Node Control/Rebirth), then a DBIRTH for every device running.
    fn births(&mut self) {
        let Some(bd_seq) = self.session.as_ref().map(|s| s.bd_seq) else {
            return;
        };
        let ts = now_ms();
        let mut rebirth = Metric {
            name: Some(REBIRTH.into()),
            timestamp: Some(ts),
            datatype: Some(DataType::Boolean.code()),
            value: Some(MetricValue::BooleanValue(false)),
            ..Metric::default()
        };
        rebirth.properties = Some(crate::proto::PropertySet {
            keys: vec!["readOnly".into()],
            values: vec![bool_property(false)],
        });
        let mut bd = bd_seq_metric(bd_seq);
        bd.timestamp = Some(ts);
        let nbirth = Payload {
            timestamp: Some(ts),
            metrics: vec![bd, rebirth],
            ..Payload::default()
        };
        if !self.send(MessageType::NBirth, None, nbirth) {
            return;
        }
        log::info!(target: "plc_sparkplug", "NBIRTH sent (bdSeq {bd_seq})");
        self.births_sent = true;
        for i in 0..self.slots.len() {
            self.slots[i].born = false;
            self.device_birth(i);
        }
        self.forward_stored();
    }

    /// Sends what the store kept while no birth was out, oldest first, as DDATA of historical
    /// values (each with its own cycle's time), after the births.
    fn forward_stored(&mut self) {
        if self.forward.is_empty() {
            return;
        }
        let records = self.forward.take();
        let (mut sent, mut orphans) = (0usize, 0usize);
        for (device, mut payload) in records {
            if !self.slots.iter().any(|s| s.name == device && s.born) {
                // A device no longer served, or not running now: its past has no birth to
                // belong to.
                orphans += 1;
                continue;
            }
            payload.seq = Some(self.next_seq());
            let topic = self.topic(MessageType::DData, Some(&device));
            let result = self
                .session
                .as_ref()
                .map_or(Err("no session".to_string()), |s| {
                    s.publish_waiting(&topic, payload.encode_to_vec())
                });
            if let Err(e) = result {
                self.lose(&e);
                break;
            }
            sent += 1;
        }
        log::info!(target: "plc_sparkplug",
            "{sent} stored record(s) sent as historical data{}",
            if orphans > 0 { format!(", {orphans} of devices not running dropped") } else { String::new() });
    }

    fn device_birth(&mut self, i: usize) {
        let Some(dev) = self.slots[i].device.as_mut() else {
            return;
        };
        match dev.birth() {
            Ok(payload) => {
                let n = payload.metrics.len();
                let id = self.slots[i].name.clone();
                if self.send(MessageType::DBirth, Some(&id), payload) {
                    self.slots[i].born = true;
                    log::info!(target: "plc_sparkplug", "DBIRTH {id}: {n} metrics");
                }
            }
            Err(e) => {
                log::warn!(target: "plc_sparkplug", "device {}: {e}", self.slots[i].name);
                self.slots[i].device = None;
            }
        }
    }

    /// Deaths of devices whose program ended, births of those that came (back), data of the
    /// others.
    fn poll_devices(&mut self) {
        let now = Instant::now();
        for i in 0..self.slots.len() {
            let alive = self.slots[i].device.as_ref().map(Device::alive);
            match alive {
                Some(true) => {
                    // With no birth out the changes go to the store, to follow the next births.
                    let historical = !self.births_sent;
                    if !historical && !self.slots[i].born {
                        continue;
                    }
                    let policy = self.policy;
                    let changes = self.slots[i]
                        .device
                        .as_mut()
                        .map(|d| d.changes(&policy, historical));
                    match changes {
                        Some(Ok(Some(p))) if historical => {
                            if let Err(e) = self.forward.push(&self.slots[i].name, &p) {
                                STORE_FAILURES.warn(|| e);
                            }
                        }
                        Some(Ok(Some(p))) => {
                            let id = self.slots[i].name.clone();
                            self.send(MessageType::DData, Some(&id), p);
                        }
                        Some(Err(e)) => {
                            log::warn!(target: "plc_sparkplug", "device {}: {e}", self.slots[i].name)
                        }
                        _ => {}
                    }
                }
                Some(false) => {
                    let id = self.slots[i].name.clone();
                    log::info!(target: "plc_sparkplug", "device {id}: its program ended");
                    self.slots[i].device = None;
                    self.slots[i].next_try = now + REATTACH;
                    if std::mem::take(&mut self.slots[i].born) {
                        let death = Payload {
                            timestamp: Some(now_ms()),
                            ..Payload::default()
                        };
                        self.send(MessageType::DDeath, Some(&id), death);
                    }
                }
                None if now >= self.slots[i].next_try => self.attach(i, now),
                None => {}
            }
        }
    }

    fn attach(&mut self, i: usize, now: Instant) {
        let slot = &mut self.slots[i];
        slot.next_try = now + REATTACH;
        match Device::attach(&slot.name) {
            Ok(dev) if dev.alive() => {
                log::info!(target: "plc_sparkplug",
                    "device {}: attached (layout {:016x})", slot.name, dev.layout_hash());
                slot.device = Some(dev);
                slot.said_missing = false;
                if self.births_sent {
                    self.device_birth(i);
                }
            }
            Ok(_) => {}
            Err(e) => {
                if !std::mem::replace(&mut slot.said_missing, true) {
                    log::warn!(target: "plc_sparkplug",
                        "device {}: {e}; trying again every second", slot.name);
                }
            }
        }
    }

    fn message(&mut self, topic: &str, payload: &[u8]) {
        match Topic::parse(topic) {
            Some(Topic::State { host }) if Some(&host) == self.opts.primary_host.as_ref() => {
                self.state(payload)
            }
            Some(Topic::Node {
                kind: MessageType::NCmd,
                ..
            }) => {
                if let Some(p) = self.decode(topic, payload) {
                    self.node_command(&p);
                }
            }
            Some(Topic::Node {
                kind: MessageType::DCmd,
                device: Some(device),
                ..
            }) => self.device_command(topic, &device, payload),
            _ => self.refuse(|| format!("{topic}: not a topic this edge node takes")),
        }
    }

    fn refuse(&mut self, why: impl FnOnce() -> String) {
        self.refused += 1;
        let n = self.refused;
        REFUSALS.warn(|| format!("command refused: {} ({n} refused so far)", why()));
    }

    fn decode(&mut self, topic: &str, payload: &[u8]) -> Option<Payload> {
        if payload.len() > MAX_COMMAND {
            let len = payload.len();
            self.refuse(|| format!("{topic}: {len} bytes, more than {MAX_COMMAND}"));
            return None;
        }
        match Payload::decode(payload) {
            Ok(p) => Some(p),
            Err(e) => {
                self.refuse(|| format!("{topic}: not a Sparkplug B payload ({e})"));
                None
            }
        }
    }

    fn node_command(&mut self, p: &Payload) {
        for m in &p.metrics {
            // Aliases are not given to node metrics, so a command names them.
            match (m.name.as_deref(), &m.value) {
                (Some(REBIRTH), Some(MetricValue::BooleanValue(true))) => {
                    log::info!(target: "plc_sparkplug", "rebirth requested");
                    self.births_sent = false;
                }
                (Some(REBIRTH), _) => {
                    self.refuse(|| format!("{REBIRTH} takes the Boolean true"));
                }
                (name, _) => {
                    let name = name.unwrap_or("").escape_debug().to_string();
                    self.refuse(|| format!("the node has no metric `{name}` to command"));
                }
            }
        }
    }

    fn device_command(&mut self, topic: &str, device: &str, payload: &[u8]) {
        let Some(i) = self.slots.iter().position(|s| s.name == device) else {
            let device = device.escape_debug().to_string();
            self.refuse(|| format!("no device `{device}` here"));
            return;
        };
        if !self.opts.commands {
            self.refuse(|| format!("{topic}: commands are off (start with --commands)"));
            return;
        }
        let Some(p) = self.decode(topic, payload) else {
            return;
        };
        let result = match &self.slots[i].device {
            Some(d) if self.slots[i].born => d.command(&p),
            _ => Err("the device's program is not running".into()),
        };
        match result {
            Ok(n) => log::info!(target: "plc_sparkplug", "{topic}: {n} value(s) written"),
            Err(e) => self.refuse(|| format!("{topic}: {e}")),
        }
    }

    /// A STATE of the primary host: `{"online": bool, "timestamp": ms}`; an older one than the
    /// last seen is stale. Online lets the births go; offline ends the session (after the
    /// node's death) so the next one is born when the host is back.
    fn state(&mut self, payload: &[u8]) {
        let parsed: Option<(bool, u64)> = serde_json::from_slice::<serde_json::Value>(payload)
            .ok()
            .and_then(|v| Some((v.get("online")?.as_bool()?, v.get("timestamp")?.as_u64()?)));
        let Some((online, ts)) = parsed else {
            self.refuse(|| "a STATE that is not {\"online\": bool, \"timestamp\": ms}".into());
            return;
        };
        if self.last_state.is_some_and(|last| ts < last) {
            log::info!(target: "plc_sparkplug", "a stale STATE ignored");
            return;
        }
        self.last_state = Some(ts);
        log::info!(target: "plc_sparkplug",
            "primary host {}", if online { "online" } else { "offline" });
        if online {
            self.host_online = true;
        } else {
            self.host_online = false;
            if self.births_sent
                && let Some(s) = self.session.take()
            {
                let death = self.death(s.bd_seq);
                let _ = s.publish_reliably(&self.topic(MessageType::NDeath, None), death);
                s.close(Duration::from_secs(2));
                self.connected = false;
                self.births_sent = false;
                for slot in &mut self.slots {
                    slot.born = false;
                }
                self.reconnect_at = Instant::now();
            }
        }
    }
}

/// The `bdSeq` metric (Int64) of an NBIRTH or NDEATH.
fn bd_seq_metric(bd_seq: u8) -> Metric {
    Metric {
        name: Some("bdSeq".into()),
        datatype: Some(DataType::Int64.code()),
        value: Some(MetricValue::LongValue(u64::from(bd_seq))),
        ..Metric::default()
    }
}
