// Written by `tests/generated.rs`: edit that, not this.

use core::mem::size_of;
use plc_core::{FixedString, GlobalMemory, PlcStruct, PlcType};
use proptest::prelude::*;
use zerocopy::{FromBytes, IntoBytes};

type Word = u16;
type Flag = bool;

#[derive(PlcStruct, Debug, Clone, Copy, PartialEq)]
pub struct Pair {
    pub a: u16,
    #[plc(source = "a", bit = 3)]
    pub b: bool,
    pub c: f32,
}

impl Pair {
    fn reference_unpack(&mut self) {
        self.b = (self.a >> 3) & 1 != 0;
    }

    fn reference_pack(&mut self) {
        self.a = (self.a & !(1 << 3)) | ((self.b as u16) << 3);
    }
}

/// Field-by-field conversions, as the derive's straight-line code does them.
trait Reference: GlobalMemory {
    fn reference_store(&self) -> Vec<u8>;
    fn reference_load(&mut self, bytes: &[u8]);
    fn reference_unpack(&mut self);
    fn reference_pack(&mut self);
    fn reference_unpack_nested(&mut self);
    fn reference_pack_nested(&mut self);
}

/// Loads, stores, unpacks and packs `bytes` both ways and compares the results as bytes (NaN
/// is not equal to itself).
fn agree<T: Reference + Clone>(bytes: &[u8]) {
    let image = T::Image::read_from_bytes(bytes).unwrap();
    let mut ours = T::from_image(&image);
    let mut theirs = T::from_image(&image);
    ours.load_image(&image);
    theirs.reference_load(bytes);
    assert_eq!(ours.reference_store(), theirs.reference_store(), "load_image");
    assert_eq!(ours.to_image().as_bytes(), theirs.reference_store().as_slice(), "store_image");
    ours.unpack_bits();
    theirs.reference_unpack();
    assert_eq!(ours.reference_store(), theirs.reference_store(), "unpack_bits");
    // Other values in the bools before packing, so every bit changes somewhere.
    let mut flipped = ours.to_image();
    flipped.as_mut_bytes().iter_mut().for_each(|b| *b = !*b);
    let bools = T::from_image(&flipped);
    let mut ours = bools.clone();
    let mut theirs = bools;
    ours.pack_bits();
    theirs.reference_pack();
    assert_eq!(ours.reference_store(), theirs.reference_store(), "pack_bits");
}

#[derive(GlobalMemory, Debug, Clone)]
pub struct Random0 {
    pub f0: i32,
    pub f1: u16,
    pub f2: u64,
    pub f3: [u16; 3],
    pub f4: u64,
    pub f5: u16,
    pub f6: u64,
    pub f7: [u16; 3],
    pub f8: u64,
    pub f9: u16,
    pub f10: u64,
    pub f11: [u16; 3],
    pub f12: u64,
    pub f13: u16,
    pub f14: u64,
    pub f15: [u16; 3],
    pub f16: u64,
    pub f17: u16,
    pub f18: u64,
    pub f19: [u16; 3],
    pub f20: u64,
    pub f21: u16,
    pub f22: u64,
    pub f23: [u16; 3],
    pub f24: u64,
    pub f25: u16,
    pub f26: u64,
    pub f27: [u16; 3],
    pub f28: u64,
    pub f29: u16,
    pub f30: u64,
    pub f31: [u16; 3],
    pub f32: u64,
    pub f33: u16,
    pub f34: u64,
    pub f35: [u16; 3],
    pub f36: u64,
    pub f37: u16,
    pub f38: u64,
    pub f39: [u16; 3],
    pub f40: u64,
    pub f41: u16,
    pub f42: u64,
    pub f43: [u16; 3],
    pub f44: u64,
    pub f45: u16,
    pub f46: u64,
    pub f47: [u16; 3],
    pub f48: u64,
    pub f49: u16,
    pub f50: u64,
    pub f51: [u16; 3],
    pub f52: u64,
    pub f53: u16,
    pub f54: u64,
    pub f55: [u16; 3],
    pub f56: u64,
    pub f57: u16,
    pub f58: u64,
    pub f59: [u16; 3],
    pub f60: u64,
    pub f61: u16,
    pub f62: u64,
    pub f63: [u16; 3],
    pub f64: u64,
    pub f65: u16,
    pub f66: u64,
    pub f67: [u16; 3],
    pub f68: u64,
    pub f69: u16,
    pub f70: u64,
    pub f71: [u16; 3],
    pub f72: u64,
    pub f73: u16,
    pub f74: u64,
    pub f75: [u16; 3],
    pub f76: u64,
    pub f77: u16,
    pub f78: u64,
    pub f79: [u16; 3],
    pub f80: u64,
    pub f81: u16,
    pub f82: u64,
    pub f83: [u16; 3],
    pub f84: u64,
    pub f85: u16,
    pub f86: u64,
    pub f87: [u16; 3],
    pub f88: u64,
    pub f89: u16,
    pub f90: u64,
    pub f91: [u16; 3],
    pub f92: u64,
    pub f93: u16,
    pub f94: u64,
    pub f95: [u16; 3],
    pub f96: u64,
    pub f97: u16,
    pub f98: u64,
    pub f99: [u16; 3],
    pub f100: u64,
    pub f101: u16,
    pub f102: u64,
    pub f103: [u16; 3],
    pub f104: u64,
    pub f105: u64,
    pub f106: f64,
    pub f107: u32,
    pub f108: u8,
    pub f109: f64,
    pub f110: [Pair; 2],
    pub f111: u16,
    pub f112: u16,
    pub f113: u16,
    #[plc(source = "f111", bit = 15)]
    pub f114: bool,
    #[plc(source = "f112", bit = 14)]
    pub f115: bool,
    #[plc(source = "f111", bit = 4)]
    pub f116: bool,
    #[plc(source = "f113", bit = 15)]
    pub f117: bool,
    #[plc(source = "f113", bit = 13)]
    pub f118: bool,
    #[plc(source = "f113", bit = 5)]
    pub f119: bool,
    #[plc(source = "f113", bit = 12)]
    pub f120: bool,
    #[plc(source = "f113", bit = 2)]
    pub f121: bool,
    #[plc(source = "f112", bit = 9)]
    pub f122: bool,
    #[plc(source = "f113", bit = 0)]
    pub f123: bool,
    #[plc(source = "f111", bit = 2)]
    pub f124: bool,
    #[plc(source = "f111", bit = 5)]
    pub f125: bool,
    #[plc(source = "f111", bit = 12)]
    pub f126: bool,
    #[plc(source = "f111", bit = 9)]
    pub f127: bool,
    #[plc(source = "f112", bit = 2)]
    pub f128: bool,
    #[plc(source = "f111", bit = 6)]
    pub f129: bool,
    #[plc(source = "f113", bit = 9)]
    pub f130: bool,
    #[plc(source = "f112", bit = 6)]
    pub f131: bool,
    #[plc(source = "f112", bit = 8)]
    pub f132: bool,
    pub f133: u16,
    pub f134: u16,
    pub f135: u16,
    #[plc(source = "f133", bit = 5)]
    pub f136: bool,
    #[plc(source = "f134", bit = 1)]
    pub f137: bool,
    #[plc(source = "f134", bit = 14)]
    pub f138: bool,
    #[plc(source = "f135", bit = 9)]
    pub f139: bool,
    #[plc(source = "f134", bit = 12)]
    pub f140: bool,
    pub f141: u64,
    pub f142: i8,
    pub f143: i32,
    pub f144: u64,
    pub f145: i8,
    pub f146: i32,
    pub f147: u64,
    pub f148: i8,
    pub f149: i32,
    pub f150: u64,
    pub f151: i8,
    pub f152: i32,
    pub f153: u64,
    pub f154: i8,
    pub f155: i32,
    pub f156: u64,
    pub f157: i8,
    pub f158: i32,
    pub f159: u64,
    pub f160: i8,
    pub f161: i32,
    pub f162: u64,
    pub f163: i8,
    pub f164: i32,
    pub f165: u64,
    pub f166: i8,
    pub f167: i32,
    pub f168: u64,
    pub f169: i8,
    pub f170: i32,
    pub f171: u64,
    pub f172: i8,
    pub f173: i32,
    pub f174: u64,
    pub f175: i8,
    pub f176: i32,
    pub f177: u64,
    pub f178: i8,
    pub f179: i32,
    pub f180: u64,
    pub f181: i8,
    pub f182: i32,
    pub f183: u64,
    pub f184: i8,
    pub f185: i32,
    pub f186: u64,
    pub f187: i8,
    pub f188: i32,
    pub f189: u64,
    pub f190: i8,
    pub f191: i32,
    pub f192: u64,
    pub f193: i8,
    pub f194: i32,
    pub f195: u64,
    pub f196: i8,
    pub f197: i32,
    pub f198: u64,
    pub f199: i8,
    pub f200: i32,
    pub f201: u64,
    pub f202: i8,
    pub f203: i32,
    pub f204: u64,
    pub f205: i8,
    pub f206: i32,
    pub f207: u64,
    pub f208: i8,
    pub f209: i32,
    pub f210: u64,
    pub f211: i8,
    pub f212: i32,
    pub f213: u64,
    pub f214: i8,
    pub f215: i32,
    pub f216: u64,
    pub f217: i8,
    pub f218: i32,
    pub f219: u64,
    pub f220: i8,
    pub f221: i32,
    pub f222: u64,
    pub f223: i8,
    pub f224: i32,
    pub f225: Word,
    pub f226: Word,
    pub f227: Word,
    pub f228: Word,
    pub f229: Word,
    pub f230: Word,
    pub f231: Word,
    #[plc(source = "f225", bit = 6)]
    pub f232: Flag,
    #[plc(source = "f225", bit = 7)]
    pub f233: Flag,
    #[plc(source = "f225", bit = 8)]
    pub f234: Flag,
    #[plc(source = "f225", bit = 9)]
    pub f235: Flag,
    #[plc(source = "f225", bit = 10)]
    pub f236: Flag,
    #[plc(source = "f225", bit = 11)]
    pub f237: Flag,
    #[plc(source = "f225", bit = 12)]
    pub f238: Flag,
    #[plc(source = "f225", bit = 13)]
    pub f239: Flag,
    #[plc(source = "f225", bit = 14)]
    pub f240: Flag,
    #[plc(source = "f226", bit = 6)]
    pub f241: Flag,
    #[plc(source = "f226", bit = 7)]
    pub f242: Flag,
    #[plc(source = "f226", bit = 8)]
    pub f243: Flag,
    #[plc(source = "f226", bit = 9)]
    pub f244: Flag,
    #[plc(source = "f226", bit = 10)]
    pub f245: Flag,
    #[plc(source = "f226", bit = 11)]
    pub f246: Flag,
    #[plc(source = "f226", bit = 12)]
    pub f247: Flag,
    #[plc(source = "f226", bit = 13)]
    pub f248: Flag,
    #[plc(source = "f226", bit = 14)]
    pub f249: Flag,
    #[plc(source = "f227", bit = 6)]
    pub f250: Flag,
    #[plc(source = "f227", bit = 7)]
    pub f251: Flag,
    #[plc(source = "f227", bit = 8)]
    pub f252: Flag,
    #[plc(source = "f227", bit = 9)]
    pub f253: Flag,
    #[plc(source = "f227", bit = 10)]
    pub f254: Flag,
    #[plc(source = "f227", bit = 11)]
    pub f255: Flag,
    #[plc(source = "f227", bit = 12)]
    pub f256: Flag,
    #[plc(source = "f227", bit = 13)]
    pub f257: Flag,
    #[plc(source = "f227", bit = 14)]
    pub f258: Flag,
    #[plc(source = "f228", bit = 6)]
    pub f259: Flag,
    #[plc(source = "f228", bit = 7)]
    pub f260: Flag,
    #[plc(source = "f228", bit = 8)]
    pub f261: Flag,
    #[plc(source = "f228", bit = 9)]
    pub f262: Flag,
    #[plc(source = "f228", bit = 10)]
    pub f263: Flag,
    #[plc(source = "f228", bit = 11)]
    pub f264: Flag,
    #[plc(source = "f228", bit = 12)]
    pub f265: Flag,
    #[plc(source = "f228", bit = 13)]
    pub f266: Flag,
    #[plc(source = "f228", bit = 14)]
    pub f267: Flag,
    #[plc(source = "f229", bit = 6)]
    pub f268: Flag,
    #[plc(source = "f229", bit = 7)]
    pub f269: Flag,
    #[plc(source = "f229", bit = 8)]
    pub f270: Flag,
    #[plc(source = "f229", bit = 9)]
    pub f271: Flag,
    #[plc(source = "f229", bit = 10)]
    pub f272: Flag,
    #[plc(source = "f229", bit = 11)]
    pub f273: Flag,
    #[plc(source = "f229", bit = 12)]
    pub f274: Flag,
    #[plc(source = "f229", bit = 13)]
    pub f275: Flag,
    #[plc(source = "f229", bit = 14)]
    pub f276: Flag,
    #[plc(source = "f230", bit = 6)]
    pub f277: Flag,
    #[plc(source = "f230", bit = 7)]
    pub f278: Flag,
    #[plc(source = "f230", bit = 8)]
    pub f279: Flag,
    #[plc(source = "f230", bit = 9)]
    pub f280: Flag,
    #[plc(source = "f230", bit = 10)]
    pub f281: Flag,
    #[plc(source = "f230", bit = 11)]
    pub f282: Flag,
    #[plc(source = "f230", bit = 12)]
    pub f283: Flag,
    #[plc(source = "f230", bit = 13)]
    pub f284: Flag,
    #[plc(source = "f230", bit = 14)]
    pub f285: Flag,
    #[plc(source = "f231", bit = 6)]
    pub f286: Flag,
    #[plc(source = "f231", bit = 7)]
    pub f287: Flag,
    #[plc(source = "f231", bit = 8)]
    pub f288: Flag,
    #[plc(source = "f231", bit = 9)]
    pub f289: Flag,
    #[plc(source = "f231", bit = 10)]
    pub f290: Flag,
    #[plc(source = "f231", bit = 11)]
    pub f291: Flag,
    #[plc(source = "f231", bit = 12)]
    pub f292: Flag,
    #[plc(source = "f231", bit = 13)]
    pub f293: Flag,
    #[plc(source = "f231", bit = 14)]
    pub f294: Flag,
    pub f295: i32,
    pub f296: Flag,
    pub f297: Pair,
}

impl Reference for Random0 {
    fn reference_store(&self) -> Vec<u8> {
        let mut b = Vec::new();
        b.extend_from_slice(<i32 as PlcType>::to_repr(&self.f0).as_bytes());
        b.extend_from_slice(<u16 as PlcType>::to_repr(&self.f1).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f2).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f3).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f4).as_bytes());
        b.extend_from_slice(<u16 as PlcType>::to_repr(&self.f5).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f6).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f7).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f8).as_bytes());
        b.extend_from_slice(<u16 as PlcType>::to_repr(&self.f9).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f10).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f11).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f12).as_bytes());
        b.extend_from_slice(<u16 as PlcType>::to_repr(&self.f13).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f14).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f15).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f16).as_bytes());
        b.extend_from_slice(<u16 as PlcType>::to_repr(&self.f17).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f18).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f19).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f20).as_bytes());
        b.extend_from_slice(<u16 as PlcType>::to_repr(&self.f21).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f22).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f23).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f24).as_bytes());
        b.extend_from_slice(<u16 as PlcType>::to_repr(&self.f25).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f26).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f27).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f28).as_bytes());
        b.extend_from_slice(<u16 as PlcType>::to_repr(&self.f29).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f30).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f31).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f32).as_bytes());
        b.extend_from_slice(<u16 as PlcType>::to_repr(&self.f33).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f34).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f35).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f36).as_bytes());
        b.extend_from_slice(<u16 as PlcType>::to_repr(&self.f37).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f38).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f39).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f40).as_bytes());
        b.extend_from_slice(<u16 as PlcType>::to_repr(&self.f41).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f42).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f43).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f44).as_bytes());
        b.extend_from_slice(<u16 as PlcType>::to_repr(&self.f45).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f46).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f47).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f48).as_bytes());
        b.extend_from_slice(<u16 as PlcType>::to_repr(&self.f49).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f50).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f51).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f52).as_bytes());
        b.extend_from_slice(<u16 as PlcType>::to_repr(&self.f53).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f54).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f55).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f56).as_bytes());
        b.extend_from_slice(<u16 as PlcType>::to_repr(&self.f57).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f58).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f59).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f60).as_bytes());
        b.extend_from_slice(<u16 as PlcType>::to_repr(&self.f61).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f62).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f63).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f64).as_bytes());
        b.extend_from_slice(<u16 as PlcType>::to_repr(&self.f65).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f66).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f67).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f68).as_bytes());
        b.extend_from_slice(<u16 as PlcType>::to_repr(&self.f69).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f70).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f71).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f72).as_bytes());
        b.extend_from_slice(<u16 as PlcType>::to_repr(&self.f73).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f74).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f75).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f76).as_bytes());
        b.extend_from_slice(<u16 as PlcType>::to_repr(&self.f77).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f78).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f79).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f80).as_bytes());
        b.extend_from_slice(<u16 as PlcType>::to_repr(&self.f81).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f82).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f83).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f84).as_bytes());
        b.extend_from_slice(<u16 as PlcType>::to_repr(&self.f85).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f86).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f87).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f88).as_bytes());
        b.extend_from_slice(<u16 as PlcType>::to_repr(&self.f89).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f90).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f91).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f92).as_bytes());
        b.extend_from_slice(<u16 as PlcType>::to_repr(&self.f93).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f94).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f95).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f96).as_bytes());
        b.extend_from_slice(<u16 as PlcType>::to_repr(&self.f97).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f98).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f99).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f100).as_bytes());
        b.extend_from_slice(<u16 as PlcType>::to_repr(&self.f101).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f102).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f103).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f104).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f105).as_bytes());
        b.extend_from_slice(<f64 as PlcType>::to_repr(&self.f106).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f107).as_bytes());
        b.extend_from_slice(<u8 as PlcType>::to_repr(&self.f108).as_bytes());
        b.extend_from_slice(<f64 as PlcType>::to_repr(&self.f109).as_bytes());
        b.extend_from_slice(<[Pair; 2] as PlcType>::to_repr(&self.f110).as_bytes());
        b.extend_from_slice(<u16 as PlcType>::to_repr(&self.f111).as_bytes());
        b.extend_from_slice(<u16 as PlcType>::to_repr(&self.f112).as_bytes());
        b.extend_from_slice(<u16 as PlcType>::to_repr(&self.f113).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f114).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f115).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f116).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f117).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f118).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f119).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f120).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f121).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f122).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f123).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f124).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f125).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f126).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f127).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f128).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f129).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f130).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f131).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f132).as_bytes());
        b.extend_from_slice(<u16 as PlcType>::to_repr(&self.f133).as_bytes());
        b.extend_from_slice(<u16 as PlcType>::to_repr(&self.f134).as_bytes());
        b.extend_from_slice(<u16 as PlcType>::to_repr(&self.f135).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f136).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f137).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f138).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f139).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f140).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f141).as_bytes());
        b.extend_from_slice(<i8 as PlcType>::to_repr(&self.f142).as_bytes());
        b.extend_from_slice(<i32 as PlcType>::to_repr(&self.f143).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f144).as_bytes());
        b.extend_from_slice(<i8 as PlcType>::to_repr(&self.f145).as_bytes());
        b.extend_from_slice(<i32 as PlcType>::to_repr(&self.f146).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f147).as_bytes());
        b.extend_from_slice(<i8 as PlcType>::to_repr(&self.f148).as_bytes());
        b.extend_from_slice(<i32 as PlcType>::to_repr(&self.f149).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f150).as_bytes());
        b.extend_from_slice(<i8 as PlcType>::to_repr(&self.f151).as_bytes());
        b.extend_from_slice(<i32 as PlcType>::to_repr(&self.f152).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f153).as_bytes());
        b.extend_from_slice(<i8 as PlcType>::to_repr(&self.f154).as_bytes());
        b.extend_from_slice(<i32 as PlcType>::to_repr(&self.f155).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f156).as_bytes());
        b.extend_from_slice(<i8 as PlcType>::to_repr(&self.f157).as_bytes());
        b.extend_from_slice(<i32 as PlcType>::to_repr(&self.f158).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f159).as_bytes());
        b.extend_from_slice(<i8 as PlcType>::to_repr(&self.f160).as_bytes());
        b.extend_from_slice(<i32 as PlcType>::to_repr(&self.f161).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f162).as_bytes());
        b.extend_from_slice(<i8 as PlcType>::to_repr(&self.f163).as_bytes());
        b.extend_from_slice(<i32 as PlcType>::to_repr(&self.f164).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f165).as_bytes());
        b.extend_from_slice(<i8 as PlcType>::to_repr(&self.f166).as_bytes());
        b.extend_from_slice(<i32 as PlcType>::to_repr(&self.f167).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f168).as_bytes());
        b.extend_from_slice(<i8 as PlcType>::to_repr(&self.f169).as_bytes());
        b.extend_from_slice(<i32 as PlcType>::to_repr(&self.f170).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f171).as_bytes());
        b.extend_from_slice(<i8 as PlcType>::to_repr(&self.f172).as_bytes());
        b.extend_from_slice(<i32 as PlcType>::to_repr(&self.f173).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f174).as_bytes());
        b.extend_from_slice(<i8 as PlcType>::to_repr(&self.f175).as_bytes());
        b.extend_from_slice(<i32 as PlcType>::to_repr(&self.f176).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f177).as_bytes());
        b.extend_from_slice(<i8 as PlcType>::to_repr(&self.f178).as_bytes());
        b.extend_from_slice(<i32 as PlcType>::to_repr(&self.f179).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f180).as_bytes());
        b.extend_from_slice(<i8 as PlcType>::to_repr(&self.f181).as_bytes());
        b.extend_from_slice(<i32 as PlcType>::to_repr(&self.f182).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f183).as_bytes());
        b.extend_from_slice(<i8 as PlcType>::to_repr(&self.f184).as_bytes());
        b.extend_from_slice(<i32 as PlcType>::to_repr(&self.f185).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f186).as_bytes());
        b.extend_from_slice(<i8 as PlcType>::to_repr(&self.f187).as_bytes());
        b.extend_from_slice(<i32 as PlcType>::to_repr(&self.f188).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f189).as_bytes());
        b.extend_from_slice(<i8 as PlcType>::to_repr(&self.f190).as_bytes());
        b.extend_from_slice(<i32 as PlcType>::to_repr(&self.f191).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f192).as_bytes());
        b.extend_from_slice(<i8 as PlcType>::to_repr(&self.f193).as_bytes());
        b.extend_from_slice(<i32 as PlcType>::to_repr(&self.f194).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f195).as_bytes());
        b.extend_from_slice(<i8 as PlcType>::to_repr(&self.f196).as_bytes());
        b.extend_from_slice(<i32 as PlcType>::to_repr(&self.f197).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f198).as_bytes());
        b.extend_from_slice(<i8 as PlcType>::to_repr(&self.f199).as_bytes());
        b.extend_from_slice(<i32 as PlcType>::to_repr(&self.f200).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f201).as_bytes());
        b.extend_from_slice(<i8 as PlcType>::to_repr(&self.f202).as_bytes());
        b.extend_from_slice(<i32 as PlcType>::to_repr(&self.f203).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f204).as_bytes());
        b.extend_from_slice(<i8 as PlcType>::to_repr(&self.f205).as_bytes());
        b.extend_from_slice(<i32 as PlcType>::to_repr(&self.f206).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f207).as_bytes());
        b.extend_from_slice(<i8 as PlcType>::to_repr(&self.f208).as_bytes());
        b.extend_from_slice(<i32 as PlcType>::to_repr(&self.f209).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f210).as_bytes());
        b.extend_from_slice(<i8 as PlcType>::to_repr(&self.f211).as_bytes());
        b.extend_from_slice(<i32 as PlcType>::to_repr(&self.f212).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f213).as_bytes());
        b.extend_from_slice(<i8 as PlcType>::to_repr(&self.f214).as_bytes());
        b.extend_from_slice(<i32 as PlcType>::to_repr(&self.f215).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f216).as_bytes());
        b.extend_from_slice(<i8 as PlcType>::to_repr(&self.f217).as_bytes());
        b.extend_from_slice(<i32 as PlcType>::to_repr(&self.f218).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f219).as_bytes());
        b.extend_from_slice(<i8 as PlcType>::to_repr(&self.f220).as_bytes());
        b.extend_from_slice(<i32 as PlcType>::to_repr(&self.f221).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f222).as_bytes());
        b.extend_from_slice(<i8 as PlcType>::to_repr(&self.f223).as_bytes());
        b.extend_from_slice(<i32 as PlcType>::to_repr(&self.f224).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f225).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f226).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f227).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f228).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f229).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f230).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f231).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f232).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f233).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f234).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f235).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f236).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f237).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f238).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f239).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f240).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f241).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f242).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f243).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f244).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f245).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f246).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f247).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f248).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f249).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f250).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f251).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f252).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f253).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f254).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f255).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f256).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f257).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f258).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f259).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f260).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f261).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f262).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f263).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f264).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f265).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f266).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f267).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f268).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f269).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f270).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f271).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f272).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f273).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f274).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f275).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f276).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f277).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f278).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f279).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f280).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f281).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f282).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f283).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f284).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f285).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f286).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f287).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f288).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f289).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f290).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f291).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f292).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f293).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f294).as_bytes());
        b.extend_from_slice(<i32 as PlcType>::to_repr(&self.f295).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f296).as_bytes());
        b.extend_from_slice(<Pair as PlcType>::to_repr(&self.f297).as_bytes());
        b
    }

    fn reference_load(&mut self, b: &[u8]) {
        let mut at = 0;
        self.f0 = <i32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i32 as PlcType>::Repr>();
        self.f1 = <u16 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u16 as PlcType>::Repr>();
        self.f2 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f3 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f4 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f5 = <u16 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u16 as PlcType>::Repr>();
        self.f6 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f7 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f8 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f9 = <u16 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u16 as PlcType>::Repr>();
        self.f10 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f11 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f12 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f13 = <u16 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u16 as PlcType>::Repr>();
        self.f14 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f15 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f16 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f17 = <u16 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u16 as PlcType>::Repr>();
        self.f18 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f19 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f20 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f21 = <u16 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u16 as PlcType>::Repr>();
        self.f22 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f23 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f24 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f25 = <u16 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u16 as PlcType>::Repr>();
        self.f26 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f27 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f28 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f29 = <u16 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u16 as PlcType>::Repr>();
        self.f30 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f31 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f32 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f33 = <u16 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u16 as PlcType>::Repr>();
        self.f34 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f35 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f36 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f37 = <u16 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u16 as PlcType>::Repr>();
        self.f38 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f39 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f40 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f41 = <u16 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u16 as PlcType>::Repr>();
        self.f42 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f43 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f44 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f45 = <u16 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u16 as PlcType>::Repr>();
        self.f46 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f47 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f48 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f49 = <u16 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u16 as PlcType>::Repr>();
        self.f50 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f51 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f52 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f53 = <u16 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u16 as PlcType>::Repr>();
        self.f54 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f55 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f56 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f57 = <u16 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u16 as PlcType>::Repr>();
        self.f58 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f59 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f60 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f61 = <u16 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u16 as PlcType>::Repr>();
        self.f62 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f63 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f64 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f65 = <u16 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u16 as PlcType>::Repr>();
        self.f66 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f67 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f68 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f69 = <u16 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u16 as PlcType>::Repr>();
        self.f70 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f71 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f72 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f73 = <u16 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u16 as PlcType>::Repr>();
        self.f74 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f75 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f76 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f77 = <u16 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u16 as PlcType>::Repr>();
        self.f78 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f79 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f80 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f81 = <u16 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u16 as PlcType>::Repr>();
        self.f82 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f83 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f84 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f85 = <u16 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u16 as PlcType>::Repr>();
        self.f86 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f87 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f88 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f89 = <u16 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u16 as PlcType>::Repr>();
        self.f90 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f91 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f92 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f93 = <u16 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u16 as PlcType>::Repr>();
        self.f94 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f95 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f96 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f97 = <u16 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u16 as PlcType>::Repr>();
        self.f98 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f99 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f100 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f101 = <u16 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u16 as PlcType>::Repr>();
        self.f102 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f103 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f104 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f105 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f106 = <f64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<f64 as PlcType>::Repr>();
        self.f107 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f108 = <u8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u8 as PlcType>::Repr>();
        self.f109 = <f64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<f64 as PlcType>::Repr>();
        self.f110 = <[Pair; 2] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[Pair; 2] as PlcType>::Repr>();
        self.f111 = <u16 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u16 as PlcType>::Repr>();
        self.f112 = <u16 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u16 as PlcType>::Repr>();
        self.f113 = <u16 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u16 as PlcType>::Repr>();
        self.f114 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f115 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f116 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f117 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f118 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f119 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f120 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f121 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f122 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f123 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f124 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f125 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f126 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f127 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f128 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f129 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f130 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f131 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f132 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f133 = <u16 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u16 as PlcType>::Repr>();
        self.f134 = <u16 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u16 as PlcType>::Repr>();
        self.f135 = <u16 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u16 as PlcType>::Repr>();
        self.f136 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f137 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f138 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f139 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f140 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f141 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f142 = <i8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i8 as PlcType>::Repr>();
        self.f143 = <i32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i32 as PlcType>::Repr>();
        self.f144 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f145 = <i8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i8 as PlcType>::Repr>();
        self.f146 = <i32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i32 as PlcType>::Repr>();
        self.f147 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f148 = <i8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i8 as PlcType>::Repr>();
        self.f149 = <i32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i32 as PlcType>::Repr>();
        self.f150 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f151 = <i8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i8 as PlcType>::Repr>();
        self.f152 = <i32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i32 as PlcType>::Repr>();
        self.f153 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f154 = <i8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i8 as PlcType>::Repr>();
        self.f155 = <i32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i32 as PlcType>::Repr>();
        self.f156 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f157 = <i8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i8 as PlcType>::Repr>();
        self.f158 = <i32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i32 as PlcType>::Repr>();
        self.f159 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f160 = <i8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i8 as PlcType>::Repr>();
        self.f161 = <i32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i32 as PlcType>::Repr>();
        self.f162 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f163 = <i8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i8 as PlcType>::Repr>();
        self.f164 = <i32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i32 as PlcType>::Repr>();
        self.f165 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f166 = <i8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i8 as PlcType>::Repr>();
        self.f167 = <i32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i32 as PlcType>::Repr>();
        self.f168 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f169 = <i8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i8 as PlcType>::Repr>();
        self.f170 = <i32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i32 as PlcType>::Repr>();
        self.f171 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f172 = <i8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i8 as PlcType>::Repr>();
        self.f173 = <i32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i32 as PlcType>::Repr>();
        self.f174 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f175 = <i8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i8 as PlcType>::Repr>();
        self.f176 = <i32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i32 as PlcType>::Repr>();
        self.f177 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f178 = <i8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i8 as PlcType>::Repr>();
        self.f179 = <i32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i32 as PlcType>::Repr>();
        self.f180 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f181 = <i8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i8 as PlcType>::Repr>();
        self.f182 = <i32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i32 as PlcType>::Repr>();
        self.f183 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f184 = <i8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i8 as PlcType>::Repr>();
        self.f185 = <i32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i32 as PlcType>::Repr>();
        self.f186 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f187 = <i8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i8 as PlcType>::Repr>();
        self.f188 = <i32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i32 as PlcType>::Repr>();
        self.f189 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f190 = <i8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i8 as PlcType>::Repr>();
        self.f191 = <i32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i32 as PlcType>::Repr>();
        self.f192 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f193 = <i8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i8 as PlcType>::Repr>();
        self.f194 = <i32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i32 as PlcType>::Repr>();
        self.f195 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f196 = <i8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i8 as PlcType>::Repr>();
        self.f197 = <i32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i32 as PlcType>::Repr>();
        self.f198 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f199 = <i8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i8 as PlcType>::Repr>();
        self.f200 = <i32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i32 as PlcType>::Repr>();
        self.f201 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f202 = <i8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i8 as PlcType>::Repr>();
        self.f203 = <i32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i32 as PlcType>::Repr>();
        self.f204 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f205 = <i8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i8 as PlcType>::Repr>();
        self.f206 = <i32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i32 as PlcType>::Repr>();
        self.f207 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f208 = <i8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i8 as PlcType>::Repr>();
        self.f209 = <i32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i32 as PlcType>::Repr>();
        self.f210 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f211 = <i8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i8 as PlcType>::Repr>();
        self.f212 = <i32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i32 as PlcType>::Repr>();
        self.f213 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f214 = <i8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i8 as PlcType>::Repr>();
        self.f215 = <i32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i32 as PlcType>::Repr>();
        self.f216 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f217 = <i8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i8 as PlcType>::Repr>();
        self.f218 = <i32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i32 as PlcType>::Repr>();
        self.f219 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f220 = <i8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i8 as PlcType>::Repr>();
        self.f221 = <i32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i32 as PlcType>::Repr>();
        self.f222 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f223 = <i8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i8 as PlcType>::Repr>();
        self.f224 = <i32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i32 as PlcType>::Repr>();
        self.f225 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f226 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f227 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f228 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f229 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f230 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f231 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f232 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f233 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f234 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f235 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f236 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f237 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f238 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f239 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f240 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f241 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f242 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f243 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f244 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f245 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f246 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f247 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f248 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f249 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f250 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f251 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f252 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f253 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f254 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f255 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f256 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f257 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f258 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f259 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f260 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f261 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f262 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f263 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f264 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f265 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f266 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f267 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f268 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f269 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f270 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f271 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f272 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f273 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f274 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f275 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f276 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f277 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f278 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f279 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f280 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f281 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f282 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f283 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f284 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f285 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f286 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f287 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f288 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f289 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f290 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f291 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f292 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f293 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f294 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f295 = <i32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i32 as PlcType>::Repr>();
        self.f296 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f297 = <Pair as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Pair as PlcType>::Repr>();
        assert_eq!(at, b.len());
    }

    fn reference_unpack(&mut self) {
        self.f114 = (self.f111 >> 15) & 1 != 0;
        self.f115 = (self.f112 >> 14) & 1 != 0;
        self.f116 = (self.f111 >> 4) & 1 != 0;
        self.f117 = (self.f113 >> 15) & 1 != 0;
        self.f118 = (self.f113 >> 13) & 1 != 0;
        self.f119 = (self.f113 >> 5) & 1 != 0;
        self.f120 = (self.f113 >> 12) & 1 != 0;
        self.f121 = (self.f113 >> 2) & 1 != 0;
        self.f122 = (self.f112 >> 9) & 1 != 0;
        self.f123 = (self.f113 >> 0) & 1 != 0;
        self.f124 = (self.f111 >> 2) & 1 != 0;
        self.f125 = (self.f111 >> 5) & 1 != 0;
        self.f126 = (self.f111 >> 12) & 1 != 0;
        self.f127 = (self.f111 >> 9) & 1 != 0;
        self.f128 = (self.f112 >> 2) & 1 != 0;
        self.f129 = (self.f111 >> 6) & 1 != 0;
        self.f130 = (self.f113 >> 9) & 1 != 0;
        self.f131 = (self.f112 >> 6) & 1 != 0;
        self.f132 = (self.f112 >> 8) & 1 != 0;
        self.f136 = (self.f133 >> 5) & 1 != 0;
        self.f137 = (self.f134 >> 1) & 1 != 0;
        self.f138 = (self.f134 >> 14) & 1 != 0;
        self.f139 = (self.f135 >> 9) & 1 != 0;
        self.f140 = (self.f134 >> 12) & 1 != 0;
        self.f232 = (self.f225 >> 6) & 1 != 0;
        self.f233 = (self.f225 >> 7) & 1 != 0;
        self.f234 = (self.f225 >> 8) & 1 != 0;
        self.f235 = (self.f225 >> 9) & 1 != 0;
        self.f236 = (self.f225 >> 10) & 1 != 0;
        self.f237 = (self.f225 >> 11) & 1 != 0;
        self.f238 = (self.f225 >> 12) & 1 != 0;
        self.f239 = (self.f225 >> 13) & 1 != 0;
        self.f240 = (self.f225 >> 14) & 1 != 0;
        self.f241 = (self.f226 >> 6) & 1 != 0;
        self.f242 = (self.f226 >> 7) & 1 != 0;
        self.f243 = (self.f226 >> 8) & 1 != 0;
        self.f244 = (self.f226 >> 9) & 1 != 0;
        self.f245 = (self.f226 >> 10) & 1 != 0;
        self.f246 = (self.f226 >> 11) & 1 != 0;
        self.f247 = (self.f226 >> 12) & 1 != 0;
        self.f248 = (self.f226 >> 13) & 1 != 0;
        self.f249 = (self.f226 >> 14) & 1 != 0;
        self.f250 = (self.f227 >> 6) & 1 != 0;
        self.f251 = (self.f227 >> 7) & 1 != 0;
        self.f252 = (self.f227 >> 8) & 1 != 0;
        self.f253 = (self.f227 >> 9) & 1 != 0;
        self.f254 = (self.f227 >> 10) & 1 != 0;
        self.f255 = (self.f227 >> 11) & 1 != 0;
        self.f256 = (self.f227 >> 12) & 1 != 0;
        self.f257 = (self.f227 >> 13) & 1 != 0;
        self.f258 = (self.f227 >> 14) & 1 != 0;
        self.f259 = (self.f228 >> 6) & 1 != 0;
        self.f260 = (self.f228 >> 7) & 1 != 0;
        self.f261 = (self.f228 >> 8) & 1 != 0;
        self.f262 = (self.f228 >> 9) & 1 != 0;
        self.f263 = (self.f228 >> 10) & 1 != 0;
        self.f264 = (self.f228 >> 11) & 1 != 0;
        self.f265 = (self.f228 >> 12) & 1 != 0;
        self.f266 = (self.f228 >> 13) & 1 != 0;
        self.f267 = (self.f228 >> 14) & 1 != 0;
        self.f268 = (self.f229 >> 6) & 1 != 0;
        self.f269 = (self.f229 >> 7) & 1 != 0;
        self.f270 = (self.f229 >> 8) & 1 != 0;
        self.f271 = (self.f229 >> 9) & 1 != 0;
        self.f272 = (self.f229 >> 10) & 1 != 0;
        self.f273 = (self.f229 >> 11) & 1 != 0;
        self.f274 = (self.f229 >> 12) & 1 != 0;
        self.f275 = (self.f229 >> 13) & 1 != 0;
        self.f276 = (self.f229 >> 14) & 1 != 0;
        self.f277 = (self.f230 >> 6) & 1 != 0;
        self.f278 = (self.f230 >> 7) & 1 != 0;
        self.f279 = (self.f230 >> 8) & 1 != 0;
        self.f280 = (self.f230 >> 9) & 1 != 0;
        self.f281 = (self.f230 >> 10) & 1 != 0;
        self.f282 = (self.f230 >> 11) & 1 != 0;
        self.f283 = (self.f230 >> 12) & 1 != 0;
        self.f284 = (self.f230 >> 13) & 1 != 0;
        self.f285 = (self.f230 >> 14) & 1 != 0;
        self.f286 = (self.f231 >> 6) & 1 != 0;
        self.f287 = (self.f231 >> 7) & 1 != 0;
        self.f288 = (self.f231 >> 8) & 1 != 0;
        self.f289 = (self.f231 >> 9) & 1 != 0;
        self.f290 = (self.f231 >> 10) & 1 != 0;
        self.f291 = (self.f231 >> 11) & 1 != 0;
        self.f292 = (self.f231 >> 12) & 1 != 0;
        self.f293 = (self.f231 >> 13) & 1 != 0;
        self.f294 = (self.f231 >> 14) & 1 != 0;
        self.reference_unpack_nested();
    }

    fn reference_pack(&mut self) {
        self.reference_pack_nested();
        self.f111 = (self.f111 & !(1 << 15)) | ((self.f114 as u16) << 15);
        self.f112 = (self.f112 & !(1 << 14)) | ((self.f115 as u16) << 14);
        self.f111 = (self.f111 & !(1 << 4)) | ((self.f116 as u16) << 4);
        self.f113 = (self.f113 & !(1 << 15)) | ((self.f117 as u16) << 15);
        self.f113 = (self.f113 & !(1 << 13)) | ((self.f118 as u16) << 13);
        self.f113 = (self.f113 & !(1 << 5)) | ((self.f119 as u16) << 5);
        self.f113 = (self.f113 & !(1 << 12)) | ((self.f120 as u16) << 12);
        self.f113 = (self.f113 & !(1 << 2)) | ((self.f121 as u16) << 2);
        self.f112 = (self.f112 & !(1 << 9)) | ((self.f122 as u16) << 9);
        self.f113 = (self.f113 & !(1 << 0)) | ((self.f123 as u16) << 0);
        self.f111 = (self.f111 & !(1 << 2)) | ((self.f124 as u16) << 2);
        self.f111 = (self.f111 & !(1 << 5)) | ((self.f125 as u16) << 5);
        self.f111 = (self.f111 & !(1 << 12)) | ((self.f126 as u16) << 12);
        self.f111 = (self.f111 & !(1 << 9)) | ((self.f127 as u16) << 9);
        self.f112 = (self.f112 & !(1 << 2)) | ((self.f128 as u16) << 2);
        self.f111 = (self.f111 & !(1 << 6)) | ((self.f129 as u16) << 6);
        self.f113 = (self.f113 & !(1 << 9)) | ((self.f130 as u16) << 9);
        self.f112 = (self.f112 & !(1 << 6)) | ((self.f131 as u16) << 6);
        self.f112 = (self.f112 & !(1 << 8)) | ((self.f132 as u16) << 8);
        self.f133 = (self.f133 & !(1 << 5)) | ((self.f136 as u16) << 5);
        self.f134 = (self.f134 & !(1 << 1)) | ((self.f137 as u16) << 1);
        self.f134 = (self.f134 & !(1 << 14)) | ((self.f138 as u16) << 14);
        self.f135 = (self.f135 & !(1 << 9)) | ((self.f139 as u16) << 9);
        self.f134 = (self.f134 & !(1 << 12)) | ((self.f140 as u16) << 12);
        self.f225 = (self.f225 & !(1 << 6)) | ((self.f232 as Word) << 6);
        self.f225 = (self.f225 & !(1 << 7)) | ((self.f233 as Word) << 7);
        self.f225 = (self.f225 & !(1 << 8)) | ((self.f234 as Word) << 8);
        self.f225 = (self.f225 & !(1 << 9)) | ((self.f235 as Word) << 9);
        self.f225 = (self.f225 & !(1 << 10)) | ((self.f236 as Word) << 10);
        self.f225 = (self.f225 & !(1 << 11)) | ((self.f237 as Word) << 11);
        self.f225 = (self.f225 & !(1 << 12)) | ((self.f238 as Word) << 12);
        self.f225 = (self.f225 & !(1 << 13)) | ((self.f239 as Word) << 13);
        self.f225 = (self.f225 & !(1 << 14)) | ((self.f240 as Word) << 14);
        self.f226 = (self.f226 & !(1 << 6)) | ((self.f241 as Word) << 6);
        self.f226 = (self.f226 & !(1 << 7)) | ((self.f242 as Word) << 7);
        self.f226 = (self.f226 & !(1 << 8)) | ((self.f243 as Word) << 8);
        self.f226 = (self.f226 & !(1 << 9)) | ((self.f244 as Word) << 9);
        self.f226 = (self.f226 & !(1 << 10)) | ((self.f245 as Word) << 10);
        self.f226 = (self.f226 & !(1 << 11)) | ((self.f246 as Word) << 11);
        self.f226 = (self.f226 & !(1 << 12)) | ((self.f247 as Word) << 12);
        self.f226 = (self.f226 & !(1 << 13)) | ((self.f248 as Word) << 13);
        self.f226 = (self.f226 & !(1 << 14)) | ((self.f249 as Word) << 14);
        self.f227 = (self.f227 & !(1 << 6)) | ((self.f250 as Word) << 6);
        self.f227 = (self.f227 & !(1 << 7)) | ((self.f251 as Word) << 7);
        self.f227 = (self.f227 & !(1 << 8)) | ((self.f252 as Word) << 8);
        self.f227 = (self.f227 & !(1 << 9)) | ((self.f253 as Word) << 9);
        self.f227 = (self.f227 & !(1 << 10)) | ((self.f254 as Word) << 10);
        self.f227 = (self.f227 & !(1 << 11)) | ((self.f255 as Word) << 11);
        self.f227 = (self.f227 & !(1 << 12)) | ((self.f256 as Word) << 12);
        self.f227 = (self.f227 & !(1 << 13)) | ((self.f257 as Word) << 13);
        self.f227 = (self.f227 & !(1 << 14)) | ((self.f258 as Word) << 14);
        self.f228 = (self.f228 & !(1 << 6)) | ((self.f259 as Word) << 6);
        self.f228 = (self.f228 & !(1 << 7)) | ((self.f260 as Word) << 7);
        self.f228 = (self.f228 & !(1 << 8)) | ((self.f261 as Word) << 8);
        self.f228 = (self.f228 & !(1 << 9)) | ((self.f262 as Word) << 9);
        self.f228 = (self.f228 & !(1 << 10)) | ((self.f263 as Word) << 10);
        self.f228 = (self.f228 & !(1 << 11)) | ((self.f264 as Word) << 11);
        self.f228 = (self.f228 & !(1 << 12)) | ((self.f265 as Word) << 12);
        self.f228 = (self.f228 & !(1 << 13)) | ((self.f266 as Word) << 13);
        self.f228 = (self.f228 & !(1 << 14)) | ((self.f267 as Word) << 14);
        self.f229 = (self.f229 & !(1 << 6)) | ((self.f268 as Word) << 6);
        self.f229 = (self.f229 & !(1 << 7)) | ((self.f269 as Word) << 7);
        self.f229 = (self.f229 & !(1 << 8)) | ((self.f270 as Word) << 8);
        self.f229 = (self.f229 & !(1 << 9)) | ((self.f271 as Word) << 9);
        self.f229 = (self.f229 & !(1 << 10)) | ((self.f272 as Word) << 10);
        self.f229 = (self.f229 & !(1 << 11)) | ((self.f273 as Word) << 11);
        self.f229 = (self.f229 & !(1 << 12)) | ((self.f274 as Word) << 12);
        self.f229 = (self.f229 & !(1 << 13)) | ((self.f275 as Word) << 13);
        self.f229 = (self.f229 & !(1 << 14)) | ((self.f276 as Word) << 14);
        self.f230 = (self.f230 & !(1 << 6)) | ((self.f277 as Word) << 6);
        self.f230 = (self.f230 & !(1 << 7)) | ((self.f278 as Word) << 7);
        self.f230 = (self.f230 & !(1 << 8)) | ((self.f279 as Word) << 8);
        self.f230 = (self.f230 & !(1 << 9)) | ((self.f280 as Word) << 9);
        self.f230 = (self.f230 & !(1 << 10)) | ((self.f281 as Word) << 10);
        self.f230 = (self.f230 & !(1 << 11)) | ((self.f282 as Word) << 11);
        self.f230 = (self.f230 & !(1 << 12)) | ((self.f283 as Word) << 12);
        self.f230 = (self.f230 & !(1 << 13)) | ((self.f284 as Word) << 13);
        self.f230 = (self.f230 & !(1 << 14)) | ((self.f285 as Word) << 14);
        self.f231 = (self.f231 & !(1 << 6)) | ((self.f286 as Word) << 6);
        self.f231 = (self.f231 & !(1 << 7)) | ((self.f287 as Word) << 7);
        self.f231 = (self.f231 & !(1 << 8)) | ((self.f288 as Word) << 8);
        self.f231 = (self.f231 & !(1 << 9)) | ((self.f289 as Word) << 9);
        self.f231 = (self.f231 & !(1 << 10)) | ((self.f290 as Word) << 10);
        self.f231 = (self.f231 & !(1 << 11)) | ((self.f291 as Word) << 11);
        self.f231 = (self.f231 & !(1 << 12)) | ((self.f292 as Word) << 12);
        self.f231 = (self.f231 & !(1 << 13)) | ((self.f293 as Word) << 13);
        self.f231 = (self.f231 & !(1 << 14)) | ((self.f294 as Word) << 14);
    }

    fn reference_unpack_nested(&mut self) {
        self.f110.iter_mut().for_each(Pair::reference_unpack);
        self.f297.reference_unpack();
    }

    fn reference_pack_nested(&mut self) {
        self.f110.iter_mut().for_each(Pair::reference_pack);
        self.f297.reference_pack();
    }
}


