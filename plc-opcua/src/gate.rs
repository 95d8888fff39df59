//! The server's door: every client connection comes through here, so that no one client
//! address can take what the others need. async-opcua bounds sessions only in all (one client
//! with 20 anonymous sessions locked operators out) and neither knows nor bounds connections
//! or a client's address. The gate listens on the public port, keeps per address at most a
//! number of connections and of sessions, and in all at most a number of connections, and
//! passes each admitted connection on to the server, which listens on a loopback port of its
//! own.
//!
//! Sessions are counted from the client's messages without decoding them: every OPC UA TCP
//! chunk starts with its type and length (Part 6, 7.1.2), and the first chunk of a request on
//! a channel that is not encrypted starts its body with the request's type. A CreateSession
//! counts against its address while its connection is open, less the CloseSessions sent; when
//! the connection ends without closing them they still count for as long as the server keeps
//! a session without its client (its longest session timeout). Requests on encrypted channels
//! are not counted: only a client whose certificate the server trusts can make a session
//! there. Local users can reach the server's own port, and any 127.0.0.0/8 address: the
//! addresses bounded here are the network's.

use opcua::types::StatusCode;
use plc_shm::LogLimit;
use std::collections::HashMap;
use std::net::{IpAddr, SocketAddr};
use std::sync::{Arc, Mutex, PoisonError};
use std::time::{Duration, Instant};
use tokio::io::{AsyncReadExt, AsyncWrite, AsyncWriteExt};
use tokio::net::tcp::{OwnedReadHalf, OwnedWriteHalf};
use tokio::net::{TcpListener, TcpStream};

/// What the gate allows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct GateLimits {
    /// Connections in all.
    pub connections: usize,
    /// Connections from one address.
    pub connections_per_address: usize,
    /// Sessions made from one address.
    pub sessions_per_address: usize,
    /// How long a session whose connection ended still counts (the server's longest session
    /// timeout).
    pub session_hold: Duration,
}

/// The largest chunk passed on (async-opcua's buffers are 64 KiB; a client may ask for more).
const MAX_CHUNK: usize = 1 << 20;
/// The type of a CreateSessionRequest's binary encoding (ns=0;i=461), as a four-byte NodeId.
const CREATE_SESSION: [u8; 4] = [0x01, 0x00, 0xCD, 0x01];
/// The type of a CloseSessionRequest's binary encoding (ns=0;i=473).
const CLOSE_SESSION: [u8; 4] = [0x01, 0x00, 0xD9, 0x01];
/// Where a request's type is in a first MSG chunk: header (8), secure channel id (4), token
/// id (4), sequence number (4), request id (4).
const TYPE_AT: usize = 24;
/// Addresses remembered at most (each with open connections or held sessions).
const MAX_ADDRESSES: usize = 65_536;

/// Refused connections and sessions, logged at a bounded rate.
static REFUSED: LogLimit = LogLimit::new("plc_opcua::gate");

/// The counts of one address.
#[derive(Default)]
struct Peer {
    connections: usize,
    /// Sessions made on its open connections and not closed.
    sessions: usize,
    /// Sessions of ended connections, each counted until its instant.
    held: Vec<(Instant, usize)>,
}

impl Peer {
    fn sessions(&mut self, now: Instant) -> usize {
        self.held.retain(|(until, _)| *until > now);
        self.sessions + self.held.iter().map(|(_, n)| n).sum::<usize>()
    }
}

/// The counts of every address.
pub struct Gate {
    limits: GateLimits,
    peers: Mutex<HashMap<IpAddr, Peer>>,
}

impl Gate {
    /// A gate with these limits.
    pub fn new(limits: GateLimits) -> Gate {
        Gate {
            limits,
            peers: Mutex::default(),
        }
    }

