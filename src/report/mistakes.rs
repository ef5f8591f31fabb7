//! The mistake catalog's descriptions for people, in the chosen language:
//! each language's words say a mistake by its code
//! (`ReportWords::mistake`, one exhaustive match per language).

use crate::report::lang::Lang;
use crate::report::words;
use crate::tutor::diagnose::Code;

/// What the student did, in `lang`.
pub fn mistake_text(m: Code, lang: Lang) -> &'static str {
    words::of(lang).mistake(m)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_mistake_reads_differently_in_each_language() {
        for m in Code::all() {
            let (en, id) = (mistake_text(m, Lang::En), mistake_text(m, Lang::Id));
            assert!(!en.trim().is_empty(), "{m}");
            assert_ne!(id, en, "no Indonesian text for {m}");
        }
    }
}
