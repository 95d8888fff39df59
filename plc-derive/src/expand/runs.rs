//! Runs: stretches of fields that repeat one block of field types, converted by one loop
//! whose code does not grow with the fields.
//!
//! Straight-line conversions cost a few bytes of machine code per variable; a 10,000-variable
//! struct's `load_image`, `store_image` and bit moves come to about 220 KB, run once per cycle
//! against a 32 KiB instruction cache, and the cycle stops growing linearly (docs/benchmarks-history.md,
//! "Linear growth"). A run is converted in a loop over its repetitions instead. Where the
//! fields of a run are in the image is known (one after the other); where they are in the
//! struct only the compiler knows (a plain struct's layout is its choice), so each run carries
//! its fields' `offset_of!` in a `const` and `run_steps` checks, at compile time, that every
//! column steps evenly: then the loop computes the addresses (and the compiler can vectorise
//! it), otherwise it reads them from that table. Either way it is the same conversion as the
//! straight-line code, `PlcType::from_repr` / `to_repr` of the field's own type.

use crate::ast::Container;
use quote::ToTokens;

/// Fields in a run below which straight-line code is kept: short runs are as fast either way
/// and the straight-line code is what small structs have always had. Measured with
/// `plc-bench` (docs/benchmarks-history.md, "Linear growth").
pub const MIN_RUN_FIELDS: usize = 64;

/// Mapped bools in a bit run below which straight-line bit moves are kept.
pub const MIN_BIT_RUN: usize = 64;

/// The longest block of field types a run may repeat: long enough for the groups a
/// declaration repeats (an axis's ten variables, a word's bools), short enough that finding
/// runs stays cheap.
const MAX_PERIOD: usize = 16;

/// Fields `start..start + period * reps`: a block of `period` field types repeated `reps`
/// (at least 2) times.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Run {
    pub start: usize,
    pub period: usize,
    pub reps: usize,
}

impl Run {
    pub fn len(&self) -> usize {
        self.period * self.reps
    }
}

/// One field converted on its own, or a run.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Piece {
    Field(usize),
    Run(Run),
}

/// What makes two fields the same type here: the same type tokens in the same struct name
/// the same type (an alias included), whatever it is; the loops rely on it to read and write
/// a run's fields through their offsets. Only a type macro could expand to different types
/// from the same tokens: such a field is in no run.
fn type_keys(c: &Container) -> Vec<String> {
    c.vars
        .iter()
        .enumerate()
        .map(|(i, v)| {
            let key = v.ty.to_token_stream().to_string();
            if key.contains('!') {
                format!("{i} !")
            } else {
                key
            }
        })
        .collect()
}

/// The fields in declaration order as single fields and runs of at least `min` fields.
pub fn pieces(c: &Container, min: usize) -> Vec<Piece> {
    split(&type_keys(c), min)
}

fn split(keys: &[String], min: usize) -> Vec<Piece> {
    let mut out = Vec::new();
    let mut i = 0;
    while i < keys.len() {
        match longest_run(keys, i) {
            Some(run) if run.len() >= min => {
                out.push(Piece::Run(run));
                i += run.len();
            }
            _ => {
                out.push(Piece::Field(i));
                i += 1;
            }
        }
    }
    out
}

/// The run starting at `start` that covers most fields (the shortest block among equals).
fn longest_run(keys: &[String], start: usize) -> Option<Run> {
    let mut best: Option<Run> = None;
    for period in 1..=MAX_PERIOD.min((keys.len() - start) / 2) {
        let block = &keys[start..start + period];
        let mut reps = 1;
        while keys[start + reps * period..]
            .get(..period)
            .is_some_and(|next| next == block)
        {
            reps += 1;
        }
        if reps >= 2 && best.is_none_or(|b| period * reps > b.len()) {
            best = Some(Run {
                start,
                period,
                reps,
            });
        }
    }
    best
}

/// Mapped bools `start..start + words * bits`, in declaration order: each group of `bits`
/// of them takes bits `first_bit..first_bit + bits` of one source word, the groups' words
/// being consecutive fields `source..source + words` of one type, and the bools all of one
/// type.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BitRun {
    pub start: usize,
    pub source: usize,
    pub first_bit: u32,
    pub bits: usize,
    pub words: usize,
}

impl BitRun {
    pub fn len(&self) -> usize {
        self.bits * self.words
    }
}