    fn peers(&self) -> std::sync::MutexGuard<'_, HashMap<IpAddr, Peer>> {
        self.peers.lock().unwrap_or_else(PoisonError::into_inner)
    }

    /// Admits a connection from `ip`, or says why not.
    fn admit(&self, ip: IpAddr) -> Result<(), &'static str> {
        let mut peers = self.peers();
        let now = Instant::now();
        let open: usize = peers.values().map(|p| p.connections).sum();
        if open >= self.limits.connections {
            return Err("the server holds its most connections");
        }
        if !peers.contains_key(&ip) && peers.len() >= MAX_ADDRESSES {
            peers.retain(|_, p| p.connections > 0 || p.sessions(now) > 0);
            if peers.len() >= MAX_ADDRESSES {
                return Err("the server remembers its most client addresses");
            }
        }
        let peer = peers.entry(ip).or_default();
        if peer.connections >= self.limits.connections_per_address {
            return Err("this address holds its most connections");
        }
        peer.connections += 1;
        Ok(())
    }

    /// A session asked for on a connection from `ip`: counted, or refused.
    fn open_session(&self, ip: IpAddr) -> bool {
        let mut peers = self.peers();
        let peer = peers.entry(ip).or_default();
        if peer.sessions(Instant::now()) >= self.limits.sessions_per_address {
            return false;
        }
        peer.sessions += 1;
        true
    }

    fn close_session(&self, ip: IpAddr) {
        if let Some(peer) = self.peers().get_mut(&ip) {
            peer.sessions = peer.sessions.saturating_sub(1);
        }
    }

    /// A connection from `ip` ended with `sessions` of its sessions not closed.
    fn leave(&self, ip: IpAddr, sessions: usize) {
        let mut peers = self.peers();
        let now = Instant::now();
        let Some(peer) = peers.get_mut(&ip) else {
            return;
        };
        peer.connections = peer.connections.saturating_sub(1);
        let sessions = sessions.min(peer.sessions);
        peer.sessions -= sessions;
        if sessions > 0 {
            peer.held.push((now + self.limits.session_hold, sessions));
        }
        if peer.connections == 0 && peer.sessions(now) == 0 {
            peers.remove(&ip);
        }
    }

    /// Sessions that count against `ip` now.
    pub fn sessions_of(&self, ip: IpAddr) -> usize {
        self.peers()
            .get_mut(&ip)
            .map_or(0, |p| p.sessions(Instant::now()))
    }

    /// Accepts connections on `public` and passes the admitted ones on to `server`, until the
    /// listener fails.
    pub async fn run(self: Arc<Self>, public: TcpListener, server: SocketAddr) {
        loop {
            let (client, from) = match public.accept().await {
                Ok(c) => c,
                Err(e) => {
                    // Out of descriptors, say: wait instead of spinning.
                    REFUSED.warn(|| format!("OPC UA: cannot accept a connection: {e}"));
                    tokio::time::sleep(Duration::from_millis(100)).await;
                    continue;
                }
            };
            let ip = canonical(from.ip());
            if let Err(why) = self.admit(ip) {
                REFUSED.warn(|| format!("OPC UA connection from {ip} refused: {why}"));
                tokio::spawn(refuse(client, StatusCode::BadMaxConnectionsReached, why));
                continue;
            }
            let gate = self.clone();
            tokio::spawn(async move {
                let kept = gate.pass(client, ip, server).await;
                gate.leave(ip, kept);
            });
        }
    }

    /// Passes one connection on until either side ends it; the sessions it made and did not
    /// close.
    async fn pass(&self, client: TcpStream, ip: IpAddr, server: SocketAddr) -> usize {
        let Ok(upstream) = TcpStream::connect(server).await else {
            refuse(
                client,
                StatusCode::BadServerHalted,
                "the server is not running",
            )
            .await;
            return 0;
        };
        // Small messages (a notification) go at once, as the server's own socket would send
        // them (see `listen`).
        let _ = client.set_nodelay(true);
        let _ = upstream.set_nodelay(true);
        let (mut from_client, mut to_client) = client.into_split();
        let (mut from_server, mut to_server) = upstream.into_split();
        let mut sessions = 0;
        let refused = tokio::select! {
            r = self.requests(&mut from_client, &mut to_server, ip, &mut sessions) => r,
            _ = answers(&mut from_server, &mut to_client) => false,
        };
        if refused {
            let why = "this client address holds its most sessions";
            send_error(&mut to_client, StatusCode::BadTooManySessions, why).await;
        }
        sessions
    }

    /// Passes the client's chunks on, counting sessions; ends at the first chunk that is not
    /// one (false), or at a session too many (true: the connection is answered with an Error
    /// message and closed).
    async fn requests(
        &self,
        from: &mut OwnedReadHalf,
        to: &mut OwnedWriteHalf,
        ip: IpAddr,
        sessions: &mut usize,
    ) -> bool {
        let mut chunk = Vec::new();
        // Whether the next MSG chunk continues a message (its body is no request's start).
        let mut continuing = false;
        loop {
            let mut header = [0u8; 8];
            if from.read_exact(&mut header).await.is_err() {
                return false;
            }
            let size = u32::from_le_bytes([header[4], header[5], header[6], header[7]]) as usize;
            if !(8..=MAX_CHUNK).contains(&size) {
                return false;
            }
            chunk.clear();
            chunk.extend_from_slice(&header);
            chunk.resize(size, 0);
            if from.read_exact(&mut chunk[8..]).await.is_err() {
                return false;
            }
            if &header[..3] == b"MSG" {
                if !continuing {
                    match chunk.get(TYPE_AT..TYPE_AT + 4) {
                        Some(t) if t == CREATE_SESSION => {
                            if !self.open_session(ip) {
                                REFUSED.warn(|| {
                                    format!(
                                        "OPC UA session from {ip} refused: the address holds \
                                         its {} sessions",
                                        self.limits.sessions_per_address
                                    )
                                });
                                return true;
                            }
                            *sessions += 1;
                        }
                        Some(t) if t == CLOSE_SESSION && *sessions > 0 => {
                            *sessions -= 1;
                            self.close_session(ip);
                        }
                        _ => {}
                    }
                }
                continuing = header[3] == b'C';
            }
            if to.write_all(&chunk).await.is_err() {
                return false;
            }
        }
    }
}

