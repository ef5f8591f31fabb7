//! The names of a step's values in English: each name as its JSON key
//! spells it (`Name`'s `Display`, docs/spec.md §3), so the text and the
//! JSON say the same words, written once.

use super::En;
use crate::stages::trace::Name;

impl super::super::names::NameWords for En {
    fn name(&self, n: &Name) -> String {
        n.to_string()
    }
}