#[derive(GlobalMemory, Debug, Clone)]
pub struct Random1 {
    pub f0: Word,
    pub f1: i64,
    pub f2: i16,
    pub f3: Word,
    pub f4: i64,
    pub f5: i16,
    pub f6: Word,
    pub f7: i64,
    pub f8: i16,
    pub f9: Word,
    pub f10: i64,
    pub f11: i16,
    pub f12: Word,
    pub f13: i64,
    pub f14: i16,
    pub f15: Word,
    pub f16: i64,
    pub f17: i16,
    pub f18: Word,
    pub f19: i64,
    pub f20: i16,
    pub f21: Word,
    pub f22: i64,
    pub f23: i16,
    pub f24: Word,
    pub f25: i64,
    pub f26: i16,
    pub f27: Word,
    pub f28: i64,
    pub f29: i16,
    pub f30: Word,
    pub f31: i64,
    pub f32: i16,
    pub f33: Word,
    pub f34: i64,
    pub f35: i16,
    pub f36: Word,
    pub f37: i64,
    pub f38: i16,
    pub f39: Word,
    pub f40: i64,
    pub f41: i16,
    pub f42: Word,
    pub f43: i64,
    pub f44: i16,
    pub f45: u16,
    pub f46: u16,
    pub f47: u16,
    #[plc(source = "f45", bit = 11)]
    pub f48: bool,
    #[plc(source = "f45", bit = 5)]
    pub f49: bool,
    #[plc(source = "f47", bit = 9)]
    pub f50: bool,
    #[plc(source = "f47", bit = 13)]
    pub f51: bool,
    #[plc(source = "f45", bit = 0)]
    pub f52: bool,
    #[plc(source = "f45", bit = 3)]
    pub f53: bool,
    #[plc(source = "f47", bit = 4)]
    pub f54: bool,
    #[plc(source = "f45", bit = 1)]
    pub f55: bool,
    #[plc(source = "f46", bit = 10)]
    pub f56: bool,
    #[plc(source = "f45", bit = 13)]
    pub f57: bool,
    #[plc(source = "f46", bit = 15)]
    pub f58: bool,
    #[plc(source = "f45", bit = 10)]
    pub f59: bool,
    #[plc(source = "f45", bit = 7)]
    pub f60: bool,
    #[plc(source = "f45", bit = 2)]
    pub f61: bool,
    pub f62: [Pair; 2],
    pub f63: i64,
    pub f64: i32,
    pub f65: i8,
    pub f66: i32,
    pub f67: Pair,
    pub f68: u64,
    pub f69: [[i8; 2]; 2],
    pub f70: u64,
    pub f71: i32,
    pub f72: Pair,
    pub f73: u64,
    pub f74: [[i8; 2]; 2],
    pub f75: u64,
    pub f76: i32,
    pub f77: Pair,
    pub f78: u64,
    pub f79: [[i8; 2]; 2],
    pub f80: u64,
    pub f81: i32,
    pub f82: Pair,
    pub f83: u64,
    pub f84: [[i8; 2]; 2],
    pub f85: u64,
    pub f86: i32,
    pub f87: Pair,
    pub f88: u64,
    pub f89: [[i8; 2]; 2],
    pub f90: u64,
    pub f91: i32,
    pub f92: Pair,
    pub f93: u64,
    pub f94: [[i8; 2]; 2],
    pub f95: u64,
    pub f96: i32,
    pub f97: Pair,
    pub f98: u64,
    pub f99: [[i8; 2]; 2],
    pub f100: u64,
    pub f101: i32,
    pub f102: Pair,
    pub f103: u64,
    pub f104: [[i8; 2]; 2],
    pub f105: u64,
    pub f106: i32,
    pub f107: Pair,
    pub f108: u64,
    pub f109: [[i8; 2]; 2],
    pub f110: u64,
    pub f111: i32,
    pub f112: Pair,
    pub f113: u64,
    pub f114: [[i8; 2]; 2],
    pub f115: u64,
    pub f116: i32,
    pub f117: Pair,
    pub f118: u64,
    pub f119: [[i8; 2]; 2],
    pub f120: u64,
    pub f121: u16,
    pub f122: u16,
    pub f123: u16,
    #[plc(source = "f121", bit = 11)]
    pub f124: bool,
    #[plc(source = "f122", bit = 11)]
    pub f125: bool,
    #[plc(source = "f121", bit = 9)]
    pub f126: bool,
    #[plc(source = "f123", bit = 3)]
    pub f127: bool,
    #[plc(source = "f123", bit = 7)]
    pub f128: bool,
    #[plc(source = "f122", bit = 10)]
    pub f129: bool,
    #[plc(source = "f123", bit = 13)]
    pub f130: bool,
    #[plc(source = "f122", bit = 9)]
    pub f131: bool,
    #[plc(source = "f121", bit = 8)]
    pub f132: bool,
    #[plc(source = "f122", bit = 0)]
    pub f133: bool,
    #[plc(source = "f122", bit = 13)]
    pub f134: bool,
    pub f135: [u16; 3],
    pub f136: FixedString<5>,
    pub f137: Flag,
    pub f138: Word,
    pub f139: [u16; 3],
    pub f140: [u16; 3],
    pub f141: FixedString<5>,
    pub f142: Flag,
    pub f143: Word,
    pub f144: [u16; 3],
    pub f145: [u16; 3],
    pub f146: FixedString<5>,
    pub f147: Flag,
    pub f148: Word,
    pub f149: [u16; 3],
    pub f150: [u16; 3],
    pub f151: FixedString<5>,
    pub f152: Flag,
    pub f153: Word,
    pub f154: [u16; 3],
    pub f155: [u16; 3],
    pub f156: FixedString<5>,
    pub f157: Flag,
    pub f158: Word,
    pub f159: [u16; 3],
    pub f160: [u16; 3],
    pub f161: FixedString<5>,
    pub f162: Flag,
    pub f163: Word,
    pub f164: [u16; 3],
    pub f165: [u16; 3],
    pub f166: FixedString<5>,
    pub f167: Flag,
    pub f168: Word,
    pub f169: [u16; 3],
    pub f170: [u16; 3],
    pub f171: FixedString<5>,
    pub f172: Flag,
    pub f173: Word,
    pub f174: [u16; 3],
    pub f175: [u16; 3],
    pub f176: FixedString<5>,
    pub f177: Flag,
    pub f178: Word,
    pub f179: [u16; 3],
    pub f180: [u16; 3],
    pub f181: FixedString<5>,
    pub f182: Flag,
    pub f183: Word,
    pub f184: [u16; 3],
    pub f185: [u16; 3],
    pub f186: FixedString<5>,
    pub f187: Flag,
    pub f188: Word,
    pub f189: [u16; 3],
    pub f190: [u16; 3],
    pub f191: FixedString<5>,
    pub f192: Flag,
    pub f193: Word,
    pub f194: [u16; 3],
    pub f195: [u16; 3],
    pub f196: FixedString<5>,
    pub f197: Flag,
    pub f198: Word,
    pub f199: [u16; 3],
    pub f200: [u16; 3],
    pub f201: FixedString<5>,
    pub f202: Flag,
    pub f203: Word,
    pub f204: [u16; 3],
    pub f205: [u16; 3],
    pub f206: FixedString<5>,
    pub f207: Flag,
    pub f208: Word,
    pub f209: [u16; 3],
    pub f210: [u16; 3],
    pub f211: FixedString<5>,
    pub f212: Flag,
    pub f213: Word,
    pub f214: [u16; 3],
    pub f215: [u16; 3],
    pub f216: FixedString<5>,
    pub f217: Flag,
    pub f218: Word,
    pub f219: [u16; 3],
    pub f220: [u16; 3],
    pub f221: FixedString<5>,
    pub f222: Flag,
    pub f223: Word,
    pub f224: [u16; 3],
    pub f225: [u16; 3],
    pub f226: FixedString<5>,
    pub f227: Flag,
    pub f228: Word,
    pub f229: [u16; 3],
    pub f230: [u16; 3],
    pub f231: FixedString<5>,
    pub f232: Flag,
    pub f233: Word,
    pub f234: [u16; 3],
    pub f235: [u16; 3],
    pub f236: FixedString<5>,
    pub f237: Flag,
    pub f238: Word,
    pub f239: [u16; 3],
    pub f240: [u16; 3],
    pub f241: FixedString<5>,
    pub f242: Flag,
    pub f243: Word,
    pub f244: [u16; 3],
    pub f245: [u16; 3],
    pub f246: FixedString<5>,
    pub f247: Flag,
    pub f248: Word,
    pub f249: [u16; 3],
    pub f250: [u16; 3],
    pub f251: FixedString<5>,
    pub f252: Flag,
    pub f253: Word,
    pub f254: [u16; 3],
    pub f255: [u16; 3],
    pub f256: FixedString<5>,
    pub f257: Flag,
    pub f258: Word,
    pub f259: [u16; 3],
    pub f260: [u16; 3],
    pub f261: FixedString<5>,
    pub f262: Flag,
    pub f263: Word,
    pub f264: [u16; 3],
    pub f265: Flag,
    pub f266: bool,
    pub f267: [Pair; 2],
    pub f268: [[i8; 2]; 2],
    pub f269: [u16; 3],
    pub f270: f32,
    pub f271: [u16; 3],
    pub f272: [u16; 3],
    pub f273: u16,
    pub f274: [[i8; 2]; 2],
}

