//! The standard function blocks of IEC 61131-3 as a variable list names them (`"type": "TON"`):
//! the types of `plc_core::fb`, which the list uses without declaring them and the generated
//! code names by path.

use plc_core::{PlcType, VarInfo, fb};

/// One standard function block.
pub struct StandardBlock {
    /// Its IEC name, as a list writes it (`TON`).
    pub name: &'static str,
    /// Its Rust type, as the generated code names it.
    pub rust: &'static str,
    /// Its members (inputs, outputs and state), in image order.
    pub members: &'static [VarInfo],
}

fn block<T: PlcType>(rust: &'static str) -> StandardBlock {
    StandardBlock {
        // Every block of `plc_core::fb` is a PlcStruct with its IEC name.
        name: T::TYPE_NAME.unwrap_or(rust),
        rust,
        members: T::MEMBERS,
    }
}

/// Every standard function block.
pub fn blocks() -> [StandardBlock; 10] {
    [
        block::<fb::Ton>("plc_core::fb::Ton"),
        block::<fb::Tof>("plc_core::fb::Tof"),
        block::<fb::Tp>("plc_core::fb::Tp"),
        block::<fb::RTrig>("plc_core::fb::RTrig"),
        block::<fb::FTrig>("plc_core::fb::FTrig"),
        block::<fb::Ctu>("plc_core::fb::Ctu"),
        block::<fb::Ctd>("plc_core::fb::Ctd"),
        block::<fb::Ctud>("plc_core::fb::Ctud"),
        block::<fb::Sr>("plc_core::fb::Sr"),
        block::<fb::Rs>("plc_core::fb::Rs"),
    ]
}

/// Whether `name` is a standard function block's, in any case (a list cannot declare a type
/// of that name: `"type": "TON"` names the standard one).
pub fn is_standard(name: &str) -> bool {
    blocks().iter().any(|b| b.name.eq_ignore_ascii_case(name))
}

/// The standard block named `name` exactly whose members are `members` (by name, in order): how
/// an export tells a standard block from a user's structure given the same name.
#[cfg_attr(not(feature = "export"), allow(dead_code))]
pub fn standard_with_members<'a>(
    name: &str,
    members: impl ExactSizeIterator<Item = &'a str>,
) -> Option<StandardBlock> {
    let members: Vec<&str> = members.collect();
    blocks().into_iter().find(|b| {
        b.name == name
            && b.members.len() == members.len()
            && b.members.iter().zip(&members).all(|(m, n)| m.name == *n)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The bytes of a block's image: the importer sizes a list's image from the members.
    fn image_bytes<T: PlcType>() -> usize {
        size_of::<T::Repr>()
    }

    #[test]
    fn each_block_has_its_iec_name_and_an_image_of_its_basic_members() {
        let names: Vec<&str> = blocks().iter().map(|b| b.name).collect();
        assert_eq!(
            names,
            [
                "TON", "TOF", "TP", "R_TRIG", "F_TRIG", "CTU", "CTD", "CTUD", "SR", "RS"
            ]
        );
        let sizes = [
            image_bytes::<fb::Ton>(),
            image_bytes::<fb::Tof>(),
            image_bytes::<fb::Tp>(),
            image_bytes::<fb::RTrig>(),
            image_bytes::<fb::FTrig>(),
            image_bytes::<fb::Ctu>(),
            image_bytes::<fb::Ctd>(),
            image_bytes::<fb::Ctud>(),
            image_bytes::<fb::Sr>(),
            image_bytes::<fb::Rs>(),
        ];
        for (b, size) in blocks().iter().zip(sizes) {
            let members: usize = b.members.iter().map(|m| m.iec_type.image_size()).sum();
            assert_eq!(members, size, "{}", b.name);
            let basic = |m: &VarInfo| m.members().is_empty() && m.dims.is_empty();
            assert!(b.members.iter().all(basic), "{}", b.name);
        }
        assert!(is_standard("ton") && !is_standard("Axis"));
    }
}
