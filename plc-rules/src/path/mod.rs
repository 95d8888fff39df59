//! Paths that name one value inside a program's variables: `speed`, `grid[1,2]`, `grid[5]`,
//! `axes[1].pos`, `press.delay.ET`.
//!
//! A path is a variable's name, then for each structure level a `.` and a member's name; any
//! name may be followed by an index in brackets: as many 0-based coordinates as the array has
//! dimensions (`grid[1,2]`), or one flat row-major index (`grid[5]`, the form tools always
//! took). Names compare case-insensitively, as IEC 61131-3 identifiers do.
//!
//! The parser allocates nothing (plc-core uses it in `no_std`) and reads a path once, front to
//! back, so its cost is bounded by the path's length.
//!
//! ```
//! use plc_rules::path::{Index, Segment, segments};
//! let s: Vec<_> = segments("axes[1].pos").collect::<Result<_, _>>().unwrap();
//! assert_eq!(s[0], Segment { name: "axes", index: Some(Index::new(&[1])) });
//! assert_eq!(s[1], Segment { name: "pos", index: None });
//! assert!(segments("axes[1]..pos").any(|s| s.is_err()));
//! ```

use core::fmt;

mod locate;
#[cfg(feature = "std")]
mod walk;
pub use locate::{Found, LocateError, Node, element_leaves, leaf, leaves, locate, member_writable};
#[cfg(feature = "std")]
pub use walk::{Basic, Structure, Visit, walk};

/// At most this many coordinates in one index (arrays have at most 3 dimensions).
pub const MAX_COORDS: usize = 3;

/// An index in brackets: 1 to 3 coordinates.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Index {
    coords: [usize; MAX_COORDS],
    len: u8,
}

impl Index {
    /// An index of these coordinates (at most 3; more are cut).
    pub fn new(coords: &[usize]) -> Index {
        let mut c = [0; MAX_COORDS];
        let len = coords.len().min(MAX_COORDS);
        c[..len].copy_from_slice(&coords[..len]);
        Index {
            coords: c,
            len: len as u8,
        }
    }

    /// The coordinates as written.
    pub fn coords(&self) -> &[usize] {
        &self.coords[..self.len as usize]
    }

    /// The row-major element this index names in an array of `dims`: one coordinate per
    /// dimension, or a single flat index below the number of elements.
    pub fn flat(&self, dims: &[usize]) -> Result<usize, PathError> {
        let coords = self.coords();
        let elements = crate::access::elements(dims);
        if dims.is_empty() {
            return Err(PathError::NotAnArray);
        }
        if coords.len() == 1 && dims.len() > 1 {
            return if coords[0] < elements {
                Ok(coords[0])
            } else {
                Err(PathError::OutOfRange {
                    index: coords[0],
                    len: elements,
                })
            };
        }
        if coords.len() != dims.len() {
            return Err(PathError::WrongRank {
                given: coords.len(),
                dims: dims.len(),
            });
        }
        let mut flat = 0usize;
        for (&c, &d) in coords.iter().zip(dims) {
            if c >= d {
                return Err(PathError::OutOfRange { index: c, len: d });
            }
            flat = flat * d + c;
        }
        Ok(flat)
    }
}

/// One step of a path: a name and its index, if any.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Segment<'a> {
    /// The variable's or member's name, as written.
    pub name: &'a str,
    /// The index in brackets after it.
    pub index: Option<Index>,
}

/// Why a path does not name a value.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PathError {
    /// The path is empty, or a `.` is not followed by a name.
    MissingName,
    /// A character that cannot be in a path at this place.
    Unexpected {
        /// The character.
        found: char,
        /// Its byte position in the path.
        at: usize,
    },
    /// A `[` without its `]`, or an index that is not a number.
    BadIndex {
        /// Byte position of the `[`.
        at: usize,
    },
    /// More than 3 coordinates in one index.
    TooManyCoords,
    /// An index on a variable that is not an array.
    NotAnArray,
    /// An array element named by the wrong number of coordinates.
    WrongRank {
        /// Coordinates given.
        given: usize,
        /// Dimensions of the array.
        dims: usize,
    },
    /// A coordinate beyond its dimension.
    OutOfRange {
        /// The coordinate given.
        index: usize,
        /// The dimension's length.
        len: usize,
    },
}