impl Reference for Random1 {
    fn reference_store(&self) -> Vec<u8> {
        let mut b = Vec::new();
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f0).as_bytes());
        b.extend_from_slice(<i64 as PlcType>::to_repr(&self.f1).as_bytes());
        b.extend_from_slice(<i16 as PlcType>::to_repr(&self.f2).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f3).as_bytes());
        b.extend_from_slice(<i64 as PlcType>::to_repr(&self.f4).as_bytes());
        b.extend_from_slice(<i16 as PlcType>::to_repr(&self.f5).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f6).as_bytes());
        b.extend_from_slice(<i64 as PlcType>::to_repr(&self.f7).as_bytes());
        b.extend_from_slice(<i16 as PlcType>::to_repr(&self.f8).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f9).as_bytes());
        b.extend_from_slice(<i64 as PlcType>::to_repr(&self.f10).as_bytes());
        b.extend_from_slice(<i16 as PlcType>::to_repr(&self.f11).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f12).as_bytes());
        b.extend_from_slice(<i64 as PlcType>::to_repr(&self.f13).as_bytes());
        b.extend_from_slice(<i16 as PlcType>::to_repr(&self.f14).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f15).as_bytes());
        b.extend_from_slice(<i64 as PlcType>::to_repr(&self.f16).as_bytes());
        b.extend_from_slice(<i16 as PlcType>::to_repr(&self.f17).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f18).as_bytes());
        b.extend_from_slice(<i64 as PlcType>::to_repr(&self.f19).as_bytes());
        b.extend_from_slice(<i16 as PlcType>::to_repr(&self.f20).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f21).as_bytes());
        b.extend_from_slice(<i64 as PlcType>::to_repr(&self.f22).as_bytes());
        b.extend_from_slice(<i16 as PlcType>::to_repr(&self.f23).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f24).as_bytes());
        b.extend_from_slice(<i64 as PlcType>::to_repr(&self.f25).as_bytes());
        b.extend_from_slice(<i16 as PlcType>::to_repr(&self.f26).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f27).as_bytes());
        b.extend_from_slice(<i64 as PlcType>::to_repr(&self.f28).as_bytes());
        b.extend_from_slice(<i16 as PlcType>::to_repr(&self.f29).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f30).as_bytes());
        b.extend_from_slice(<i64 as PlcType>::to_repr(&self.f31).as_bytes());
        b.extend_from_slice(<i16 as PlcType>::to_repr(&self.f32).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f33).as_bytes());
        b.extend_from_slice(<i64 as PlcType>::to_repr(&self.f34).as_bytes());
        b.extend_from_slice(<i16 as PlcType>::to_repr(&self.f35).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f36).as_bytes());
        b.extend_from_slice(<i64 as PlcType>::to_repr(&self.f37).as_bytes());
        b.extend_from_slice(<i16 as PlcType>::to_repr(&self.f38).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f39).as_bytes());
        b.extend_from_slice(<i64 as PlcType>::to_repr(&self.f40).as_bytes());
        b.extend_from_slice(<i16 as PlcType>::to_repr(&self.f41).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f42).as_bytes());
        b.extend_from_slice(<i64 as PlcType>::to_repr(&self.f43).as_bytes());
        b.extend_from_slice(<i16 as PlcType>::to_repr(&self.f44).as_bytes());
        b.extend_from_slice(<u16 as PlcType>::to_repr(&self.f45).as_bytes());
        b.extend_from_slice(<u16 as PlcType>::to_repr(&self.f46).as_bytes());
        b.extend_from_slice(<u16 as PlcType>::to_repr(&self.f47).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f48).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f49).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f50).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f51).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f52).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f53).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f54).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f55).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f56).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f57).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f58).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f59).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f60).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f61).as_bytes());
        b.extend_from_slice(<[Pair; 2] as PlcType>::to_repr(&self.f62).as_bytes());
        b.extend_from_slice(<i64 as PlcType>::to_repr(&self.f63).as_bytes());
        b.extend_from_slice(<i32 as PlcType>::to_repr(&self.f64).as_bytes());
        b.extend_from_slice(<i8 as PlcType>::to_repr(&self.f65).as_bytes());
        b.extend_from_slice(<i32 as PlcType>::to_repr(&self.f66).as_bytes());
        b.extend_from_slice(<Pair as PlcType>::to_repr(&self.f67).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f68).as_bytes());
        b.extend_from_slice(<[[i8; 2]; 2] as PlcType>::to_repr(&self.f69).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f70).as_bytes());
        b.extend_from_slice(<i32 as PlcType>::to_repr(&self.f71).as_bytes());
        b.extend_from_slice(<Pair as PlcType>::to_repr(&self.f72).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f73).as_bytes());
        b.extend_from_slice(<[[i8; 2]; 2] as PlcType>::to_repr(&self.f74).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f75).as_bytes());
        b.extend_from_slice(<i32 as PlcType>::to_repr(&self.f76).as_bytes());
        b.extend_from_slice(<Pair as PlcType>::to_repr(&self.f77).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f78).as_bytes());
        b.extend_from_slice(<[[i8; 2]; 2] as PlcType>::to_repr(&self.f79).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f80).as_bytes());
        b.extend_from_slice(<i32 as PlcType>::to_repr(&self.f81).as_bytes());
        b.extend_from_slice(<Pair as PlcType>::to_repr(&self.f82).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f83).as_bytes());
        b.extend_from_slice(<[[i8; 2]; 2] as PlcType>::to_repr(&self.f84).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f85).as_bytes());
        b.extend_from_slice(<i32 as PlcType>::to_repr(&self.f86).as_bytes());
        b.extend_from_slice(<Pair as PlcType>::to_repr(&self.f87).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f88).as_bytes());
        b.extend_from_slice(<[[i8; 2]; 2] as PlcType>::to_repr(&self.f89).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f90).as_bytes());
        b.extend_from_slice(<i32 as PlcType>::to_repr(&self.f91).as_bytes());
        b.extend_from_slice(<Pair as PlcType>::to_repr(&self.f92).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f93).as_bytes());
        b.extend_from_slice(<[[i8; 2]; 2] as PlcType>::to_repr(&self.f94).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f95).as_bytes());
        b.extend_from_slice(<i32 as PlcType>::to_repr(&self.f96).as_bytes());
        b.extend_from_slice(<Pair as PlcType>::to_repr(&self.f97).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f98).as_bytes());
        b.extend_from_slice(<[[i8; 2]; 2] as PlcType>::to_repr(&self.f99).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f100).as_bytes());
        b.extend_from_slice(<i32 as PlcType>::to_repr(&self.f101).as_bytes());
        b.extend_from_slice(<Pair as PlcType>::to_repr(&self.f102).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f103).as_bytes());
        b.extend_from_slice(<[[i8; 2]; 2] as PlcType>::to_repr(&self.f104).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f105).as_bytes());
        b.extend_from_slice(<i32 as PlcType>::to_repr(&self.f106).as_bytes());
        b.extend_from_slice(<Pair as PlcType>::to_repr(&self.f107).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f108).as_bytes());
        b.extend_from_slice(<[[i8; 2]; 2] as PlcType>::to_repr(&self.f109).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f110).as_bytes());
        b.extend_from_slice(<i32 as PlcType>::to_repr(&self.f111).as_bytes());
        b.extend_from_slice(<Pair as PlcType>::to_repr(&self.f112).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f113).as_bytes());
        b.extend_from_slice(<[[i8; 2]; 2] as PlcType>::to_repr(&self.f114).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f115).as_bytes());
        b.extend_from_slice(<i32 as PlcType>::to_repr(&self.f116).as_bytes());
        b.extend_from_slice(<Pair as PlcType>::to_repr(&self.f117).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f118).as_bytes());
        b.extend_from_slice(<[[i8; 2]; 2] as PlcType>::to_repr(&self.f119).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f120).as_bytes());
        b.extend_from_slice(<u16 as PlcType>::to_repr(&self.f121).as_bytes());
        b.extend_from_slice(<u16 as PlcType>::to_repr(&self.f122).as_bytes());
        b.extend_from_slice(<u16 as PlcType>::to_repr(&self.f123).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f124).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f125).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f126).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f127).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f128).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f129).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f130).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f131).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f132).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f133).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f134).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f135).as_bytes());
        b.extend_from_slice(<FixedString<5> as PlcType>::to_repr(&self.f136).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f137).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f138).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f139).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f140).as_bytes());
        b.extend_from_slice(<FixedString<5> as PlcType>::to_repr(&self.f141).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f142).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f143).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f144).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f145).as_bytes());
        b.extend_from_slice(<FixedString<5> as PlcType>::to_repr(&self.f146).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f147).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f148).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f149).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f150).as_bytes());
        b.extend_from_slice(<FixedString<5> as PlcType>::to_repr(&self.f151).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f152).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f153).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f154).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f155).as_bytes());
        b.extend_from_slice(<FixedString<5> as PlcType>::to_repr(&self.f156).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f157).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f158).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f159).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f160).as_bytes());
        b.extend_from_slice(<FixedString<5> as PlcType>::to_repr(&self.f161).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f162).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f163).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f164).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f165).as_bytes());
        b.extend_from_slice(<FixedString<5> as PlcType>::to_repr(&self.f166).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f167).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f168).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f169).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f170).as_bytes());
        b.extend_from_slice(<FixedString<5> as PlcType>::to_repr(&self.f171).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f172).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f173).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f174).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f175).as_bytes());
        b.extend_from_slice(<FixedString<5> as PlcType>::to_repr(&self.f176).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f177).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f178).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f179).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f180).as_bytes());
        b.extend_from_slice(<FixedString<5> as PlcType>::to_repr(&self.f181).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f182).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f183).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f184).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f185).as_bytes());
        b.extend_from_slice(<FixedString<5> as PlcType>::to_repr(&self.f186).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f187).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f188).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f189).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f190).as_bytes());
        b.extend_from_slice(<FixedString<5> as PlcType>::to_repr(&self.f191).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f192).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f193).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f194).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f195).as_bytes());
        b.extend_from_slice(<FixedString<5> as PlcType>::to_repr(&self.f196).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f197).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f198).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f199).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f200).as_bytes());
        b.extend_from_slice(<FixedString<5> as PlcType>::to_repr(&self.f201).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f202).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f203).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f204).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f205).as_bytes());
        b.extend_from_slice(<FixedString<5> as PlcType>::to_repr(&self.f206).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f207).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f208).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f209).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f210).as_bytes());
        b.extend_from_slice(<FixedString<5> as PlcType>::to_repr(&self.f211).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f212).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f213).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f214).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f215).as_bytes());
        b.extend_from_slice(<FixedString<5> as PlcType>::to_repr(&self.f216).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f217).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f218).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f219).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f220).as_bytes());
        b.extend_from_slice(<FixedString<5> as PlcType>::to_repr(&self.f221).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f222).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f223).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f224).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f225).as_bytes());
        b.extend_from_slice(<FixedString<5> as PlcType>::to_repr(&self.f226).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f227).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f228).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f229).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f230).as_bytes());
        b.extend_from_slice(<FixedString<5> as PlcType>::to_repr(&self.f231).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f232).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f233).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f234).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f235).as_bytes());
        b.extend_from_slice(<FixedString<5> as PlcType>::to_repr(&self.f236).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f237).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f238).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f239).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f240).as_bytes());
        b.extend_from_slice(<FixedString<5> as PlcType>::to_repr(&self.f241).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f242).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f243).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f244).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f245).as_bytes());
        b.extend_from_slice(<FixedString<5> as PlcType>::to_repr(&self.f246).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f247).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f248).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f249).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f250).as_bytes());
        b.extend_from_slice(<FixedString<5> as PlcType>::to_repr(&self.f251).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f252).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f253).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f254).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f255).as_bytes());
        b.extend_from_slice(<FixedString<5> as PlcType>::to_repr(&self.f256).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f257).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f258).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f259).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f260).as_bytes());
        b.extend_from_slice(<FixedString<5> as PlcType>::to_repr(&self.f261).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f262).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f263).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f264).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f265).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f266).as_bytes());
        b.extend_from_slice(<[Pair; 2] as PlcType>::to_repr(&self.f267).as_bytes());
        b.extend_from_slice(<[[i8; 2]; 2] as PlcType>::to_repr(&self.f268).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f269).as_bytes());
        b.extend_from_slice(<f32 as PlcType>::to_repr(&self.f270).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f271).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f272).as_bytes());
        b.extend_from_slice(<u16 as PlcType>::to_repr(&self.f273).as_bytes());
        b.extend_from_slice(<[[i8; 2]; 2] as PlcType>::to_repr(&self.f274).as_bytes());
        b
    }

    fn reference_load(&mut self, b: &[u8]) {
        let mut at = 0;
        self.f0 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f1 = <i64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i64 as PlcType>::Repr>();
        self.f2 = <i16 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i16 as PlcType>::Repr>();
        self.f3 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f4 = <i64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i64 as PlcType>::Repr>();
        self.f5 = <i16 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i16 as PlcType>::Repr>();
        self.f6 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f7 = <i64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i64 as PlcType>::Repr>();
        self.f8 = <i16 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i16 as PlcType>::Repr>();
        self.f9 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f10 = <i64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i64 as PlcType>::Repr>();
        self.f11 = <i16 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i16 as PlcType>::Repr>();
        self.f12 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f13 = <i64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i64 as PlcType>::Repr>();
        self.f14 = <i16 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i16 as PlcType>::Repr>();
        self.f15 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f16 = <i64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i64 as PlcType>::Repr>();
        self.f17 = <i16 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i16 as PlcType>::Repr>();
        self.f18 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f19 = <i64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i64 as PlcType>::Repr>();
        self.f20 = <i16 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i16 as PlcType>::Repr>();
        self.f21 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f22 = <i64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i64 as PlcType>::Repr>();
        self.f23 = <i16 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i16 as PlcType>::Repr>();
        self.f24 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f25 = <i64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i64 as PlcType>::Repr>();
        self.f26 = <i16 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i16 as PlcType>::Repr>();
        self.f27 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f28 = <i64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i64 as PlcType>::Repr>();
        self.f29 = <i16 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i16 as PlcType>::Repr>();
        self.f30 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f31 = <i64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i64 as PlcType>::Repr>();
        self.f32 = <i16 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i16 as PlcType>::Repr>();
        self.f33 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f34 = <i64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i64 as PlcType>::Repr>();
        self.f35 = <i16 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i16 as PlcType>::Repr>();
        self.f36 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f37 = <i64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i64 as PlcType>::Repr>();
        self.f38 = <i16 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i16 as PlcType>::Repr>();
        self.f39 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f40 = <i64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i64 as PlcType>::Repr>();
        self.f41 = <i16 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i16 as PlcType>::Repr>();
        self.f42 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f43 = <i64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i64 as PlcType>::Repr>();
        self.f44 = <i16 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i16 as PlcType>::Repr>();
        self.f45 = <u16 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u16 as PlcType>::Repr>();
        self.f46 = <u16 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u16 as PlcType>::Repr>();
        self.f47 = <u16 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u16 as PlcType>::Repr>();
        self.f48 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f49 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f50 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f51 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f52 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f53 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f54 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f55 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f56 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f57 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f58 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f59 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f60 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f61 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f62 = <[Pair; 2] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[Pair; 2] as PlcType>::Repr>();
        self.f63 = <i64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i64 as PlcType>::Repr>();
        self.f64 = <i32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i32 as PlcType>::Repr>();
        self.f65 = <i8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i8 as PlcType>::Repr>();
        self.f66 = <i32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i32 as PlcType>::Repr>();
        self.f67 = <Pair as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Pair as PlcType>::Repr>();
        self.f68 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f69 = <[[i8; 2]; 2] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[[i8; 2]; 2] as PlcType>::Repr>();
        self.f70 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f71 = <i32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i32 as PlcType>::Repr>();
        self.f72 = <Pair as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Pair as PlcType>::Repr>();
        self.f73 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f74 = <[[i8; 2]; 2] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[[i8; 2]; 2] as PlcType>::Repr>();
        self.f75 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f76 = <i32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i32 as PlcType>::Repr>();
        self.f77 = <Pair as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Pair as PlcType>::Repr>();
        self.f78 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f79 = <[[i8; 2]; 2] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[[i8; 2]; 2] as PlcType>::Repr>();
        self.f80 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f81 = <i32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i32 as PlcType>::Repr>();
        self.f82 = <Pair as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Pair as PlcType>::Repr>();
        self.f83 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f84 = <[[i8; 2]; 2] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[[i8; 2]; 2] as PlcType>::Repr>();
        self.f85 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f86 = <i32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i32 as PlcType>::Repr>();
        self.f87 = <Pair as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Pair as PlcType>::Repr>();
        self.f88 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f89 = <[[i8; 2]; 2] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[[i8; 2]; 2] as PlcType>::Repr>();
        self.f90 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f91 = <i32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i32 as PlcType>::Repr>();
        self.f92 = <Pair as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Pair as PlcType>::Repr>();
        self.f93 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f94 = <[[i8; 2]; 2] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[[i8; 2]; 2] as PlcType>::Repr>();
        self.f95 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f96 = <i32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i32 as PlcType>::Repr>();
        self.f97 = <Pair as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Pair as PlcType>::Repr>();
        self.f98 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f99 = <[[i8; 2]; 2] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[[i8; 2]; 2] as PlcType>::Repr>();
        self.f100 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f101 = <i32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i32 as PlcType>::Repr>();
        self.f102 = <Pair as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Pair as PlcType>::Repr>();
        self.f103 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f104 = <[[i8; 2]; 2] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[[i8; 2]; 2] as PlcType>::Repr>();
        self.f105 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f106 = <i32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i32 as PlcType>::Repr>();
        self.f107 = <Pair as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Pair as PlcType>::Repr>();
        self.f108 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f109 = <[[i8; 2]; 2] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[[i8; 2]; 2] as PlcType>::Repr>();
        self.f110 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f111 = <i32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i32 as PlcType>::Repr>();
        self.f112 = <Pair as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Pair as PlcType>::Repr>();
        self.f113 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f114 = <[[i8; 2]; 2] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[[i8; 2]; 2] as PlcType>::Repr>();
        self.f115 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f116 = <i32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<i32 as PlcType>::Repr>();
        self.f117 = <Pair as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Pair as PlcType>::Repr>();
        self.f118 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f119 = <[[i8; 2]; 2] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[[i8; 2]; 2] as PlcType>::Repr>();
        self.f120 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f121 = <u16 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u16 as PlcType>::Repr>();
        self.f122 = <u16 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u16 as PlcType>::Repr>();
        self.f123 = <u16 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u16 as PlcType>::Repr>();
        self.f124 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f125 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f126 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f127 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f128 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f129 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f130 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f131 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f132 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f133 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f134 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f135 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f136 = <FixedString<5> as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<FixedString<5> as PlcType>::Repr>();
        self.f137 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f138 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f139 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f140 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f141 = <FixedString<5> as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<FixedString<5> as PlcType>::Repr>();
        self.f142 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f143 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f144 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f145 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f146 = <FixedString<5> as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<FixedString<5> as PlcType>::Repr>();
        self.f147 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f148 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f149 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f150 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f151 = <FixedString<5> as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<FixedString<5> as PlcType>::Repr>();
        self.f152 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f153 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f154 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f155 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f156 = <FixedString<5> as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<FixedString<5> as PlcType>::Repr>();
        self.f157 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f158 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f159 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f160 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f161 = <FixedString<5> as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<FixedString<5> as PlcType>::Repr>();
        self.f162 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f163 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f164 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f165 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f166 = <FixedString<5> as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<FixedString<5> as PlcType>::Repr>();
        self.f167 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f168 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f169 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f170 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f171 = <FixedString<5> as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<FixedString<5> as PlcType>::Repr>();
        self.f172 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f173 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f174 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f175 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f176 = <FixedString<5> as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<FixedString<5> as PlcType>::Repr>();
        self.f177 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f178 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f179 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f180 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f181 = <FixedString<5> as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<FixedString<5> as PlcType>::Repr>();
        self.f182 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f183 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f184 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f185 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f186 = <FixedString<5> as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<FixedString<5> as PlcType>::Repr>();
        self.f187 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f188 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f189 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f190 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f191 = <FixedString<5> as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<FixedString<5> as PlcType>::Repr>();
        self.f192 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f193 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f194 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f195 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f196 = <FixedString<5> as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<FixedString<5> as PlcType>::Repr>();
        self.f197 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f198 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f199 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f200 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f201 = <FixedString<5> as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<FixedString<5> as PlcType>::Repr>();
        self.f202 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f203 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f204 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f205 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f206 = <FixedString<5> as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<FixedString<5> as PlcType>::Repr>();
        self.f207 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f208 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f209 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f210 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f211 = <FixedString<5> as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<FixedString<5> as PlcType>::Repr>();
        self.f212 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f213 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f214 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f215 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f216 = <FixedString<5> as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<FixedString<5> as PlcType>::Repr>();
        self.f217 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f218 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f219 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f220 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f221 = <FixedString<5> as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<FixedString<5> as PlcType>::Repr>();
        self.f222 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f223 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f224 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f225 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f226 = <FixedString<5> as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<FixedString<5> as PlcType>::Repr>();
        self.f227 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f228 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f229 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f230 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f231 = <FixedString<5> as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<FixedString<5> as PlcType>::Repr>();
        self.f232 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f233 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f234 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f235 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f236 = <FixedString<5> as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<FixedString<5> as PlcType>::Repr>();
        self.f237 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f238 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f239 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f240 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f241 = <FixedString<5> as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<FixedString<5> as PlcType>::Repr>();
        self.f242 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f243 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f244 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f245 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f246 = <FixedString<5> as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<FixedString<5> as PlcType>::Repr>();
        self.f247 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f248 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f249 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f250 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f251 = <FixedString<5> as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<FixedString<5> as PlcType>::Repr>();
        self.f252 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f253 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f254 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f255 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f256 = <FixedString<5> as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<FixedString<5> as PlcType>::Repr>();
        self.f257 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f258 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f259 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f260 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f261 = <FixedString<5> as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<FixedString<5> as PlcType>::Repr>();
        self.f262 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f263 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f264 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f265 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f266 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f267 = <[Pair; 2] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[Pair; 2] as PlcType>::Repr>();
        self.f268 = <[[i8; 2]; 2] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[[i8; 2]; 2] as PlcType>::Repr>();
        self.f269 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f270 = <f32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<f32 as PlcType>::Repr>();
        self.f271 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f272 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f273 = <u16 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u16 as PlcType>::Repr>();
        self.f274 = <[[i8; 2]; 2] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[[i8; 2]; 2] as PlcType>::Repr>();
        assert_eq!(at, b.len());
    }

    fn reference_unpack(&mut self) {
        self.f48 = (self.f45 >> 11) & 1 != 0;
        self.f49 = (self.f45 >> 5) & 1 != 0;
        self.f50 = (self.f47 >> 9) & 1 != 0;
        self.f51 = (self.f47 >> 13) & 1 != 0;
        self.f52 = (self.f45 >> 0) & 1 != 0;
        self.f53 = (self.f45 >> 3) & 1 != 0;
        self.f54 = (self.f47 >> 4) & 1 != 0;
        self.f55 = (self.f45 >> 1) & 1 != 0;
        self.f56 = (self.f46 >> 10) & 1 != 0;
        self.f57 = (self.f45 >> 13) & 1 != 0;
        self.f58 = (self.f46 >> 15) & 1 != 0;
        self.f59 = (self.f45 >> 10) & 1 != 0;
        self.f60 = (self.f45 >> 7) & 1 != 0;
        self.f61 = (self.f45 >> 2) & 1 != 0;
        self.f124 = (self.f121 >> 11) & 1 != 0;
        self.f125 = (self.f122 >> 11) & 1 != 0;
        self.f126 = (self.f121 >> 9) & 1 != 0;
        self.f127 = (self.f123 >> 3) & 1 != 0;
        self.f128 = (self.f123 >> 7) & 1 != 0;
        self.f129 = (self.f122 >> 10) & 1 != 0;
        self.f130 = (self.f123 >> 13) & 1 != 0;
        self.f131 = (self.f122 >> 9) & 1 != 0;
        self.f132 = (self.f121 >> 8) & 1 != 0;
        self.f133 = (self.f122 >> 0) & 1 != 0;
        self.f134 = (self.f122 >> 13) & 1 != 0;
        self.reference_unpack_nested();
    }

    fn reference_pack(&mut self) {
        self.reference_pack_nested();
        self.f45 = (self.f45 & !(1 << 11)) | ((self.f48 as u16) << 11);
        self.f45 = (self.f45 & !(1 << 5)) | ((self.f49 as u16) << 5);
        self.f47 = (self.f47 & !(1 << 9)) | ((self.f50 as u16) << 9);
        self.f47 = (self.f47 & !(1 << 13)) | ((self.f51 as u16) << 13);
        self.f45 = (self.f45 & !(1 << 0)) | ((self.f52 as u16) << 0);
        self.f45 = (self.f45 & !(1 << 3)) | ((self.f53 as u16) << 3);
        self.f47 = (self.f47 & !(1 << 4)) | ((self.f54 as u16) << 4);
        self.f45 = (self.f45 & !(1 << 1)) | ((self.f55 as u16) << 1);
        self.f46 = (self.f46 & !(1 << 10)) | ((self.f56 as u16) << 10);
        self.f45 = (self.f45 & !(1 << 13)) | ((self.f57 as u16) << 13);
        self.f46 = (self.f46 & !(1 << 15)) | ((self.f58 as u16) << 15);
        self.f45 = (self.f45 & !(1 << 10)) | ((self.f59 as u16) << 10);
        self.f45 = (self.f45 & !(1 << 7)) | ((self.f60 as u16) << 7);
        self.f45 = (self.f45 & !(1 << 2)) | ((self.f61 as u16) << 2);
        self.f121 = (self.f121 & !(1 << 11)) | ((self.f124 as u16) << 11);
        self.f122 = (self.f122 & !(1 << 11)) | ((self.f125 as u16) << 11);
        self.f121 = (self.f121 & !(1 << 9)) | ((self.f126 as u16) << 9);
        self.f123 = (self.f123 & !(1 << 3)) | ((self.f127 as u16) << 3);
        self.f123 = (self.f123 & !(1 << 7)) | ((self.f128 as u16) << 7);
        self.f122 = (self.f122 & !(1 << 10)) | ((self.f129 as u16) << 10);
        self.f123 = (self.f123 & !(1 << 13)) | ((self.f130 as u16) << 13);
        self.f122 = (self.f122 & !(1 << 9)) | ((self.f131 as u16) << 9);
        self.f121 = (self.f121 & !(1 << 8)) | ((self.f132 as u16) << 8);
        self.f122 = (self.f122 & !(1 << 0)) | ((self.f133 as u16) << 0);
        self.f122 = (self.f122 & !(1 << 13)) | ((self.f134 as u16) << 13);
    }

    fn reference_unpack_nested(&mut self) {
        self.f62.iter_mut().for_each(Pair::reference_unpack);
        self.f67.reference_unpack();
        self.f72.reference_unpack();
        self.f77.reference_unpack();
        self.f82.reference_unpack();
        self.f87.reference_unpack();
        self.f92.reference_unpack();
        self.f97.reference_unpack();
        self.f102.reference_unpack();
        self.f107.reference_unpack();
        self.f112.reference_unpack();
        self.f117.reference_unpack();
        self.f267.iter_mut().for_each(Pair::reference_unpack);
    }

    fn reference_pack_nested(&mut self) {
        self.f62.iter_mut().for_each(Pair::reference_pack);
        self.f67.reference_pack();
        self.f72.reference_pack();
        self.f77.reference_pack();
        self.f82.reference_pack();
        self.f87.reference_pack();
        self.f92.reference_pack();
        self.f97.reference_pack();
        self.f102.reference_pack();
        self.f107.reference_pack();
        self.f112.reference_pack();
        self.f117.reference_pack();
        self.f267.iter_mut().for_each(Pair::reference_pack);
    }
}