/// Passes the server's bytes on as they come.
async fn answers(from: &mut OwnedReadHalf, to: &mut OwnedWriteHalf) {
    let mut buf = vec![0u8; 64 << 10];
    loop {
        match from.read(&mut buf).await {
            Ok(0) | Err(_) => return,
            Ok(n) => {
                if to.write_all(&buf[..n]).await.is_err() {
                    return;
                }
            }
        }
    }
}

/// Answers a connection with an OPC UA Error message (`status` and why) and closes it.
async fn refuse(mut client: TcpStream, status: StatusCode, why: &str) {
    send_error(&mut client, status, why).await;
}

/// Sends an OPC UA Error message (Part 6, 7.1.2.5: `status` and why) and ends the sending side,
/// within a second.
async fn send_error(to: &mut (impl AsyncWrite + Unpin), status: StatusCode, why: &str) {
    let reason = why.as_bytes();
    let size = 8 + 4 + 4 + reason.len();
    let mut message = Vec::with_capacity(size);
    message.extend_from_slice(b"ERRF");
    message.extend_from_slice(&(size as u32).to_le_bytes());
    message.extend_from_slice(&status.bits().to_le_bytes());
    message.extend_from_slice(&(reason.len() as i32).to_le_bytes());
    message.extend_from_slice(reason);
    let send = async {
        let _ = to.write_all(&message).await;
        let _ = to.shutdown().await;
    };
    let _ = tokio::time::timeout(Duration::from_secs(1), send).await;
}

/// An IPv4 client seen on an IPv6 socket is the IPv4 address.
fn canonical(ip: IpAddr) -> IpAddr {
    match ip {
        IpAddr::V6(v6) => v6.to_ipv4_mapped().map_or(ip, IpAddr::V4),
        v4 => v4,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn gate() -> Gate {
        Gate::new(GateLimits {
            connections: 5,
            connections_per_address: 3,
            sessions_per_address: 2,
            session_hold: Duration::from_millis(200),
        })
    }

    #[test]
    fn an_address_holds_its_share_of_connections_and_all_hold_the_total() {
        let g = gate();
        let (a, b, c): (IpAddr, IpAddr, IpAddr) = (
            "127.0.0.1".parse().unwrap(),
            "127.0.0.2".parse().unwrap(),
            "127.0.0.3".parse().unwrap(),
        );
        for _ in 0..3 {
            g.admit(a).unwrap();
        }
        assert!(g.admit(a).unwrap_err().contains("this address"));
        g.admit(b).unwrap();
        g.admit(b).unwrap();
        assert!(g.admit(c).unwrap_err().contains("most connections"));
        g.leave(a, 0);
        g.admit(c).unwrap();
    }

    #[test]
    fn sessions_count_while_open_and_for_the_hold_after_their_connection_ends() {
        let g = gate();
        let a: IpAddr = "10.1.2.3".parse().unwrap();
        g.admit(a).unwrap();
        assert!(g.open_session(a) && g.open_session(a));
        assert!(!g.open_session(a), "a third session from one address");
        g.close_session(a);
        assert!(g.open_session(a));
        g.leave(a, 2);
        assert_eq!(g.sessions_of(a), 2, "held after the connection ended");
        std::thread::sleep(Duration::from_millis(250));
        assert_eq!(g.sessions_of(a), 0);
        assert!(g.peers().is_empty() || g.sessions_of(a) == 0);
    }

    #[test]
    fn ipv4_mapped_addresses_are_their_ipv4_address() {
        let mapped: IpAddr = "::ffff:127.0.0.2".parse().unwrap();
        assert_eq!(canonical(mapped), "127.0.0.2".parse::<IpAddr>().unwrap());
    }
}
