//! Checks that bytes are a shared library for this machine whose every loadable segment lies
//! inside them. The dynamic loader maps segments from the file: one that reaches past a
//! truncated file's end is memory that faults (`SIGBUS`) when the code touches it, killing
//! the process that loaded it. Only the ELF header and the program headers are read, each
//! through checked offsets.

/// `e_type` of a shared object.
const ET_DYN: u16 = 3;
/// `p_type` of a loadable segment.
const PT_LOAD: u32 = 1;
/// `p_type` of the dynamic section.
const PT_DYNAMIC: u32 = 2;
/// The ELF header of a 64-bit file.
const EHDR_SIZE: usize = 64;
/// One program header of a 64-bit file.
const PHDR_SIZE: usize = 56;
/// More program headers than any linker writes for a library (a few dozen): a bound on work.
const MAX_PHDRS: usize = 512;

/// The ELF machine code of this host.
const HOST_MACHINE: u16 = if cfg!(target_arch = "x86_64") {
    62
} else if cfg!(target_arch = "aarch64") {
    183
} else if cfg!(target_arch = "riscv64") {
    243
} else {
    0
};

/// What is wrong with a file that is not a loadable library here.
#[derive(Debug, PartialEq, Eq)]
pub enum ElfIssue {
    /// Not an ELF shared library for this machine.
    NotALibrary(String),
    /// A segment or a header lies outside the file.
    Damaged(String),
}

fn u16_at(b: &[u8], at: usize) -> Option<u16> {
    Some(u16::from_le_bytes(b.get(at..at + 2)?.try_into().ok()?))
}
fn u32_at(b: &[u8], at: usize) -> Option<u32> {
    Some(u32::from_le_bytes(b.get(at..at + 4)?.try_into().ok()?))
}
fn u64_at(b: &[u8], at: usize) -> Option<u64> {
    Some(u64::from_le_bytes(b.get(at..at + 8)?.try_into().ok()?))
}