#[derive(GlobalMemory, Debug, Clone)]
pub struct Random2 {
    pub f0: Flag,
    pub f1: u64,
    pub f2: u32,
    pub f3: Flag,
    pub f4: u64,
    pub f5: u32,
    pub f6: Flag,
    pub f7: u64,
    pub f8: u32,
    pub f9: Flag,
    pub f10: u64,
    pub f11: u32,
    pub f12: Flag,
    pub f13: u64,
    pub f14: u32,
    pub f15: Flag,
    pub f16: u64,
    pub f17: u32,
    pub f18: Flag,
    pub f19: u64,
    pub f20: u32,
    pub f21: Flag,
    pub f22: u64,
    pub f23: u32,
    pub f24: Flag,
    pub f25: u64,
    pub f26: u32,
    pub f27: Flag,
    pub f28: u64,
    pub f29: u32,
    pub f30: Flag,
    pub f31: u64,
    pub f32: u32,
    pub f33: Flag,
    pub f34: u64,
    pub f35: u32,
    pub f36: Flag,
    pub f37: u64,
    pub f38: u32,
    pub f39: Flag,
    pub f40: u64,
    pub f41: u32,
    pub f42: Flag,
    pub f43: u64,
    pub f44: u32,
    pub f45: Flag,
    pub f46: u64,
    pub f47: u32,
    pub f48: Flag,
    pub f49: u64,
    pub f50: u32,
    pub f51: Flag,
    pub f52: u64,
    pub f53: u32,
    pub f54: Flag,
    pub f55: u64,
    pub f56: u32,
    pub f57: Flag,
    pub f58: u64,
    pub f59: u32,
    pub f60: Flag,
    pub f61: u64,
    pub f62: u32,
    pub f63: Flag,
    pub f64: u64,
    pub f65: u32,
    pub f66: Flag,
    pub f67: u64,
    pub f68: u32,
    pub f69: Flag,
    pub f70: u64,
    pub f71: u32,
    pub f72: Flag,
    pub f73: u64,
    pub f74: u32,
    pub f75: u16,
    pub f76: u16,
    pub f77: u16,
    #[plc(source = "f77", bit = 0)]
    pub f78: bool,
    #[plc(source = "f77", bit = 15)]
    pub f79: bool,
    #[plc(source = "f76", bit = 1)]
    pub f80: bool,
    #[plc(source = "f75", bit = 3)]
    pub f81: bool,
    #[plc(source = "f75", bit = 1)]
    pub f82: bool,
    pub f83: u32,
    pub f84: f64,
    pub f85: u32,
    pub f86: f64,
    pub f87: u32,
    pub f88: f64,
    pub f89: u32,
    pub f90: f64,
    pub f91: u32,
    pub f92: f64,
    pub f93: u32,
    pub f94: f64,
    pub f95: u32,
    pub f96: f64,
    pub f97: u32,
    pub f98: f64,
    pub f99: u32,
    pub f100: f64,
    pub f101: u32,
    pub f102: f64,
    pub f103: u32,
    pub f104: f64,
    pub f105: u32,
    pub f106: f64,
    pub f107: u32,
    pub f108: f64,
    pub f109: u32,
    pub f110: f64,
    pub f111: u32,
    pub f112: f64,
    pub f113: u32,
    pub f114: f64,
    pub f115: u32,
    pub f116: f64,
    pub f117: u32,
    pub f118: f64,
    pub f119: u32,
    pub f120: f64,
    pub f121: u32,
    pub f122: f64,
    pub f123: u32,
    pub f124: f64,
    pub f125: u32,
    pub f126: f64,
    pub f127: u32,
    pub f128: f64,
    pub f129: u32,
    pub f130: f64,
    pub f131: u32,
    pub f132: f64,
    pub f133: u32,
    pub f134: f64,
    pub f135: u32,
    pub f136: f64,
    pub f137: u32,
    pub f138: f64,
    pub f139: u32,
    pub f140: f64,
    pub f141: u32,
    pub f142: f64,
    pub f143: u32,
    pub f144: f64,
    pub f145: u32,
    pub f146: f64,
    pub f147: u32,
    pub f148: f64,
    pub f149: u32,
    pub f150: f64,
    pub f151: u32,
    pub f152: f64,
    pub f153: u32,
    pub f154: f64,
    pub f155: u32,
    pub f156: f64,
    pub f157: u32,
    pub f158: f64,
    pub f159: u32,
    pub f160: f64,
    pub f161: u32,
    pub f162: f64,
    pub f163: u32,
    pub f164: f64,
    pub f165: u32,
    pub f166: f64,
    pub f167: FixedString<5>,
    pub f168: u64,
    pub f169: [[i8; 2]; 2],
    pub f170: f64,
    pub f171: u64,
    pub f172: u64,
    pub f173: u64,
    pub f174: u64,
    pub f175: u64,
    pub f176: u64,
    pub f177: u64,
    pub f178: u64,
    pub f179: u64,
    pub f180: u64,
    pub f181: u64,
    pub f182: u64,
    pub f183: u64,
    #[plc(source = "f171", bit = 15)]
    pub f184: Flag,
    #[plc(source = "f171", bit = 16)]
    pub f185: Flag,
    #[plc(source = "f171", bit = 17)]
    pub f186: Flag,
    #[plc(source = "f171", bit = 18)]
    pub f187: Flag,
    #[plc(source = "f171", bit = 19)]
    pub f188: Flag,
    #[plc(source = "f171", bit = 20)]
    pub f189: Flag,
    #[plc(source = "f171", bit = 21)]
    pub f190: Flag,
    #[plc(source = "f171", bit = 22)]
    pub f191: Flag,
    #[plc(source = "f171", bit = 23)]
    pub f192: Flag,
    #[plc(source = "f171", bit = 24)]
    pub f193: Flag,
    #[plc(source = "f171", bit = 25)]
    pub f194: Flag,
    #[plc(source = "f171", bit = 26)]
    pub f195: Flag,
    #[plc(source = "f171", bit = 27)]
    pub f196: Flag,
    #[plc(source = "f171", bit = 28)]
    pub f197: Flag,
    #[plc(source = "f171", bit = 29)]
    pub f198: Flag,
    #[plc(source = "f171", bit = 30)]
    pub f199: Flag,
    #[plc(source = "f171", bit = 31)]
    pub f200: Flag,
    #[plc(source = "f171", bit = 32)]
    pub f201: Flag,
    #[plc(source = "f171", bit = 33)]
    pub f202: Flag,
    #[plc(source = "f171", bit = 34)]
    pub f203: Flag,
    #[plc(source = "f172", bit = 15)]
    pub f204: Flag,
    #[plc(source = "f172", bit = 16)]
    pub f205: Flag,
    #[plc(source = "f172", bit = 17)]
    pub f206: Flag,
    #[plc(source = "f172", bit = 18)]
    pub f207: Flag,
    #[plc(source = "f172", bit = 19)]
    pub f208: Flag,
    #[plc(source = "f172", bit = 20)]
    pub f209: Flag,
    #[plc(source = "f172", bit = 21)]
    pub f210: Flag,
    #[plc(source = "f172", bit = 22)]
    pub f211: Flag,
    #[plc(source = "f172", bit = 23)]
    pub f212: Flag,
    #[plc(source = "f172", bit = 24)]
    pub f213: Flag,
    #[plc(source = "f172", bit = 25)]
    pub f214: Flag,
    #[plc(source = "f172", bit = 26)]
    pub f215: Flag,
    #[plc(source = "f172", bit = 27)]
    pub f216: Flag,
    #[plc(source = "f172", bit = 28)]
    pub f217: Flag,
    #[plc(source = "f172", bit = 29)]
    pub f218: Flag,
    #[plc(source = "f172", bit = 30)]
    pub f219: Flag,
    #[plc(source = "f172", bit = 31)]
    pub f220: Flag,
    #[plc(source = "f172", bit = 32)]
    pub f221: Flag,
    #[plc(source = "f172", bit = 33)]
    pub f222: Flag,
    #[plc(source = "f172", bit = 34)]
    pub f223: Flag,
    #[plc(source = "f173", bit = 15)]
    pub f224: Flag,
    #[plc(source = "f173", bit = 16)]
    pub f225: Flag,
    #[plc(source = "f173", bit = 17)]
    pub f226: Flag,
    #[plc(source = "f173", bit = 18)]
    pub f227: Flag,
    #[plc(source = "f173", bit = 19)]
    pub f228: Flag,
    #[plc(source = "f173", bit = 20)]
    pub f229: Flag,
    #[plc(source = "f173", bit = 21)]
    pub f230: Flag,
    #[plc(source = "f173", bit = 22)]
    pub f231: Flag,
    #[plc(source = "f173", bit = 23)]
    pub f232: Flag,
    #[plc(source = "f173", bit = 24)]
    pub f233: Flag,
    #[plc(source = "f173", bit = 25)]
    pub f234: Flag,
    #[plc(source = "f173", bit = 26)]
    pub f235: Flag,
    #[plc(source = "f173", bit = 27)]
    pub f236: Flag,
    #[plc(source = "f173", bit = 28)]
    pub f237: Flag,
    #[plc(source = "f173", bit = 29)]
    pub f238: Flag,
    #[plc(source = "f173", bit = 30)]
    pub f239: Flag,
    #[plc(source = "f173", bit = 31)]
    pub f240: Flag,
    #[plc(source = "f173", bit = 32)]
    pub f241: Flag,
    #[plc(source = "f173", bit = 33)]
    pub f242: Flag,
    #[plc(source = "f173", bit = 34)]
    pub f243: Flag,
    #[plc(source = "f174", bit = 15)]
    pub f244: Flag,
    #[plc(source = "f174", bit = 16)]
    pub f245: Flag,
    #[plc(source = "f174", bit = 17)]
    pub f246: Flag,
    #[plc(source = "f174", bit = 18)]
    pub f247: Flag,
    #[plc(source = "f174", bit = 19)]
    pub f248: Flag,
    #[plc(source = "f174", bit = 20)]
    pub f249: Flag,
    #[plc(source = "f174", bit = 21)]
    pub f250: Flag,
    #[plc(source = "f174", bit = 22)]
    pub f251: Flag,
    #[plc(source = "f174", bit = 23)]
    pub f252: Flag,
    #[plc(source = "f174", bit = 24)]
    pub f253: Flag,
    #[plc(source = "f174", bit = 25)]
    pub f254: Flag,
    #[plc(source = "f174", bit = 26)]
    pub f255: Flag,
    #[plc(source = "f174", bit = 27)]
    pub f256: Flag,
    #[plc(source = "f174", bit = 28)]
    pub f257: Flag,
    #[plc(source = "f174", bit = 29)]
    pub f258: Flag,
    #[plc(source = "f174", bit = 30)]
    pub f259: Flag,
    #[plc(source = "f174", bit = 31)]
    pub f260: Flag,
    #[plc(source = "f174", bit = 32)]
    pub f261: Flag,
    #[plc(source = "f174", bit = 33)]
    pub f262: Flag,
    #[plc(source = "f174", bit = 34)]
    pub f263: Flag,
    #[plc(source = "f175", bit = 15)]
    pub f264: Flag,
    #[plc(source = "f175", bit = 16)]
    pub f265: Flag,
    #[plc(source = "f175", bit = 17)]
    pub f266: Flag,
    #[plc(source = "f175", bit = 18)]
    pub f267: Flag,
    #[plc(source = "f175", bit = 19)]
    pub f268: Flag,
    #[plc(source = "f175", bit = 20)]
    pub f269: Flag,
    #[plc(source = "f175", bit = 21)]
    pub f270: Flag,
    #[plc(source = "f175", bit = 22)]
    pub f271: Flag,
    #[plc(source = "f175", bit = 23)]
    pub f272: Flag,
    #[plc(source = "f175", bit = 24)]
    pub f273: Flag,
    #[plc(source = "f175", bit = 25)]
    pub f274: Flag,
    #[plc(source = "f175", bit = 26)]
    pub f275: Flag,
    #[plc(source = "f175", bit = 27)]
    pub f276: Flag,
    #[plc(source = "f175", bit = 28)]
    pub f277: Flag,
    #[plc(source = "f175", bit = 29)]
    pub f278: Flag,
    #[plc(source = "f175", bit = 30)]
    pub f279: Flag,
    #[plc(source = "f175", bit = 31)]
    pub f280: Flag,
    #[plc(source = "f175", bit = 32)]
    pub f281: Flag,
    #[plc(source = "f175", bit = 33)]
    pub f282: Flag,
    #[plc(source = "f175", bit = 34)]
    pub f283: Flag,
    #[plc(source = "f176", bit = 15)]
    pub f284: Flag,
    #[plc(source = "f176", bit = 16)]
    pub f285: Flag,
    #[plc(source = "f176", bit = 17)]
    pub f286: Flag,
    #[plc(source = "f176", bit = 18)]
    pub f287: Flag,
    #[plc(source = "f176", bit = 19)]
    pub f288: Flag,
    #[plc(source = "f176", bit = 20)]
    pub f289: Flag,
    #[plc(source = "f176", bit = 21)]
    pub f290: Flag,
    #[plc(source = "f176", bit = 22)]
    pub f291: Flag,
    #[plc(source = "f176", bit = 23)]
    pub f292: Flag,
    #[plc(source = "f176", bit = 24)]
    pub f293: Flag,
    #[plc(source = "f176", bit = 25)]
    pub f294: Flag,
    #[plc(source = "f176", bit = 26)]
    pub f295: Flag,
    #[plc(source = "f176", bit = 27)]
    pub f296: Flag,
    #[plc(source = "f176", bit = 28)]
    pub f297: Flag,
    #[plc(source = "f176", bit = 29)]
    pub f298: Flag,
    #[plc(source = "f176", bit = 30)]
    pub f299: Flag,
    #[plc(source = "f176", bit = 31)]
    pub f300: Flag,
    #[plc(source = "f176", bit = 32)]
    pub f301: Flag,
    #[plc(source = "f176", bit = 33)]
    pub f302: Flag,
    #[plc(source = "f176", bit = 34)]
    pub f303: Flag,
    #[plc(source = "f177", bit = 15)]
    pub f304: Flag,
    #[plc(source = "f177", bit = 16)]
    pub f305: Flag,
    #[plc(source = "f177", bit = 17)]
    pub f306: Flag,
    #[plc(source = "f177", bit = 18)]
    pub f307: Flag,
    #[plc(source = "f177", bit = 19)]
    pub f308: Flag,
    #[plc(source = "f177", bit = 20)]
    pub f309: Flag,
    #[plc(source = "f177", bit = 21)]
    pub f310: Flag,
    #[plc(source = "f177", bit = 22)]
    pub f311: Flag,
    #[plc(source = "f177", bit = 23)]
    pub f312: Flag,
    #[plc(source = "f177", bit = 24)]
    pub f313: Flag,
    #[plc(source = "f177", bit = 25)]
    pub f314: Flag,
    #[plc(source = "f177", bit = 26)]
    pub f315: Flag,
    #[plc(source = "f177", bit = 27)]
    pub f316: Flag,
    #[plc(source = "f177", bit = 28)]
    pub f317: Flag,
    #[plc(source = "f177", bit = 29)]
    pub f318: Flag,
    #[plc(source = "f177", bit = 30)]
    pub f319: Flag,
    #[plc(source = "f177", bit = 31)]
    pub f320: Flag,
    #[plc(source = "f177", bit = 32)]
    pub f321: Flag,
    #[plc(source = "f177", bit = 33)]
    pub f322: Flag,
    #[plc(source = "f177", bit = 34)]
    pub f323: Flag,
    #[plc(source = "f178", bit = 15)]
    pub f324: Flag,
    #[plc(source = "f178", bit = 16)]
    pub f325: Flag,
    #[plc(source = "f178", bit = 17)]
    pub f326: Flag,
    #[plc(source = "f178", bit = 18)]
    pub f327: Flag,
    #[plc(source = "f178", bit = 19)]
    pub f328: Flag,
    #[plc(source = "f178", bit = 20)]
    pub f329: Flag,
    #[plc(source = "f178", bit = 21)]
    pub f330: Flag,
    #[plc(source = "f178", bit = 22)]
    pub f331: Flag,
    #[plc(source = "f178", bit = 23)]
    pub f332: Flag,
    #[plc(source = "f178", bit = 24)]
    pub f333: Flag,
    #[plc(source = "f178", bit = 25)]
    pub f334: Flag,
    #[plc(source = "f178", bit = 26)]
    pub f335: Flag,
    #[plc(source = "f178", bit = 27)]
    pub f336: Flag,
    #[plc(source = "f178", bit = 28)]
    pub f337: Flag,
    #[plc(source = "f178", bit = 29)]
    pub f338: Flag,
    #[plc(source = "f178", bit = 30)]
    pub f339: Flag,
    #[plc(source = "f178", bit = 31)]
    pub f340: Flag,
    #[plc(source = "f178", bit = 32)]
    pub f341: Flag,
    #[plc(source = "f178", bit = 33)]
    pub f342: Flag,
    #[plc(source = "f178", bit = 34)]
    pub f343: Flag,
    #[plc(source = "f179", bit = 15)]
    pub f344: Flag,
    #[plc(source = "f179", bit = 16)]
    pub f345: Flag,
    #[plc(source = "f179", bit = 17)]
    pub f346: Flag,
    #[plc(source = "f179", bit = 18)]
    pub f347: Flag,
    #[plc(source = "f179", bit = 19)]
    pub f348: Flag,
    #[plc(source = "f179", bit = 20)]
    pub f349: Flag,
    #[plc(source = "f179", bit = 21)]
    pub f350: Flag,
    #[plc(source = "f179", bit = 22)]
    pub f351: Flag,
    #[plc(source = "f179", bit = 23)]
    pub f352: Flag,
    #[plc(source = "f179", bit = 24)]
    pub f353: Flag,
    #[plc(source = "f179", bit = 25)]
    pub f354: Flag,
    #[plc(source = "f179", bit = 26)]
    pub f355: Flag,
    #[plc(source = "f179", bit = 27)]
    pub f356: Flag,
    #[plc(source = "f179", bit = 28)]
    pub f357: Flag,
    #[plc(source = "f179", bit = 29)]
    pub f358: Flag,
    #[plc(source = "f179", bit = 30)]
    pub f359: Flag,
    #[plc(source = "f179", bit = 31)]
    pub f360: Flag,
    #[plc(source = "f179", bit = 32)]
    pub f361: Flag,
    #[plc(source = "f179", bit = 33)]
    pub f362: Flag,
    #[plc(source = "f179", bit = 34)]
    pub f363: Flag,
    #[plc(source = "f180", bit = 15)]
    pub f364: Flag,
    #[plc(source = "f180", bit = 16)]
    pub f365: Flag,
    #[plc(source = "f180", bit = 17)]
    pub f366: Flag,
    #[plc(source = "f180", bit = 18)]
    pub f367: Flag,
    #[plc(source = "f180", bit = 19)]
    pub f368: Flag,
    #[plc(source = "f180", bit = 20)]
    pub f369: Flag,
    #[plc(source = "f180", bit = 21)]
    pub f370: Flag,
    #[plc(source = "f180", bit = 22)]
    pub f371: Flag,
    #[plc(source = "f180", bit = 23)]
    pub f372: Flag,
    #[plc(source = "f180", bit = 24)]
    pub f373: Flag,
    #[plc(source = "f180", bit = 25)]
    pub f374: Flag,
    #[plc(source = "f180", bit = 26)]
    pub f375: Flag,
    #[plc(source = "f180", bit = 27)]
    pub f376: Flag,
    #[plc(source = "f180", bit = 28)]
    pub f377: Flag,
    #[plc(source = "f180", bit = 29)]
    pub f378: Flag,
    #[plc(source = "f180", bit = 30)]
    pub f379: Flag,
    #[plc(source = "f180", bit = 31)]
    pub f380: Flag,
    #[plc(source = "f180", bit = 32)]
    pub f381: Flag,
    #[plc(source = "f180", bit = 33)]
    pub f382: Flag,
    #[plc(source = "f180", bit = 34)]
    pub f383: Flag,
    #[plc(source = "f181", bit = 15)]
    pub f384: Flag,
    #[plc(source = "f181", bit = 16)]
    pub f385: Flag,
    #[plc(source = "f181", bit = 17)]
    pub f386: Flag,
    #[plc(source = "f181", bit = 18)]
    pub f387: Flag,
    #[plc(source = "f181", bit = 19)]
    pub f388: Flag,
    #[plc(source = "f181", bit = 20)]
    pub f389: Flag,
    #[plc(source = "f181", bit = 21)]
    pub f390: Flag,
    #[plc(source = "f181", bit = 22)]
    pub f391: Flag,
    #[plc(source = "f181", bit = 23)]
    pub f392: Flag,
    #[plc(source = "f181", bit = 24)]
    pub f393: Flag,
    #[plc(source = "f181", bit = 25)]
    pub f394: Flag,
    #[plc(source = "f181", bit = 26)]
    pub f395: Flag,
    #[plc(source = "f181", bit = 27)]
    pub f396: Flag,
    #[plc(source = "f181", bit = 28)]
    pub f397: Flag,
    #[plc(source = "f181", bit = 29)]
    pub f398: Flag,
    #[plc(source = "f181", bit = 30)]
    pub f399: Flag,
    #[plc(source = "f181", bit = 31)]
    pub f400: Flag,
    #[plc(source = "f181", bit = 32)]
    pub f401: Flag,
    #[plc(source = "f181", bit = 33)]
    pub f402: Flag,
    #[plc(source = "f181", bit = 34)]
    pub f403: Flag,
    #[plc(source = "f182", bit = 15)]
    pub f404: Flag,
    #[plc(source = "f182", bit = 16)]
    pub f405: Flag,
    #[plc(source = "f182", bit = 17)]
    pub f406: Flag,
    #[plc(source = "f182", bit = 18)]
    pub f407: Flag,
    #[plc(source = "f182", bit = 19)]
    pub f408: Flag,
    #[plc(source = "f182", bit = 20)]
    pub f409: Flag,
    #[plc(source = "f182", bit = 21)]
    pub f410: Flag,
    #[plc(source = "f182", bit = 22)]
    pub f411: Flag,
    #[plc(source = "f182", bit = 23)]
    pub f412: Flag,
    #[plc(source = "f182", bit = 24)]
    pub f413: Flag,
    #[plc(source = "f182", bit = 25)]
    pub f414: Flag,
    #[plc(source = "f182", bit = 26)]
    pub f415: Flag,
    #[plc(source = "f182", bit = 27)]
    pub f416: Flag,
    #[plc(source = "f182", bit = 28)]
    pub f417: Flag,
    #[plc(source = "f182", bit = 29)]
    pub f418: Flag,
    #[plc(source = "f182", bit = 30)]
    pub f419: Flag,
    #[plc(source = "f182", bit = 31)]
    pub f420: Flag,
    #[plc(source = "f182", bit = 32)]
    pub f421: Flag,
    #[plc(source = "f182", bit = 33)]
    pub f422: Flag,
    #[plc(source = "f182", bit = 34)]
    pub f423: Flag,
    #[plc(source = "f183", bit = 15)]
    pub f424: Flag,
    #[plc(source = "f183", bit = 16)]
    pub f425: Flag,
    #[plc(source = "f183", bit = 17)]
    pub f426: Flag,
    #[plc(source = "f183", bit = 18)]
    pub f427: Flag,
    #[plc(source = "f183", bit = 19)]
    pub f428: Flag,
    #[plc(source = "f183", bit = 20)]
    pub f429: Flag,
    #[plc(source = "f183", bit = 21)]
    pub f430: Flag,
    #[plc(source = "f183", bit = 22)]
    pub f431: Flag,
    #[plc(source = "f183", bit = 23)]
    pub f432: Flag,
    #[plc(source = "f183", bit = 24)]
    pub f433: Flag,
    #[plc(source = "f183", bit = 25)]
    pub f434: Flag,
    #[plc(source = "f183", bit = 26)]
    pub f435: Flag,
    #[plc(source = "f183", bit = 27)]
    pub f436: Flag,
    #[plc(source = "f183", bit = 28)]
    pub f437: Flag,
    #[plc(source = "f183", bit = 29)]
    pub f438: Flag,
    #[plc(source = "f183", bit = 30)]
    pub f439: Flag,
    #[plc(source = "f183", bit = 31)]
    pub f440: Flag,
    #[plc(source = "f183", bit = 32)]
    pub f441: Flag,
    #[plc(source = "f183", bit = 33)]
    pub f442: Flag,
    #[plc(source = "f183", bit = 34)]
    pub f443: Flag,
    pub f444: Word,
    pub f445: [u16; 3],
    pub f446: [[i8; 2]; 2],
    pub f447: u8,
    pub f448: Word,
    pub f449: [u16; 3],
    pub f450: [[i8; 2]; 2],
    pub f451: u8,
    pub f452: Word,
    pub f453: [u16; 3],
    pub f454: [[i8; 2]; 2],
    pub f455: u8,
    pub f456: Word,
    pub f457: [u16; 3],
    pub f458: [[i8; 2]; 2],
    pub f459: u8,
    pub f460: Word,
    pub f461: [u16; 3],
    pub f462: [[i8; 2]; 2],
    pub f463: u8,
    pub f464: Word,
    pub f465: [u16; 3],
    pub f466: [[i8; 2]; 2],
    pub f467: u8,
    pub f468: Word,
    pub f469: [u16; 3],
    pub f470: [[i8; 2]; 2],
    pub f471: u8,
    pub f472: Word,
    pub f473: [u16; 3],
    pub f474: [[i8; 2]; 2],
    pub f475: u8,
    pub f476: Word,
    pub f477: [u16; 3],
    pub f478: [[i8; 2]; 2],
    pub f479: u8,
    pub f480: Word,
    pub f481: [u16; 3],
    pub f482: [[i8; 2]; 2],
    pub f483: u8,
    pub f484: Word,
    pub f485: [u16; 3],
    pub f486: [[i8; 2]; 2],
    pub f487: u8,
    pub f488: Word,
    pub f489: [u16; 3],
    pub f490: [[i8; 2]; 2],
    pub f491: u8,
    pub f492: Word,
    pub f493: [u16; 3],
    pub f494: [[i8; 2]; 2],
    pub f495: u8,
    pub f496: Word,
    pub f497: [u16; 3],
    pub f498: [[i8; 2]; 2],
    pub f499: u8,
    pub f500: Word,
    pub f501: [u16; 3],
    pub f502: [[i8; 2]; 2],
    pub f503: u8,
    pub f504: Word,
    pub f505: [u16; 3],
    pub f506: [[i8; 2]; 2],
    pub f507: u8,
    pub f508: Word,
    pub f509: [u16; 3],
    pub f510: [[i8; 2]; 2],
    pub f511: u8,
    pub f512: Word,
    pub f513: [u16; 3],
    pub f514: [[i8; 2]; 2],
    pub f515: u8,
    pub f516: Word,
    pub f517: [u16; 3],
    pub f518: [[i8; 2]; 2],
    pub f519: u8,
    pub f520: Word,
    pub f521: [u16; 3],
    pub f522: [[i8; 2]; 2],
    pub f523: u8,
    pub f524: Word,
    pub f525: [u16; 3],
    pub f526: [[i8; 2]; 2],
    pub f527: u8,
    pub f528: Word,
    pub f529: [u16; 3],
    pub f530: [[i8; 2]; 2],
    pub f531: u8,
    pub f532: Word,
    pub f533: [u16; 3],
    pub f534: [[i8; 2]; 2],
    pub f535: u8,
    pub f536: Word,
    pub f537: [u16; 3],
    pub f538: [[i8; 2]; 2],
    pub f539: u8,
    pub f540: Word,
    pub f541: [u16; 3],
    pub f542: [[i8; 2]; 2],
    pub f543: u8,
    pub f544: Word,
    pub f545: [u16; 3],
    pub f546: [[i8; 2]; 2],
    pub f547: u8,
    pub f548: Word,
    pub f549: [u16; 3],
    pub f550: [[i8; 2]; 2],
    pub f551: u8,
    pub f552: Word,
    pub f553: [u16; 3],
    pub f554: [[i8; 2]; 2],
    pub f555: u8,
    pub f556: Word,
    pub f557: [u16; 3],
    pub f558: [[i8; 2]; 2],
    pub f559: u8,
    pub f560: Word,
    pub f561: [u16; 3],
    pub f562: [[i8; 2]; 2],
    pub f563: u8,
    pub f564: Word,
    pub f565: [u16; 3],
    pub f566: [[i8; 2]; 2],
    pub f567: u8,
    pub f568: Word,
    pub f569: [u16; 3],
    pub f570: [[i8; 2]; 2],
    pub f571: u8,
    pub f572: Word,
    pub f573: [u16; 3],
    pub f574: [[i8; 2]; 2],
    pub f575: u8,
    pub f576: Word,
    pub f577: [u16; 3],
    pub f578: [[i8; 2]; 2],
    pub f579: u8,
    pub f580: Word,
    pub f581: [u16; 3],
    pub f582: [[i8; 2]; 2],
    pub f583: u8,
    pub f584: Word,
    pub f585: [u16; 3],
    pub f586: [[i8; 2]; 2],
    pub f587: u8,
    pub f588: Word,
    pub f589: [u16; 3],
    pub f590: [[i8; 2]; 2],
    pub f591: u8,
    pub f592: Word,
    pub f593: [u16; 3],
    pub f594: [[i8; 2]; 2],
    pub f595: u8,
    pub f596: Word,
    pub f597: [u16; 3],
    pub f598: [[i8; 2]; 2],
    pub f599: u8,
    pub f600: u16,
    pub f601: u16,
    pub f602: u16,
    #[plc(source = "f600", bit = 7)]
    pub f603: bool,
    #[plc(source = "f601", bit = 11)]
    pub f604: bool,
    #[plc(source = "f601", bit = 0)]
    pub f605: bool,
    #[plc(source = "f601", bit = 12)]
    pub f606: bool,
    #[plc(source = "f602", bit = 12)]
    pub f607: bool,
    #[plc(source = "f601", bit = 7)]
    pub f608: bool,
    #[plc(source = "f600", bit = 6)]
    pub f609: bool,
    #[plc(source = "f600", bit = 1)]
    pub f610: bool,
    #[plc(source = "f600", bit = 14)]
    pub f611: bool,
    #[plc(source = "f600", bit = 12)]
    pub f612: bool,
    #[plc(source = "f600", bit = 2)]
    pub f613: bool,
    #[plc(source = "f601", bit = 6)]
    pub f614: bool,
    #[plc(source = "f602", bit = 2)]
    pub f615: bool,
    pub f616: u64,
    pub f617: u64,
    pub f618: u64,
    pub f619: u64,
    pub f620: u64,
    #[plc(source = "f616", bit = 0)]
    pub f621: Flag,
    #[plc(source = "f616", bit = 1)]
    pub f622: Flag,
    #[plc(source = "f616", bit = 2)]
    pub f623: Flag,
    #[plc(source = "f616", bit = 3)]
    pub f624: Flag,
    #[plc(source = "f616", bit = 4)]
    pub f625: Flag,
    #[plc(source = "f616", bit = 5)]
    pub f626: Flag,
    #[plc(source = "f616", bit = 6)]
    pub f627: Flag,
    #[plc(source = "f616", bit = 7)]
    pub f628: Flag,
    #[plc(source = "f616", bit = 8)]
    pub f629: Flag,
    #[plc(source = "f616", bit = 9)]
    pub f630: Flag,
    #[plc(source = "f616", bit = 10)]
    pub f631: Flag,
    #[plc(source = "f616", bit = 11)]
    pub f632: Flag,
    #[plc(source = "f616", bit = 12)]
    pub f633: Flag,
    #[plc(source = "f616", bit = 13)]
    pub f634: Flag,
    #[plc(source = "f616", bit = 14)]
    pub f635: Flag,
    #[plc(source = "f616", bit = 15)]
    pub f636: Flag,
    #[plc(source = "f616", bit = 16)]
    pub f637: Flag,
    #[plc(source = "f616", bit = 17)]
    pub f638: Flag,
    #[plc(source = "f616", bit = 18)]
    pub f639: Flag,
    #[plc(source = "f616", bit = 19)]
    pub f640: Flag,
    #[plc(source = "f616", bit = 20)]
    pub f641: Flag,
    #[plc(source = "f616", bit = 21)]
    pub f642: Flag,
    #[plc(source = "f616", bit = 22)]
    pub f643: Flag,
    #[plc(source = "f616", bit = 23)]
    pub f644: Flag,
    #[plc(source = "f616", bit = 24)]
    pub f645: Flag,
    #[plc(source = "f616", bit = 25)]
    pub f646: Flag,
    #[plc(source = "f616", bit = 26)]
    pub f647: Flag,
    #[plc(source = "f616", bit = 27)]
    pub f648: Flag,
    #[plc(source = "f616", bit = 28)]
    pub f649: Flag,
    #[plc(source = "f616", bit = 29)]
    pub f650: Flag,
    #[plc(source = "f616", bit = 30)]
    pub f651: Flag,
    #[plc(source = "f616", bit = 31)]
    pub f652: Flag,
    #[plc(source = "f616", bit = 32)]
    pub f653: Flag,
    #[plc(source = "f616", bit = 33)]
    pub f654: Flag,
    #[plc(source = "f616", bit = 34)]
    pub f655: Flag,
    #[plc(source = "f616", bit = 35)]
    pub f656: Flag,
    #[plc(source = "f616", bit = 36)]
    pub f657: Flag,
    #[plc(source = "f616", bit = 37)]
    pub f658: Flag,
    #[plc(source = "f616", bit = 38)]
    pub f659: Flag,
    #[plc(source = "f616", bit = 39)]
    pub f660: Flag,
    #[plc(source = "f616", bit = 40)]
    pub f661: Flag,
    #[plc(source = "f616", bit = 41)]
    pub f662: Flag,
    #[plc(source = "f616", bit = 42)]
    pub f663: Flag,
    #[plc(source = "f616", bit = 43)]
    pub f664: Flag,
    #[plc(source = "f616", bit = 44)]
    pub f665: Flag,
    #[plc(source = "f616", bit = 45)]
    pub f666: Flag,
    #[plc(source = "f616", bit = 46)]
    pub f667: Flag,
    #[plc(source = "f616", bit = 47)]
    pub f668: Flag,
    #[plc(source = "f616", bit = 48)]
    pub f669: Flag,
    #[plc(source = "f616", bit = 49)]
    pub f670: Flag,
    #[plc(source = "f616", bit = 50)]
    pub f671: Flag,
    #[plc(source = "f617", bit = 0)]
    pub f672: Flag,
    #[plc(source = "f617", bit = 1)]
    pub f673: Flag,
    #[plc(source = "f617", bit = 2)]
    pub f674: Flag,
    #[plc(source = "f617", bit = 3)]
    pub f675: Flag,
    #[plc(source = "f617", bit = 4)]
    pub f676: Flag,
    #[plc(source = "f617", bit = 5)]
    pub f677: Flag,
    #[plc(source = "f617", bit = 6)]
    pub f678: Flag,
    #[plc(source = "f617", bit = 7)]
    pub f679: Flag,
    #[plc(source = "f617", bit = 8)]
    pub f680: Flag,
    #[plc(source = "f617", bit = 9)]
    pub f681: Flag,
    #[plc(source = "f617", bit = 10)]
    pub f682: Flag,
    #[plc(source = "f617", bit = 11)]
    pub f683: Flag,
    #[plc(source = "f617", bit = 12)]
    pub f684: Flag,
    #[plc(source = "f617", bit = 13)]
    pub f685: Flag,
    #[plc(source = "f617", bit = 14)]
    pub f686: Flag,
    #[plc(source = "f617", bit = 15)]
    pub f687: Flag,
    #[plc(source = "f617", bit = 16)]
    pub f688: Flag,
    #[plc(source = "f617", bit = 17)]
    pub f689: Flag,
    #[plc(source = "f617", bit = 18)]
    pub f690: Flag,
    #[plc(source = "f617", bit = 19)]
    pub f691: Flag,
    #[plc(source = "f617", bit = 20)]
    pub f692: Flag,
    #[plc(source = "f617", bit = 21)]
    pub f693: Flag,
    #[plc(source = "f617", bit = 22)]
    pub f694: Flag,
    #[plc(source = "f617", bit = 23)]
    pub f695: Flag,
    #[plc(source = "f617", bit = 24)]
    pub f696: Flag,
    #[plc(source = "f617", bit = 25)]
    pub f697: Flag,
    #[plc(source = "f617", bit = 26)]
    pub f698: Flag,
    #[plc(source = "f617", bit = 27)]
    pub f699: Flag,
    #[plc(source = "f617", bit = 28)]
    pub f700: Flag,
    #[plc(source = "f617", bit = 29)]
    pub f701: Flag,
    #[plc(source = "f617", bit = 30)]
    pub f702: Flag,
    #[plc(source = "f617", bit = 31)]
    pub f703: Flag,
    #[plc(source = "f617", bit = 32)]
    pub f704: Flag,
    #[plc(source = "f617", bit = 33)]
    pub f705: Flag,
    #[plc(source = "f617", bit = 34)]
    pub f706: Flag,
    #[plc(source = "f617", bit = 35)]
    pub f707: Flag,
    #[plc(source = "f617", bit = 36)]
    pub f708: Flag,
    #[plc(source = "f617", bit = 37)]
    pub f709: Flag,
    #[plc(source = "f617", bit = 38)]
    pub f710: Flag,
    #[plc(source = "f617", bit = 39)]
    pub f711: Flag,
    #[plc(source = "f617", bit = 40)]
    pub f712: Flag,
    #[plc(source = "f617", bit = 41)]
    pub f713: Flag,
    #[plc(source = "f617", bit = 42)]
    pub f714: Flag,
    #[plc(source = "f617", bit = 43)]
    pub f715: Flag,
    #[plc(source = "f617", bit = 44)]
    pub f716: Flag,
    #[plc(source = "f617", bit = 45)]
    pub f717: Flag,
    #[plc(source = "f617", bit = 46)]
    pub f718: Flag,
    #[plc(source = "f617", bit = 47)]
    pub f719: Flag,
    #[plc(source = "f617", bit = 48)]
    pub f720: Flag,
    #[plc(source = "f617", bit = 49)]
    pub f721: Flag,
    #[plc(source = "f617", bit = 50)]
    pub f722: Flag,
    #[plc(source = "f618", bit = 0)]
    pub f723: Flag,
    #[plc(source = "f618", bit = 1)]
    pub f724: Flag,
    #[plc(source = "f618", bit = 2)]
    pub f725: Flag,
    #[plc(source = "f618", bit = 3)]
    pub f726: Flag,
    #[plc(source = "f618", bit = 4)]
    pub f727: Flag,
    #[plc(source = "f618", bit = 5)]
    pub f728: Flag,
    #[plc(source = "f618", bit = 6)]
    pub f729: Flag,
    #[plc(source = "f618", bit = 7)]
    pub f730: Flag,
    #[plc(source = "f618", bit = 8)]
    pub f731: Flag,
    #[plc(source = "f618", bit = 9)]
    pub f732: Flag,
    #[plc(source = "f618", bit = 10)]
    pub f733: Flag,
    #[plc(source = "f618", bit = 11)]
    pub f734: Flag,
    #[plc(source = "f618", bit = 12)]
    pub f735: Flag,
    #[plc(source = "f618", bit = 13)]
    pub f736: Flag,
    #[plc(source = "f618", bit = 14)]
    pub f737: Flag,
    #[plc(source = "f618", bit = 15)]
    pub f738: Flag,
    #[plc(source = "f618", bit = 16)]
    pub f739: Flag,
    #[plc(source = "f618", bit = 17)]
    pub f740: Flag,
    #[plc(source = "f618", bit = 18)]
    pub f741: Flag,
    #[plc(source = "f618", bit = 19)]
    pub f742: Flag,
    #[plc(source = "f618", bit = 20)]
    pub f743: Flag,
    #[plc(source = "f618", bit = 21)]
    pub f744: Flag,
    #[plc(source = "f618", bit = 22)]
    pub f745: Flag,
    #[plc(source = "f618", bit = 23)]
    pub f746: Flag,
    #[plc(source = "f618", bit = 24)]
    pub f747: Flag,
    #[plc(source = "f618", bit = 25)]
    pub f748: Flag,
    #[plc(source = "f618", bit = 26)]
    pub f749: Flag,
    #[plc(source = "f618", bit = 27)]
    pub f750: Flag,
    #[plc(source = "f618", bit = 28)]
    pub f751: Flag,
    #[plc(source = "f618", bit = 29)]
    pub f752: Flag,
    #[plc(source = "f618", bit = 30)]
    pub f753: Flag,
    #[plc(source = "f618", bit = 31)]
    pub f754: Flag,
    #[plc(source = "f618", bit = 32)]
    pub f755: Flag,
    #[plc(source = "f618", bit = 33)]
    pub f756: Flag,
    #[plc(source = "f618", bit = 34)]
    pub f757: Flag,
    #[plc(source = "f618", bit = 35)]
    pub f758: Flag,
    #[plc(source = "f618", bit = 36)]
    pub f759: Flag,
    #[plc(source = "f618", bit = 37)]
    pub f760: Flag,
    #[plc(source = "f618", bit = 38)]
    pub f761: Flag,
    #[plc(source = "f618", bit = 39)]
    pub f762: Flag,
    #[plc(source = "f618", bit = 40)]
    pub f763: Flag,
    #[plc(source = "f618", bit = 41)]
    pub f764: Flag,
    #[plc(source = "f618", bit = 42)]
    pub f765: Flag,
    #[plc(source = "f618", bit = 43)]
    pub f766: Flag,
    #[plc(source = "f618", bit = 44)]
    pub f767: Flag,
    #[plc(source = "f618", bit = 45)]
    pub f768: Flag,
    #[plc(source = "f618", bit = 46)]
    pub f769: Flag,
    #[plc(source = "f618", bit = 47)]
    pub f770: Flag,
    #[plc(source = "f618", bit = 48)]
    pub f771: Flag,
    #[plc(source = "f618", bit = 49)]
    pub f772: Flag,
    #[plc(source = "f618", bit = 50)]
    pub f773: Flag,
    #[plc(source = "f619", bit = 0)]
    pub f774: Flag,
    #[plc(source = "f619", bit = 1)]
    pub f775: Flag,
    #[plc(source = "f619", bit = 2)]
    pub f776: Flag,
    #[plc(source = "f619", bit = 3)]
    pub f777: Flag,
    #[plc(source = "f619", bit = 4)]
    pub f778: Flag,
    #[plc(source = "f619", bit = 5)]
    pub f779: Flag,
    #[plc(source = "f619", bit = 6)]
    pub f780: Flag,
    #[plc(source = "f619", bit = 7)]
    pub f781: Flag,
    #[plc(source = "f619", bit = 8)]
    pub f782: Flag,
    #[plc(source = "f619", bit = 9)]
    pub f783: Flag,
    #[plc(source = "f619", bit = 10)]
    pub f784: Flag,
    #[plc(source = "f619", bit = 11)]
    pub f785: Flag,
    #[plc(source = "f619", bit = 12)]
    pub f786: Flag,
    #[plc(source = "f619", bit = 13)]
    pub f787: Flag,
    #[plc(source = "f619", bit = 14)]
    pub f788: Flag,
    #[plc(source = "f619", bit = 15)]
    pub f789: Flag,
    #[plc(source = "f619", bit = 16)]
    pub f790: Flag,
    #[plc(source = "f619", bit = 17)]
    pub f791: Flag,
    #[plc(source = "f619", bit = 18)]
    pub f792: Flag,
    #[plc(source = "f619", bit = 19)]
    pub f793: Flag,
    #[plc(source = "f619", bit = 20)]
    pub f794: Flag,
    #[plc(source = "f619", bit = 21)]
    pub f795: Flag,
    #[plc(source = "f619", bit = 22)]
    pub f796: Flag,
    #[plc(source = "f619", bit = 23)]
    pub f797: Flag,
    #[plc(source = "f619", bit = 24)]
    pub f798: Flag,
    #[plc(source = "f619", bit = 25)]
    pub f799: Flag,
    #[plc(source = "f619", bit = 26)]
    pub f800: Flag,
    #[plc(source = "f619", bit = 27)]
    pub f801: Flag,
    #[plc(source = "f619", bit = 28)]
    pub f802: Flag,
    #[plc(source = "f619", bit = 29)]
    pub f803: Flag,
    #[plc(source = "f619", bit = 30)]
    pub f804: Flag,
    #[plc(source = "f619", bit = 31)]
    pub f805: Flag,
    #[plc(source = "f619", bit = 32)]
    pub f806: Flag,
    #[plc(source = "f619", bit = 33)]
    pub f807: Flag,
    #[plc(source = "f619", bit = 34)]
    pub f808: Flag,
    #[plc(source = "f619", bit = 35)]
    pub f809: Flag,
    #[plc(source = "f619", bit = 36)]
    pub f810: Flag,
    #[plc(source = "f619", bit = 37)]
    pub f811: Flag,
    #[plc(source = "f619", bit = 38)]
    pub f812: Flag,
    #[plc(source = "f619", bit = 39)]
    pub f813: Flag,
    #[plc(source = "f619", bit = 40)]
    pub f814: Flag,
    #[plc(source = "f619", bit = 41)]
    pub f815: Flag,
    #[plc(source = "f619", bit = 42)]
    pub f816: Flag,
    #[plc(source = "f619", bit = 43)]
    pub f817: Flag,
    #[plc(source = "f619", bit = 44)]
    pub f818: Flag,
    #[plc(source = "f619", bit = 45)]
    pub f819: Flag,
    #[plc(source = "f619", bit = 46)]
    pub f820: Flag,
    #[plc(source = "f619", bit = 47)]
    pub f821: Flag,
    #[plc(source = "f619", bit = 48)]
    pub f822: Flag,
    #[plc(source = "f619", bit = 49)]
    pub f823: Flag,
    #[plc(source = "f619", bit = 50)]
    pub f824: Flag,
    #[plc(source = "f620", bit = 0)]
    pub f825: Flag,
    #[plc(source = "f620", bit = 1)]
    pub f826: Flag,
    #[plc(source = "f620", bit = 2)]
    pub f827: Flag,
    #[plc(source = "f620", bit = 3)]
    pub f828: Flag,
    #[plc(source = "f620", bit = 4)]
    pub f829: Flag,
    #[plc(source = "f620", bit = 5)]
    pub f830: Flag,
    #[plc(source = "f620", bit = 6)]
    pub f831: Flag,
    #[plc(source = "f620", bit = 7)]
    pub f832: Flag,
    #[plc(source = "f620", bit = 8)]
    pub f833: Flag,
    #[plc(source = "f620", bit = 9)]
    pub f834: Flag,
    #[plc(source = "f620", bit = 10)]
    pub f835: Flag,
    #[plc(source = "f620", bit = 11)]
    pub f836: Flag,
    #[plc(source = "f620", bit = 12)]
    pub f837: Flag,
    #[plc(source = "f620", bit = 13)]
    pub f838: Flag,
    #[plc(source = "f620", bit = 14)]
    pub f839: Flag,
    #[plc(source = "f620", bit = 15)]
    pub f840: Flag,
    #[plc(source = "f620", bit = 16)]
    pub f841: Flag,
    #[plc(source = "f620", bit = 17)]
    pub f842: Flag,
    #[plc(source = "f620", bit = 18)]
    pub f843: Flag,
    #[plc(source = "f620", bit = 19)]
    pub f844: Flag,
    #[plc(source = "f620", bit = 20)]
    pub f845: Flag,
    #[plc(source = "f620", bit = 21)]
    pub f846: Flag,
    #[plc(source = "f620", bit = 22)]
    pub f847: Flag,
    #[plc(source = "f620", bit = 23)]
    pub f848: Flag,
    #[plc(source = "f620", bit = 24)]
    pub f849: Flag,
    #[plc(source = "f620", bit = 25)]
    pub f850: Flag,
    #[plc(source = "f620", bit = 26)]
    pub f851: Flag,
    #[plc(source = "f620", bit = 27)]
    pub f852: Flag,
    #[plc(source = "f620", bit = 28)]
    pub f853: Flag,
    #[plc(source = "f620", bit = 29)]
    pub f854: Flag,
    #[plc(source = "f620", bit = 30)]
    pub f855: Flag,
    #[plc(source = "f620", bit = 31)]
    pub f856: Flag,
    #[plc(source = "f620", bit = 32)]
    pub f857: Flag,
    #[plc(source = "f620", bit = 33)]
    pub f858: Flag,
    #[plc(source = "f620", bit = 34)]
    pub f859: Flag,
    #[plc(source = "f620", bit = 35)]
    pub f860: Flag,
    #[plc(source = "f620", bit = 36)]
    pub f861: Flag,
    #[plc(source = "f620", bit = 37)]
    pub f862: Flag,
    #[plc(source = "f620", bit = 38)]
    pub f863: Flag,
    #[plc(source = "f620", bit = 39)]
    pub f864: Flag,
    #[plc(source = "f620", bit = 40)]
    pub f865: Flag,
    #[plc(source = "f620", bit = 41)]
    pub f866: Flag,
    #[plc(source = "f620", bit = 42)]
    pub f867: Flag,
    #[plc(source = "f620", bit = 43)]
    pub f868: Flag,
    #[plc(source = "f620", bit = 44)]
    pub f869: Flag,
    #[plc(source = "f620", bit = 45)]
    pub f870: Flag,
    #[plc(source = "f620", bit = 46)]
    pub f871: Flag,
    #[plc(source = "f620", bit = 47)]
    pub f872: Flag,
    #[plc(source = "f620", bit = 48)]
    pub f873: Flag,
    #[plc(source = "f620", bit = 49)]
    pub f874: Flag,
    #[plc(source = "f620", bit = 50)]
    pub f875: Flag,
}

