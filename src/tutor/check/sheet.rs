//! A whole answer sheet marked: every answer judged ([`Marker::judge`]),
//! follow-through where asked, and a diagnosis consistent with the whole
//! sheet: a mistake is named only where it reproduces at least one wrong
//! answer and changes no answer the student got right; several are ranked
//! by how many answers they explain.

use super::marker::{Follow, Marker};
use super::{Diagnosis, Marked, Marking, Name, Verdict};
use crate::input::answer::{Given, Read};
use crate::msg::Msg;
use crate::tutor::diagnose::Code;
use crate::tutor::key::Key;
use std::collections::{HashMap, HashSet};

/// An answer file's key as read: a [`Key`], or a name that is none, as
/// written ([`super::Name::key`]).
type Named = std::result::Result<Key, String>;

impl Marker {
    /// Marks an answer sheet. With `from_text` the answers are the
    /// source's printed ones: only those keys are marked, and a wrong one
    /// gets the reason from the file's `[[errata]]`; otherwise the keys
    /// expected are [`Marker::keys`] plus any other key given.
    pub fn mark(&self, who: &str, answers: &[(Name, toml::Value)], from_text: bool) -> Marking {
        let answers: Vec<(Named, &toml::Value)> =
            answers.iter().map(|(k, v)| (k.key(), v)).collect();
        let keys = self.keys_marked(&answers, from_text);
        let mut first: HashMap<&Named, &toml::Value> = HashMap::new();
        for (k, v) in &answers {
            first.entry(k).or_insert(v);
        }
        let mut marked = Vec::new();
        let mut unknown = Vec::new();
        for named in &keys {
            let given = first.get(named).copied();
            // a name that is no key, or a key (a value, a whole part, one
            // component) not in the results, is reported unknown
            let found = named.as_ref().map(|k| (k, self.result.get(k)));
            let (key, expected) = match found {
                Ok((key, Some(expected))) => (key, expected),
                Ok((key, None)) => {
                    unknown.extend(given.map(|_| key.to_string()));
                    continue;
                }
                Err(name) => {
                    unknown.extend(given.map(|_| name.clone()));
                    continue;
                }
            };
            let j = match given {
                None => self.missing(),
                Some(g) if super::answer_len(g) > super::MAX_ANSWER => {
                    too_long(super::answer_len(g))
                }
                Some(g) => self.judge(key, &expected, Given::of(g)),
            };
            let mut mistakes = j.mistakes;
            if from_text {
                // the source's own answers: that it printed them is no diagnosis
                mistakes.retain(|m| *m != Code::CopiedMisprint);
            }
            marked.push(Marked {
                key: key.clone(),
                verdict: j.verdict,
                given: given.map(|g| super::shown_cut(&super::written(g))),
                given_value: given.cloned(),
                expected: Some(expected.into_owned()),
                note: j.note,
                diagnosis: mistakes,
                why: None,
                read: j.read,
                worth: self.scheme.item(key).map(|i| i.marks),
                earned: 0.0,
                method: Vec::new(),
            });
        }
        if self.settings.follow_through {
            self.credit_follow_through(&mut marked, from_text);
        }
        let diagnoses = self.diagnose(&mut marked);
        self.credit(&mut marked);
        for m in &mut marked {
            let misprint = m.diagnosis.contains(&Code::CopiedMisprint);
            if (from_text && m.verdict == Verdict::Wrong) || misprint {
                m.why = self.erratum(&m.key);
            }
        }
        Marking {
            title: self.problem().title.clone(),
            who: who.to_string(),
            answers: marked,
            diagnoses,
            unknown,
            settings: self.settings,
        }
    }

    /// The keys marked: with `from_text` those of the answers, otherwise
    /// [`Marker::keys`] and then any other key given, each once.
    fn keys_marked(&self, answers: &[(Named, &toml::Value)], from_text: bool) -> Vec<Named> {
        if from_text {
            answers.iter().map(|(k, _)| k.clone()).collect()
        } else {
            let mut k: Vec<Named> = self.scheme.keys().cloned().map(Ok).collect();
            // A set, so that many keys cost linear time (100,000 took 27 s).
            let mut seen: HashSet<Named> = k.iter().cloned().collect();
            for (given, _) in answers {
                if seen.insert(given.clone()) {
                    k.push(given.clone());
                }
            }
            k
        }
    }

    fn missing(&self) -> super::marker::Judgement {
        super::marker::Judgement {
            verdict: Verdict::Missing,
            note: Msg::NoAnswer,
            read: None,
            mistakes: vec![],
        }
    }

