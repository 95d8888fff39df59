// A string's capacity is 1..=255 bytes.
use plc_core::FixedString;

fn main() {
    let _s = FixedString::<0>::new();
}