/// The mapped bools, in declaration order, as single bools and bit runs of at least `min`.
pub fn bit_pieces(c: &Container, min: usize) -> Vec<BitPiece> {
    let keys = type_keys(c);
    let mapped: Vec<Option<(usize, u8)>> = c.vars.iter().map(|v| v.mapped_to).collect();
    split_bits(&keys, &mapped, min)
}

/// A bit-mapped bool moved on its own, or a bit run.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum BitPiece {
    Bool(usize),
    Run(BitRun),
}

fn split_bits(keys: &[String], mapped: &[Option<(usize, u8)>], min: usize) -> Vec<BitPiece> {
    let mut out = Vec::new();
    let mut i = 0;
    while i < mapped.len() {
        let Some((source, bit)) = mapped[i] else {
            i += 1;
            continue;
        };
        match bit_run(keys, mapped, i, source, bit) {
            Some(run) if run.len() >= min => {
                out.push(BitPiece::Run(run));
                i += run.len();
            }
            _ => {
                out.push(BitPiece::Bool(i));
                i += 1;
            }
        }
    }
    out
}

/// The bit run starting at mapped bool `start`, if its first word's bools continue onto a
/// second word the same way.
fn bit_run(
    keys: &[String],
    mapped: &[Option<(usize, u8)>],
    start: usize,
    source: usize,
    first_bit: u8,
) -> Option<BitRun> {
    let same_bool = |i: usize| keys.get(i) == Some(&keys[start]);
    let at = |i: usize| mapped.get(i).copied().flatten();
    // The first word's group: consecutive bits of `source`.
    let mut bits = 0;
    while same_bool(start + bits)
        && at(start + bits) == Some((source, first_bit.checked_add(bits as u8)?))
    {
        bits += 1;
    }
    let group_fits = |w: usize| {
        let word = source + w;
        keys.get(word) == Some(&keys[source])
            && (0..bits).all(|j| {
                let i = start + w * bits + j;
                same_bool(i) && at(i) == Some((word, first_bit + j as u8))
            })
    };
    let mut words = 1;
    while group_fits(words) {
        words += 1;
    }
    (words >= 2).then_some(BitRun {
        start,
        source,
        first_bit: u32::from(first_bit),
        bits,
        words,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn keys(types: &str) -> Vec<String> {
        types.split(' ').map(str::to_string).collect()
    }

    #[test]
    fn a_repeated_block_is_one_run_and_the_rest_single_fields() {
        let k = keys("u8 u16 f32 u16 f32 u16 f32 bool");
        let run = Run {
            start: 1,
            period: 2,
            reps: 3,
        };
        assert_eq!(
            split(&k, 2),
            [Piece::Field(0), Piece::Run(run), Piece::Field(7)]
        );
        assert_eq!(split(&k, 7).len(), k.len(), "below the minimum: fields");
    }

    #[test]
    fn the_shortest_block_wins_among_equal_runs() {
        let k = keys("u16 u16 u16 u16");
        let run = Run {
            start: 0,
            period: 1,
            reps: 4,
        };
        assert_eq!(split(&k, 2), [Piece::Run(run)]);
    }

    #[test]
    fn bools_on_consecutive_words_are_a_bit_run() {
        // Words 0 and 1 (u16), then bits 2..5 of each, then one bool of word 0.
        let k = keys("u16 u16 bool bool bool bool bool bool bool");
        let m = |s, b| Some((s, b));
        let mapped = [
            None,
            None,
            m(0, 2),
            m(0, 3),
            m(0, 4),
            m(1, 2),
            m(1, 3),
            m(1, 4),
            m(0, 9),
        ];
        let run = BitRun {
            start: 2,
            source: 0,
            first_bit: 2,
            bits: 3,
            words: 2,
        };
        assert_eq!(
            split_bits(&k, &mapped, 2),
            [BitPiece::Run(run), BitPiece::Bool(8)]
        );
        assert_eq!(split_bits(&k, &mapped, 7).len(), 7);
    }

    #[test]
    fn a_word_of_another_type_ends_a_bit_run() {
        let k = keys("u16 u32 bool bool");
        let mapped = [None, None, Some((0, 0)), Some((1, 0))];
        assert_eq!(
            split_bits(&k, &mapped, 1),
            [BitPiece::Bool(2), BitPiece::Bool(3)]
        );
    }
}
