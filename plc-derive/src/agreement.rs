//! The derive's half of the agreement test: each row's Rust form, read by the derive's own
//! syn-to-model conversion, gives the row's issue kinds (the importer's half reads the JSON
//! form).

include!("../../plc-rules/src/decl/agreement_table.rs");

#[test]
fn the_rust_form_of_each_row_gives_its_issue_kinds() {
    for row in ROWS {
        let input: syn::DeriveInput =
            syn::parse_str(row.rust).unwrap_or_else(|e| panic!("{}: {e}", row.rule));
        let mut cx = crate::ctxt::Ctxt::default();
        // A row declaring a structure type says so with its derive attribute.
        let kind = if row.rust.contains("derive(PlcStruct)") {
            crate::ast::Kind::PlcStruct
        } else {
            crate::ast::Kind::GlobalMemory
        };
        let Some(c) = crate::ast::parse(&input, kind, &mut cx) else {
            panic!("{}: no struct", row.rule)
        };
        // The conversion's own issues (an unknown direction), then the checker's, warnings
        // included.
        let mut kinds = cx.kinds.clone();
        kinds.extend(
            plc_rules::decl::check(&c.decl)
                .issues
                .iter()
                .map(|i| i.kind.name()),
        );
        assert_eq!(
            sorted(kinds),
            sorted(row.kinds.iter().copied()),
            "{}",
            row.rule
        );
    }
    assert!(ROWS.len() >= 40);
}