impl fmt::Display for PathError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            PathError::MissingName => f.write_str("a name is missing (write `axes[1].pos`)"),
            PathError::Unexpected { found, at } => {
                write!(f, "unexpected `{found}` at position {at}")
            }
            PathError::BadIndex { at } => write!(
                f,
                "the index at position {at} must be 0-based numbers in brackets, such as [2] or \
                 [1,2]"
            ),
            PathError::TooManyCoords => f.write_str("an index has at most 3 coordinates"),
            PathError::NotAnArray => f.write_str("not an array: remove the index"),
            PathError::WrongRank { given, dims } => write!(
                f,
                "the array has {dims} dimensions: give {dims} coordinates or one flat index, \
                 not {given}"
            ),
            PathError::OutOfRange { index, len } => {
                write!(f, "index {index} is out of range 0..{len}")
            }
        }
    }
}

#[cfg(feature = "std")]
impl std::error::Error for PathError {}

/// The coordinates of row-major element `flat` of an array of `dims`, as a path writes them
/// (`1,2`): how tools name each element of an array of structures.
///
/// ```
/// assert_eq!(plc_rules::path::coordinates(5, &[2, 3]), "1,2");
/// ```
#[cfg(feature = "std")]
pub fn coordinates(mut flat: usize, dims: &[usize]) -> std::string::String {
    use std::string::ToString;
    let mut c = std::vec![0; dims.len()];
    for (slot, &d) in c.iter_mut().zip(dims).rev() {
        *slot = flat % d.max(1);
        flat /= d.max(1);
    }
    c.iter()
        .map(|x| x.to_string())
        .collect::<std::vec::Vec<_>>()
        .join(",")
}

/// The segments of `path`, front to back; the first error ends them.
pub fn segments(path: &str) -> Segments<'_> {
    Segments {
        text: path.trim(),
        pos: 0,
        done: false,
    }
}

/// Iterator over a path's segments; see [`segments`].
#[derive(Clone, Debug)]
pub struct Segments<'a> {
    text: &'a str,
    pos: usize,
    done: bool,
}

impl<'a> Segments<'a> {
    fn fail(&mut self, e: PathError) -> Option<Result<Segment<'a>, PathError>> {
        self.done = true;
        Some(Err(e))
    }
}

fn is_name_char(c: u8) -> bool {
    c.is_ascii_alphanumeric() || c == b'_'
}

impl<'a> Iterator for Segments<'a> {
    type Item = Result<Segment<'a>, PathError>;

    fn next(&mut self) -> Option<Self::Item> {
        if self.done {
            return None;
        }
        let bytes = self.text.as_bytes();
        if self.pos > 0 {
            // After a segment: the end, or a `.` and the next name.
            match bytes.get(self.pos) {
                None => {
                    self.done = true;
                    return None;
                }
                Some(b'.') => self.pos += 1,
                Some(_) => {
                    let found = self.text[self.pos..].chars().next().unwrap_or('?');
                    let at = self.pos;
                    return self.fail(PathError::Unexpected { found, at });
                }
            }
        }
        let start = self.pos;
        while bytes.get(self.pos).is_some_and(|&c| is_name_char(c)) {
            self.pos += 1;
        }
        if self.pos == start {
            return match self.text[start..].chars().next() {
                None => self.fail(PathError::MissingName),
                Some(found) => self.fail(PathError::Unexpected { found, at: start }),
            };
        }
        let name = &self.text[start..self.pos];
        let mut index = None;
        if bytes.get(self.pos) == Some(&b'[') {
            let open = self.pos;
            let Some(close) = self.text[open..].find(']').map(|i| open + i) else {
                return self.fail(PathError::BadIndex { at: open });
            };
            let mut coords = [0usize; MAX_COORDS];
            let mut len = 0;
            for part in self.text[open + 1..close].split(',') {
                if len == MAX_COORDS {
                    return self.fail(PathError::TooManyCoords);
                }
                match part.trim().parse::<usize>() {
                    Ok(n) if !part.trim().starts_with('+') => coords[len] = n,
                    _ => return self.fail(PathError::BadIndex { at: open }),
                }
                len += 1;
            }
            index = Some(Index::new(&coords[..len]));
            self.pos = close + 1;
        }
        Some(Ok(Segment { name, index }))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn parse(p: &str) -> Result<Vec<Segment<'_>>, PathError> {
        segments(p).collect()
    }

