//! SII EEPROM images: parsing the word dumps in `data/`, and the ESC's EEPROM interface
//! (registers 0x0500-0x050F) as ethercrab drives it.

/// Words in an image (2 KiB, as the real dumps; word 0x3E = 0x000F).
pub const WORDS: usize = 1024;

/// Parses `WORDADDR: w0 w1 ... w7` lines. `????` (not captured) reads as 0 before the End
/// category and as 0xFFFF (erased EEPROM) after it.
pub fn parse(text: &str) -> Vec<u16> {
    let mut words = vec![None; WORDS];
    for line in text.lines() {
        let Some((addr, rest)) = line.split_once(':') else {
            continue;
        };
        let Ok(addr) = usize::from_str_radix(addr.trim(), 16) else {
            continue;
        };
        for (i, w) in rest.split_whitespace().enumerate() {
            if let (Some(slot), Ok(v)) = (words.get_mut(addr + i), u16::from_str_radix(w, 16)) {
                *slot = Some(v);
            }
        }
    }
    let end = end_of_categories(&words);
    let mut out: Vec<u16> = words
        .iter()
        .enumerate()
        .map(|(i, w)| w.unwrap_or(if i < end { 0 } else { 0xFFFF }))
        .collect();
    if out[0x3E] == 0 {
        out[0x3E] = 0x000F;
    }
    out
}

/// The word after the End category (0xFFFF header), following the category chain from 0x40.
fn end_of_categories(words: &[Option<u16>]) -> usize {
    let mut at = 0x40;
    while at + 1 < words.len() {
        match (words[at], words[at + 1]) {
            (Some(0xFFFF), _) => return at + 1,
            (Some(_), Some(len)) => at += 2 + len as usize,
            _ => return at,
        }
    }
    words.len()
}

/// Vendor, product, revision and serial (words 0x08-0x0F).
pub fn identity(words: &[u16]) -> (u32, u32, u32) {
    let dword = |w: usize| words[w] as u32 | (words[w + 1] as u32) << 16;
    (dword(0x08), dword(0x0A), dword(0x0C))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_ek1100_image_holds_its_identity() {
        let w = parse(include_str!("../data/sii-EK1100-full.txt"));
        assert_eq!(identity(&w), (2, 0x044C_2C52, 0x0012_0000));
        assert_eq!(w[0x3E], 0x000F);
    }

    #[test]
    fn missing_words_read_as_zero_then_erased() {
        let w = parse(include_str!("../data/sii-EL1004.txt"));
        assert_eq!(identity(&w), (2, 0x03EC_3052, 0x0013_0000));
        assert_eq!(w[0x1A], 0);
        assert_eq!(w[0xC2], 0xFFFF);
        assert_eq!(w[0x200], 0xFFFF);
    }
}
