//! Any bytes: the reader answers without a panic, takes nothing damaged for a record, and a
//! file cut anywhere reads as the whole lines before the cut.

use super::super::read::Contents;
use super::file_of;
use proptest::prelude::*;

proptest! {
    #[test]
    fn random_bytes_never_panic(bytes in proptest::collection::vec(any::<u8>(), 0..4096)) {
        let c = Contents::from_bytes(&bytes, 10);
        prop_assert!(c.records().len() <= 10);
    }

    #[test]
    fn random_lines_of_almost_json_never_panic(
        lines in proptest::collection::vec("[0-9a-f]{8} \\{[\"a-z:,0-9{}\\[\\]. -]{0,80}\\}", 0..50)
    ) {
        let text = lines.join("\n");
        let _ = Contents::from_bytes(text.as_bytes(), 100);
    }

    /// A file cut at any byte: the records before the cut, nothing else, and the rest torn.
    #[test]
    fn a_cut_anywhere_reads_the_whole_lines_before_it(cut in 0usize..2_000) {
        let whole = file_of(30);
        let cut = cut.min(whole.len());
        let c = Contents::from_bytes(&whole[..cut], 100);
        let whole_lines = whole[..cut].iter().filter(|&&b| b == b'\n').count();
        prop_assert_eq!(c.records().len(), whole_lines);
        prop_assert!(c.damage().is_empty());
        prop_assert_eq!(c.torn().is_some(), cut > 0 && whole[cut - 1] != b'\n');
    }

    /// Bytes changed at random: every record read is one that was written, unchanged.
    #[test]
    fn changed_bytes_never_make_a_garbled_record(
        changes in proptest::collection::vec((any::<prop::sample::Index>(), any::<u8>()), 1..20)
    ) {
        let whole = file_of(40);
        let good = Contents::from_bytes(&whole, 100);
        let mut bytes = whole.clone();
        for (at, b) in changes {
            let i = at.index(bytes.len());
            bytes[i] = b;
        }
        let c = Contents::from_bytes(&bytes, 100);
        for r in c.records() {
            prop_assert!(good.records().contains(r), "{:?} was never written", r);
        }
    }
}