impl Reference for Random2 {
    fn reference_store(&self) -> Vec<u8> {
        let mut b = Vec::new();
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f0).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f1).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f2).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f3).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f4).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f5).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f6).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f7).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f8).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f9).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f10).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f11).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f12).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f13).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f14).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f15).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f16).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f17).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f18).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f19).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f20).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f21).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f22).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f23).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f24).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f25).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f26).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f27).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f28).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f29).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f30).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f31).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f32).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f33).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f34).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f35).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f36).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f37).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f38).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f39).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f40).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f41).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f42).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f43).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f44).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f45).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f46).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f47).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f48).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f49).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f50).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f51).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f52).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f53).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f54).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f55).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f56).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f57).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f58).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f59).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f60).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f61).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f62).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f63).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f64).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f65).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f66).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f67).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f68).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f69).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f70).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f71).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f72).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f73).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f74).as_bytes());
        b.extend_from_slice(<u16 as PlcType>::to_repr(&self.f75).as_bytes());
        b.extend_from_slice(<u16 as PlcType>::to_repr(&self.f76).as_bytes());
        b.extend_from_slice(<u16 as PlcType>::to_repr(&self.f77).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f78).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f79).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f80).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f81).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f82).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f83).as_bytes());
        b.extend_from_slice(<f64 as PlcType>::to_repr(&self.f84).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f85).as_bytes());
        b.extend_from_slice(<f64 as PlcType>::to_repr(&self.f86).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f87).as_bytes());
        b.extend_from_slice(<f64 as PlcType>::to_repr(&self.f88).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f89).as_bytes());
        b.extend_from_slice(<f64 as PlcType>::to_repr(&self.f90).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f91).as_bytes());
        b.extend_from_slice(<f64 as PlcType>::to_repr(&self.f92).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f93).as_bytes());
        b.extend_from_slice(<f64 as PlcType>::to_repr(&self.f94).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f95).as_bytes());
        b.extend_from_slice(<f64 as PlcType>::to_repr(&self.f96).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f97).as_bytes());
        b.extend_from_slice(<f64 as PlcType>::to_repr(&self.f98).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f99).as_bytes());
        b.extend_from_slice(<f64 as PlcType>::to_repr(&self.f100).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f101).as_bytes());
        b.extend_from_slice(<f64 as PlcType>::to_repr(&self.f102).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f103).as_bytes());
        b.extend_from_slice(<f64 as PlcType>::to_repr(&self.f104).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f105).as_bytes());
        b.extend_from_slice(<f64 as PlcType>::to_repr(&self.f106).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f107).as_bytes());
        b.extend_from_slice(<f64 as PlcType>::to_repr(&self.f108).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f109).as_bytes());
        b.extend_from_slice(<f64 as PlcType>::to_repr(&self.f110).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f111).as_bytes());
        b.extend_from_slice(<f64 as PlcType>::to_repr(&self.f112).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f113).as_bytes());
        b.extend_from_slice(<f64 as PlcType>::to_repr(&self.f114).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f115).as_bytes());
        b.extend_from_slice(<f64 as PlcType>::to_repr(&self.f116).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f117).as_bytes());
        b.extend_from_slice(<f64 as PlcType>::to_repr(&self.f118).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f119).as_bytes());
        b.extend_from_slice(<f64 as PlcType>::to_repr(&self.f120).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f121).as_bytes());
        b.extend_from_slice(<f64 as PlcType>::to_repr(&self.f122).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f123).as_bytes());
        b.extend_from_slice(<f64 as PlcType>::to_repr(&self.f124).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f125).as_bytes());
        b.extend_from_slice(<f64 as PlcType>::to_repr(&self.f126).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f127).as_bytes());
        b.extend_from_slice(<f64 as PlcType>::to_repr(&self.f128).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f129).as_bytes());
        b.extend_from_slice(<f64 as PlcType>::to_repr(&self.f130).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f131).as_bytes());
        b.extend_from_slice(<f64 as PlcType>::to_repr(&self.f132).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f133).as_bytes());
        b.extend_from_slice(<f64 as PlcType>::to_repr(&self.f134).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f135).as_bytes());
        b.extend_from_slice(<f64 as PlcType>::to_repr(&self.f136).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f137).as_bytes());
        b.extend_from_slice(<f64 as PlcType>::to_repr(&self.f138).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f139).as_bytes());
        b.extend_from_slice(<f64 as PlcType>::to_repr(&self.f140).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f141).as_bytes());
        b.extend_from_slice(<f64 as PlcType>::to_repr(&self.f142).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f143).as_bytes());
        b.extend_from_slice(<f64 as PlcType>::to_repr(&self.f144).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f145).as_bytes());
        b.extend_from_slice(<f64 as PlcType>::to_repr(&self.f146).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f147).as_bytes());
        b.extend_from_slice(<f64 as PlcType>::to_repr(&self.f148).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f149).as_bytes());
        b.extend_from_slice(<f64 as PlcType>::to_repr(&self.f150).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f151).as_bytes());
        b.extend_from_slice(<f64 as PlcType>::to_repr(&self.f152).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f153).as_bytes());
        b.extend_from_slice(<f64 as PlcType>::to_repr(&self.f154).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f155).as_bytes());
        b.extend_from_slice(<f64 as PlcType>::to_repr(&self.f156).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f157).as_bytes());
        b.extend_from_slice(<f64 as PlcType>::to_repr(&self.f158).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f159).as_bytes());
        b.extend_from_slice(<f64 as PlcType>::to_repr(&self.f160).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f161).as_bytes());
        b.extend_from_slice(<f64 as PlcType>::to_repr(&self.f162).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f163).as_bytes());
        b.extend_from_slice(<f64 as PlcType>::to_repr(&self.f164).as_bytes());
        b.extend_from_slice(<u32 as PlcType>::to_repr(&self.f165).as_bytes());
        b.extend_from_slice(<f64 as PlcType>::to_repr(&self.f166).as_bytes());
        b.extend_from_slice(<FixedString<5> as PlcType>::to_repr(&self.f167).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f168).as_bytes());
        b.extend_from_slice(<[[i8; 2]; 2] as PlcType>::to_repr(&self.f169).as_bytes());
        b.extend_from_slice(<f64 as PlcType>::to_repr(&self.f170).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f171).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f172).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f173).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f174).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f175).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f176).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f177).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f178).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f179).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f180).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f181).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f182).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f183).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f184).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f185).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f186).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f187).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f188).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f189).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f190).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f191).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f192).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f193).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f194).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f195).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f196).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f197).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f198).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f199).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f200).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f201).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f202).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f203).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f204).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f205).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f206).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f207).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f208).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f209).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f210).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f211).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f212).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f213).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f214).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f215).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f216).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f217).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f218).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f219).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f220).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f221).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f222).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f223).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f224).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f225).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f226).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f227).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f228).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f229).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f230).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f231).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f232).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f233).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f234).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f235).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f236).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f237).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f238).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f239).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f240).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f241).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f242).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f243).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f244).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f245).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f246).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f247).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f248).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f249).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f250).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f251).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f252).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f253).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f254).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f255).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f256).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f257).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f258).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f259).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f260).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f261).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f262).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f263).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f264).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f265).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f266).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f267).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f268).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f269).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f270).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f271).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f272).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f273).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f274).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f275).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f276).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f277).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f278).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f279).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f280).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f281).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f282).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f283).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f284).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f285).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f286).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f287).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f288).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f289).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f290).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f291).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f292).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f293).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f294).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f295).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f296).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f297).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f298).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f299).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f300).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f301).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f302).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f303).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f304).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f305).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f306).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f307).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f308).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f309).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f310).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f311).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f312).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f313).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f314).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f315).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f316).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f317).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f318).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f319).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f320).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f321).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f322).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f323).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f324).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f325).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f326).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f327).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f328).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f329).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f330).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f331).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f332).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f333).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f334).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f335).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f336).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f337).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f338).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f339).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f340).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f341).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f342).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f343).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f344).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f345).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f346).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f347).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f348).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f349).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f350).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f351).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f352).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f353).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f354).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f355).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f356).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f357).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f358).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f359).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f360).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f361).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f362).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f363).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f364).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f365).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f366).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f367).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f368).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f369).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f370).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f371).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f372).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f373).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f374).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f375).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f376).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f377).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f378).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f379).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f380).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f381).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f382).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f383).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f384).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f385).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f386).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f387).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f388).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f389).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f390).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f391).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f392).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f393).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f394).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f395).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f396).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f397).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f398).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f399).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f400).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f401).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f402).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f403).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f404).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f405).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f406).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f407).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f408).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f409).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f410).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f411).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f412).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f413).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f414).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f415).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f416).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f417).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f418).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f419).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f420).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f421).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f422).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f423).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f424).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f425).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f426).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f427).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f428).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f429).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f430).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f431).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f432).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f433).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f434).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f435).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f436).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f437).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f438).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f439).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f440).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f441).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f442).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f443).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f444).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f445).as_bytes());
        b.extend_from_slice(<[[i8; 2]; 2] as PlcType>::to_repr(&self.f446).as_bytes());
        b.extend_from_slice(<u8 as PlcType>::to_repr(&self.f447).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f448).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f449).as_bytes());
        b.extend_from_slice(<[[i8; 2]; 2] as PlcType>::to_repr(&self.f450).as_bytes());
        b.extend_from_slice(<u8 as PlcType>::to_repr(&self.f451).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f452).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f453).as_bytes());
        b.extend_from_slice(<[[i8; 2]; 2] as PlcType>::to_repr(&self.f454).as_bytes());
        b.extend_from_slice(<u8 as PlcType>::to_repr(&self.f455).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f456).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f457).as_bytes());
        b.extend_from_slice(<[[i8; 2]; 2] as PlcType>::to_repr(&self.f458).as_bytes());
        b.extend_from_slice(<u8 as PlcType>::to_repr(&self.f459).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f460).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f461).as_bytes());
        b.extend_from_slice(<[[i8; 2]; 2] as PlcType>::to_repr(&self.f462).as_bytes());
        b.extend_from_slice(<u8 as PlcType>::to_repr(&self.f463).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f464).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f465).as_bytes());
        b.extend_from_slice(<[[i8; 2]; 2] as PlcType>::to_repr(&self.f466).as_bytes());
        b.extend_from_slice(<u8 as PlcType>::to_repr(&self.f467).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f468).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f469).as_bytes());
        b.extend_from_slice(<[[i8; 2]; 2] as PlcType>::to_repr(&self.f470).as_bytes());
        b.extend_from_slice(<u8 as PlcType>::to_repr(&self.f471).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f472).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f473).as_bytes());
        b.extend_from_slice(<[[i8; 2]; 2] as PlcType>::to_repr(&self.f474).as_bytes());
        b.extend_from_slice(<u8 as PlcType>::to_repr(&self.f475).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f476).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f477).as_bytes());
        b.extend_from_slice(<[[i8; 2]; 2] as PlcType>::to_repr(&self.f478).as_bytes());
        b.extend_from_slice(<u8 as PlcType>::to_repr(&self.f479).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f480).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f481).as_bytes());
        b.extend_from_slice(<[[i8; 2]; 2] as PlcType>::to_repr(&self.f482).as_bytes());
        b.extend_from_slice(<u8 as PlcType>::to_repr(&self.f483).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f484).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f485).as_bytes());
        b.extend_from_slice(<[[i8; 2]; 2] as PlcType>::to_repr(&self.f486).as_bytes());
        b.extend_from_slice(<u8 as PlcType>::to_repr(&self.f487).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f488).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f489).as_bytes());
        b.extend_from_slice(<[[i8; 2]; 2] as PlcType>::to_repr(&self.f490).as_bytes());
        b.extend_from_slice(<u8 as PlcType>::to_repr(&self.f491).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f492).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f493).as_bytes());
        b.extend_from_slice(<[[i8; 2]; 2] as PlcType>::to_repr(&self.f494).as_bytes());
        b.extend_from_slice(<u8 as PlcType>::to_repr(&self.f495).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f496).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f497).as_bytes());
        b.extend_from_slice(<[[i8; 2]; 2] as PlcType>::to_repr(&self.f498).as_bytes());
        b.extend_from_slice(<u8 as PlcType>::to_repr(&self.f499).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f500).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f501).as_bytes());
        b.extend_from_slice(<[[i8; 2]; 2] as PlcType>::to_repr(&self.f502).as_bytes());
        b.extend_from_slice(<u8 as PlcType>::to_repr(&self.f503).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f504).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f505).as_bytes());
        b.extend_from_slice(<[[i8; 2]; 2] as PlcType>::to_repr(&self.f506).as_bytes());
        b.extend_from_slice(<u8 as PlcType>::to_repr(&self.f507).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f508).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f509).as_bytes());
        b.extend_from_slice(<[[i8; 2]; 2] as PlcType>::to_repr(&self.f510).as_bytes());
        b.extend_from_slice(<u8 as PlcType>::to_repr(&self.f511).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f512).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f513).as_bytes());
        b.extend_from_slice(<[[i8; 2]; 2] as PlcType>::to_repr(&self.f514).as_bytes());
        b.extend_from_slice(<u8 as PlcType>::to_repr(&self.f515).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f516).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f517).as_bytes());
        b.extend_from_slice(<[[i8; 2]; 2] as PlcType>::to_repr(&self.f518).as_bytes());
        b.extend_from_slice(<u8 as PlcType>::to_repr(&self.f519).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f520).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f521).as_bytes());
        b.extend_from_slice(<[[i8; 2]; 2] as PlcType>::to_repr(&self.f522).as_bytes());
        b.extend_from_slice(<u8 as PlcType>::to_repr(&self.f523).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f524).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f525).as_bytes());
        b.extend_from_slice(<[[i8; 2]; 2] as PlcType>::to_repr(&self.f526).as_bytes());
        b.extend_from_slice(<u8 as PlcType>::to_repr(&self.f527).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f528).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f529).as_bytes());
        b.extend_from_slice(<[[i8; 2]; 2] as PlcType>::to_repr(&self.f530).as_bytes());
        b.extend_from_slice(<u8 as PlcType>::to_repr(&self.f531).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f532).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f533).as_bytes());
        b.extend_from_slice(<[[i8; 2]; 2] as PlcType>::to_repr(&self.f534).as_bytes());
        b.extend_from_slice(<u8 as PlcType>::to_repr(&self.f535).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f536).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f537).as_bytes());
        b.extend_from_slice(<[[i8; 2]; 2] as PlcType>::to_repr(&self.f538).as_bytes());
        b.extend_from_slice(<u8 as PlcType>::to_repr(&self.f539).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f540).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f541).as_bytes());
        b.extend_from_slice(<[[i8; 2]; 2] as PlcType>::to_repr(&self.f542).as_bytes());
        b.extend_from_slice(<u8 as PlcType>::to_repr(&self.f543).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f544).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f545).as_bytes());
        b.extend_from_slice(<[[i8; 2]; 2] as PlcType>::to_repr(&self.f546).as_bytes());
        b.extend_from_slice(<u8 as PlcType>::to_repr(&self.f547).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f548).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f549).as_bytes());
        b.extend_from_slice(<[[i8; 2]; 2] as PlcType>::to_repr(&self.f550).as_bytes());
        b.extend_from_slice(<u8 as PlcType>::to_repr(&self.f551).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f552).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f553).as_bytes());
        b.extend_from_slice(<[[i8; 2]; 2] as PlcType>::to_repr(&self.f554).as_bytes());
        b.extend_from_slice(<u8 as PlcType>::to_repr(&self.f555).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f556).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f557).as_bytes());
        b.extend_from_slice(<[[i8; 2]; 2] as PlcType>::to_repr(&self.f558).as_bytes());
        b.extend_from_slice(<u8 as PlcType>::to_repr(&self.f559).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f560).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f561).as_bytes());
        b.extend_from_slice(<[[i8; 2]; 2] as PlcType>::to_repr(&self.f562).as_bytes());
        b.extend_from_slice(<u8 as PlcType>::to_repr(&self.f563).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f564).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f565).as_bytes());
        b.extend_from_slice(<[[i8; 2]; 2] as PlcType>::to_repr(&self.f566).as_bytes());
        b.extend_from_slice(<u8 as PlcType>::to_repr(&self.f567).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f568).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f569).as_bytes());
        b.extend_from_slice(<[[i8; 2]; 2] as PlcType>::to_repr(&self.f570).as_bytes());
        b.extend_from_slice(<u8 as PlcType>::to_repr(&self.f571).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f572).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f573).as_bytes());
        b.extend_from_slice(<[[i8; 2]; 2] as PlcType>::to_repr(&self.f574).as_bytes());
        b.extend_from_slice(<u8 as PlcType>::to_repr(&self.f575).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f576).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f577).as_bytes());
        b.extend_from_slice(<[[i8; 2]; 2] as PlcType>::to_repr(&self.f578).as_bytes());
        b.extend_from_slice(<u8 as PlcType>::to_repr(&self.f579).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f580).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f581).as_bytes());
        b.extend_from_slice(<[[i8; 2]; 2] as PlcType>::to_repr(&self.f582).as_bytes());
        b.extend_from_slice(<u8 as PlcType>::to_repr(&self.f583).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f584).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f585).as_bytes());
        b.extend_from_slice(<[[i8; 2]; 2] as PlcType>::to_repr(&self.f586).as_bytes());
        b.extend_from_slice(<u8 as PlcType>::to_repr(&self.f587).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f588).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f589).as_bytes());
        b.extend_from_slice(<[[i8; 2]; 2] as PlcType>::to_repr(&self.f590).as_bytes());
        b.extend_from_slice(<u8 as PlcType>::to_repr(&self.f591).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f592).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f593).as_bytes());
        b.extend_from_slice(<[[i8; 2]; 2] as PlcType>::to_repr(&self.f594).as_bytes());
        b.extend_from_slice(<u8 as PlcType>::to_repr(&self.f595).as_bytes());
        b.extend_from_slice(<Word as PlcType>::to_repr(&self.f596).as_bytes());
        b.extend_from_slice(<[u16; 3] as PlcType>::to_repr(&self.f597).as_bytes());
        b.extend_from_slice(<[[i8; 2]; 2] as PlcType>::to_repr(&self.f598).as_bytes());
        b.extend_from_slice(<u8 as PlcType>::to_repr(&self.f599).as_bytes());
        b.extend_from_slice(<u16 as PlcType>::to_repr(&self.f600).as_bytes());
        b.extend_from_slice(<u16 as PlcType>::to_repr(&self.f601).as_bytes());
        b.extend_from_slice(<u16 as PlcType>::to_repr(&self.f602).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f603).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f604).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f605).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f606).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f607).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f608).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f609).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f610).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f611).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f612).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f613).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f614).as_bytes());
        b.extend_from_slice(<bool as PlcType>::to_repr(&self.f615).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f616).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f617).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f618).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f619).as_bytes());
        b.extend_from_slice(<u64 as PlcType>::to_repr(&self.f620).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f621).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f622).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f623).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f624).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f625).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f626).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f627).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f628).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f629).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f630).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f631).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f632).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f633).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f634).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f635).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f636).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f637).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f638).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f639).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f640).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f641).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f642).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f643).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f644).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f645).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f646).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f647).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f648).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f649).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f650).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f651).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f652).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f653).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f654).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f655).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f656).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f657).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f658).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f659).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f660).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f661).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f662).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f663).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f664).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f665).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f666).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f667).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f668).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f669).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f670).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f671).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f672).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f673).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f674).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f675).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f676).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f677).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f678).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f679).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f680).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f681).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f682).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f683).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f684).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f685).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f686).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f687).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f688).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f689).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f690).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f691).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f692).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f693).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f694).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f695).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f696).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f697).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f698).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f699).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f700).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f701).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f702).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f703).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f704).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f705).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f706).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f707).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f708).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f709).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f710).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f711).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f712).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f713).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f714).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f715).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f716).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f717).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f718).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f719).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f720).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f721).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f722).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f723).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f724).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f725).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f726).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f727).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f728).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f729).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f730).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f731).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f732).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f733).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f734).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f735).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f736).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f737).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f738).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f739).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f740).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f741).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f742).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f743).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f744).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f745).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f746).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f747).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f748).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f749).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f750).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f751).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f752).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f753).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f754).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f755).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f756).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f757).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f758).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f759).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f760).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f761).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f762).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f763).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f764).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f765).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f766).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f767).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f768).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f769).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f770).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f771).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f772).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f773).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f774).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f775).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f776).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f777).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f778).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f779).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f780).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f781).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f782).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f783).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f784).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f785).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f786).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f787).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f788).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f789).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f790).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f791).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f792).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f793).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f794).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f795).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f796).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f797).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f798).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f799).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f800).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f801).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f802).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f803).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f804).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f805).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f806).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f807).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f808).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f809).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f810).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f811).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f812).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f813).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f814).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f815).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f816).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f817).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f818).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f819).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f820).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f821).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f822).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f823).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f824).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f825).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f826).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f827).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f828).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f829).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f830).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f831).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f832).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f833).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f834).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f835).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f836).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f837).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f838).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f839).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f840).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f841).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f842).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f843).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f844).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f845).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f846).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f847).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f848).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f849).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f850).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f851).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f852).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f853).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f854).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f855).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f856).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f857).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f858).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f859).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f860).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f861).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f862).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f863).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f864).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f865).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f866).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f867).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f868).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f869).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f870).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f871).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f872).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f873).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f874).as_bytes());
        b.extend_from_slice(<Flag as PlcType>::to_repr(&self.f875).as_bytes());
        b
    }

    fn reference_load(&mut self, b: &[u8]) {
        let mut at = 0;
        self.f0 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f1 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f2 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f3 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f4 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f5 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f6 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f7 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f8 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f9 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f10 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f11 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f12 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f13 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f14 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f15 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f16 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f17 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f18 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f19 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f20 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f21 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f22 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f23 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f24 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f25 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f26 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f27 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f28 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f29 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f30 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f31 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f32 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f33 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f34 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f35 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f36 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f37 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f38 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f39 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f40 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f41 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f42 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f43 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f44 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f45 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f46 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f47 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f48 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f49 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f50 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f51 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f52 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f53 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f54 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f55 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f56 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f57 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f58 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f59 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f60 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f61 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f62 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f63 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f64 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f65 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f66 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f67 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f68 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f69 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f70 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f71 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f72 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f73 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f74 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f75 = <u16 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u16 as PlcType>::Repr>();
        self.f76 = <u16 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u16 as PlcType>::Repr>();
        self.f77 = <u16 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u16 as PlcType>::Repr>();
        self.f78 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f79 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f80 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f81 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f82 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f83 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f84 = <f64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<f64 as PlcType>::Repr>();
        self.f85 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f86 = <f64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<f64 as PlcType>::Repr>();
        self.f87 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f88 = <f64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<f64 as PlcType>::Repr>();
        self.f89 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f90 = <f64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<f64 as PlcType>::Repr>();
        self.f91 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f92 = <f64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<f64 as PlcType>::Repr>();
        self.f93 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f94 = <f64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<f64 as PlcType>::Repr>();
        self.f95 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f96 = <f64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<f64 as PlcType>::Repr>();
        self.f97 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f98 = <f64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<f64 as PlcType>::Repr>();
        self.f99 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f100 = <f64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<f64 as PlcType>::Repr>();
        self.f101 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f102 = <f64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<f64 as PlcType>::Repr>();
        self.f103 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f104 = <f64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<f64 as PlcType>::Repr>();
        self.f105 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f106 = <f64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<f64 as PlcType>::Repr>();
        self.f107 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f108 = <f64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<f64 as PlcType>::Repr>();
        self.f109 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f110 = <f64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<f64 as PlcType>::Repr>();
        self.f111 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f112 = <f64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<f64 as PlcType>::Repr>();
        self.f113 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f114 = <f64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<f64 as PlcType>::Repr>();
        self.f115 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f116 = <f64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<f64 as PlcType>::Repr>();
        self.f117 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f118 = <f64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<f64 as PlcType>::Repr>();
        self.f119 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f120 = <f64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<f64 as PlcType>::Repr>();
        self.f121 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f122 = <f64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<f64 as PlcType>::Repr>();
        self.f123 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f124 = <f64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<f64 as PlcType>::Repr>();
        self.f125 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f126 = <f64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<f64 as PlcType>::Repr>();
        self.f127 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f128 = <f64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<f64 as PlcType>::Repr>();
        self.f129 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f130 = <f64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<f64 as PlcType>::Repr>();
        self.f131 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f132 = <f64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<f64 as PlcType>::Repr>();
        self.f133 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f134 = <f64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<f64 as PlcType>::Repr>();
        self.f135 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f136 = <f64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<f64 as PlcType>::Repr>();
        self.f137 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f138 = <f64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<f64 as PlcType>::Repr>();
        self.f139 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f140 = <f64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<f64 as PlcType>::Repr>();
        self.f141 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f142 = <f64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<f64 as PlcType>::Repr>();
        self.f143 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f144 = <f64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<f64 as PlcType>::Repr>();
        self.f145 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f146 = <f64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<f64 as PlcType>::Repr>();
        self.f147 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f148 = <f64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<f64 as PlcType>::Repr>();
        self.f149 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f150 = <f64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<f64 as PlcType>::Repr>();
        self.f151 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f152 = <f64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<f64 as PlcType>::Repr>();
        self.f153 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f154 = <f64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<f64 as PlcType>::Repr>();
        self.f155 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f156 = <f64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<f64 as PlcType>::Repr>();
        self.f157 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f158 = <f64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<f64 as PlcType>::Repr>();
        self.f159 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f160 = <f64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<f64 as PlcType>::Repr>();
        self.f161 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f162 = <f64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<f64 as PlcType>::Repr>();
        self.f163 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f164 = <f64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<f64 as PlcType>::Repr>();
        self.f165 = <u32 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u32 as PlcType>::Repr>();
        self.f166 = <f64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<f64 as PlcType>::Repr>();
        self.f167 = <FixedString<5> as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<FixedString<5> as PlcType>::Repr>();
        self.f168 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f169 = <[[i8; 2]; 2] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[[i8; 2]; 2] as PlcType>::Repr>();
        self.f170 = <f64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<f64 as PlcType>::Repr>();
        self.f171 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f172 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f173 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f174 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f175 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f176 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f177 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f178 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f179 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f180 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f181 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f182 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f183 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f184 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f185 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f186 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f187 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f188 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f189 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f190 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f191 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f192 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f193 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f194 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f195 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f196 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f197 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f198 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f199 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f200 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f201 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f202 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f203 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f204 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f205 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f206 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f207 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f208 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f209 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f210 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f211 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f212 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f213 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f214 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f215 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f216 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f217 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f218 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f219 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f220 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f221 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f222 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f223 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f224 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f225 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f226 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f227 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f228 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f229 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f230 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f231 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f232 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f233 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f234 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f235 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f236 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f237 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f238 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f239 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f240 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f241 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f242 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f243 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f244 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f245 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f246 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f247 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f248 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f249 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f250 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f251 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f252 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f253 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f254 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f255 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f256 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f257 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f258 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f259 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f260 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f261 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f262 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f263 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f264 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f265 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f266 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f267 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f268 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f269 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f270 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f271 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f272 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f273 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f274 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f275 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f276 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f277 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f278 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f279 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f280 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f281 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f282 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f283 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f284 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f285 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f286 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f287 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f288 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f289 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f290 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f291 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f292 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f293 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f294 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f295 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f296 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f297 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f298 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f299 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f300 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f301 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f302 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f303 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f304 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f305 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f306 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f307 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f308 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f309 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f310 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f311 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f312 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f313 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f314 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f315 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f316 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f317 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f318 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f319 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f320 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f321 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f322 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f323 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f324 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f325 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f326 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f327 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f328 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f329 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f330 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f331 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f332 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f333 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f334 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f335 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f336 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f337 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f338 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f339 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f340 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f341 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f342 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f343 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f344 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f345 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f346 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f347 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f348 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f349 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f350 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f351 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f352 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f353 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f354 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f355 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f356 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f357 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f358 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f359 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f360 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f361 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f362 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f363 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f364 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f365 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f366 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f367 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f368 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f369 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f370 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f371 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f372 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f373 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f374 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f375 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f376 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f377 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f378 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f379 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f380 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f381 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f382 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f383 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f384 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f385 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f386 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f387 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f388 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f389 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f390 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f391 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f392 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f393 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f394 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f395 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f396 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f397 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f398 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f399 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f400 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f401 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f402 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f403 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f404 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f405 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f406 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f407 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f408 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f409 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f410 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f411 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f412 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f413 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f414 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f415 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f416 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f417 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f418 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f419 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f420 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f421 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f422 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f423 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f424 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f425 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f426 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f427 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f428 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f429 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f430 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f431 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f432 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f433 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f434 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f435 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f436 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f437 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f438 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f439 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f440 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f441 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f442 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f443 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f444 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f445 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f446 = <[[i8; 2]; 2] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[[i8; 2]; 2] as PlcType>::Repr>();
        self.f447 = <u8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u8 as PlcType>::Repr>();
        self.f448 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f449 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f450 = <[[i8; 2]; 2] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[[i8; 2]; 2] as PlcType>::Repr>();
        self.f451 = <u8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u8 as PlcType>::Repr>();
        self.f452 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f453 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f454 = <[[i8; 2]; 2] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[[i8; 2]; 2] as PlcType>::Repr>();
        self.f455 = <u8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u8 as PlcType>::Repr>();
        self.f456 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f457 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f458 = <[[i8; 2]; 2] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[[i8; 2]; 2] as PlcType>::Repr>();
        self.f459 = <u8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u8 as PlcType>::Repr>();
        self.f460 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f461 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f462 = <[[i8; 2]; 2] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[[i8; 2]; 2] as PlcType>::Repr>();
        self.f463 = <u8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u8 as PlcType>::Repr>();
        self.f464 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f465 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f466 = <[[i8; 2]; 2] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[[i8; 2]; 2] as PlcType>::Repr>();
        self.f467 = <u8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u8 as PlcType>::Repr>();
        self.f468 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f469 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f470 = <[[i8; 2]; 2] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[[i8; 2]; 2] as PlcType>::Repr>();
        self.f471 = <u8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u8 as PlcType>::Repr>();
        self.f472 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f473 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f474 = <[[i8; 2]; 2] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[[i8; 2]; 2] as PlcType>::Repr>();
        self.f475 = <u8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u8 as PlcType>::Repr>();
        self.f476 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f477 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f478 = <[[i8; 2]; 2] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[[i8; 2]; 2] as PlcType>::Repr>();
        self.f479 = <u8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u8 as PlcType>::Repr>();
        self.f480 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f481 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f482 = <[[i8; 2]; 2] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[[i8; 2]; 2] as PlcType>::Repr>();
        self.f483 = <u8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u8 as PlcType>::Repr>();
        self.f484 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f485 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f486 = <[[i8; 2]; 2] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[[i8; 2]; 2] as PlcType>::Repr>();
        self.f487 = <u8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u8 as PlcType>::Repr>();
        self.f488 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f489 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f490 = <[[i8; 2]; 2] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[[i8; 2]; 2] as PlcType>::Repr>();
        self.f491 = <u8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u8 as PlcType>::Repr>();
        self.f492 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f493 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f494 = <[[i8; 2]; 2] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[[i8; 2]; 2] as PlcType>::Repr>();
        self.f495 = <u8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u8 as PlcType>::Repr>();
        self.f496 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f497 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f498 = <[[i8; 2]; 2] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[[i8; 2]; 2] as PlcType>::Repr>();
        self.f499 = <u8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u8 as PlcType>::Repr>();
        self.f500 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f501 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f502 = <[[i8; 2]; 2] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[[i8; 2]; 2] as PlcType>::Repr>();
        self.f503 = <u8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u8 as PlcType>::Repr>();
        self.f504 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f505 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f506 = <[[i8; 2]; 2] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[[i8; 2]; 2] as PlcType>::Repr>();
        self.f507 = <u8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u8 as PlcType>::Repr>();
        self.f508 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f509 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f510 = <[[i8; 2]; 2] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[[i8; 2]; 2] as PlcType>::Repr>();
        self.f511 = <u8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u8 as PlcType>::Repr>();
        self.f512 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f513 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f514 = <[[i8; 2]; 2] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[[i8; 2]; 2] as PlcType>::Repr>();
        self.f515 = <u8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u8 as PlcType>::Repr>();
        self.f516 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f517 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f518 = <[[i8; 2]; 2] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[[i8; 2]; 2] as PlcType>::Repr>();
        self.f519 = <u8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u8 as PlcType>::Repr>();
        self.f520 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f521 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f522 = <[[i8; 2]; 2] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[[i8; 2]; 2] as PlcType>::Repr>();
        self.f523 = <u8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u8 as PlcType>::Repr>();
        self.f524 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f525 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f526 = <[[i8; 2]; 2] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[[i8; 2]; 2] as PlcType>::Repr>();
        self.f527 = <u8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u8 as PlcType>::Repr>();
        self.f528 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f529 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f530 = <[[i8; 2]; 2] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[[i8; 2]; 2] as PlcType>::Repr>();
        self.f531 = <u8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u8 as PlcType>::Repr>();
        self.f532 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f533 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f534 = <[[i8; 2]; 2] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[[i8; 2]; 2] as PlcType>::Repr>();
        self.f535 = <u8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u8 as PlcType>::Repr>();
        self.f536 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f537 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f538 = <[[i8; 2]; 2] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[[i8; 2]; 2] as PlcType>::Repr>();
        self.f539 = <u8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u8 as PlcType>::Repr>();
        self.f540 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f541 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f542 = <[[i8; 2]; 2] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[[i8; 2]; 2] as PlcType>::Repr>();
        self.f543 = <u8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u8 as PlcType>::Repr>();
        self.f544 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f545 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f546 = <[[i8; 2]; 2] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[[i8; 2]; 2] as PlcType>::Repr>();
        self.f547 = <u8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u8 as PlcType>::Repr>();
        self.f548 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f549 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f550 = <[[i8; 2]; 2] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[[i8; 2]; 2] as PlcType>::Repr>();
        self.f551 = <u8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u8 as PlcType>::Repr>();
        self.f552 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f553 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f554 = <[[i8; 2]; 2] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[[i8; 2]; 2] as PlcType>::Repr>();
        self.f555 = <u8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u8 as PlcType>::Repr>();
        self.f556 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f557 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f558 = <[[i8; 2]; 2] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[[i8; 2]; 2] as PlcType>::Repr>();
        self.f559 = <u8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u8 as PlcType>::Repr>();
        self.f560 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f561 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f562 = <[[i8; 2]; 2] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[[i8; 2]; 2] as PlcType>::Repr>();
        self.f563 = <u8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u8 as PlcType>::Repr>();
        self.f564 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f565 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f566 = <[[i8; 2]; 2] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[[i8; 2]; 2] as PlcType>::Repr>();
        self.f567 = <u8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u8 as PlcType>::Repr>();
        self.f568 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f569 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f570 = <[[i8; 2]; 2] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[[i8; 2]; 2] as PlcType>::Repr>();
        self.f571 = <u8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u8 as PlcType>::Repr>();
        self.f572 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f573 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f574 = <[[i8; 2]; 2] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[[i8; 2]; 2] as PlcType>::Repr>();
        self.f575 = <u8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u8 as PlcType>::Repr>();
        self.f576 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f577 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f578 = <[[i8; 2]; 2] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[[i8; 2]; 2] as PlcType>::Repr>();
        self.f579 = <u8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u8 as PlcType>::Repr>();
        self.f580 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f581 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f582 = <[[i8; 2]; 2] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[[i8; 2]; 2] as PlcType>::Repr>();
        self.f583 = <u8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u8 as PlcType>::Repr>();
        self.f584 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f585 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f586 = <[[i8; 2]; 2] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[[i8; 2]; 2] as PlcType>::Repr>();
        self.f587 = <u8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u8 as PlcType>::Repr>();
        self.f588 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f589 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f590 = <[[i8; 2]; 2] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[[i8; 2]; 2] as PlcType>::Repr>();
        self.f591 = <u8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u8 as PlcType>::Repr>();
        self.f592 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f593 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f594 = <[[i8; 2]; 2] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[[i8; 2]; 2] as PlcType>::Repr>();
        self.f595 = <u8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u8 as PlcType>::Repr>();
        self.f596 = <Word as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Word as PlcType>::Repr>();
        self.f597 = <[u16; 3] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[u16; 3] as PlcType>::Repr>();
        self.f598 = <[[i8; 2]; 2] as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<[[i8; 2]; 2] as PlcType>::Repr>();
        self.f599 = <u8 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u8 as PlcType>::Repr>();
        self.f600 = <u16 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u16 as PlcType>::Repr>();
        self.f601 = <u16 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u16 as PlcType>::Repr>();
        self.f602 = <u16 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u16 as PlcType>::Repr>();
        self.f603 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f604 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f605 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f606 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f607 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f608 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f609 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f610 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f611 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f612 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f613 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f614 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f615 = <bool as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<bool as PlcType>::Repr>();
        self.f616 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f617 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f618 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f619 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f620 = <u64 as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<u64 as PlcType>::Repr>();
        self.f621 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f622 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f623 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f624 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f625 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f626 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f627 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f628 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f629 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f630 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f631 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f632 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f633 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f634 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f635 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f636 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f637 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f638 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f639 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f640 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f641 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f642 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f643 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f644 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f645 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f646 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f647 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f648 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f649 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f650 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f651 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f652 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f653 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f654 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f655 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f656 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f657 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f658 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f659 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f660 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f661 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f662 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f663 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f664 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f665 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f666 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f667 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f668 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f669 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f670 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f671 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f672 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f673 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f674 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f675 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f676 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f677 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f678 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f679 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f680 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f681 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f682 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f683 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f684 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f685 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f686 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f687 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f688 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f689 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f690 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f691 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f692 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f693 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f694 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f695 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f696 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f697 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f698 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f699 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f700 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f701 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f702 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f703 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f704 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f705 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f706 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f707 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f708 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f709 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f710 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f711 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f712 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f713 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f714 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f715 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f716 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f717 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f718 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f719 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f720 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f721 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f722 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f723 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f724 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f725 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f726 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f727 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f728 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f729 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f730 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f731 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f732 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f733 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f734 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f735 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f736 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f737 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f738 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f739 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f740 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f741 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f742 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f743 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f744 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f745 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f746 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f747 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f748 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f749 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f750 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f751 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f752 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f753 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f754 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f755 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f756 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f757 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f758 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f759 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f760 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f761 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f762 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f763 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f764 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f765 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f766 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f767 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f768 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f769 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f770 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f771 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f772 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f773 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f774 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f775 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f776 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f777 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f778 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f779 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f780 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f781 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f782 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f783 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f784 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f785 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f786 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f787 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f788 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f789 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f790 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f791 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f792 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f793 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f794 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f795 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f796 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f797 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f798 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f799 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f800 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f801 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f802 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f803 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f804 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f805 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f806 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f807 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f808 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f809 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f810 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f811 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f812 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f813 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f814 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f815 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f816 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f817 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f818 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f819 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f820 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f821 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f822 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f823 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f824 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f825 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f826 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f827 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f828 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f829 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f830 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f831 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f832 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f833 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f834 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f835 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f836 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f837 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f838 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f839 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f840 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f841 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f842 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f843 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f844 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f845 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f846 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f847 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f848 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f849 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f850 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f851 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f852 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f853 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f854 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f855 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f856 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f857 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f858 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f859 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f860 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f861 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f862 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f863 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f864 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f865 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f866 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f867 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f868 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f869 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f870 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f871 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f872 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f873 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f874 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        self.f875 = <Flag as PlcType>::from_repr(&FromBytes::read_from_prefix(&b[at..]).unwrap().0);
        at += size_of::<<Flag as PlcType>::Repr>();
        assert_eq!(at, b.len());
    }

    fn reference_unpack(&mut self) {
        self.f78 = (self.f77 >> 0) & 1 != 0;
        self.f79 = (self.f77 >> 15) & 1 != 0;
        self.f80 = (self.f76 >> 1) & 1 != 0;
        self.f81 = (self.f75 >> 3) & 1 != 0;
        self.f82 = (self.f75 >> 1) & 1 != 0;
        self.f184 = (self.f171 >> 15) & 1 != 0;
        self.f185 = (self.f171 >> 16) & 1 != 0;
        self.f186 = (self.f171 >> 17) & 1 != 0;
        self.f187 = (self.f171 >> 18) & 1 != 0;
        self.f188 = (self.f171 >> 19) & 1 != 0;
        self.f189 = (self.f171 >> 20) & 1 != 0;
        self.f190 = (self.f171 >> 21) & 1 != 0;
        self.f191 = (self.f171 >> 22) & 1 != 0;
        self.f192 = (self.f171 >> 23) & 1 != 0;
        self.f193 = (self.f171 >> 24) & 1 != 0;
        self.f194 = (self.f171 >> 25) & 1 != 0;
        self.f195 = (self.f171 >> 26) & 1 != 0;
        self.f196 = (self.f171 >> 27) & 1 != 0;
        self.f197 = (self.f171 >> 28) & 1 != 0;
        self.f198 = (self.f171 >> 29) & 1 != 0;
        self.f199 = (self.f171 >> 30) & 1 != 0;
        self.f200 = (self.f171 >> 31) & 1 != 0;
        self.f201 = (self.f171 >> 32) & 1 != 0;
        self.f202 = (self.f171 >> 33) & 1 != 0;
        self.f203 = (self.f171 >> 34) & 1 != 0;
        self.f204 = (self.f172 >> 15) & 1 != 0;
        self.f205 = (self.f172 >> 16) & 1 != 0;
        self.f206 = (self.f172 >> 17) & 1 != 0;
        self.f207 = (self.f172 >> 18) & 1 != 0;
        self.f208 = (self.f172 >> 19) & 1 != 0;
        self.f209 = (self.f172 >> 20) & 1 != 0;
        self.f210 = (self.f172 >> 21) & 1 != 0;
        self.f211 = (self.f172 >> 22) & 1 != 0;
        self.f212 = (self.f172 >> 23) & 1 != 0;
        self.f213 = (self.f172 >> 24) & 1 != 0;
        self.f214 = (self.f172 >> 25) & 1 != 0;
        self.f215 = (self.f172 >> 26) & 1 != 0;
        self.f216 = (self.f172 >> 27) & 1 != 0;
        self.f217 = (self.f172 >> 28) & 1 != 0;
        self.f218 = (self.f172 >> 29) & 1 != 0;
        self.f219 = (self.f172 >> 30) & 1 != 0;
        self.f220 = (self.f172 >> 31) & 1 != 0;
        self.f221 = (self.f172 >> 32) & 1 != 0;
        self.f222 = (self.f172 >> 33) & 1 != 0;
        self.f223 = (self.f172 >> 34) & 1 != 0;
        self.f224 = (self.f173 >> 15) & 1 != 0;
        self.f225 = (self.f173 >> 16) & 1 != 0;
        self.f226 = (self.f173 >> 17) & 1 != 0;
        self.f227 = (self.f173 >> 18) & 1 != 0;
        self.f228 = (self.f173 >> 19) & 1 != 0;
        self.f229 = (self.f173 >> 20) & 1 != 0;
        self.f230 = (self.f173 >> 21) & 1 != 0;
        self.f231 = (self.f173 >> 22) & 1 != 0;
        self.f232 = (self.f173 >> 23) & 1 != 0;
        self.f233 = (self.f173 >> 24) & 1 != 0;
        self.f234 = (self.f173 >> 25) & 1 != 0;
        self.f235 = (self.f173 >> 26) & 1 != 0;
        self.f236 = (self.f173 >> 27) & 1 != 0;
        self.f237 = (self.f173 >> 28) & 1 != 0;
        self.f238 = (self.f173 >> 29) & 1 != 0;
        self.f239 = (self.f173 >> 30) & 1 != 0;
        self.f240 = (self.f173 >> 31) & 1 != 0;
        self.f241 = (self.f173 >> 32) & 1 != 0;
        self.f242 = (self.f173 >> 33) & 1 != 0;
        self.f243 = (self.f173 >> 34) & 1 != 0;
        self.f244 = (self.f174 >> 15) & 1 != 0;
        self.f245 = (self.f174 >> 16) & 1 != 0;
        self.f246 = (self.f174 >> 17) & 1 != 0;
        self.f247 = (self.f174 >> 18) & 1 != 0;
        self.f248 = (self.f174 >> 19) & 1 != 0;
        self.f249 = (self.f174 >> 20) & 1 != 0;
        self.f250 = (self.f174 >> 21) & 1 != 0;
        self.f251 = (self.f174 >> 22) & 1 != 0;
        self.f252 = (self.f174 >> 23) & 1 != 0;
        self.f253 = (self.f174 >> 24) & 1 != 0;
        self.f254 = (self.f174 >> 25) & 1 != 0;
        self.f255 = (self.f174 >> 26) & 1 != 0;
        self.f256 = (self.f174 >> 27) & 1 != 0;
        self.f257 = (self.f174 >> 28) & 1 != 0;
        self.f258 = (self.f174 >> 29) & 1 != 0;
        self.f259 = (self.f174 >> 30) & 1 != 0;
        self.f260 = (self.f174 >> 31) & 1 != 0;
        self.f261 = (self.f174 >> 32) & 1 != 0;
        self.f262 = (self.f174 >> 33) & 1 != 0;
        self.f263 = (self.f174 >> 34) & 1 != 0;
        self.f264 = (self.f175 >> 15) & 1 != 0;
        self.f265 = (self.f175 >> 16) & 1 != 0;
        self.f266 = (self.f175 >> 17) & 1 != 0;
        self.f267 = (self.f175 >> 18) & 1 != 0;
        self.f268 = (self.f175 >> 19) & 1 != 0;
        self.f269 = (self.f175 >> 20) & 1 != 0;
        self.f270 = (self.f175 >> 21) & 1 != 0;
        self.f271 = (self.f175 >> 22) & 1 != 0;
        self.f272 = (self.f175 >> 23) & 1 != 0;
        self.f273 = (self.f175 >> 24) & 1 != 0;
        self.f274 = (self.f175 >> 25) & 1 != 0;
        self.f275 = (self.f175 >> 26) & 1 != 0;
        self.f276 = (self.f175 >> 27) & 1 != 0;
        self.f277 = (self.f175 >> 28) & 1 != 0;
        self.f278 = (self.f175 >> 29) & 1 != 0;
        self.f279 = (self.f175 >> 30) & 1 != 0;
        self.f280 = (self.f175 >> 31) & 1 != 0;
        self.f281 = (self.f175 >> 32) & 1 != 0;
        self.f282 = (self.f175 >> 33) & 1 != 0;
        self.f283 = (self.f175 >> 34) & 1 != 0;
        self.f284 = (self.f176 >> 15) & 1 != 0;
        self.f285 = (self.f176 >> 16) & 1 != 0;
        self.f286 = (self.f176 >> 17) & 1 != 0;
        self.f287 = (self.f176 >> 18) & 1 != 0;
        self.f288 = (self.f176 >> 19) & 1 != 0;
        self.f289 = (self.f176 >> 20) & 1 != 0;
        self.f290 = (self.f176 >> 21) & 1 != 0;
        self.f291 = (self.f176 >> 22) & 1 != 0;
        self.f292 = (self.f176 >> 23) & 1 != 0;
        self.f293 = (self.f176 >> 24) & 1 != 0;
        self.f294 = (self.f176 >> 25) & 1 != 0;
        self.f295 = (self.f176 >> 26) & 1 != 0;
        self.f296 = (self.f176 >> 27) & 1 != 0;
        self.f297 = (self.f176 >> 28) & 1 != 0;
        self.f298 = (self.f176 >> 29) & 1 != 0;
        self.f299 = (self.f176 >> 30) & 1 != 0;
        self.f300 = (self.f176 >> 31) & 1 != 0;
        self.f301 = (self.f176 >> 32) & 1 != 0;
        self.f302 = (self.f176 >> 33) & 1 != 0;
        self.f303 = (self.f176 >> 34) & 1 != 0;
        self.f304 = (self.f177 >> 15) & 1 != 0;
        self.f305 = (self.f177 >> 16) & 1 != 0;
        self.f306 = (self.f177 >> 17) & 1 != 0;
        self.f307 = (self.f177 >> 18) & 1 != 0;
        self.f308 = (self.f177 >> 19) & 1 != 0;
        self.f309 = (self.f177 >> 20) & 1 != 0;
        self.f310 = (self.f177 >> 21) & 1 != 0;
        self.f311 = (self.f177 >> 22) & 1 != 0;
        self.f312 = (self.f177 >> 23) & 1 != 0;
        self.f313 = (self.f177 >> 24) & 1 != 0;
        self.f314 = (self.f177 >> 25) & 1 != 0;
        self.f315 = (self.f177 >> 26) & 1 != 0;
        self.f316 = (self.f177 >> 27) & 1 != 0;
        self.f317 = (self.f177 >> 28) & 1 != 0;
        self.f318 = (self.f177 >> 29) & 1 != 0;
        self.f319 = (self.f177 >> 30) & 1 != 0;
        self.f320 = (self.f177 >> 31) & 1 != 0;
        self.f321 = (self.f177 >> 32) & 1 != 0;
        self.f322 = (self.f177 >> 33) & 1 != 0;
        self.f323 = (self.f177 >> 34) & 1 != 0;
        self.f324 = (self.f178 >> 15) & 1 != 0;
        self.f325 = (self.f178 >> 16) & 1 != 0;
        self.f326 = (self.f178 >> 17) & 1 != 0;
        self.f327 = (self.f178 >> 18) & 1 != 0;
        self.f328 = (self.f178 >> 19) & 1 != 0;
        self.f329 = (self.f178 >> 20) & 1 != 0;
        self.f330 = (self.f178 >> 21) & 1 != 0;
        self.f331 = (self.f178 >> 22) & 1 != 0;
        self.f332 = (self.f178 >> 23) & 1 != 0;
        self.f333 = (self.f178 >> 24) & 1 != 0;
        self.f334 = (self.f178 >> 25) & 1 != 0;
        self.f335 = (self.f178 >> 26) & 1 != 0;
        self.f336 = (self.f178 >> 27) & 1 != 0;
        self.f337 = (self.f178 >> 28) & 1 != 0;
        self.f338 = (self.f178 >> 29) & 1 != 0;
        self.f339 = (self.f178 >> 30) & 1 != 0;
        self.f340 = (self.f178 >> 31) & 1 != 0;
        self.f341 = (self.f178 >> 32) & 1 != 0;
        self.f342 = (self.f178 >> 33) & 1 != 0;
        self.f343 = (self.f178 >> 34) & 1 != 0;
        self.f344 = (self.f179 >> 15) & 1 != 0;
        self.f345 = (self.f179 >> 16) & 1 != 0;
        self.f346 = (self.f179 >> 17) & 1 != 0;
        self.f347 = (self.f179 >> 18) & 1 != 0;
        self.f348 = (self.f179 >> 19) & 1 != 0;
        self.f349 = (self.f179 >> 20) & 1 != 0;
        self.f350 = (self.f179 >> 21) & 1 != 0;
        self.f351 = (self.f179 >> 22) & 1 != 0;
        self.f352 = (self.f179 >> 23) & 1 != 0;
        self.f353 = (self.f179 >> 24) & 1 != 0;
        self.f354 = (self.f179 >> 25) & 1 != 0;
        self.f355 = (self.f179 >> 26) & 1 != 0;
        self.f356 = (self.f179 >> 27) & 1 != 0;
        self.f357 = (self.f179 >> 28) & 1 != 0;
        self.f358 = (self.f179 >> 29) & 1 != 0;
        self.f359 = (self.f179 >> 30) & 1 != 0;
        self.f360 = (self.f179 >> 31) & 1 != 0;
        self.f361 = (self.f179 >> 32) & 1 != 0;
        self.f362 = (self.f179 >> 33) & 1 != 0;
        self.f363 = (self.f179 >> 34) & 1 != 0;
        self.f364 = (self.f180 >> 15) & 1 != 0;
        self.f365 = (self.f180 >> 16) & 1 != 0;
        self.f366 = (self.f180 >> 17) & 1 != 0;
        self.f367 = (self.f180 >> 18) & 1 != 0;
        self.f368 = (self.f180 >> 19) & 1 != 0;
        self.f369 = (self.f180 >> 20) & 1 != 0;
        self.f370 = (self.f180 >> 21) & 1 != 0;
        self.f371 = (self.f180 >> 22) & 1 != 0;
        self.f372 = (self.f180 >> 23) & 1 != 0;
        self.f373 = (self.f180 >> 24) & 1 != 0;
        self.f374 = (self.f180 >> 25) & 1 != 0;
        self.f375 = (self.f180 >> 26) & 1 != 0;
        self.f376 = (self.f180 >> 27) & 1 != 0;
        self.f377 = (self.f180 >> 28) & 1 != 0;
        self.f378 = (self.f180 >> 29) & 1 != 0;
        self.f379 = (self.f180 >> 30) & 1 != 0;
        self.f380 = (self.f180 >> 31) & 1 != 0;
        self.f381 = (self.f180 >> 32) & 1 != 0;
        self.f382 = (self.f180 >> 33) & 1 != 0;
        self.f383 = (self.f180 >> 34) & 1 != 0;
        self.f384 = (self.f181 >> 15) & 1 != 0;
        self.f385 = (self.f181 >> 16) & 1 != 0;
        self.f386 = (self.f181 >> 17) & 1 != 0;
        self.f387 = (self.f181 >> 18) & 1 != 0;
        self.f388 = (self.f181 >> 19) & 1 != 0;
        self.f389 = (self.f181 >> 20) & 1 != 0;
        self.f390 = (self.f181 >> 21) & 1 != 0;
        self.f391 = (self.f181 >> 22) & 1 != 0;
        self.f392 = (self.f181 >> 23) & 1 != 0;
        self.f393 = (self.f181 >> 24) & 1 != 0;
        self.f394 = (self.f181 >> 25) & 1 != 0;
        self.f395 = (self.f181 >> 26) & 1 != 0;
        self.f396 = (self.f181 >> 27) & 1 != 0;
        self.f397 = (self.f181 >> 28) & 1 != 0;
        self.f398 = (self.f181 >> 29) & 1 != 0;
        self.f399 = (self.f181 >> 30) & 1 != 0;
        self.f400 = (self.f181 >> 31) & 1 != 0;
        self.f401 = (self.f181 >> 32) & 1 != 0;
        self.f402 = (self.f181 >> 33) & 1 != 0;
        self.f403 = (self.f181 >> 34) & 1 != 0;
        self.f404 = (self.f182 >> 15) & 1 != 0;
        self.f405 = (self.f182 >> 16) & 1 != 0;
        self.f406 = (self.f182 >> 17) & 1 != 0;
        self.f407 = (self.f182 >> 18) & 1 != 0;
        self.f408 = (self.f182 >> 19) & 1 != 0;
        self.f409 = (self.f182 >> 20) & 1 != 0;
        self.f410 = (self.f182 >> 21) & 1 != 0;
        self.f411 = (self.f182 >> 22) & 1 != 0;
        self.f412 = (self.f182 >> 23) & 1 != 0;
        self.f413 = (self.f182 >> 24) & 1 != 0;
        self.f414 = (self.f182 >> 25) & 1 != 0;
        self.f415 = (self.f182 >> 26) & 1 != 0;
        self.f416 = (self.f182 >> 27) & 1 != 0;
        self.f417 = (self.f182 >> 28) & 1 != 0;
        self.f418 = (self.f182 >> 29) & 1 != 0;
        self.f419 = (self.f182 >> 30) & 1 != 0;
        self.f420 = (self.f182 >> 31) & 1 != 0;
        self.f421 = (self.f182 >> 32) & 1 != 0;
        self.f422 = (self.f182 >> 33) & 1 != 0;
        self.f423 = (self.f182 >> 34) & 1 != 0;
        self.f424 = (self.f183 >> 15) & 1 != 0;
        self.f425 = (self.f183 >> 16) & 1 != 0;
        self.f426 = (self.f183 >> 17) & 1 != 0;
        self.f427 = (self.f183 >> 18) & 1 != 0;
        self.f428 = (self.f183 >> 19) & 1 != 0;
        self.f429 = (self.f183 >> 20) & 1 != 0;
        self.f430 = (self.f183 >> 21) & 1 != 0;
        self.f431 = (self.f183 >> 22) & 1 != 0;
        self.f432 = (self.f183 >> 23) & 1 != 0;
        self.f433 = (self.f183 >> 24) & 1 != 0;
        self.f434 = (self.f183 >> 25) & 1 != 0;
        self.f435 = (self.f183 >> 26) & 1 != 0;
        self.f436 = (self.f183 >> 27) & 1 != 0;
        self.f437 = (self.f183 >> 28) & 1 != 0;
        self.f438 = (self.f183 >> 29) & 1 != 0;
        self.f439 = (self.f183 >> 30) & 1 != 0;
        self.f440 = (self.f183 >> 31) & 1 != 0;
        self.f441 = (self.f183 >> 32) & 1 != 0;
        self.f442 = (self.f183 >> 33) & 1 != 0;
        self.f443 = (self.f183 >> 34) & 1 != 0;
        self.f603 = (self.f600 >> 7) & 1 != 0;
        self.f604 = (self.f601 >> 11) & 1 != 0;
        self.f605 = (self.f601 >> 0) & 1 != 0;
        self.f606 = (self.f601 >> 12) & 1 != 0;
        self.f607 = (self.f602 >> 12) & 1 != 0;
        self.f608 = (self.f601 >> 7) & 1 != 0;
        self.f609 = (self.f600 >> 6) & 1 != 0;
        self.f610 = (self.f600 >> 1) & 1 != 0;
        self.f611 = (self.f600 >> 14) & 1 != 0;
        self.f612 = (self.f600 >> 12) & 1 != 0;
        self.f613 = (self.f600 >> 2) & 1 != 0;
        self.f614 = (self.f601 >> 6) & 1 != 0;
        self.f615 = (self.f602 >> 2) & 1 != 0;
        self.f621 = (self.f616 >> 0) & 1 != 0;
        self.f622 = (self.f616 >> 1) & 1 != 0;
        self.f623 = (self.f616 >> 2) & 1 != 0;
        self.f624 = (self.f616 >> 3) & 1 != 0;
        self.f625 = (self.f616 >> 4) & 1 != 0;
        self.f626 = (self.f616 >> 5) & 1 != 0;
        self.f627 = (self.f616 >> 6) & 1 != 0;
        self.f628 = (self.f616 >> 7) & 1 != 0;
        self.f629 = (self.f616 >> 8) & 1 != 0;
        self.f630 = (self.f616 >> 9) & 1 != 0;
        self.f631 = (self.f616 >> 10) & 1 != 0;
        self.f632 = (self.f616 >> 11) & 1 != 0;
        self.f633 = (self.f616 >> 12) & 1 != 0;
        self.f634 = (self.f616 >> 13) & 1 != 0;
        self.f635 = (self.f616 >> 14) & 1 != 0;
        self.f636 = (self.f616 >> 15) & 1 != 0;
        self.f637 = (self.f616 >> 16) & 1 != 0;
        self.f638 = (self.f616 >> 17) & 1 != 0;
        self.f639 = (self.f616 >> 18) & 1 != 0;
        self.f640 = (self.f616 >> 19) & 1 != 0;
        self.f641 = (self.f616 >> 20) & 1 != 0;
        self.f642 = (self.f616 >> 21) & 1 != 0;
        self.f643 = (self.f616 >> 22) & 1 != 0;
        self.f644 = (self.f616 >> 23) & 1 != 0;
        self.f645 = (self.f616 >> 24) & 1 != 0;
        self.f646 = (self.f616 >> 25) & 1 != 0;
        self.f647 = (self.f616 >> 26) & 1 != 0;
        self.f648 = (self.f616 >> 27) & 1 != 0;
        self.f649 = (self.f616 >> 28) & 1 != 0;
        self.f650 = (self.f616 >> 29) & 1 != 0;
        self.f651 = (self.f616 >> 30) & 1 != 0;
        self.f652 = (self.f616 >> 31) & 1 != 0;
        self.f653 = (self.f616 >> 32) & 1 != 0;
        self.f654 = (self.f616 >> 33) & 1 != 0;
        self.f655 = (self.f616 >> 34) & 1 != 0;
        self.f656 = (self.f616 >> 35) & 1 != 0;
        self.f657 = (self.f616 >> 36) & 1 != 0;
        self.f658 = (self.f616 >> 37) & 1 != 0;
        self.f659 = (self.f616 >> 38) & 1 != 0;
        self.f660 = (self.f616 >> 39) & 1 != 0;
        self.f661 = (self.f616 >> 40) & 1 != 0;
        self.f662 = (self.f616 >> 41) & 1 != 0;
        self.f663 = (self.f616 >> 42) & 1 != 0;
        self.f664 = (self.f616 >> 43) & 1 != 0;
        self.f665 = (self.f616 >> 44) & 1 != 0;
        self.f666 = (self.f616 >> 45) & 1 != 0;
        self.f667 = (self.f616 >> 46) & 1 != 0;
        self.f668 = (self.f616 >> 47) & 1 != 0;
        self.f669 = (self.f616 >> 48) & 1 != 0;
        self.f670 = (self.f616 >> 49) & 1 != 0;
        self.f671 = (self.f616 >> 50) & 1 != 0;
        self.f672 = (self.f617 >> 0) & 1 != 0;
        self.f673 = (self.f617 >> 1) & 1 != 0;
        self.f674 = (self.f617 >> 2) & 1 != 0;
        self.f675 = (self.f617 >> 3) & 1 != 0;
        self.f676 = (self.f617 >> 4) & 1 != 0;
        self.f677 = (self.f617 >> 5) & 1 != 0;
        self.f678 = (self.f617 >> 6) & 1 != 0;
        self.f679 = (self.f617 >> 7) & 1 != 0;
        self.f680 = (self.f617 >> 8) & 1 != 0;
        self.f681 = (self.f617 >> 9) & 1 != 0;
        self.f682 = (self.f617 >> 10) & 1 != 0;
        self.f683 = (self.f617 >> 11) & 1 != 0;
        self.f684 = (self.f617 >> 12) & 1 != 0;
        self.f685 = (self.f617 >> 13) & 1 != 0;
        self.f686 = (self.f617 >> 14) & 1 != 0;
        self.f687 = (self.f617 >> 15) & 1 != 0;
        self.f688 = (self.f617 >> 16) & 1 != 0;
        self.f689 = (self.f617 >> 17) & 1 != 0;
        self.f690 = (self.f617 >> 18) & 1 != 0;
        self.f691 = (self.f617 >> 19) & 1 != 0;
        self.f692 = (self.f617 >> 20) & 1 != 0;
        self.f693 = (self.f617 >> 21) & 1 != 0;
        self.f694 = (self.f617 >> 22) & 1 != 0;
        self.f695 = (self.f617 >> 23) & 1 != 0;
        self.f696 = (self.f617 >> 24) & 1 != 0;
        self.f697 = (self.f617 >> 25) & 1 != 0;
        self.f698 = (self.f617 >> 26) & 1 != 0;
        self.f699 = (self.f617 >> 27) & 1 != 0;
        self.f700 = (self.f617 >> 28) & 1 != 0;
        self.f701 = (self.f617 >> 29) & 1 != 0;
        self.f702 = (self.f617 >> 30) & 1 != 0;
        self.f703 = (self.f617 >> 31) & 1 != 0;
        self.f704 = (self.f617 >> 32) & 1 != 0;
        self.f705 = (self.f617 >> 33) & 1 != 0;
        self.f706 = (self.f617 >> 34) & 1 != 0;
        self.f707 = (self.f617 >> 35) & 1 != 0;
        self.f708 = (self.f617 >> 36) & 1 != 0;
        self.f709 = (self.f617 >> 37) & 1 != 0;
        self.f710 = (self.f617 >> 38) & 1 != 0;
        self.f711 = (self.f617 >> 39) & 1 != 0;
        self.f712 = (self.f617 >> 40) & 1 != 0;
        self.f713 = (self.f617 >> 41) & 1 != 0;
        self.f714 = (self.f617 >> 42) & 1 != 0;
        self.f715 = (self.f617 >> 43) & 1 != 0;
        self.f716 = (self.f617 >> 44) & 1 != 0;
        self.f717 = (self.f617 >> 45) & 1 != 0;
        self.f718 = (self.f617 >> 46) & 1 != 0;
        self.f719 = (self.f617 >> 47) & 1 != 0;
        self.f720 = (self.f617 >> 48) & 1 != 0;
        self.f721 = (self.f617 >> 49) & 1 != 0;
        self.f722 = (self.f617 >> 50) & 1 != 0;
        self.f723 = (self.f618 >> 0) & 1 != 0;
        self.f724 = (self.f618 >> 1) & 1 != 0;
        self.f725 = (self.f618 >> 2) & 1 != 0;
        self.f726 = (self.f618 >> 3) & 1 != 0;
        self.f727 = (self.f618 >> 4) & 1 != 0;
        self.f728 = (self.f618 >> 5) & 1 != 0;
        self.f729 = (self.f618 >> 6) & 1 != 0;
        self.f730 = (self.f618 >> 7) & 1 != 0;
        self.f731 = (self.f618 >> 8) & 1 != 0;
        self.f732 = (self.f618 >> 9) & 1 != 0;
        self.f733 = (self.f618 >> 10) & 1 != 0;
        self.f734 = (self.f618 >> 11) & 1 != 0;
        self.f735 = (self.f618 >> 12) & 1 != 0;
        self.f736 = (self.f618 >> 13) & 1 != 0;
        self.f737 = (self.f618 >> 14) & 1 != 0;
        self.f738 = (self.f618 >> 15) & 1 != 0;
        self.f739 = (self.f618 >> 16) & 1 != 0;
        self.f740 = (self.f618 >> 17) & 1 != 0;
        self.f741 = (self.f618 >> 18) & 1 != 0;
        self.f742 = (self.f618 >> 19) & 1 != 0;
        self.f743 = (self.f618 >> 20) & 1 != 0;
        self.f744 = (self.f618 >> 21) & 1 != 0;
        self.f745 = (self.f618 >> 22) & 1 != 0;
        self.f746 = (self.f618 >> 23) & 1 != 0;
        self.f747 = (self.f618 >> 24) & 1 != 0;
        self.f748 = (self.f618 >> 25) & 1 != 0;
        self.f749 = (self.f618 >> 26) & 1 != 0;
        self.f750 = (self.f618 >> 27) & 1 != 0;
        self.f751 = (self.f618 >> 28) & 1 != 0;
        self.f752 = (self.f618 >> 29) & 1 != 0;
        self.f753 = (self.f618 >> 30) & 1 != 0;
        self.f754 = (self.f618 >> 31) & 1 != 0;
        self.f755 = (self.f618 >> 32) & 1 != 0;
        self.f756 = (self.f618 >> 33) & 1 != 0;
        self.f757 = (self.f618 >> 34) & 1 != 0;
        self.f758 = (self.f618 >> 35) & 1 != 0;
        self.f759 = (self.f618 >> 36) & 1 != 0;
        self.f760 = (self.f618 >> 37) & 1 != 0;
        self.f761 = (self.f618 >> 38) & 1 != 0;
        self.f762 = (self.f618 >> 39) & 1 != 0;
        self.f763 = (self.f618 >> 40) & 1 != 0;
        self.f764 = (self.f618 >> 41) & 1 != 0;
        self.f765 = (self.f618 >> 42) & 1 != 0;
        self.f766 = (self.f618 >> 43) & 1 != 0;
        self.f767 = (self.f618 >> 44) & 1 != 0;
        self.f768 = (self.f618 >> 45) & 1 != 0;
        self.f769 = (self.f618 >> 46) & 1 != 0;
        self.f770 = (self.f618 >> 47) & 1 != 0;
        self.f771 = (self.f618 >> 48) & 1 != 0;
        self.f772 = (self.f618 >> 49) & 1 != 0;
        self.f773 = (self.f618 >> 50) & 1 != 0;
        self.f774 = (self.f619 >> 0) & 1 != 0;
        self.f775 = (self.f619 >> 1) & 1 != 0;
        self.f776 = (self.f619 >> 2) & 1 != 0;
        self.f777 = (self.f619 >> 3) & 1 != 0;
        self.f778 = (self.f619 >> 4) & 1 != 0;
        self.f779 = (self.f619 >> 5) & 1 != 0;
        self.f780 = (self.f619 >> 6) & 1 != 0;
        self.f781 = (self.f619 >> 7) & 1 != 0;
        self.f782 = (self.f619 >> 8) & 1 != 0;
        self.f783 = (self.f619 >> 9) & 1 != 0;
        self.f784 = (self.f619 >> 10) & 1 != 0;
        self.f785 = (self.f619 >> 11) & 1 != 0;
        self.f786 = (self.f619 >> 12) & 1 != 0;
        self.f787 = (self.f619 >> 13) & 1 != 0;
        self.f788 = (self.f619 >> 14) & 1 != 0;
        self.f789 = (self.f619 >> 15) & 1 != 0;
        self.f790 = (self.f619 >> 16) & 1 != 0;
        self.f791 = (self.f619 >> 17) & 1 != 0;
        self.f792 = (self.f619 >> 18) & 1 != 0;
        self.f793 = (self.f619 >> 19) & 1 != 0;
        self.f794 = (self.f619 >> 20) & 1 != 0;
        self.f795 = (self.f619 >> 21) & 1 != 0;
        self.f796 = (self.f619 >> 22) & 1 != 0;
        self.f797 = (self.f619 >> 23) & 1 != 0;
        self.f798 = (self.f619 >> 24) & 1 != 0;
        self.f799 = (self.f619 >> 25) & 1 != 0;
        self.f800 = (self.f619 >> 26) & 1 != 0;
        self.f801 = (self.f619 >> 27) & 1 != 0;
        self.f802 = (self.f619 >> 28) & 1 != 0;
        self.f803 = (self.f619 >> 29) & 1 != 0;
        self.f804 = (self.f619 >> 30) & 1 != 0;
        self.f805 = (self.f619 >> 31) & 1 != 0;
        self.f806 = (self.f619 >> 32) & 1 != 0;
        self.f807 = (self.f619 >> 33) & 1 != 0;
        self.f808 = (self.f619 >> 34) & 1 != 0;
        self.f809 = (self.f619 >> 35) & 1 != 0;
        self.f810 = (self.f619 >> 36) & 1 != 0;
        self.f811 = (self.f619 >> 37) & 1 != 0;
        self.f812 = (self.f619 >> 38) & 1 != 0;
        self.f813 = (self.f619 >> 39) & 1 != 0;
        self.f814 = (self.f619 >> 40) & 1 != 0;
        self.f815 = (self.f619 >> 41) & 1 != 0;
        self.f816 = (self.f619 >> 42) & 1 != 0;
        self.f817 = (self.f619 >> 43) & 1 != 0;
        self.f818 = (self.f619 >> 44) & 1 != 0;
        self.f819 = (self.f619 >> 45) & 1 != 0;
        self.f820 = (self.f619 >> 46) & 1 != 0;
        self.f821 = (self.f619 >> 47) & 1 != 0;
        self.f822 = (self.f619 >> 48) & 1 != 0;
        self.f823 = (self.f619 >> 49) & 1 != 0;
        self.f824 = (self.f619 >> 50) & 1 != 0;
        self.f825 = (self.f620 >> 0) & 1 != 0;
        self.f826 = (self.f620 >> 1) & 1 != 0;
        self.f827 = (self.f620 >> 2) & 1 != 0;
        self.f828 = (self.f620 >> 3) & 1 != 0;
        self.f829 = (self.f620 >> 4) & 1 != 0;
        self.f830 = (self.f620 >> 5) & 1 != 0;
        self.f831 = (self.f620 >> 6) & 1 != 0;
        self.f832 = (self.f620 >> 7) & 1 != 0;
        self.f833 = (self.f620 >> 8) & 1 != 0;
        self.f834 = (self.f620 >> 9) & 1 != 0;
        self.f835 = (self.f620 >> 10) & 1 != 0;
        self.f836 = (self.f620 >> 11) & 1 != 0;
        self.f837 = (self.f620 >> 12) & 1 != 0;
        self.f838 = (self.f620 >> 13) & 1 != 0;
        self.f839 = (self.f620 >> 14) & 1 != 0;
        self.f840 = (self.f620 >> 15) & 1 != 0;
        self.f841 = (self.f620 >> 16) & 1 != 0;
        self.f842 = (self.f620 >> 17) & 1 != 0;
        self.f843 = (self.f620 >> 18) & 1 != 0;
        self.f844 = (self.f620 >> 19) & 1 != 0;
        self.f845 = (self.f620 >> 20) & 1 != 0;
        self.f846 = (self.f620 >> 21) & 1 != 0;
        self.f847 = (self.f620 >> 22) & 1 != 0;
        self.f848 = (self.f620 >> 23) & 1 != 0;
        self.f849 = (self.f620 >> 24) & 1 != 0;
        self.f850 = (self.f620 >> 25) & 1 != 0;
        self.f851 = (self.f620 >> 26) & 1 != 0;
        self.f852 = (self.f620 >> 27) & 1 != 0;
        self.f853 = (self.f620 >> 28) & 1 != 0;
        self.f854 = (self.f620 >> 29) & 1 != 0;
        self.f855 = (self.f620 >> 30) & 1 != 0;
        self.f856 = (self.f620 >> 31) & 1 != 0;
        self.f857 = (self.f620 >> 32) & 1 != 0;
        self.f858 = (self.f620 >> 33) & 1 != 0;
        self.f859 = (self.f620 >> 34) & 1 != 0;
        self.f860 = (self.f620 >> 35) & 1 != 0;
        self.f861 = (self.f620 >> 36) & 1 != 0;
        self.f862 = (self.f620 >> 37) & 1 != 0;
        self.f863 = (self.f620 >> 38) & 1 != 0;
        self.f864 = (self.f620 >> 39) & 1 != 0;
        self.f865 = (self.f620 >> 40) & 1 != 0;
        self.f866 = (self.f620 >> 41) & 1 != 0;
        self.f867 = (self.f620 >> 42) & 1 != 0;
        self.f868 = (self.f620 >> 43) & 1 != 0;
        self.f869 = (self.f620 >> 44) & 1 != 0;
        self.f870 = (self.f620 >> 45) & 1 != 0;
        self.f871 = (self.f620 >> 46) & 1 != 0;
        self.f872 = (self.f620 >> 47) & 1 != 0;
        self.f873 = (self.f620 >> 48) & 1 != 0;
        self.f874 = (self.f620 >> 49) & 1 != 0;
        self.f875 = (self.f620 >> 50) & 1 != 0;
        self.reference_unpack_nested();
    }

    fn reference_pack(&mut self) {
        self.reference_pack_nested();
        self.f77 = (self.f77 & !(1 << 0)) | ((self.f78 as u16) << 0);
        self.f77 = (self.f77 & !(1 << 15)) | ((self.f79 as u16) << 15);
        self.f76 = (self.f76 & !(1 << 1)) | ((self.f80 as u16) << 1);
        self.f75 = (self.f75 & !(1 << 3)) | ((self.f81 as u16) << 3);
        self.f75 = (self.f75 & !(1 << 1)) | ((self.f82 as u16) << 1);
        self.f171 = (self.f171 & !(1 << 15)) | ((self.f184 as u64) << 15);
        self.f171 = (self.f171 & !(1 << 16)) | ((self.f185 as u64) << 16);
        self.f171 = (self.f171 & !(1 << 17)) | ((self.f186 as u64) << 17);
        self.f171 = (self.f171 & !(1 << 18)) | ((self.f187 as u64) << 18);
        self.f171 = (self.f171 & !(1 << 19)) | ((self.f188 as u64) << 19);
        self.f171 = (self.f171 & !(1 << 20)) | ((self.f189 as u64) << 20);
        self.f171 = (self.f171 & !(1 << 21)) | ((self.f190 as u64) << 21);
        self.f171 = (self.f171 & !(1 << 22)) | ((self.f191 as u64) << 22);
        self.f171 = (self.f171 & !(1 << 23)) | ((self.f192 as u64) << 23);
        self.f171 = (self.f171 & !(1 << 24)) | ((self.f193 as u64) << 24);
        self.f171 = (self.f171 & !(1 << 25)) | ((self.f194 as u64) << 25);
        self.f171 = (self.f171 & !(1 << 26)) | ((self.f195 as u64) << 26);
        self.f171 = (self.f171 & !(1 << 27)) | ((self.f196 as u64) << 27);
        self.f171 = (self.f171 & !(1 << 28)) | ((self.f197 as u64) << 28);
        self.f171 = (self.f171 & !(1 << 29)) | ((self.f198 as u64) << 29);
        self.f171 = (self.f171 & !(1 << 30)) | ((self.f199 as u64) << 30);
        self.f171 = (self.f171 & !(1 << 31)) | ((self.f200 as u64) << 31);
        self.f171 = (self.f171 & !(1 << 32)) | ((self.f201 as u64) << 32);
        self.f171 = (self.f171 & !(1 << 33)) | ((self.f202 as u64) << 33);
        self.f171 = (self.f171 & !(1 << 34)) | ((self.f203 as u64) << 34);
        self.f172 = (self.f172 & !(1 << 15)) | ((self.f204 as u64) << 15);
        self.f172 = (self.f172 & !(1 << 16)) | ((self.f205 as u64) << 16);
        self.f172 = (self.f172 & !(1 << 17)) | ((self.f206 as u64) << 17);
        self.f172 = (self.f172 & !(1 << 18)) | ((self.f207 as u64) << 18);
        self.f172 = (self.f172 & !(1 << 19)) | ((self.f208 as u64) << 19);
        self.f172 = (self.f172 & !(1 << 20)) | ((self.f209 as u64) << 20);
        self.f172 = (self.f172 & !(1 << 21)) | ((self.f210 as u64) << 21);
        self.f172 = (self.f172 & !(1 << 22)) | ((self.f211 as u64) << 22);
        self.f172 = (self.f172 & !(1 << 23)) | ((self.f212 as u64) << 23);
        self.f172 = (self.f172 & !(1 << 24)) | ((self.f213 as u64) << 24);
        self.f172 = (self.f172 & !(1 << 25)) | ((self.f214 as u64) << 25);
        self.f172 = (self.f172 & !(1 << 26)) | ((self.f215 as u64) << 26);
        self.f172 = (self.f172 & !(1 << 27)) | ((self.f216 as u64) << 27);
        self.f172 = (self.f172 & !(1 << 28)) | ((self.f217 as u64) << 28);
        self.f172 = (self.f172 & !(1 << 29)) | ((self.f218 as u64) << 29);
        self.f172 = (self.f172 & !(1 << 30)) | ((self.f219 as u64) << 30);
        self.f172 = (self.f172 & !(1 << 31)) | ((self.f220 as u64) << 31);
        self.f172 = (self.f172 & !(1 << 32)) | ((self.f221 as u64) << 32);
        self.f172 = (self.f172 & !(1 << 33)) | ((self.f222 as u64) << 33);
        self.f172 = (self.f172 & !(1 << 34)) | ((self.f223 as u64) << 34);
        self.f173 = (self.f173 & !(1 << 15)) | ((self.f224 as u64) << 15);
        self.f173 = (self.f173 & !(1 << 16)) | ((self.f225 as u64) << 16);
        self.f173 = (self.f173 & !(1 << 17)) | ((self.f226 as u64) << 17);
        self.f173 = (self.f173 & !(1 << 18)) | ((self.f227 as u64) << 18);
        self.f173 = (self.f173 & !(1 << 19)) | ((self.f228 as u64) << 19);
        self.f173 = (self.f173 & !(1 << 20)) | ((self.f229 as u64) << 20);
        self.f173 = (self.f173 & !(1 << 21)) | ((self.f230 as u64) << 21);
        self.f173 = (self.f173 & !(1 << 22)) | ((self.f231 as u64) << 22);
        self.f173 = (self.f173 & !(1 << 23)) | ((self.f232 as u64) << 23);
        self.f173 = (self.f173 & !(1 << 24)) | ((self.f233 as u64) << 24);
        self.f173 = (self.f173 & !(1 << 25)) | ((self.f234 as u64) << 25);
        self.f173 = (self.f173 & !(1 << 26)) | ((self.f235 as u64) << 26);
        self.f173 = (self.f173 & !(1 << 27)) | ((self.f236 as u64) << 27);
        self.f173 = (self.f173 & !(1 << 28)) | ((self.f237 as u64) << 28);
        self.f173 = (self.f173 & !(1 << 29)) | ((self.f238 as u64) << 29);
        self.f173 = (self.f173 & !(1 << 30)) | ((self.f239 as u64) << 30);
        self.f173 = (self.f173 & !(1 << 31)) | ((self.f240 as u64) << 31);
        self.f173 = (self.f173 & !(1 << 32)) | ((self.f241 as u64) << 32);
        self.f173 = (self.f173 & !(1 << 33)) | ((self.f242 as u64) << 33);
        self.f173 = (self.f173 & !(1 << 34)) | ((self.f243 as u64) << 34);
        self.f174 = (self.f174 & !(1 << 15)) | ((self.f244 as u64) << 15);
        self.f174 = (self.f174 & !(1 << 16)) | ((self.f245 as u64) << 16);
        self.f174 = (self.f174 & !(1 << 17)) | ((self.f246 as u64) << 17);
        self.f174 = (self.f174 & !(1 << 18)) | ((self.f247 as u64) << 18);
        self.f174 = (self.f174 & !(1 << 19)) | ((self.f248 as u64) << 19);
        self.f174 = (self.f174 & !(1 << 20)) | ((self.f249 as u64) << 20);
        self.f174 = (self.f174 & !(1 << 21)) | ((self.f250 as u64) << 21);
        self.f174 = (self.f174 & !(1 << 22)) | ((self.f251 as u64) << 22);
        self.f174 = (self.f174 & !(1 << 23)) | ((self.f252 as u64) << 23);
        self.f174 = (self.f174 & !(1 << 24)) | ((self.f253 as u64) << 24);
        self.f174 = (self.f174 & !(1 << 25)) | ((self.f254 as u64) << 25);
        self.f174 = (self.f174 & !(1 << 26)) | ((self.f255 as u64) << 26);
        self.f174 = (self.f174 & !(1 << 27)) | ((self.f256 as u64) << 27);
        self.f174 = (self.f174 & !(1 << 28)) | ((self.f257 as u64) << 28);
        self.f174 = (self.f174 & !(1 << 29)) | ((self.f258 as u64) << 29);
        self.f174 = (self.f174 & !(1 << 30)) | ((self.f259 as u64) << 30);
        self.f174 = (self.f174 & !(1 << 31)) | ((self.f260 as u64) << 31);
        self.f174 = (self.f174 & !(1 << 32)) | ((self.f261 as u64) << 32);
        self.f174 = (self.f174 & !(1 << 33)) | ((self.f262 as u64) << 33);
        self.f174 = (self.f174 & !(1 << 34)) | ((self.f263 as u64) << 34);
        self.f175 = (self.f175 & !(1 << 15)) | ((self.f264 as u64) << 15);
        self.f175 = (self.f175 & !(1 << 16)) | ((self.f265 as u64) << 16);
        self.f175 = (self.f175 & !(1 << 17)) | ((self.f266 as u64) << 17);
        self.f175 = (self.f175 & !(1 << 18)) | ((self.f267 as u64) << 18);
        self.f175 = (self.f175 & !(1 << 19)) | ((self.f268 as u64) << 19);
        self.f175 = (self.f175 & !(1 << 20)) | ((self.f269 as u64) << 20);
        self.f175 = (self.f175 & !(1 << 21)) | ((self.f270 as u64) << 21);
        self.f175 = (self.f175 & !(1 << 22)) | ((self.f271 as u64) << 22);
        self.f175 = (self.f175 & !(1 << 23)) | ((self.f272 as u64) << 23);
        self.f175 = (self.f175 & !(1 << 24)) | ((self.f273 as u64) << 24);
        self.f175 = (self.f175 & !(1 << 25)) | ((self.f274 as u64) << 25);
        self.f175 = (self.f175 & !(1 << 26)) | ((self.f275 as u64) << 26);
        self.f175 = (self.f175 & !(1 << 27)) | ((self.f276 as u64) << 27);
        self.f175 = (self.f175 & !(1 << 28)) | ((self.f277 as u64) << 28);
        self.f175 = (self.f175 & !(1 << 29)) | ((self.f278 as u64) << 29);
        self.f175 = (self.f175 & !(1 << 30)) | ((self.f279 as u64) << 30);
        self.f175 = (self.f175 & !(1 << 31)) | ((self.f280 as u64) << 31);
        self.f175 = (self.f175 & !(1 << 32)) | ((self.f281 as u64) << 32);
        self.f175 = (self.f175 & !(1 << 33)) | ((self.f282 as u64) << 33);
        self.f175 = (self.f175 & !(1 << 34)) | ((self.f283 as u64) << 34);
        self.f176 = (self.f176 & !(1 << 15)) | ((self.f284 as u64) << 15);
        self.f176 = (self.f176 & !(1 << 16)) | ((self.f285 as u64) << 16);
        self.f176 = (self.f176 & !(1 << 17)) | ((self.f286 as u64) << 17);
        self.f176 = (self.f176 & !(1 << 18)) | ((self.f287 as u64) << 18);
        self.f176 = (self.f176 & !(1 << 19)) | ((self.f288 as u64) << 19);
        self.f176 = (self.f176 & !(1 << 20)) | ((self.f289 as u64) << 20);
        self.f176 = (self.f176 & !(1 << 21)) | ((self.f290 as u64) << 21);
        self.f176 = (self.f176 & !(1 << 22)) | ((self.f291 as u64) << 22);
        self.f176 = (self.f176 & !(1 << 23)) | ((self.f292 as u64) << 23);
        self.f176 = (self.f176 & !(1 << 24)) | ((self.f293 as u64) << 24);
        self.f176 = (self.f176 & !(1 << 25)) | ((self.f294 as u64) << 25);
        self.f176 = (self.f176 & !(1 << 26)) | ((self.f295 as u64) << 26);
        self.f176 = (self.f176 & !(1 << 27)) | ((self.f296 as u64) << 27);
        self.f176 = (self.f176 & !(1 << 28)) | ((self.f297 as u64) << 28);
        self.f176 = (self.f176 & !(1 << 29)) | ((self.f298 as u64) << 29);
        self.f176 = (self.f176 & !(1 << 30)) | ((self.f299 as u64) << 30);
        self.f176 = (self.f176 & !(1 << 31)) | ((self.f300 as u64) << 31);
        self.f176 = (self.f176 & !(1 << 32)) | ((self.f301 as u64) << 32);
        self.f176 = (self.f176 & !(1 << 33)) | ((self.f302 as u64) << 33);
        self.f176 = (self.f176 & !(1 << 34)) | ((self.f303 as u64) << 34);
        self.f177 = (self.f177 & !(1 << 15)) | ((self.f304 as u64) << 15);
        self.f177 = (self.f177 & !(1 << 16)) | ((self.f305 as u64) << 16);
        self.f177 = (self.f177 & !(1 << 17)) | ((self.f306 as u64) << 17);
        self.f177 = (self.f177 & !(1 << 18)) | ((self.f307 as u64) << 18);
        self.f177 = (self.f177 & !(1 << 19)) | ((self.f308 as u64) << 19);
        self.f177 = (self.f177 & !(1 << 20)) | ((self.f309 as u64) << 20);
        self.f177 = (self.f177 & !(1 << 21)) | ((self.f310 as u64) << 21);
        self.f177 = (self.f177 & !(1 << 22)) | ((self.f311 as u64) << 22);
        self.f177 = (self.f177 & !(1 << 23)) | ((self.f312 as u64) << 23);
        self.f177 = (self.f177 & !(1 << 24)) | ((self.f313 as u64) << 24);
        self.f177 = (self.f177 & !(1 << 25)) | ((self.f314 as u64) << 25);
        self.f177 = (self.f177 & !(1 << 26)) | ((self.f315 as u64) << 26);
        self.f177 = (self.f177 & !(1 << 27)) | ((self.f316 as u64) << 27);
        self.f177 = (self.f177 & !(1 << 28)) | ((self.f317 as u64) << 28);
        self.f177 = (self.f177 & !(1 << 29)) | ((self.f318 as u64) << 29);
        self.f177 = (self.f177 & !(1 << 30)) | ((self.f319 as u64) << 30);
        self.f177 = (self.f177 & !(1 << 31)) | ((self.f320 as u64) << 31);
        self.f177 = (self.f177 & !(1 << 32)) | ((self.f321 as u64) << 32);
        self.f177 = (self.f177 & !(1 << 33)) | ((self.f322 as u64) << 33);
        self.f177 = (self.f177 & !(1 << 34)) | ((self.f323 as u64) << 34);
        self.f178 = (self.f178 & !(1 << 15)) | ((self.f324 as u64) << 15);
        self.f178 = (self.f178 & !(1 << 16)) | ((self.f325 as u64) << 16);
        self.f178 = (self.f178 & !(1 << 17)) | ((self.f326 as u64) << 17);
        self.f178 = (self.f178 & !(1 << 18)) | ((self.f327 as u64) << 18);
        self.f178 = (self.f178 & !(1 << 19)) | ((self.f328 as u64) << 19);
        self.f178 = (self.f178 & !(1 << 20)) | ((self.f329 as u64) << 20);
        self.f178 = (self.f178 & !(1 << 21)) | ((self.f330 as u64) << 21);
        self.f178 = (self.f178 & !(1 << 22)) | ((self.f331 as u64) << 22);
        self.f178 = (self.f178 & !(1 << 23)) | ((self.f332 as u64) << 23);
        self.f178 = (self.f178 & !(1 << 24)) | ((self.f333 as u64) << 24);
        self.f178 = (self.f178 & !(1 << 25)) | ((self.f334 as u64) << 25);
        self.f178 = (self.f178 & !(1 << 26)) | ((self.f335 as u64) << 26);
        self.f178 = (self.f178 & !(1 << 27)) | ((self.f336 as u64) << 27);
        self.f178 = (self.f178 & !(1 << 28)) | ((self.f337 as u64) << 28);
        self.f178 = (self.f178 & !(1 << 29)) | ((self.f338 as u64) << 29);
        self.f178 = (self.f178 & !(1 << 30)) | ((self.f339 as u64) << 30);
        self.f178 = (self.f178 & !(1 << 31)) | ((self.f340 as u64) << 31);
        self.f178 = (self.f178 & !(1 << 32)) | ((self.f341 as u64) << 32);
        self.f178 = (self.f178 & !(1 << 33)) | ((self.f342 as u64) << 33);
        self.f178 = (self.f178 & !(1 << 34)) | ((self.f343 as u64) << 34);
        self.f179 = (self.f179 & !(1 << 15)) | ((self.f344 as u64) << 15);
        self.f179 = (self.f179 & !(1 << 16)) | ((self.f345 as u64) << 16);
        self.f179 = (self.f179 & !(1 << 17)) | ((self.f346 as u64) << 17);
        self.f179 = (self.f179 & !(1 << 18)) | ((self.f347 as u64) << 18);
        self.f179 = (self.f179 & !(1 << 19)) | ((self.f348 as u64) << 19);
        self.f179 = (self.f179 & !(1 << 20)) | ((self.f349 as u64) << 20);
        self.f179 = (self.f179 & !(1 << 21)) | ((self.f350 as u64) << 21);
        self.f179 = (self.f179 & !(1 << 22)) | ((self.f351 as u64) << 22);
        self.f179 = (self.f179 & !(1 << 23)) | ((self.f352 as u64) << 23);
        self.f179 = (self.f179 & !(1 << 24)) | ((self.f353 as u64) << 24);
        self.f179 = (self.f179 & !(1 << 25)) | ((self.f354 as u64) << 25);
        self.f179 = (self.f179 & !(1 << 26)) | ((self.f355 as u64) << 26);
        self.f179 = (self.f179 & !(1 << 27)) | ((self.f356 as u64) << 27);
        self.f179 = (self.f179 & !(1 << 28)) | ((self.f357 as u64) << 28);
        self.f179 = (self.f179 & !(1 << 29)) | ((self.f358 as u64) << 29);
        self.f179 = (self.f179 & !(1 << 30)) | ((self.f359 as u64) << 30);
        self.f179 = (self.f179 & !(1 << 31)) | ((self.f360 as u64) << 31);
        self.f179 = (self.f179 & !(1 << 32)) | ((self.f361 as u64) << 32);
        self.f179 = (self.f179 & !(1 << 33)) | ((self.f362 as u64) << 33);
        self.f179 = (self.f179 & !(1 << 34)) | ((self.f363 as u64) << 34);
        self.f180 = (self.f180 & !(1 << 15)) | ((self.f364 as u64) << 15);
        self.f180 = (self.f180 & !(1 << 16)) | ((self.f365 as u64) << 16);
        self.f180 = (self.f180 & !(1 << 17)) | ((self.f366 as u64) << 17);
        self.f180 = (self.f180 & !(1 << 18)) | ((self.f367 as u64) << 18);
        self.f180 = (self.f180 & !(1 << 19)) | ((self.f368 as u64) << 19);
        self.f180 = (self.f180 & !(1 << 20)) | ((self.f369 as u64) << 20);
        self.f180 = (self.f180 & !(1 << 21)) | ((self.f370 as u64) << 21);
        self.f180 = (self.f180 & !(1 << 22)) | ((self.f371 as u64) << 22);
        self.f180 = (self.f180 & !(1 << 23)) | ((self.f372 as u64) << 23);
        self.f180 = (self.f180 & !(1 << 24)) | ((self.f373 as u64) << 24);
        self.f180 = (self.f180 & !(1 << 25)) | ((self.f374 as u64) << 25);
        self.f180 = (self.f180 & !(1 << 26)) | ((self.f375 as u64) << 26);
        self.f180 = (self.f180 & !(1 << 27)) | ((self.f376 as u64) << 27);
        self.f180 = (self.f180 & !(1 << 28)) | ((self.f377 as u64) << 28);
        self.f180 = (self.f180 & !(1 << 29)) | ((self.f378 as u64) << 29);
        self.f180 = (self.f180 & !(1 << 30)) | ((self.f379 as u64) << 30);
        self.f180 = (self.f180 & !(1 << 31)) | ((self.f380 as u64) << 31);
        self.f180 = (self.f180 & !(1 << 32)) | ((self.f381 as u64) << 32);
        self.f180 = (self.f180 & !(1 << 33)) | ((self.f382 as u64) << 33);
        self.f180 = (self.f180 & !(1 << 34)) | ((self.f383 as u64) << 34);
        self.f181 = (self.f181 & !(1 << 15)) | ((self.f384 as u64) << 15);
        self.f181 = (self.f181 & !(1 << 16)) | ((self.f385 as u64) << 16);
        self.f181 = (self.f181 & !(1 << 17)) | ((self.f386 as u64) << 17);
        self.f181 = (self.f181 & !(1 << 18)) | ((self.f387 as u64) << 18);
        self.f181 = (self.f181 & !(1 << 19)) | ((self.f388 as u64) << 19);
        self.f181 = (self.f181 & !(1 << 20)) | ((self.f389 as u64) << 20);
        self.f181 = (self.f181 & !(1 << 21)) | ((self.f390 as u64) << 21);
        self.f181 = (self.f181 & !(1 << 22)) | ((self.f391 as u64) << 22);
        self.f181 = (self.f181 & !(1 << 23)) | ((self.f392 as u64) << 23);
        self.f181 = (self.f181 & !(1 << 24)) | ((self.f393 as u64) << 24);
        self.f181 = (self.f181 & !(1 << 25)) | ((self.f394 as u64) << 25);
        self.f181 = (self.f181 & !(1 << 26)) | ((self.f395 as u64) << 26);
        self.f181 = (self.f181 & !(1 << 27)) | ((self.f396 as u64) << 27);
        self.f181 = (self.f181 & !(1 << 28)) | ((self.f397 as u64) << 28);
        self.f181 = (self.f181 & !(1 << 29)) | ((self.f398 as u64) << 29);
        self.f181 = (self.f181 & !(1 << 30)) | ((self.f399 as u64) << 30);
        self.f181 = (self.f181 & !(1 << 31)) | ((self.f400 as u64) << 31);
        self.f181 = (self.f181 & !(1 << 32)) | ((self.f401 as u64) << 32);
        self.f181 = (self.f181 & !(1 << 33)) | ((self.f402 as u64) << 33);
        self.f181 = (self.f181 & !(1 << 34)) | ((self.f403 as u64) << 34);
        self.f182 = (self.f182 & !(1 << 15)) | ((self.f404 as u64) << 15);
        self.f182 = (self.f182 & !(1 << 16)) | ((self.f405 as u64) << 16);
        self.f182 = (self.f182 & !(1 << 17)) | ((self.f406 as u64) << 17);
        self.f182 = (self.f182 & !(1 << 18)) | ((self.f407 as u64) << 18);
        self.f182 = (self.f182 & !(1 << 19)) | ((self.f408 as u64) << 19);
        self.f182 = (self.f182 & !(1 << 20)) | ((self.f409 as u64) << 20);
        self.f182 = (self.f182 & !(1 << 21)) | ((self.f410 as u64) << 21);
        self.f182 = (self.f182 & !(1 << 22)) | ((self.f411 as u64) << 22);
        self.f182 = (self.f182 & !(1 << 23)) | ((self.f412 as u64) << 23);
        self.f182 = (self.f182 & !(1 << 24)) | ((self.f413 as u64) << 24);
        self.f182 = (self.f182 & !(1 << 25)) | ((self.f414 as u64) << 25);
        self.f182 = (self.f182 & !(1 << 26)) | ((self.f415 as u64) << 26);
        self.f182 = (self.f182 & !(1 << 27)) | ((self.f416 as u64) << 27);
        self.f182 = (self.f182 & !(1 << 28)) | ((self.f417 as u64) << 28);
        self.f182 = (self.f182 & !(1 << 29)) | ((self.f418 as u64) << 29);
        self.f182 = (self.f182 & !(1 << 30)) | ((self.f419 as u64) << 30);
        self.f182 = (self.f182 & !(1 << 31)) | ((self.f420 as u64) << 31);
        self.f182 = (self.f182 & !(1 << 32)) | ((self.f421 as u64) << 32);
        self.f182 = (self.f182 & !(1 << 33)) | ((self.f422 as u64) << 33);
        self.f182 = (self.f182 & !(1 << 34)) | ((self.f423 as u64) << 34);
        self.f183 = (self.f183 & !(1 << 15)) | ((self.f424 as u64) << 15);
        self.f183 = (self.f183 & !(1 << 16)) | ((self.f425 as u64) << 16);
        self.f183 = (self.f183 & !(1 << 17)) | ((self.f426 as u64) << 17);
        self.f183 = (self.f183 & !(1 << 18)) | ((self.f427 as u64) << 18);
        self.f183 = (self.f183 & !(1 << 19)) | ((self.f428 as u64) << 19);
        self.f183 = (self.f183 & !(1 << 20)) | ((self.f429 as u64) << 20);
        self.f183 = (self.f183 & !(1 << 21)) | ((self.f430 as u64) << 21);
        self.f183 = (self.f183 & !(1 << 22)) | ((self.f431 as u64) << 22);
        self.f183 = (self.f183 & !(1 << 23)) | ((self.f432 as u64) << 23);
        self.f183 = (self.f183 & !(1 << 24)) | ((self.f433 as u64) << 24);
        self.f183 = (self.f183 & !(1 << 25)) | ((self.f434 as u64) << 25);
        self.f183 = (self.f183 & !(1 << 26)) | ((self.f435 as u64) << 26);
        self.f183 = (self.f183 & !(1 << 27)) | ((self.f436 as u64) << 27);
        self.f183 = (self.f183 & !(1 << 28)) | ((self.f437 as u64) << 28);
        self.f183 = (self.f183 & !(1 << 29)) | ((self.f438 as u64) << 29);
        self.f183 = (self.f183 & !(1 << 30)) | ((self.f439 as u64) << 30);
        self.f183 = (self.f183 & !(1 << 31)) | ((self.f440 as u64) << 31);
        self.f183 = (self.f183 & !(1 << 32)) | ((self.f441 as u64) << 32);
        self.f183 = (self.f183 & !(1 << 33)) | ((self.f442 as u64) << 33);
        self.f183 = (self.f183 & !(1 << 34)) | ((self.f443 as u64) << 34);
        self.f600 = (self.f600 & !(1 << 7)) | ((self.f603 as u16) << 7);
        self.f601 = (self.f601 & !(1 << 11)) | ((self.f604 as u16) << 11);
        self.f601 = (self.f601 & !(1 << 0)) | ((self.f605 as u16) << 0);
        self.f601 = (self.f601 & !(1 << 12)) | ((self.f606 as u16) << 12);
        self.f602 = (self.f602 & !(1 << 12)) | ((self.f607 as u16) << 12);
        self.f601 = (self.f601 & !(1 << 7)) | ((self.f608 as u16) << 7);
        self.f600 = (self.f600 & !(1 << 6)) | ((self.f609 as u16) << 6);
        self.f600 = (self.f600 & !(1 << 1)) | ((self.f610 as u16) << 1);
        self.f600 = (self.f600 & !(1 << 14)) | ((self.f611 as u16) << 14);
        self.f600 = (self.f600 & !(1 << 12)) | ((self.f612 as u16) << 12);
        self.f600 = (self.f600 & !(1 << 2)) | ((self.f613 as u16) << 2);
        self.f601 = (self.f601 & !(1 << 6)) | ((self.f614 as u16) << 6);
        self.f602 = (self.f602 & !(1 << 2)) | ((self.f615 as u16) << 2);
        self.f616 = (self.f616 & !(1 << 0)) | ((self.f621 as u64) << 0);
        self.f616 = (self.f616 & !(1 << 1)) | ((self.f622 as u64) << 1);
        self.f616 = (self.f616 & !(1 << 2)) | ((self.f623 as u64) << 2);
        self.f616 = (self.f616 & !(1 << 3)) | ((self.f624 as u64) << 3);
        self.f616 = (self.f616 & !(1 << 4)) | ((self.f625 as u64) << 4);
        self.f616 = (self.f616 & !(1 << 5)) | ((self.f626 as u64) << 5);
        self.f616 = (self.f616 & !(1 << 6)) | ((self.f627 as u64) << 6);
        self.f616 = (self.f616 & !(1 << 7)) | ((self.f628 as u64) << 7);
        self.f616 = (self.f616 & !(1 << 8)) | ((self.f629 as u64) << 8);
        self.f616 = (self.f616 & !(1 << 9)) | ((self.f630 as u64) << 9);
        self.f616 = (self.f616 & !(1 << 10)) | ((self.f631 as u64) << 10);
        self.f616 = (self.f616 & !(1 << 11)) | ((self.f632 as u64) << 11);
        self.f616 = (self.f616 & !(1 << 12)) | ((self.f633 as u64) << 12);
        self.f616 = (self.f616 & !(1 << 13)) | ((self.f634 as u64) << 13);
        self.f616 = (self.f616 & !(1 << 14)) | ((self.f635 as u64) << 14);
        self.f616 = (self.f616 & !(1 << 15)) | ((self.f636 as u64) << 15);
        self.f616 = (self.f616 & !(1 << 16)) | ((self.f637 as u64) << 16);
        self.f616 = (self.f616 & !(1 << 17)) | ((self.f638 as u64) << 17);
        self.f616 = (self.f616 & !(1 << 18)) | ((self.f639 as u64) << 18);
        self.f616 = (self.f616 & !(1 << 19)) | ((self.f640 as u64) << 19);
        self.f616 = (self.f616 & !(1 << 20)) | ((self.f641 as u64) << 20);
        self.f616 = (self.f616 & !(1 << 21)) | ((self.f642 as u64) << 21);
        self.f616 = (self.f616 & !(1 << 22)) | ((self.f643 as u64) << 22);
        self.f616 = (self.f616 & !(1 << 23)) | ((self.f644 as u64) << 23);
        self.f616 = (self.f616 & !(1 << 24)) | ((self.f645 as u64) << 24);
        self.f616 = (self.f616 & !(1 << 25)) | ((self.f646 as u64) << 25);
        self.f616 = (self.f616 & !(1 << 26)) | ((self.f647 as u64) << 26);
        self.f616 = (self.f616 & !(1 << 27)) | ((self.f648 as u64) << 27);
        self.f616 = (self.f616 & !(1 << 28)) | ((self.f649 as u64) << 28);
        self.f616 = (self.f616 & !(1 << 29)) | ((self.f650 as u64) << 29);
        self.f616 = (self.f616 & !(1 << 30)) | ((self.f651 as u64) << 30);
        self.f616 = (self.f616 & !(1 << 31)) | ((self.f652 as u64) << 31);
        self.f616 = (self.f616 & !(1 << 32)) | ((self.f653 as u64) << 32);
        self.f616 = (self.f616 & !(1 << 33)) | ((self.f654 as u64) << 33);
        self.f616 = (self.f616 & !(1 << 34)) | ((self.f655 as u64) << 34);
        self.f616 = (self.f616 & !(1 << 35)) | ((self.f656 as u64) << 35);
        self.f616 = (self.f616 & !(1 << 36)) | ((self.f657 as u64) << 36);
        self.f616 = (self.f616 & !(1 << 37)) | ((self.f658 as u64) << 37);
        self.f616 = (self.f616 & !(1 << 38)) | ((self.f659 as u64) << 38);
        self.f616 = (self.f616 & !(1 << 39)) | ((self.f660 as u64) << 39);
        self.f616 = (self.f616 & !(1 << 40)) | ((self.f661 as u64) << 40);
        self.f616 = (self.f616 & !(1 << 41)) | ((self.f662 as u64) << 41);
        self.f616 = (self.f616 & !(1 << 42)) | ((self.f663 as u64) << 42);
        self.f616 = (self.f616 & !(1 << 43)) | ((self.f664 as u64) << 43);
        self.f616 = (self.f616 & !(1 << 44)) | ((self.f665 as u64) << 44);
        self.f616 = (self.f616 & !(1 << 45)) | ((self.f666 as u64) << 45);
        self.f616 = (self.f616 & !(1 << 46)) | ((self.f667 as u64) << 46);
        self.f616 = (self.f616 & !(1 << 47)) | ((self.f668 as u64) << 47);
        self.f616 = (self.f616 & !(1 << 48)) | ((self.f669 as u64) << 48);
        self.f616 = (self.f616 & !(1 << 49)) | ((self.f670 as u64) << 49);
        self.f616 = (self.f616 & !(1 << 50)) | ((self.f671 as u64) << 50);
        self.f617 = (self.f617 & !(1 << 0)) | ((self.f672 as u64) << 0);
        self.f617 = (self.f617 & !(1 << 1)) | ((self.f673 as u64) << 1);
        self.f617 = (self.f617 & !(1 << 2)) | ((self.f674 as u64) << 2);
        self.f617 = (self.f617 & !(1 << 3)) | ((self.f675 as u64) << 3);
        self.f617 = (self.f617 & !(1 << 4)) | ((self.f676 as u64) << 4);
        self.f617 = (self.f617 & !(1 << 5)) | ((self.f677 as u64) << 5);
        self.f617 = (self.f617 & !(1 << 6)) | ((self.f678 as u64) << 6);
        self.f617 = (self.f617 & !(1 << 7)) | ((self.f679 as u64) << 7);
        self.f617 = (self.f617 & !(1 << 8)) | ((self.f680 as u64) << 8);
        self.f617 = (self.f617 & !(1 << 9)) | ((self.f681 as u64) << 9);
        self.f617 = (self.f617 & !(1 << 10)) | ((self.f682 as u64) << 10);
        self.f617 = (self.f617 & !(1 << 11)) | ((self.f683 as u64) << 11);
        self.f617 = (self.f617 & !(1 << 12)) | ((self.f684 as u64) << 12);
        self.f617 = (self.f617 & !(1 << 13)) | ((self.f685 as u64) << 13);
        self.f617 = (self.f617 & !(1 << 14)) | ((self.f686 as u64) << 14);
        self.f617 = (self.f617 & !(1 << 15)) | ((self.f687 as u64) << 15);
        self.f617 = (self.f617 & !(1 << 16)) | ((self.f688 as u64) << 16);
        self.f617 = (self.f617 & !(1 << 17)) | ((self.f689 as u64) << 17);
        self.f617 = (self.f617 & !(1 << 18)) | ((self.f690 as u64) << 18);
        self.f617 = (self.f617 & !(1 << 19)) | ((self.f691 as u64) << 19);
        self.f617 = (self.f617 & !(1 << 20)) | ((self.f692 as u64) << 20);
        self.f617 = (self.f617 & !(1 << 21)) | ((self.f693 as u64) << 21);
        self.f617 = (self.f617 & !(1 << 22)) | ((self.f694 as u64) << 22);
        self.f617 = (self.f617 & !(1 << 23)) | ((self.f695 as u64) << 23);
        self.f617 = (self.f617 & !(1 << 24)) | ((self.f696 as u64) << 24);
        self.f617 = (self.f617 & !(1 << 25)) | ((self.f697 as u64) << 25);
        self.f617 = (self.f617 & !(1 << 26)) | ((self.f698 as u64) << 26);
        self.f617 = (self.f617 & !(1 << 27)) | ((self.f699 as u64) << 27);
        self.f617 = (self.f617 & !(1 << 28)) | ((self.f700 as u64) << 28);
        self.f617 = (self.f617 & !(1 << 29)) | ((self.f701 as u64) << 29);
        self.f617 = (self.f617 & !(1 << 30)) | ((self.f702 as u64) << 30);
        self.f617 = (self.f617 & !(1 << 31)) | ((self.f703 as u64) << 31);
        self.f617 = (self.f617 & !(1 << 32)) | ((self.f704 as u64) << 32);
        self.f617 = (self.f617 & !(1 << 33)) | ((self.f705 as u64) << 33);
        self.f617 = (self.f617 & !(1 << 34)) | ((self.f706 as u64) << 34);
        self.f617 = (self.f617 & !(1 << 35)) | ((self.f707 as u64) << 35);
        self.f617 = (self.f617 & !(1 << 36)) | ((self.f708 as u64) << 36);
        self.f617 = (self.f617 & !(1 << 37)) | ((self.f709 as u64) << 37);
        self.f617 = (self.f617 & !(1 << 38)) | ((self.f710 as u64) << 38);
        self.f617 = (self.f617 & !(1 << 39)) | ((self.f711 as u64) << 39);
        self.f617 = (self.f617 & !(1 << 40)) | ((self.f712 as u64) << 40);
        self.f617 = (self.f617 & !(1 << 41)) | ((self.f713 as u64) << 41);
        self.f617 = (self.f617 & !(1 << 42)) | ((self.f714 as u64) << 42);
        self.f617 = (self.f617 & !(1 << 43)) | ((self.f715 as u64) << 43);
        self.f617 = (self.f617 & !(1 << 44)) | ((self.f716 as u64) << 44);
        self.f617 = (self.f617 & !(1 << 45)) | ((self.f717 as u64) << 45);
        self.f617 = (self.f617 & !(1 << 46)) | ((self.f718 as u64) << 46);
        self.f617 = (self.f617 & !(1 << 47)) | ((self.f719 as u64) << 47);
        self.f617 = (self.f617 & !(1 << 48)) | ((self.f720 as u64) << 48);
        self.f617 = (self.f617 & !(1 << 49)) | ((self.f721 as u64) << 49);
        self.f617 = (self.f617 & !(1 << 50)) | ((self.f722 as u64) << 50);
        self.f618 = (self.f618 & !(1 << 0)) | ((self.f723 as u64) << 0);
        self.f618 = (self.f618 & !(1 << 1)) | ((self.f724 as u64) << 1);
        self.f618 = (self.f618 & !(1 << 2)) | ((self.f725 as u64) << 2);
        self.f618 = (self.f618 & !(1 << 3)) | ((self.f726 as u64) << 3);
        self.f618 = (self.f618 & !(1 << 4)) | ((self.f727 as u64) << 4);
        self.f618 = (self.f618 & !(1 << 5)) | ((self.f728 as u64) << 5);
        self.f618 = (self.f618 & !(1 << 6)) | ((self.f729 as u64) << 6);
        self.f618 = (self.f618 & !(1 << 7)) | ((self.f730 as u64) << 7);
        self.f618 = (self.f618 & !(1 << 8)) | ((self.f731 as u64) << 8);
        self.f618 = (self.f618 & !(1 << 9)) | ((self.f732 as u64) << 9);
        self.f618 = (self.f618 & !(1 << 10)) | ((self.f733 as u64) << 10);
        self.f618 = (self.f618 & !(1 << 11)) | ((self.f734 as u64) << 11);
        self.f618 = (self.f618 & !(1 << 12)) | ((self.f735 as u64) << 12);
        self.f618 = (self.f618 & !(1 << 13)) | ((self.f736 as u64) << 13);
        self.f618 = (self.f618 & !(1 << 14)) | ((self.f737 as u64) << 14);
        self.f618 = (self.f618 & !(1 << 15)) | ((self.f738 as u64) << 15);
        self.f618 = (self.f618 & !(1 << 16)) | ((self.f739 as u64) << 16);
        self.f618 = (self.f618 & !(1 << 17)) | ((self.f740 as u64) << 17);
        self.f618 = (self.f618 & !(1 << 18)) | ((self.f741 as u64) << 18);
        self.f618 = (self.f618 & !(1 << 19)) | ((self.f742 as u64) << 19);
        self.f618 = (self.f618 & !(1 << 20)) | ((self.f743 as u64) << 20);
        self.f618 = (self.f618 & !(1 << 21)) | ((self.f744 as u64) << 21);
        self.f618 = (self.f618 & !(1 << 22)) | ((self.f745 as u64) << 22);
        self.f618 = (self.f618 & !(1 << 23)) | ((self.f746 as u64) << 23);
        self.f618 = (self.f618 & !(1 << 24)) | ((self.f747 as u64) << 24);
        self.f618 = (self.f618 & !(1 << 25)) | ((self.f748 as u64) << 25);
        self.f618 = (self.f618 & !(1 << 26)) | ((self.f749 as u64) << 26);
        self.f618 = (self.f618 & !(1 << 27)) | ((self.f750 as u64) << 27);
        self.f618 = (self.f618 & !(1 << 28)) | ((self.f751 as u64) << 28);
        self.f618 = (self.f618 & !(1 << 29)) | ((self.f752 as u64) << 29);
        self.f618 = (self.f618 & !(1 << 30)) | ((self.f753 as u64) << 30);
        self.f618 = (self.f618 & !(1 << 31)) | ((self.f754 as u64) << 31);
        self.f618 = (self.f618 & !(1 << 32)) | ((self.f755 as u64) << 32);
        self.f618 = (self.f618 & !(1 << 33)) | ((self.f756 as u64) << 33);
        self.f618 = (self.f618 & !(1 << 34)) | ((self.f757 as u64) << 34);
        self.f618 = (self.f618 & !(1 << 35)) | ((self.f758 as u64) << 35);
        self.f618 = (self.f618 & !(1 << 36)) | ((self.f759 as u64) << 36);
        self.f618 = (self.f618 & !(1 << 37)) | ((self.f760 as u64) << 37);
        self.f618 = (self.f618 & !(1 << 38)) | ((self.f761 as u64) << 38);
        self.f618 = (self.f618 & !(1 << 39)) | ((self.f762 as u64) << 39);
        self.f618 = (self.f618 & !(1 << 40)) | ((self.f763 as u64) << 40);
        self.f618 = (self.f618 & !(1 << 41)) | ((self.f764 as u64) << 41);
        self.f618 = (self.f618 & !(1 << 42)) | ((self.f765 as u64) << 42);
        self.f618 = (self.f618 & !(1 << 43)) | ((self.f766 as u64) << 43);
        self.f618 = (self.f618 & !(1 << 44)) | ((self.f767 as u64) << 44);
        self.f618 = (self.f618 & !(1 << 45)) | ((self.f768 as u64) << 45);
        self.f618 = (self.f618 & !(1 << 46)) | ((self.f769 as u64) << 46);
        self.f618 = (self.f618 & !(1 << 47)) | ((self.f770 as u64) << 47);
        self.f618 = (self.f618 & !(1 << 48)) | ((self.f771 as u64) << 48);
        self.f618 = (self.f618 & !(1 << 49)) | ((self.f772 as u64) << 49);
        self.f618 = (self.f618 & !(1 << 50)) | ((self.f773 as u64) << 50);
        self.f619 = (self.f619 & !(1 << 0)) | ((self.f774 as u64) << 0);
        self.f619 = (self.f619 & !(1 << 1)) | ((self.f775 as u64) << 1);
        self.f619 = (self.f619 & !(1 << 2)) | ((self.f776 as u64) << 2);
        self.f619 = (self.f619 & !(1 << 3)) | ((self.f777 as u64) << 3);
        self.f619 = (self.f619 & !(1 << 4)) | ((self.f778 as u64) << 4);
        self.f619 = (self.f619 & !(1 << 5)) | ((self.f779 as u64) << 5);
        self.f619 = (self.f619 & !(1 << 6)) | ((self.f780 as u64) << 6);
        self.f619 = (self.f619 & !(1 << 7)) | ((self.f781 as u64) << 7);
        self.f619 = (self.f619 & !(1 << 8)) | ((self.f782 as u64) << 8);
        self.f619 = (self.f619 & !(1 << 9)) | ((self.f783 as u64) << 9);
        self.f619 = (self.f619 & !(1 << 10)) | ((self.f784 as u64) << 10);
        self.f619 = (self.f619 & !(1 << 11)) | ((self.f785 as u64) << 11);
        self.f619 = (self.f619 & !(1 << 12)) | ((self.f786 as u64) << 12);
        self.f619 = (self.f619 & !(1 << 13)) | ((self.f787 as u64) << 13);
        self.f619 = (self.f619 & !(1 << 14)) | ((self.f788 as u64) << 14);
        self.f619 = (self.f619 & !(1 << 15)) | ((self.f789 as u64) << 15);
        self.f619 = (self.f619 & !(1 << 16)) | ((self.f790 as u64) << 16);
        self.f619 = (self.f619 & !(1 << 17)) | ((self.f791 as u64) << 17);
        self.f619 = (self.f619 & !(1 << 18)) | ((self.f792 as u64) << 18);
        self.f619 = (self.f619 & !(1 << 19)) | ((self.f793 as u64) << 19);
        self.f619 = (self.f619 & !(1 << 20)) | ((self.f794 as u64) << 20);
        self.f619 = (self.f619 & !(1 << 21)) | ((self.f795 as u64) << 21);
        self.f619 = (self.f619 & !(1 << 22)) | ((self.f796 as u64) << 22);
        self.f619 = (self.f619 & !(1 << 23)) | ((self.f797 as u64) << 23);
        self.f619 = (self.f619 & !(1 << 24)) | ((self.f798 as u64) << 24);
        self.f619 = (self.f619 & !(1 << 25)) | ((self.f799 as u64) << 25);
        self.f619 = (self.f619 & !(1 << 26)) | ((self.f800 as u64) << 26);
        self.f619 = (self.f619 & !(1 << 27)) | ((self.f801 as u64) << 27);
        self.f619 = (self.f619 & !(1 << 28)) | ((self.f802 as u64) << 28);
        self.f619 = (self.f619 & !(1 << 29)) | ((self.f803 as u64) << 29);
        self.f619 = (self.f619 & !(1 << 30)) | ((self.f804 as u64) << 30);
        self.f619 = (self.f619 & !(1 << 31)) | ((self.f805 as u64) << 31);
        self.f619 = (self.f619 & !(1 << 32)) | ((self.f806 as u64) << 32);
        self.f619 = (self.f619 & !(1 << 33)) | ((self.f807 as u64) << 33);
        self.f619 = (self.f619 & !(1 << 34)) | ((self.f808 as u64) << 34);
        self.f619 = (self.f619 & !(1 << 35)) | ((self.f809 as u64) << 35);
        self.f619 = (self.f619 & !(1 << 36)) | ((self.f810 as u64) << 36);
        self.f619 = (self.f619 & !(1 << 37)) | ((self.f811 as u64) << 37);
        self.f619 = (self.f619 & !(1 << 38)) | ((self.f812 as u64) << 38);
        self.f619 = (self.f619 & !(1 << 39)) | ((self.f813 as u64) << 39);
        self.f619 = (self.f619 & !(1 << 40)) | ((self.f814 as u64) << 40);
        self.f619 = (self.f619 & !(1 << 41)) | ((self.f815 as u64) << 41);
        self.f619 = (self.f619 & !(1 << 42)) | ((self.f816 as u64) << 42);
        self.f619 = (self.f619 & !(1 << 43)) | ((self.f817 as u64) << 43);
        self.f619 = (self.f619 & !(1 << 44)) | ((self.f818 as u64) << 44);
        self.f619 = (self.f619 & !(1 << 45)) | ((self.f819 as u64) << 45);
        self.f619 = (self.f619 & !(1 << 46)) | ((self.f820 as u64) << 46);
        self.f619 = (self.f619 & !(1 << 47)) | ((self.f821 as u64) << 47);
        self.f619 = (self.f619 & !(1 << 48)) | ((self.f822 as u64) << 48);
        self.f619 = (self.f619 & !(1 << 49)) | ((self.f823 as u64) << 49);
        self.f619 = (self.f619 & !(1 << 50)) | ((self.f824 as u64) << 50);
        self.f620 = (self.f620 & !(1 << 0)) | ((self.f825 as u64) << 0);
        self.f620 = (self.f620 & !(1 << 1)) | ((self.f826 as u64) << 1);
        self.f620 = (self.f620 & !(1 << 2)) | ((self.f827 as u64) << 2);
        self.f620 = (self.f620 & !(1 << 3)) | ((self.f828 as u64) << 3);
        self.f620 = (self.f620 & !(1 << 4)) | ((self.f829 as u64) << 4);
        self.f620 = (self.f620 & !(1 << 5)) | ((self.f830 as u64) << 5);
        self.f620 = (self.f620 & !(1 << 6)) | ((self.f831 as u64) << 6);
        self.f620 = (self.f620 & !(1 << 7)) | ((self.f832 as u64) << 7);
        self.f620 = (self.f620 & !(1 << 8)) | ((self.f833 as u64) << 8);
        self.f620 = (self.f620 & !(1 << 9)) | ((self.f834 as u64) << 9);
        self.f620 = (self.f620 & !(1 << 10)) | ((self.f835 as u64) << 10);
        self.f620 = (self.f620 & !(1 << 11)) | ((self.f836 as u64) << 11);
        self.f620 = (self.f620 & !(1 << 12)) | ((self.f837 as u64) << 12);
        self.f620 = (self.f620 & !(1 << 13)) | ((self.f838 as u64) << 13);
        self.f620 = (self.f620 & !(1 << 14)) | ((self.f839 as u64) << 14);
        self.f620 = (self.f620 & !(1 << 15)) | ((self.f840 as u64) << 15);
        self.f620 = (self.f620 & !(1 << 16)) | ((self.f841 as u64) << 16);
        self.f620 = (self.f620 & !(1 << 17)) | ((self.f842 as u64) << 17);
        self.f620 = (self.f620 & !(1 << 18)) | ((self.f843 as u64) << 18);
        self.f620 = (self.f620 & !(1 << 19)) | ((self.f844 as u64) << 19);
        self.f620 = (self.f620 & !(1 << 20)) | ((self.f845 as u64) << 20);
        self.f620 = (self.f620 & !(1 << 21)) | ((self.f846 as u64) << 21);
        self.f620 = (self.f620 & !(1 << 22)) | ((self.f847 as u64) << 22);
        self.f620 = (self.f620 & !(1 << 23)) | ((self.f848 as u64) << 23);
        self.f620 = (self.f620 & !(1 << 24)) | ((self.f849 as u64) << 24);
        self.f620 = (self.f620 & !(1 << 25)) | ((self.f850 as u64) << 25);
        self.f620 = (self.f620 & !(1 << 26)) | ((self.f851 as u64) << 26);
        self.f620 = (self.f620 & !(1 << 27)) | ((self.f852 as u64) << 27);
        self.f620 = (self.f620 & !(1 << 28)) | ((self.f853 as u64) << 28);
        self.f620 = (self.f620 & !(1 << 29)) | ((self.f854 as u64) << 29);
        self.f620 = (self.f620 & !(1 << 30)) | ((self.f855 as u64) << 30);
        self.f620 = (self.f620 & !(1 << 31)) | ((self.f856 as u64) << 31);
        self.f620 = (self.f620 & !(1 << 32)) | ((self.f857 as u64) << 32);
        self.f620 = (self.f620 & !(1 << 33)) | ((self.f858 as u64) << 33);
        self.f620 = (self.f620 & !(1 << 34)) | ((self.f859 as u64) << 34);
        self.f620 = (self.f620 & !(1 << 35)) | ((self.f860 as u64) << 35);
        self.f620 = (self.f620 & !(1 << 36)) | ((self.f861 as u64) << 36);
        self.f620 = (self.f620 & !(1 << 37)) | ((self.f862 as u64) << 37);
        self.f620 = (self.f620 & !(1 << 38)) | ((self.f863 as u64) << 38);
        self.f620 = (self.f620 & !(1 << 39)) | ((self.f864 as u64) << 39);
        self.f620 = (self.f620 & !(1 << 40)) | ((self.f865 as u64) << 40);
        self.f620 = (self.f620 & !(1 << 41)) | ((self.f866 as u64) << 41);
        self.f620 = (self.f620 & !(1 << 42)) | ((self.f867 as u64) << 42);
        self.f620 = (self.f620 & !(1 << 43)) | ((self.f868 as u64) << 43);
        self.f620 = (self.f620 & !(1 << 44)) | ((self.f869 as u64) << 44);
        self.f620 = (self.f620 & !(1 << 45)) | ((self.f870 as u64) << 45);
        self.f620 = (self.f620 & !(1 << 46)) | ((self.f871 as u64) << 46);
        self.f620 = (self.f620 & !(1 << 47)) | ((self.f872 as u64) << 47);
        self.f620 = (self.f620 & !(1 << 48)) | ((self.f873 as u64) << 48);
        self.f620 = (self.f620 & !(1 << 49)) | ((self.f874 as u64) << 49);
        self.f620 = (self.f620 & !(1 << 50)) | ((self.f875 as u64) << 50);
    }

    fn reference_unpack_nested(&mut self) {
    }

    fn reference_pack_nested(&mut self) {
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn loops_agree_with_field_by_field_code_random0(
        bytes in proptest::collection::vec(any::<u8>(), size_of::<<Random0 as GlobalMemory>::Image>())
    ) {
        agree::<Random0>(&bytes);
    }

    #[test]
    fn loops_agree_with_field_by_field_code_random1(
        bytes in proptest::collection::vec(any::<u8>(), size_of::<<Random1 as GlobalMemory>::Image>())
    ) {
        agree::<Random1>(&bytes);
    }

    #[test]
    fn loops_agree_with_field_by_field_code_random2(
        bytes in proptest::collection::vec(any::<u8>(), size_of::<<Random2 as GlobalMemory>::Image>())
    ) {
        agree::<Random2>(&bytes);
    }
}
