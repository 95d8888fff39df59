//! A minimal pcapng reader: enhanced and simple packet blocks with their timestamps, enough
//! for the Wireshark captures in `data/` (little-endian, one interface).

/// One captured packet: time in nanoseconds and the Ethernet frame.
pub struct Packet {
    pub time_ns: u64,
    pub data: Vec<u8>,
}

fn u16_at(b: &[u8], at: usize) -> u16 {
    u16::from_le_bytes([b[at], b[at + 1]])
}

fn u32_at(b: &[u8], at: usize) -> u32 {
    u32::from_le_bytes([b[at], b[at + 1], b[at + 2], b[at + 3]])
}

/// Nanoseconds per timestamp unit from an interface description block's options
/// (`if_tsresol`, option 9; default microseconds).
fn resolution_ns(block: &[u8]) -> u64 {
    let mut at = 16;
    while at + 4 <= block.len() - 4 {
        let (code, len) = (u16_at(block, at), u16_at(block, at + 2) as usize);
        if code == 0 {
            break;
        }
        if code == 9 && len == 1 {
            let v = block[at + 4];
            let per_second: f64 = if v & 0x80 == 0 {
                10f64.powi(v as i32)
            } else {
                2f64.powi((v & 0x7F) as i32)
            };
            return (1e9 / per_second).max(1.0) as u64;
        }
        at += 4 + len.div_ceil(4) * 4;
    }
    1_000
}

/// Every packet of a pcapng capture, in order.
pub fn packets(file: &[u8]) -> Vec<Packet> {
    let mut out = Vec::new();
    let mut unit_ns = 1_000;
    let mut at = 0;
    while at + 12 <= file.len() {
        let kind = u32_at(file, at);
        let len = u32_at(file, at + 4) as usize;
        if len < 12 || at + len > file.len() {
            break;
        }
        let block = &file[at..at + len];
        match kind {
            1 => unit_ns = resolution_ns(block),
            6 => {
                let ts = (u32_at(block, 12) as u64) << 32 | u32_at(block, 16) as u64;
                let captured = u32_at(block, 20) as usize;
                out.push(Packet {
                    time_ns: ts * unit_ns,
                    data: block[28..28 + captured].to_vec(),
                });
            }
            3 => {
                let original = u32_at(block, 8) as usize;
                out.push(Packet {
                    time_ns: 0,
                    data: block[12..(12 + original).min(len - 4)].to_vec(),
                });
            }
            _ => {}
        }
        at += len;
    }
    out
}
