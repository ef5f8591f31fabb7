//! The language of everything grafika prints for people: English or Bahasa
//! Indonesia (the course's own). A plain value at the bottom of the layers,
//! so every layer (the problem reader's `_id` texts included) takes the
//! language as this one type, never a `bool`; `report::lang` gives its words
//! and number style.
//!
//! Chosen by `--lang`, else `GRAFIKA_LANG` (a code, `id` or `en`, or a
//! locale name such as `id_ID.UTF-8`), else the locale: a value of
//! `LC_ALL`, `LC_MESSAGES` or `LANG` (the first one set, in that order)
//! starting with `id` selects Indonesian, anything else English.

/// A language grafika speaks.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Lang {
    /// English.
    #[default]
    En,
    /// Bahasa Indonesia.
    Id,
}

impl Lang {
    /// Every language, in the order `--lang` lists them.
    pub const ALL: [Lang; 2] = [Lang::Id, Lang::En];

    /// The code `--lang` and `GRAFIKA_LANG` take: `id` or `en`.
    pub fn code(self) -> &'static str {
        match self {
            Lang::En => "en",
            Lang::Id => "id",
        }
    }

    /// The language of a code (`id`, `en`, case-insensitive), if it is one.
    pub fn from_code(code: &str) -> Option<Lang> {
        Lang::ALL
            .into_iter()
            .find(|l| l.code().eq_ignore_ascii_case(code.trim()))
    }

    /// The language of a locale name (`id_ID.UTF-8` → Indonesian; `C`,
    /// `en_US.UTF-8`, anything else → English).
    pub fn from_locale(locale: &str) -> Lang {
        if locale.to_ascii_lowercase().starts_with("id") {
            Lang::Id
        } else {
            Lang::En
        }
    }

    /// The language of `GRAFIKA_LANG`: a code (`id`, `en`) or a locale
    /// name of either language (`id_ID.UTF-8`, `en_GB`, `C`); `None` for
    /// anything else (an empty value, `fr_FR`).
    fn from_grafika_lang(v: &str) -> Option<Lang> {
        let v = v.trim();
        let l = v.to_ascii_lowercase();
        match Lang::from_code(v) {
            Some(lang) => Some(lang),
            None if l.starts_with("id_") || l.starts_with("id-") || l.starts_with("id.") => {
                Some(Lang::Id)
            }
            None if l.starts_with("en_") || l.starts_with("en-") || l.starts_with("en.") => {
                Some(Lang::En)
            }
            None if l == "c" || l == "posix" || l.starts_with("c.") => Some(Lang::En),
            None => None,
        }
    }

    /// The language when no `--lang` is given, from the environment (the
    /// function `var` reads a variable; `std::env::var` in the program).
    pub fn from_env(var: impl Fn(&str) -> Option<String>) -> Lang {
        if let Some(l) = var("GRAFIKA_LANG").and_then(|v| Lang::from_grafika_lang(&v)) {
            return l;
        }
        ["LC_ALL", "LC_MESSAGES", "LANG"]
            .into_iter()
            .filter_map(|k| var(k).filter(|v| !v.is_empty()))
            .map(|v| Lang::from_locale(&v))
            .next()
            .unwrap_or_default()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn env<'a>(pairs: &'a [(&'a str, &'a str)]) -> impl Fn(&str) -> Option<String> + 'a {
        move |k| {
            pairs
                .iter()
                .find(|(n, _)| *n == k)
                .map(|(_, v)| v.to_string())
        }
    }

    #[test]
    fn an_indonesian_locale_selects_indonesian() {
        assert_eq!(Lang::from_env(env(&[("LANG", "id_ID.UTF-8")])), Lang::Id);
        assert_eq!(Lang::from_env(env(&[("LANG", "en_US.UTF-8")])), Lang::En);
        assert_eq!(Lang::from_env(env(&[])), Lang::En);
    }

    #[test]
    fn lc_all_comes_before_lang_and_grafika_lang_before_both() {
        let e = [("LC_ALL", "C"), ("LANG", "id_ID.UTF-8")];
        assert_eq!(Lang::from_env(env(&e)), Lang::En);
        let e = [("GRAFIKA_LANG", "id"), ("LC_ALL", "C")];
        assert_eq!(Lang::from_env(env(&e)), Lang::Id);
    }

    #[test]
    fn grafika_lang_takes_a_locale_name_too() {
        // Issue 28: GRAFIKA_LANG=id_ID.UTF-8 fell back to English.
        let e = [("GRAFIKA_LANG", "id_ID.UTF-8"), ("LANG", "C")];
        assert_eq!(Lang::from_env(env(&e)), Lang::Id);
        let e = [("GRAFIKA_LANG", "en_US.UTF-8"), ("LANG", "id_ID.UTF-8")];
        assert_eq!(Lang::from_env(env(&e)), Lang::En);
        // Not a language grafika speaks: the locale decides.
        let e = [("GRAFIKA_LANG", "fr_FR.UTF-8"), ("LANG", "id_ID.UTF-8")];
        assert_eq!(Lang::from_env(env(&e)), Lang::Id);
        // `idx` is neither a code nor a locale name.
        let e = [("GRAFIKA_LANG", "idx"), ("LANG", "C")];
        assert_eq!(Lang::from_env(env(&e)), Lang::En);
    }

    #[test]
    fn an_empty_variable_is_skipped() {
        let e = [("LC_ALL", ""), ("LANG", "id_ID.UTF-8")];
        assert_eq!(Lang::from_env(env(&e)), Lang::Id);
    }
}
