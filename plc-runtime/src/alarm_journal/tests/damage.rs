//! Damaged lines and a torn end: reported with where they are, the other records read.

use super::super::frame::Item;
use super::super::read::Contents;
use super::{file_of, line};

#[test]
fn a_byte_flipped_in_the_middle_damages_one_record_the_others_read() {
    let mut bytes = file_of(100);
    let line_len = bytes.len() / 100;
    // Lines differ in length by a few digits: find where each starts.
    let starts: Vec<usize> = std::iter::once(0)
        .chain(
            bytes
                .iter()
                .enumerate()
                .filter(|(_, b)| **b == b'\n')
                .map(|(i, _)| i + 1),
        )
        .collect();
    let at = starts[49] + line_len / 2;
    bytes[at] ^= 0x20;
    let c = Contents::from_bytes(&bytes, 10_000);
    assert_eq!(c.records().len(), 99);
    assert!(c.records().iter().all(|r| r.seq != 50));
    assert_eq!(c.damage().len(), 1);
    let d = &c.damage()[0];
    assert_eq!((d.line, d.offset), (50, starts[49] as u64));
    assert!(d.why.contains("checksum"), "{}", d.why);
    assert_eq!(d.after, Some(49));
    assert!(d.to_string().starts_with("line 50 (byte "), "{d}");
    assert!(
        d.to_string().contains("after record #49) is damaged"),
        "{d}"
    );
    assert!(c.torn().is_none());
    assert_eq!(c.next_seq(), 101);
}

#[test]
fn a_flipped_newline_damages_the_two_lines_it_joined_and_no_more() {
    let mut bytes = file_of(10);
    let nl = bytes.iter().position(|&b| b == b'\n').unwrap();
    bytes[nl] = b'x';
    let c = Contents::from_bytes(&bytes, 100);
    assert_eq!(c.records().len(), 8);
    assert_eq!(c.damage().len(), 1);
    assert_eq!(c.records()[0].seq, 3);
}

#[test]
fn a_torn_last_record_is_reported_never_read() {
    let whole = file_of(5);
    let last_start = whole[..whole.len() - 1]
        .iter()
        .rposition(|&b| b == b'\n')
        .unwrap()
        + 1;
    // Every cut inside the last line, even one that leaves its JSON complete but no newline.
    for cut in last_start + 1..whole.len() {
        let c = Contents::from_bytes(&whole[..cut], 100);
        assert_eq!(c.records().len(), 4, "cut at {cut}");
        assert!(c.damage().is_empty());
        let torn = c.torn().expect("torn");
        assert_eq!(
            (torn.offset, torn.len),
            (last_start as u64, cut - last_start)
        );
    }
    assert!(Contents::from_bytes(&whole, 100).torn().is_none());
}

#[test]
fn a_header_only_counts_as_the_first_line() {
    let mut bytes = line(Item::Header { dropped: 7 });
    bytes.extend(file_of(2));
    bytes.extend(line(Item::Header { dropped: 1_000 }));
    let c = Contents::from_bytes(&bytes, 100);
    assert_eq!(c.dropped(), 7);
    assert_eq!(c.damage().len(), 1);
    assert_eq!(c.damage()[0].line, 4);
}

#[test]
fn records_past_the_capacity_count_as_dropped() {
    let mut bytes = line(Item::Header { dropped: 3 });
    bytes.extend(file_of(30));
    let c = Contents::from_bytes(&bytes, 20);
    assert_eq!(c.records().len(), 20);
    assert_eq!(c.records()[0].seq, 11);
    assert_eq!(c.dropped(), 13);
    // The states still count every record in the file.
    assert_eq!(c.states().len(), 10);
}

#[test]
fn history_since_a_time() {
    let c = Contents::from_bytes(&file_of(10), 100);
    let seqs: Vec<u64> = c.history(Some(7)).map(|r| r.seq).collect();
    assert_eq!(seqs, [7, 8, 9, 10]);
    assert_eq!(c.history(None).count(), 10);
    assert_eq!(c.history(Some(11)).count(), 0);
}

#[test]
fn history_since_a_time_when_the_clock_was_set_back() {
    use super::super::frame::Item;
    use super::raised;
    let mut bytes = Vec::new();
    for (seq, t) in [(1, 100), (2, 50), (3, 120)] {
        let mut r = raised(seq, "door");
        r.time_ns = t;
        bytes.extend(line(Item::Record(r)));
    }
    let c = Contents::from_bytes(&bytes, 10);
    let seqs: Vec<u64> = c.history(Some(90)).map(|r| r.seq).collect();
    assert_eq!(seqs, [1, 3]);
}
