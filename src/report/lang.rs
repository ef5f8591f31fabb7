//! The language of everything grafika prints for people: English or Bahasa
//! Indonesia (the course's own). JSON keys, codes and numbers never depend on
//! it; only the words, and the decimal mark of numbers in text, do.
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

/// The words for `lang`: both languages must be given, so a sentence without
/// its translation does not compile.
pub fn tr<'a>(lang: Lang, en: &'a str, id: &'a str) -> &'a str {
    match lang {
        Lang::En => en,
        Lang::Id => id,
    }
}

/// How numbers are written for people: the decimal mark and the separator
/// between the components of a vector. The one place either is chosen:
/// English (and a Moodle quiz with `--decimal point`) writes `(0.5, 2, 3)`;
/// Indonesian (and `--decimal comma`) writes `(0,5; 2; 3)`, so a comma never
/// reads both as a decimal mark and as a separator.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct NumStyle {
    /// The decimal mark: `.` or `,`.
    pub mark: char,
    /// Between a vector's components: `, ` or `; `.
    pub sep: &'static str,
}

impl NumStyle {
    /// `0.5`, `(0.5, 2, 3)`.
    pub const POINT: NumStyle = NumStyle {
        mark: '.',
        sep: ", ",
    };
    /// `0,5`, `(0,5; 2; 3)`.
    pub const COMMA: NumStyle = NumStyle {
        mark: ',',
        sep: "; ",
    };

    /// The numbers of `lang`: the point in English, the comma in Indonesian.
    pub fn of(lang: Lang) -> NumStyle {
        match lang {
            Lang::En => NumStyle::POINT,
            Lang::Id => NumStyle::COMMA,
        }
    }

    /// One number (or a formula of numbers: `−√2/60 ≈ −0.02357`, `1.5e-3`,
    /// `12.35 ms`) that was formatted with the point, written with this mark.
    pub fn number(self, pointed: &str) -> String {
        pointed
            .chars()
            .map(|c| if c == '.' { self.mark } else { c })
            .collect()
    }

    /// Values formatted the English way, with the point and `, ` between
    /// components (`(1.5, 2, 3)`, `ka = 0.2, kd = 0.5`), written in this
    /// style: the separators first, then the marks.
    pub fn values(self, english: &str) -> String {
        self.number(&self.separated(english))
    }

    /// A list or formula written with `, ` between its parts (`max(a, 0)`)
    /// with this style's separator instead; its numbers are not touched.
    pub fn separated(self, english: &str) -> String {
        english.replace(NumStyle::POINT.sep, self.sep)
    }
}

/// At most this many characters of a message are printed: an error about
/// a 100 KB input quotes its start and end, not all of it.
pub const MAX_MESSAGE: usize = 300;

/// `message` cut to [`MAX_MESSAGE`] characters, its middle replaced by the
/// number of characters left out.
pub fn cut_message(message: &str, lang: Lang) -> String {
    let n = message.chars().count();
    if n <= MAX_MESSAGE {
        return message.to_string();
    }
    let keep = MAX_MESSAGE / 2;
    let head: String = message.chars().take(keep).collect();
    let tail: String = message.chars().skip(n - keep).collect();
    let cut = n - 2 * keep;
    let said = tr(lang, "characters cut", "karakter dipotong");
    format!("{head} … ({cut} {said}) … {tail}")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_take_the_mark_and_separator_of_their_style() {
        let v = "(1.5, -2, 0.25)";
        assert_eq!(NumStyle::of(Lang::En).values(v), "(1.5, -2, 0.25)");
        assert_eq!(NumStyle::of(Lang::Id).values(v), "(1,5; -2; 0,25)");
        assert_eq!(
            NumStyle::COMMA.number("−√2/60 ≈ −0.02357"),
            "−√2/60 ≈ −0,02357"
        );
        assert_eq!(NumStyle::POINT.number("0.1"), "0.1");
        // a formula's separators change, its numbers do not
        assert_eq!(NumStyle::COMMA.separated("max(0.8, 0)"), "max(0.8; 0)");
    }

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

    #[test]
    fn tr_picks_the_language() {
        assert_eq!(tr(Lang::En, "Answer", "Jawaban"), "Answer");
        assert_eq!(tr(Lang::Id, "Answer", "Jawaban"), "Jawaban");
    }
}
