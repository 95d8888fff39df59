//! Start-up SDOs: the CoE objects a device is configured through (a filter, a presentation),
//! written in PRE-OP in the order the bus description lists them and each read back, so a
//! device that took another value, or refused one, stops the bring-up with an error naming the
//! device, the object and the abort code.

use super::config::DeviceConfig;
use super::error::EtherCatError;
use ethercrab::SubDeviceRef;
use ethercrab::error::Error as CrabError;
use std::ops::Deref;

/// Writes and checks every start-up SDO of the device at `position`.
pub(super) async fn write<S: Deref<Target = ethercrab::SubDevice>>(
    sd: &SubDeviceRef<'_, S>,
    position: usize,
    device: &DeviceConfig,
) -> Result<(), EtherCatError> {
    for sdo in &device.startup {
        let fail = |problem: String| EtherCatError::Startup {
            device: device.name.clone(),
            position,
            sdo: *sdo,
            problem,
        };
        // The description's checks make these fit; a value that does not is refused there.
        let (Ok(index), Ok(sub), Some(raw)) = (
            u16::try_from(sdo.index),
            u8::try_from(sdo.subindex),
            sdo.raw(),
        ) else {
            return Err(fail("the object or value does not fit its width".into()));
        };
        let read_back = write_one(sd, index, sub, raw, sdo.bits)
            .await
            .map_err(|e| fail(format!("refused: {e}")))?;
        if read_back != raw {
            return Err(fail(format!(
                "written as {raw:#x} but read back as {read_back:#x}: the device does not keep \
                 this value"
            )));
        }
    }
    Ok(())
}

async fn write_one<S: Deref<Target = ethercrab::SubDevice>>(
    sd: &SubDeviceRef<'_, S>,
    index: u16,
    sub: u8,
    raw: u32,
    bits: u32,
) -> Result<u32, CrabError> {
    // `raw` fits `bits` (StartupSdo::raw), so the narrowing keeps every bit.
    Ok(match bits {
        8 => {
            sd.sdo_write(index, sub, raw as u8).await?;
            u32::from(sd.sdo_read::<u8>(index, sub).await?)
        }
        16 => {
            sd.sdo_write(index, sub, raw as u16).await?;
            u32::from(sd.sdo_read::<u16>(index, sub).await?)
        }
        _ => {
            sd.sdo_write(index, sub, raw).await?;
            sd.sdo_read::<u32>(index, sub).await?
        }
    })
}

#[cfg(test)]
mod tests {
    use plc_rules::bus::StartupSdo;

    #[test]
    fn values_are_sent_as_their_width_and_refused_beyond_it() {
        let sdo = |value, bits| StartupSdo {
            index: 0x8000,
            subindex: 0x15,
            value,
            bits,
        };
        assert_eq!(sdo(1, 16).raw(), Some(1));
        assert_eq!(sdo(-1, 16).raw(), Some(0xFFFF));
        assert_eq!(sdo(255, 8).raw(), Some(255));
        assert_eq!(sdo(256, 8).raw(), None);
        assert_eq!(sdo(-129, 8).raw(), None);
        assert_eq!(sdo(1, 12).raw(), None);
        assert_eq!(sdo(0xFFFF_FFFF, 32).raw(), Some(0xFFFF_FFFF));
        assert_eq!(sdo(1, 16).to_string(), "0x8000:15");
    }
}
