//! A crate that forbids unsafe code can declare a program whose conversions run in loops
//! (runs of 64 and more same-typed fields and mapped bools): the derive's code is its own.
#![forbid(unsafe_code)]

use plc_core::GlobalMemory;

#[derive(GlobalMemory, Debug, Clone)]
pub struct Runs {
    w0: u16,
    w1: u16,
    w2: u16,
    w3: u16,
    w4: u16,
    w5: u16,
    w6: u16,
    w7: u16,
    w8: u16,
    w9: u16,
    w10: u16,
    w11: u16,
    w12: u16,
    w13: u16,
    w14: u16,
    w15: u16,
    w16: u16,
    w17: u16,
    w18: u16,
    w19: u16,
    w20: u16,
    w21: u16,
    w22: u16,
    w23: u16,
    w24: u16,
    w25: u16,
    w26: u16,
    w27: u16,
    w28: u16,
    w29: u16,
    w30: u16,
    w31: u16,
    w32: u16,
    w33: u16,
    w34: u16,
    w35: u16,
    w36: u16,
    w37: u16,
    w38: u16,
    w39: u16,
    w40: u16,
    w41: u16,
    w42: u16,
    w43: u16,
    w44: u16,
    w45: u16,
    w46: u16,
    w47: u16,
    w48: u16,
    w49: u16,
    w50: u16,
    w51: u16,
    w52: u16,
    w53: u16,
    w54: u16,
    w55: u16,
    w56: u16,
    w57: u16,
    w58: u16,
    w59: u16,
    w60: u16,
    w61: u16,
    w62: u16,
    w63: u16,
    w64: u16,
    w65: u16,
    w66: u16,
    w67: u16,
    w68: u16,
    w69: u16,
    #[plc(source = "w0", bit = 0)]
    b0: bool,
    #[plc(source = "w0", bit = 1)]
    b1: bool,
    #[plc(source = "w0", bit = 2)]
    b2: bool,
    #[plc(source = "w0", bit = 3)]
    b3: bool,
    #[plc(source = "w0", bit = 4)]
    b4: bool,
    #[plc(source = "w0", bit = 5)]
    b5: bool,
    #[plc(source = "w0", bit = 6)]
    b6: bool,
    #[plc(source = "w0", bit = 7)]
    b7: bool,
    #[plc(source = "w0", bit = 8)]
    b8: bool,
    #[plc(source = "w0", bit = 9)]
    b9: bool,
    #[plc(source = "w0", bit = 10)]
    b10: bool,
    #[plc(source = "w0", bit = 11)]
    b11: bool,
    #[plc(source = "w0", bit = 12)]
    b12: bool,
    #[plc(source = "w0", bit = 13)]
    b13: bool,
    #[plc(source = "w0", bit = 14)]
    b14: bool,
    #[plc(source = "w0", bit = 15)]
    b15: bool,
    #[plc(source = "w1", bit = 0)]
    b16: bool,
    #[plc(source = "w1", bit = 1)]
    b17: bool,
    #[plc(source = "w1", bit = 2)]
    b18: bool,
    #[plc(source = "w1", bit = 3)]
    b19: bool,
    #[plc(source = "w1", bit = 4)]
    b20: bool,
    #[plc(source = "w1", bit = 5)]
    b21: bool,
    #[plc(source = "w1", bit = 6)]
    b22: bool,
    #[plc(source = "w1", bit = 7)]
    b23: bool,
    #[plc(source = "w1", bit = 8)]
    b24: bool,
    #[plc(source = "w1", bit = 9)]
    b25: bool,
    #[plc(source = "w1", bit = 10)]
    b26: bool,
    #[plc(source = "w1", bit = 11)]
    b27: bool,
    #[plc(source = "w1", bit = 12)]
    b28: bool,
    #[plc(source = "w1", bit = 13)]
    b29: bool,
    #[plc(source = "w1", bit = 14)]
    b30: bool,
    #[plc(source = "w1", bit = 15)]
    b31: bool,
    #[plc(source = "w2", bit = 0)]
    b32: bool,
    #[plc(source = "w2", bit = 1)]
    b33: bool,
    #[plc(source = "w2", bit = 2)]
    b34: bool,
    #[plc(source = "w2", bit = 3)]
    b35: bool,
    #[plc(source = "w2", bit = 4)]
    b36: bool,
    #[plc(source = "w2", bit = 5)]
    b37: bool,
    #[plc(source = "w2", bit = 6)]
    b38: bool,
    #[plc(source = "w2", bit = 7)]
    b39: bool,
    #[plc(source = "w2", bit = 8)]
    b40: bool,
    #[plc(source = "w2", bit = 9)]
    b41: bool,
    #[plc(source = "w2", bit = 10)]
    b42: bool,
    #[plc(source = "w2", bit = 11)]
    b43: bool,
    #[plc(source = "w2", bit = 12)]
    b44: bool,
    #[plc(source = "w2", bit = 13)]
    b45: bool,
    #[plc(source = "w2", bit = 14)]
    b46: bool,
    #[plc(source = "w2", bit = 15)]
    b47: bool,
    #[plc(source = "w3", bit = 0)]
    b48: bool,
    #[plc(source = "w3", bit = 1)]
    b49: bool,
    #[plc(source = "w3", bit = 2)]
    b50: bool,
    #[plc(source = "w3", bit = 3)]
    b51: bool,
    #[plc(source = "w3", bit = 4)]
    b52: bool,
    #[plc(source = "w3", bit = 5)]
    b53: bool,
    #[plc(source = "w3", bit = 6)]
    b54: bool,
    #[plc(source = "w3", bit = 7)]
    b55: bool,
    #[plc(source = "w3", bit = 8)]
    b56: bool,
    #[plc(source = "w3", bit = 9)]
    b57: bool,
    #[plc(source = "w3", bit = 10)]
    b58: bool,
    #[plc(source = "w3", bit = 11)]
    b59: bool,
    #[plc(source = "w3", bit = 12)]
    b60: bool,
    #[plc(source = "w3", bit = 13)]
    b61: bool,
    #[plc(source = "w3", bit = 14)]
    b62: bool,
    #[plc(source = "w3", bit = 15)]
    b63: bool,
}

fn main() {
    let mut gm = Runs::default();
    gm.w1 = 0x8001;
    gm.unpack_bits();
    assert!(gm.b16 && gm.b31 && !gm.b17);
    let image = gm.to_image();
    assert_eq!(Runs::from_image(&image).w1, 0x8001);
}
