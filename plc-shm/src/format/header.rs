//! The segment's header: written once by its owner before it serves the segment, checked whole
//! by every tool that attaches (every number in it comes from another process), and watched
//! while attached (closed by its owner, or replaced).

use super::alarm_descriptor::AlarmDescriptor;
use super::alarm_table::AlarmTable;
use super::bytes;
use super::descriptor::LayoutDescriptor;
use super::layout::*;
use super::status::{RunState, Status};
use crate::error::ShmError;
use crate::limits::{MAX_DESCRIPTOR, MAX_IMAGE};
use crate::sys::base::Base;

/// What a tool learns from a segment's header.
pub struct Header {
    /// Where everything is.
    pub off: Offsets,
    /// The variables.
    pub desc: LayoutDescriptor,
    /// The owner's generation.
    pub generation: u64,
    /// The alarm states, after the descriptor.
    pub alarms: AlarmTable,
}

/// Writes the header and the descriptor (the owner, once, before it serves the segment).
pub fn write(base: &Base, json: &[u8], hash: u64, off: &Offsets, generation: u64) {
    base.store(H_VERSION, plc_rules::layout::FORMAT_VERSION as u64);
    base.store(H_LAYOUT_HASH, hash);
    base.store(H_IMAGE_SIZE, off.image_size as u64);
    base.store(H_GENERATION, generation);
    base.store(H_DESC_OFFSET, off.descriptor as u64);
    base.store(H_DESC_LEN, json.len() as u64);
    base.store(S_PID, std::process::id() as u64);
    base.store(S_STATE, RunState::Starting as u64);
    bytes::store(base, off.descriptor, json);
}

/// Checks the header of segment `name` as a tool finds it, and reads its descriptor: the
/// magic, the format version, sizes that fit together and the mapping, a descriptor that
/// parses and matches the layout hash.
pub fn read(base: &Base, name: String) -> Result<Header, ShmError> {
    if base.len() < IMAGE {
        return Err(ShmError::TooSmall {
            name,
            len: base.len(),
            needed: IMAGE,
        });
    }
    // The owner serves its segment only once its header is complete.
    let magic = base.load(H_MAGIC);
    if magic == MAGIC_CLOSED {
        return Err(closed(base, name));
    }
    if magic != MAGIC {
        return Err(ShmError::Format {
            name,
            found: format!("magic {magic:016x}"),
        });
    }
    let version = base.load(H_VERSION);
    if version != plc_rules::layout::FORMAT_VERSION as u64 {
        return Err(ShmError::Format {
            name,
            found: format!("format version {version}"),
        });
    }
    // Every number below comes from another process: checked arithmetic only.
    let header_image_size = base.load(H_IMAGE_SIZE);
    let off = usize::try_from(header_image_size)
        .ok()
        .and_then(Offsets::checked)
        .ok_or_else(|| ShmError::Corrupt {
            name: name.clone(),
            why: format!("its header gives an image size of {header_image_size} bytes"),
        })?;
    let image_size = off.image_size;
    if image_size > MAX_IMAGE {
        return Err(ShmError::Corrupt {
            name,
            why: format!(
                "its header gives an image of {image_size} bytes, more than the {MAX_IMAGE} \
                 a tool reads"
            ),
        });
    }
    let (d_off, d_len) = (base.load(H_DESC_OFFSET), base.load(H_DESC_LEN));
    if d_len > MAX_DESCRIPTOR as u64 {
        return Err(ShmError::Corrupt {
            name,
            why: format!(
                "its header gives a descriptor of {d_len} bytes, more than the \
                 {MAX_DESCRIPTOR} a tool reads"
            ),
        });
    }
    let d_end = d_off.saturating_add(d_len);
    let needed = usize::try_from(d_end)
        .unwrap_or(usize::MAX)
        .max(off.descriptor);
    if base.len() < needed {
        return Err(ShmError::TooSmall {
            name,
            len: base.len(),
            needed,
        });
    }
    if d_off != off.descriptor as u64 {
        return Err(ShmError::Corrupt {
            name,
            why: format!(
                "its header puts the descriptor at byte {d_off}, not {}",
                off.descriptor
            ),
        });
    }
    let mut json = vec![0u8; d_len as usize];
    bytes::load(base, off.descriptor, &mut json);
    let desc: LayoutDescriptor = serde_json::from_slice(&json).map_err(|e| ShmError::Corrupt {
        name: name.clone(),
        why: format!("its descriptor is not valid JSON: {e}"),
    })?;
    let hash = base.load(H_LAYOUT_HASH);
    if desc.computed_hash() != hash || desc.layout_hash != hash {
        return Err(ShmError::Corrupt {
            name,
            why: "the descriptor does not match the layout hash".into(),
        });
    }
    if desc.image_size != image_size {
        return Err(ShmError::Corrupt {
            name,
            why: format!(
                "the descriptor gives an image of {} bytes, the header {image_size}",
                desc.image_size
            ),
        });
    }
    desc.check_variables()
        .and_then(|()| AlarmDescriptor::check(&desc.alarms, desc.variables.len()))
        .map_err(|why| ShmError::Corrupt {
            name: name.clone(),
            why,
        })?;
    // The descriptor's end was checked against the mapping above.
    let alarms = AlarmTable::after(d_end as usize, desc.alarms.len());
    match alarms.end() {
        Some(end) if end <= base.len() => {}
        end => {
            return Err(ShmError::TooSmall {
                name,
                len: base.len(),
                needed: end.unwrap_or(usize::MAX),
            });
        }
    }
    Ok(Header {
        off,
        desc,
        generation: base.load(H_GENERATION),
        alarms,
    })
}

/// Errors if the owner of segment `name` stopped ([`ShmError::Closed`]) or the segment was
/// replaced since generation `generation` was attached ([`ShmError::Replaced`]).
pub fn check_current(base: &Base, generation: u64, name: &str) -> Result<(), ShmError> {
    match base.load(H_MAGIC) {
        MAGIC if base.load(H_GENERATION) == generation => Ok(()),
        MAGIC => Err(ShmError::Replaced(name.to_string())),
        MAGIC_CLOSED => Err(closed(base, name.to_string())),
        _ => Err(ShmError::Corrupt {
            name: name.to_string(),
            why: "its header changed under this tool".into(),
        }),
    }
}

/// The error of a segment whose owner stopped, saying whether it stopped because it faulted.
pub fn closed(base: &Base, name: String) -> ShmError {
    let faulted = Status::read_run_state(base) == RunState::Faulted;
    ShmError::Closed { name, faulted }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_changed_generation_is_a_replaced_segment_and_a_stop_a_closed_one() {
        let mut words = vec![0u64; STATUS / 8 + 16];
        // SAFETY: the vector's u64s are 8-byte aligned, `len` bytes long, and outlive `base`.
        let base = unsafe { Base::new(words.as_mut_ptr().cast(), words.len() * 8) };
        base.store(H_MAGIC, MAGIC);
        base.store(H_GENERATION, 7);
        assert_eq!(check_current(&base, 7, "press"), Ok(()));
        assert_eq!(
            check_current(&base, 6, "press"),
            Err(ShmError::Replaced("press".into()))
        );
        base.store(H_MAGIC, MAGIC_CLOSED);
        assert!(matches!(
            check_current(&base, 7, "press"),
            Err(ShmError::Closed { faulted: false, .. })
        ));
        base.store(H_MAGIC, 1);
        assert!(matches!(
            check_current(&base, 7, "press"),
            Err(ShmError::Corrupt { .. })
        ));
    }
}
