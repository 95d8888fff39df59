use plc_core::GlobalMemory;

// A mistake in a field's attribute is reported alone. The field keeps the name the attribute
// gives it (`EndPos`, `StartPos`), so there is no error for `end` or `for` being IEC keywords;
// where even the name cannot be read (the missing comma), the field's name is not checked.
#[derive(GlobalMemory)]
pub struct Gm {
    #[plc(name = "EndPos", initail = 3)]
    end: i32,
    #[plc(name = "StartPos", bit = "2")]
    r#for: i32,
    #[plc(name = "Cycles" initial = 3)]
    r#while: i32,
}

fn main() {}