    /// Credits, as `correct.follow_through`, each wrong answer that is right
    /// given the student's own earlier answers ([`Marker::follow`]): only
    /// wrong answers carry forward (a right one, maybe rounded, carries
    /// grafika's value), and only those that could be what their step
    /// gives; a source's misprint (copied, or the source's own answers
    /// marked) is never credited.
    fn credit_follow_through(&self, marked: &mut [Marked], from_text: bool) {
        let own: Vec<(Key, Read)> = marked
            .iter()
            .filter(|m| m.verdict == Verdict::Wrong)
            .filter_map(|m| Some((m.key.clone(), m.read.clone()?)))
            .collect();
        let own_of = |k: &Key| own.iter().find(|(x, _)| x == k).map(|(_, r)| r.clone());
        for m in marked.iter_mut().filter(|m| m.verdict == Verdict::Wrong) {
            let Some(read) = &m.read else { continue };
            let misprint = m.diagnosis.contains(&Code::CopiedMisprint)
                || (from_text && self.erratum(&m.key).is_some());
            if misprint {
                continue;
            }
            match self.follow(&m.key, read, &own_of) {
                Follow::Credited(_) => {
                    m.verdict = Verdict::FollowThrough;
                    m.note = Msg::FollowThrough;
                    m.diagnosis.clear();
                }
                Follow::Blocked(why) => m.note = why,
                Follow::Not => {}
            }
        }
    }

    /// The marks each answer asked earns by the scheme: its verdict's share
    /// of its marks, or, when it is not right, what its working earns as
    /// method marks (each method key right, by follow-through too, earns
    /// its marks, a too coarse one half), whichever is more, at most its
    /// marks. Working earns nothing of its own.
    fn credit(&self, marked: &mut [Marked]) {
        let verdicts: Vec<(Key, Verdict)> =
            marked.iter().map(|m| (m.key.clone(), m.verdict)).collect();
        let verdict = |k: &Key| verdicts.iter().find(|(x, _)| x == k).map(|(_, v)| *v);
        for m in marked.iter_mut() {
            if let Some(item) = self.scheme.item(&m.key) {
                (m.earned, m.method) = item.earned(m.verdict, &verdict);
            }
        }
    }

    /// Keeps, for each wrong answer, the mistakes that fit the whole sheet
    /// ([`Marker::fitting`]), and lists each mistake once with the answers
    /// it explains: the mistakes that explain the most first; one whose
    /// answers are all explained by an earlier one is named with it.
    fn diagnose(&self, marked: &mut [Marked]) -> Vec<Diagnosis> {
        let agreed_reads: Vec<(Key, Read)> = marked
            .iter()
            .filter(|m| m.verdict.agrees())
            .filter_map(|m| Some((m.key.clone(), m.read.clone()?)))
            .collect();
        let agreed: Vec<(&Key, &Read)> = agreed_reads.iter().map(|(k, r)| (k, r)).collect();
        let mut out: Vec<Diagnosis> = Vec::new();
        for m in marked.iter_mut() {
            let (Verdict::Wrong, Some(read)) = (m.verdict, &m.read) else {
                m.diagnosis.clear();
                continue;
            };
            let fits = self.fitting(&m.key, read, &m.diagnosis, &agreed);
            m.diagnosis = fits.clone();
            for f in fits {
                match out.iter_mut().find(|d| d.mistake == f) {
                    Some(d) => d.keys.push(m.key.clone()),
                    None => out.push(Diagnosis {
                        mistake: f,
                        keys: vec![m.key.clone()],
                        also: vec![],
                    }),
                }
            }
        }
        out.sort_by_key(|d| std::cmp::Reverse(d.keys.len()));
        let mut folded: Vec<Diagnosis> = Vec::new();
        for d in out {
            match folded
                .iter_mut()
                .find(|f| d.keys.iter().all(|k| f.keys.contains(k)))
            {
                Some(f) => f.also.push(d.mistake),
                None => folded.push(d),
            }
        }
        // each answer names its mistakes in the order they rank
        for m in marked.iter_mut() {
            m.diagnosis.sort_by_key(|c| {
                folded
                    .iter()
                    .position(|d| d.mistake == *c || d.also.contains(c))
            });
        }
        folded
    }
}

