//! The mistake catalog's descriptions for people, in the chosen language:
//! each language's words say a mistake by its code
//! (`ReportWords::mistake`, one exhaustive match per language).

use crate::report::lang::Lang;
use crate::report::words;
use crate::tutor::diagnose::Mistake;

/// What the student did, in `lang`.
pub fn mistake_text(m: &Mistake, lang: Lang) -> &'static str {
    words::of(lang).mistake(m.code)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::tutor::diagnose::CATALOG;

    #[test]
    fn every_mistake_reads_differently_in_each_language() {
        for m in CATALOG {
            let (en, id) = (mistake_text(m, Lang::En), mistake_text(m, Lang::Id));
            assert!(!en.trim().is_empty(), "{}", m.code);
            assert_ne!(id, en, "no Indonesian text for {}", m.code);
        }
    }
}
