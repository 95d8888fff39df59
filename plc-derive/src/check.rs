//! The declaration rules, applied by the one checker of the declaration model
//! (`plc_rules::decl::check`): its issues become errors under the attribute or type to change,
//! and what it resolved (bit mappings, directions, addresses) is kept for code generation.

use crate::ast::Container;
use crate::ctxt::Ctxt;

pub fn check(c: &mut Container, cx: &mut Ctxt) {
    let checked = plc_rules::decl::check(&c.decl);
    // The derive has no warnings to give on stable Rust; a shared link is fine in Rust code.
    for issue in checked.issues.iter().filter(|i| !i.is_warning()) {
        cx.issue(issue);
    }
    for (v, r) in c.vars.iter_mut().zip(checked.vars) {
        v.mapped_to = r.mapped;
        v.effective_direction = r.direction;
        v.address = r.address;
    }
}
