//! The words of an answer's keys (`view.points.A`, `window.far_top`,
//! `clip[2].intersections.left.t`): what a name of the answer tree is
//! called, what the steps call the value of a key, what a key asks for.
//! Each language writes them in its own module (`en/keys.rs`,
//! `id/keys.rs`), one exhaustive match over the typed key
//! ([`crate::tutor::key`]) per method; the plain functions here are the
//! language-neutral part (reading a key's string, numbering a segment).

use crate::tutor::key::{Key, Node, Plane, Value};

/// A plane of the clipping box by the text's own name (`kiri`, …, after
/// the outcode's bits), which English quotes beside its own word.
pub fn text_plane(p: Plane) -> &'static str {
    match p {
        Plane::Left => "kiri",
        Plane::Right => "kanan",
        Plane::Bottom => "bawah",
        Plane::Top => "atas",
        Plane::Front => "depan",
        Plane::Back => "belakang",
    }
}

/// The words of an answer's keys.
pub trait KeyWords {
    /// A name of the answer tree as the text says it (`view` →
    /// `transformasi pandang`, `points` → `titik`, `kept` →
    /// `dipertahankan`, `left` under `intersections` → `kiri`); English
    /// keeps the keys, which are also the keys of an answer file.
    fn node(&self, n: &Node) -> String;

    /// A plane of the clipping box as the text names it (`kiri`, …).
    fn plane(&self, p: Plane) -> &'static str;

    /// The name the worked steps give the value of a key (`view.n` → `n`,
    /// `view.points.A` → `A'`, `project.points.A` → `A''`,
    /// `viewport.pixels.A` → `piksel A`, `view.matrix` → `V`,
    /// `clip.intersections.left.t` → `t (kiri)`; a whole part: the part,
    /// `view` → `transformasi pandang`; a component: its value's name):
    /// the answer table of a page.
    fn answer_name(&self, k: &Key) -> String;

    /// What a key asks for, in a few words (`view.points.A` → `koordinat
    /// kamera A'`): the prompt of a practice session.
    fn answer_words(&self, k: &Key) -> String;

    /// The label of a quiz's blanks for a key, the steps' name read alone
    /// before its blanks, never a JSON key: [`answer_name`](KeyWords::answer_name)
    /// (`n`, `A'`, `piksel A`), with the text's words where that name is
    /// notation a student would not know from the question (`cos α` for
    /// `cos_alpha`, `region code P0` for `code0`; in Indonesian `batas atas
    /// (top)`, `tinggi`, `komponen diffuse`).
    fn blank_label(&self, k: &Key) -> String;
}

/// The name of the answer spelled `key` ([`KeyWords::answer_name`]); a
/// string that is no answer key (a `[printed]` key no part computes), a
/// whole part and one component (`view.points.A.1`), which the steps give
/// no name of their own, are shown as written.
pub fn name_of(words: &dyn KeyWords, key: &str) -> String {
    match key.parse::<Key>() {
        Ok(k) if k.component.is_empty() && k.value != Value::Whole => words.answer_name(&k),
        _ => key.to_string(),
    }
}

/// A name of the results under `under` (`None`: at the top) and its
/// words ([`KeyWords::node`]); a name no key has is shown as it is
/// written, with no node.
pub fn node_of(words: &dyn KeyWords, name: &str, under: Option<&Node>) -> (Option<Node>, String) {
    match Node::read(name, under) {
        Some(n) => {
            let shown = words.node(&n);
            (Some(n), shown)
        }
        None => (None, name.to_string()),
    }
}

/// `name` prefixed by its segment (`segmen 2: status`) when the clip has
/// several; `segment` is the language's word. A key's index counts from 0
/// as JSON's list does (`clip.1` is the second segment); people count from
/// 1, as the worked solution's "segment 2" does.
pub fn in_segment(segment: &str, k: &Key, name: String) -> String {
    match k.segment {
        Some(i) => format!("{segment} {}: {name}", i + 1),
        None => name,
    }
}
