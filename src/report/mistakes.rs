//! The mistake catalog's descriptions for people, in the chosen language.
//! The catalog (`tutor::diagnose::CATALOG`) keeps the English line; each
//! language's words say it (`ReportWords::mistake`), the Indonesian ones
//! by the mistake's code.

use crate::report::lang::Lang;
use crate::report::words;
use crate::tutor::diagnose::Mistake;

/// What the student did, in `lang`.
pub fn mistake_text(m: &Mistake, lang: Lang) -> &'static str {
    words::of(lang).mistake(m)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::tutor::diagnose::CATALOG;

    #[test]
    fn every_mistake_has_both_languages() {
        for m in CATALOG {
            let id = mistake_text(m, Lang::Id);
            assert_ne!(id, m.description, "no Indonesian text for {}", m.code);
            assert_eq!(mistake_text(m, Lang::En), m.description);
        }
    }
}
