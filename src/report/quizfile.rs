//! A quiz written as one file, or split into files under a size
//! (`generate --split-mb`): a PHP site's upload limit (2 MB by default)
//! refuses a larger file. A quiz is a list of [`Unit`]s, each one question
//! (a Cloze question of one variant; a GIFT question of one blank) with the
//! category it goes in; a file holds whole questions, in order, each file
//! naming the category again before its first question, so that Moodle's
//! import ("Get category from file") puts every question where the whole
//! file would have.

/// One question of a quiz file and the category it goes in.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Unit {
    /// The category's text in the file (a category question, a
    /// `$CATEGORY:` line), written before the first question of each run
    /// of questions in it.
    pub category: String,
    /// The question's text in the file.
    pub text: String,
    /// Its name, for an error that names it.
    pub name: String,
}

/// A quiz file's frame: what comes before its questions and after them.
#[derive(Clone, Copy, Debug)]
pub struct Frame {
    /// Before (an XML declaration and `<quiz>`).
    pub head: &'static str,
    /// After (`</quiz>`).
    pub foot: &'static str,
}

/// The files of `units` in `frame`: one, or with `limit` (bytes) as many
/// as it takes, each at most `limit` bytes, filled in order. A question
/// that cannot fit in a file of its own is an error: its index.
pub fn pack(units: &[Unit], frame: Frame, limit: Option<usize>) -> Result<Vec<String>, usize> {
    let mut files = Vec::new();
    let mut body = String::new();
    let mut category: Option<&str> = None;
    let room = limit.map(|l| l.saturating_sub(frame.head.len() + frame.foot.len()));
    for (i, u) in units.iter().enumerate() {
        let size = |cat: Option<&str>| {
            u.text.len() + (cat != Some(u.category.as_str())) as usize * u.category.len()
        };
        if room.is_some_and(|r| !body.is_empty() && body.len() + size(category) > r) {
            files.push(format!("{}{body}{}", frame.head, frame.foot));
            body.clear();
            category = None;
        }
        if room.is_some_and(|r| size(None) > r) {
            return Err(i);
        }
        if category != Some(u.category.as_str()) {
            body.push_str(&u.category);
            category = Some(&u.category);
        }
        body.push_str(&u.text);
    }
    if !body.is_empty() || files.is_empty() {
        files.push(format!("{}{body}{}", frame.head, frame.foot));
    }
    Ok(files)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn unit(cat: &str, text: &str) -> Unit {
        Unit {
            category: cat.into(),
            text: text.into(),
            name: text.into(),
        }
    }

    const FRAME: Frame = Frame {
        head: "<q>",
        foot: "</q>",
    };

    #[test]
    fn one_file_names_each_category_once() {
        let units = [unit("A;", "a1 "), unit("A;", "a2 "), unit("B;", "b1 ")];
        let files = pack(&units, FRAME, None).unwrap();
        assert_eq!(files, ["<q>A;a1 a2 B;b1 </q>"]);
    }

    #[test]
    fn files_stay_under_the_limit_and_repeat_the_category() {
        let units = [unit("A;", "a1 "), unit("A;", "a2 "), unit("B;", "b1 ")];
        // 15 bytes, 7 of them the frame: "A;a1 " (5) and "a2 " (3) fill
        // the 8 left, and "B;b1 " starts a file
        let files = pack(&units, FRAME, Some(15)).unwrap();
        assert_eq!(files, ["<q>A;a1 a2 </q>", "<q>B;b1 </q>"]);
        // 12 bytes: a2 starts a file and names its category again
        let files = pack(&units, FRAME, Some(12)).unwrap();
        assert_eq!(files, ["<q>A;a1 </q>", "<q>A;a2 </q>", "<q>B;b1 </q>"]);
        assert!(files.iter().all(|f| f.len() <= 12));
        // the questions, in order, are all there
        let joined: String = files.concat().replace("<q>", "").replace("</q>", "");
        assert_eq!(joined.replace("A;", "").replace("B;", ""), "a1 a2 b1 ");
    }

    #[test]
    fn a_question_larger_than_the_limit_is_named() {
        let units = [unit("A;", "a1 "), unit("A;", "a-long-one ")];
        assert_eq!(pack(&units, FRAME, Some(14)), Err(1));
    }

    #[test]
    fn no_question_is_one_empty_file() {
        assert_eq!(pack(&[], FRAME, Some(100)).unwrap(), ["<q></q>"]);
    }
}