/// An answer longer than [`super::MAX_ANSWER`] characters: not read.
fn too_long(n: usize) -> super::marker::Judgement {
    super::marker::Judgement {
        verdict: Verdict::Unparseable,
        note: Msg::AnswerTooLong(n, super::MAX_ANSWER),
        read: None,
        mistakes: vec![],
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::input::problem::ProblemIn;
    use crate::tutor::check::Settings;

    /// One component and a whole part are marked as keys; a name that is
    /// no key is unknown as written, a key not in the results in its one
    /// spelling. By hand (eye (3, 4, 12) at the origin, up y): n = (3, 4,
    /// 12)/13 and A' = (4/√17, −4/(13√17), −166/13) for A = (1, 0, 0).
    #[test]
    fn a_component_and_a_whole_part_are_marked_and_other_names_unknown() {
        let text = "title = 't'\nask = ['view']\n\
            [camera]\neye = [3, 4, 12]\nlook = [0, 0, 0]\nup = [0, 1, 0]\n\
            [points]\nA = [1, 0, 0]\n";
        let p = ProblemIn::parse(text, "t.toml").expect("parses");
        let m = Marker::new(&p, Settings::default()).expect("solves");
        let s = |x: &str| toml::Value::String(x.into());
        let answers: Vec<(Name, toml::Value)> = [
            ("view.points.A.0", s("4/sqrt(17)")),
            ("view.points.A[2]", s("-166/13")),
            ("view.n.2", s("0.5")),
            ("view", s("1")),
            ("view.bogus", s("1")),
            ("view.points.A.9", s("1")),
            ("window.top", s("1")),
        ]
        .into_iter()
        .map(|(k, v)| (Name::parse(k), v))
        .collect();
        let marking = m.mark("s", &answers, false);
        let code = |k: &str| {
            let k: Key = k.parse().expect("a key");
            (marking.answers.iter())
                .find(|a| a.key == k)
                .map(|a| a.verdict)
        };
        assert_eq!(code("view.points.A.0"), Some(Verdict::Exact));
        assert_eq!(code("view.points.A.2"), Some(Verdict::Exact));
        assert_eq!(code("view.n.2"), Some(Verdict::Wrong));
        assert_eq!(code("view"), Some(Verdict::Unparseable));
        assert_eq!(code("view.n"), Some(Verdict::Missing));
        assert_eq!(
            marking.unknown,
            ["view.bogus", "view.points.A.9", "window.top"]
        );
    }

    /// The camera of the test above: n = (3, 4, 12)/13, and u = Vup × n
    /// over its length = (12, 0, −3)/√153 = (4/√17, 0, −1/√17).
    fn camera() -> Marker {
        let text = "title = 't'\nask = ['view']\n\
            [camera]\neye = [3, 4, 12]\nlook = [0, 0, 0]\nup = [0, 1, 0]\n\
            [points]\nA = [1, 0, 0]\n";
        let p = ProblemIn::parse(text, "t.toml").expect("parses");
        Marker::new(&p, Settings::default()).expect("solves")
    }

    #[test]
    fn an_answer_files_names_are_read_as_keys_and_an_unknown_one_as_written() {
        let m = camera();
        let file = "student = 'S'\nnim = '1'\n\"view.n\" = '(3, 4, 12)/13'\n\
            [view]\nbogus = '1'\nu = '(4/sqrt(17), 0, -1/sqrt(17))'\n\
            [view.points]\nA = '(4/√17, -4/(13√17), -166/13)'\n";
        let t: toml::Table = toml::from_str(file).expect("TOML");
        let (student, answers) = crate::tutor::check::answers_from_table(&t);
        assert_eq!(student.as_deref(), Some("S"));
        let mut names: Vec<String> = answers.iter().map(|(k, _)| k.to_string()).collect();
        names.sort();
        let want = ["nim", "view.bogus", "view.n", "view.points.A", "view.u"];
        assert_eq!(names, want);
        let (nim, answers): (Vec<_>, Vec<_>) = answers.into_iter().partition(|(k, _)| k.is("nim"));
        assert_eq!(nim.len(), 1);
        let marking = m.mark("S", &answers, false);
        assert_eq!(marking.unknown, ["view.bogus"]);
        let code = |k: &str| {
            let k: Key = k.parse().expect("a key");
            (marking.answers.iter())
                .find(|a| a.key == k)
                .map(|a| a.verdict)
        };
        assert_eq!(code("view.u"), Some(Verdict::Exact));
        assert_eq!(code("view.n"), Some(Verdict::Exact));
        assert_eq!(code("view.points.A"), Some(Verdict::Exact));
    }

    #[test]
    fn judging_an_answer_parses_each_of_its_numbers_once() {
        let m = camera();
        let key: Key = "view.u".parse().expect("a key");
        let right = m.result.get(&key).expect("u");
        let given = toml::Value::String("(4/sqrt(17), 0, -1/sqrt(17))".into());
        let parsed = || crate::num::expr::PARSED.with(std::cell::Cell::get);
        // the first judgment also reads grafika's exact forms (kept)
        assert_eq!(
            m.judge(&key, &right, Given::of(&given)).verdict,
            Verdict::Exact
        );
        let before = parsed();
        assert_eq!(
            m.judge(&key, &right, Given::of(&given)).verdict,
            Verdict::Exact
        );
        assert_eq!(parsed() - before, 3);
    }
}