    #[test]
    fn names_members_and_indexes() {
        let s = parse("press.delay.ET").unwrap();
        assert_eq!(
            s.iter().map(|s| s.name).collect::<Vec<_>>(),
            ["press", "delay", "ET"]
        );
        let s = parse(" grid[1, 2] ").unwrap();
        assert_eq!(s[0].index.unwrap().coords(), &[1, 2]);
        let s = parse("a[0].b[1,2,3].c").unwrap();
        assert_eq!(s.len(), 3);
        assert_eq!(s[1].index.unwrap().coords(), &[1, 2, 3]);
    }

    #[test]
    fn refuses_what_names_nothing() {
        assert_eq!(parse(""), Err(PathError::MissingName));
        assert_eq!(parse("a."), Err(PathError::MissingName));
        assert!(matches!(
            parse("a..b"),
            Err(PathError::Unexpected { found: '.', .. })
        ));
        assert!(matches!(parse("a[1"), Err(PathError::BadIndex { .. })));
        assert!(matches!(parse("a[x]"), Err(PathError::BadIndex { .. })));
        assert!(matches!(parse("a[-1]"), Err(PathError::BadIndex { .. })));
        assert!(matches!(parse("a[+1]"), Err(PathError::BadIndex { .. })));
        assert!(matches!(parse("a[]"), Err(PathError::BadIndex { .. })));
        assert_eq!(parse("a[1,2,3,4]"), Err(PathError::TooManyCoords));
        assert!(matches!(
            parse("a b"),
            Err(PathError::Unexpected { found: ' ', .. })
        ));
        assert!(matches!(parse("a[1]x"), Err(PathError::Unexpected { .. })));
    }

    #[test]
    fn flat_index_is_row_major_or_given_flat() {
        let dims = [2, 3];
        assert_eq!(Index::new(&[1, 2]).flat(&dims), Ok(5));
        assert_eq!(Index::new(&[5]).flat(&dims), Ok(5));
        assert_eq!(
            Index::new(&[6]).flat(&dims),
            Err(PathError::OutOfRange { index: 6, len: 6 })
        );
        assert_eq!(
            Index::new(&[0, 3]).flat(&dims),
            Err(PathError::OutOfRange { index: 3, len: 3 })
        );
        assert_eq!(
            Index::new(&[0, 0, 0]).flat(&dims),
            Err(PathError::WrongRank { given: 3, dims: 2 })
        );
        assert_eq!(Index::new(&[0]).flat(&[]), Err(PathError::NotAnArray));
    }

    proptest! {
        #[test]
        fn arbitrary_text_never_panics(s in "\\PC{0,40}") {
            let n = segments(&s).take(100).count();
            prop_assert!(n <= s.len() + 1);
        }

        #[test]
        fn written_paths_parse_back(
            parts in proptest::collection::vec(("[a-zA-Z_][a-zA-Z0-9_]{0,6}",
                proptest::option::of(proptest::collection::vec(0usize..1000, 1..=3))), 1..5)
        ) {
            let text: Vec<String> = parts.iter().map(|(n, i)| match i {
                Some(c) => format!("{n}[{}]", c.iter().map(|c| c.to_string()).collect::<Vec<_>>().join(",")),
                None => n.clone(),
            }).collect();
            let text = text.join(".");
            let parsed = parse(&text).unwrap();
            prop_assert_eq!(parsed.len(), parts.len());
            for (seg, (n, i)) in parsed.iter().zip(&parts) {
                prop_assert_eq!(seg.name, n.as_str());
                prop_assert_eq!(seg.index.map(|i| i.coords().to_vec()), i.clone());
            }
        }
    }
}