/// Checks `bytes` as described in the module's documentation.
pub fn check(bytes: &[u8]) -> Result<(), ElfIssue> {
    let not = |why: &str| ElfIssue::NotALibrary(why.into());
    if bytes.len() < 4 || &bytes[..4] != b"\x7fELF" {
        return Err(not("it is not an ELF file (no `\\x7fELF` at its start)"));
    }
    if bytes.len() < EHDR_SIZE {
        return Err(ElfIssue::Damaged(format!(
            "it ends after {} bytes, inside its ELF header",
            bytes.len()
        )));
    }
    if bytes[4] != 2 || bytes[5] != 1 || cfg!(not(target_endian = "little")) {
        return Err(not("it is not a 64-bit little-endian ELF file"));
    }
    let e_type = u16_at(bytes, 16).unwrap_or(0);
    let machine = u16_at(bytes, 18).unwrap_or(0);
    if e_type != ET_DYN {
        return Err(not(&format!(
            "it is an ELF file of type {e_type}, not a shared library (type {ET_DYN})"
        )));
    }
    if machine != HOST_MACHINE {
        return Err(not(&format!(
            "it is built for ELF machine {machine}, this host is machine {HOST_MACHINE}"
        )));
    }
    let phoff = u64_at(bytes, 32).unwrap_or(u64::MAX);
    let phentsize = usize::from(u16_at(bytes, 54).unwrap_or(0));
    let phnum = usize::from(u16_at(bytes, 56).unwrap_or(0));
    if phentsize != PHDR_SIZE || phnum == 0 || phnum > MAX_PHDRS {
        return Err(not(&format!(
            "its program header table ({phnum} entries of {phentsize} bytes) is not a \
             library's"
        )));
    }
    let table_end = usize::try_from(phoff)
        .ok()
        .and_then(|o| o.checked_add(phnum * PHDR_SIZE));
    let Some(table_start) = table_end
        .filter(|&end| end <= bytes.len())
        .map(|end| end - phnum * PHDR_SIZE)
    else {
        return Err(ElfIssue::Damaged(format!(
            "its program header table at byte {phoff} lies beyond its {} bytes",
            bytes.len()
        )));
    };
    let mut loads = 0;
    for i in 0..phnum {
        let h = table_start + i * PHDR_SIZE;
        let p_type = u32_at(bytes, h).unwrap_or(0);
        if p_type != PT_LOAD && p_type != PT_DYNAMIC {
            continue;
        }
        let offset = u64_at(bytes, h + 8).unwrap_or(u64::MAX);
        let filesz = u64_at(bytes, h + 32).unwrap_or(u64::MAX);
        let memsz = u64_at(bytes, h + 40).unwrap_or(0);
        let end = offset.checked_add(filesz);
        if end.is_none_or(|end| end > bytes.len() as u64) {
            return Err(ElfIssue::Damaged(format!(
                "its segment {i} (bytes {offset}..{}) lies beyond the file's {} bytes",
                end.map_or("overflow".into(), |e| e.to_string()),
                bytes.len()
            )));
        }
        if p_type == PT_LOAD {
            if filesz > memsz {
                return Err(ElfIssue::Damaged(format!(
                    "its segment {i} has more bytes in the file ({filesz}) than in memory \
                     ({memsz})"
                )));
            }
            loads += 1;
        }
    }
    if loads == 0 {
        return Err(not("it has no loadable segment"));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A minimal header for this machine with one loadable segment of `filesz` bytes at 120.
    fn library(total: usize, filesz: u64) -> Vec<u8> {
        let mut b = vec![0u8; total];
        b[..4].copy_from_slice(b"\x7fELF");
        b[4] = 2;
        b[5] = 1;
        b[16..18].copy_from_slice(&ET_DYN.to_le_bytes());
        b[18..20].copy_from_slice(&HOST_MACHINE.to_le_bytes());
        b[32..40].copy_from_slice(&64u64.to_le_bytes());
        b[54..56].copy_from_slice(&(PHDR_SIZE as u16).to_le_bytes());
        b[56..58].copy_from_slice(&1u16.to_le_bytes());
        b[64..68].copy_from_slice(&PT_LOAD.to_le_bytes());
        b[72..80].copy_from_slice(&120u64.to_le_bytes());
        b[96..104].copy_from_slice(&filesz.to_le_bytes());
        b[104..112].copy_from_slice(&filesz.to_le_bytes());
        b
    }

    #[test]
    fn a_whole_library_passes() {
        assert_eq!(check(&library(200, 80)), Ok(()));
    }

    #[test]
    fn a_segment_past_the_end_is_damage() {
        let Err(ElfIssue::Damaged(why)) = check(&library(199, 80)) else {
            panic!("a truncated library passed")
        };
        assert!(
            why.contains("segment 0 (bytes 120..200)") && why.contains("199"),
            "{why}"
        );
    }

    #[test]
    fn text_and_headers_cut_short_are_refused() {
        assert!(matches!(check(b"hello"), Err(ElfIssue::NotALibrary(_))));
        assert!(matches!(
            check(&library(200, 80)[..40]),
            Err(ElfIssue::Damaged(_))
        ));
        assert!(matches!(
            check(&library(200, 80)[..100]),
            Err(ElfIssue::Damaged(_))
        ));
    }

    #[test]
    fn an_executable_is_not_a_library() {
        let mut b = library(200, 80);
        b[16] = 2;
        let Err(ElfIssue::NotALibrary(why)) = check(&b) else {
            panic!()
        };
        assert!(why.contains("type 2"), "{why}");
    }

    #[test]
    fn overflowing_offsets_are_refused_without_panicking() {
        let mut b = library(200, 80);
        b[72..80].copy_from_slice(&u64::MAX.to_le_bytes());
        assert!(matches!(check(&b), Err(ElfIssue::Damaged(_))));
        let mut b = library(200, 80);
        b[32..40].copy_from_slice(&u64::MAX.to_le_bytes());
        assert!(matches!(check(&b), Err(ElfIssue::Damaged(_))));
    }

    proptest::proptest! {
        #[test]
        fn any_bytes_give_an_answer(bytes in proptest::collection::vec(proptest::num::u8::ANY, 0..400)) {
            let _ = check(&bytes);
        }

        #[test]
        fn any_cut_of_a_library_is_refused_or_whole(cut in 0usize..200) {
            let lib = library(200, 80);
            let r = check(&lib[..cut]);
            proptest::prop_assert!(r.is_err());
        }
    }
}
