//! The importer's half of the agreement test: each row's JSON form gives the row's issue
//! kinds (the derive's half reads the Rust form).
include!("../../../plc-rules/src/decl/agreement_table.rs");

#[test]
fn the_json_form_of_each_row_gives_its_issue_kinds() {
    let mut rows = 0;
    for row in ROWS {
        let Some(json) = row.json else { continue };
        // A row declaring a structure type gives its members; the list declares them in
        // its `types` section.
        let list = if row.rust.contains("derive(PlcStruct)") {
            format!("{{ \"types\": {{ \"Axis\": {{ \"variables\": {{ {json} }} }} }} }}")
        } else {
            format!("{{ \"variables\": {{ {json} }} }}")
        };
        let parsed =
            super::super::parse::parse(&list).unwrap_or_else(|e| panic!("{}: {e}", row.rule));
        let checked = super::check(&parsed, &|_, _| None);
        let problems = checked.errors.iter().chain(&checked.warnings);
        let format: Vec<&String> = problems
            .clone()
            .filter(|p| p.kind.is_none())
            .map(|p| &p.message)
            .collect();
        assert!(format.is_empty(), "{}: {format:?}", row.rule);
        assert_eq!(
            sorted(problems.filter_map(|p| p.kind)),
            sorted(row.kinds.iter().copied()),
            "{}",
            row.rule
        );
        rows += 1;
    }
    assert!(rows >= 40, "{rows} rows with a JSON form");
}
