// A string's capacity cannot exceed 255 bytes.
use plc_core::FixedString;

fn main() {
    let mut s = FixedString::<256>::default();
    s.set("too big");
}
