//! `generate --format moodle|gift`: the files parse back (a real XML parser;
//! readings of the Cloze syntax and of GIFT that follow Moodle's import),
//! every answer and tolerance agrees with the key (the quiz accepts every
//! number `check` accepts: r·|x|, a whole pixel within half a pixel; a
//! number below the resolution asked is asked as 0), every 0 % answer is
//! the value a catalog mistake gives and names it, no absurd value is
//! offered, the instruction names the decimal mark to type, the figures
//! embedded decode to the SVG `solve --figure` writes, and the categories
//! come before their questions. What students read: no JSON key in any
//! label, one decimal mark per quiz, no empty exact form, no broken
//! matrix, the words of the quiz's language accepted, no word to the
//! lecturer, nothing Moodle would misread if typed back; a quiz split
//! under a size (`--split-mb`) holds the same questions.

mod common;
use common::*;
use grafika::input::problem::ProblemIn;
use grafika::msg::Msg;
use grafika::num::expr::parse_expr;
use grafika::num::Real;
use grafika::report::lang::Lang;
use grafika::report::mistakes::mistake_text;
use grafika::report::moodle::{moodle_xml, typeable, Decimal, Written};
use grafika::report::Style;
use grafika::tutor::check::scheme::Scheme;
use grafika::tutor::diagnose::Code;
use grafika::tutor::generate::quiz::Quiz;
use grafika::tutor::generate::{Generated, Topic};
use grafika::tutor::solve;
use std::path::{Path, PathBuf};

const R: f64 = 1e-3;

fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("grafika-moodle-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    d
}

/// One alternative of a blank: its fraction, answer and feedback.
#[derive(Debug, Clone, PartialEq)]
struct Alt {
    fraction: f64,
    answer: String,
    feedback: String,
}

/// One blank `{W:TYPE:alt~alt…}` of weight W.
#[derive(Debug, Clone, PartialEq)]
struct Blank {
    weight: u32,
    kind: String,
    alts: Vec<Alt>,
}

/// Where the next blank of a Cloze text starts: `{`, the weight's digits
/// (none reads as 1, as Moodle's `ANSWER_REGEX_NORM` does), `:`, an upper
/// case type and `:`; with its weight and where its type starts.
fn next_blank(text: &str) -> Option<(usize, u32, usize)> {
    let mut from = 0;
    while let Some(k) = text[from..].find('{').map(|k| k + from) {
        let digits = text[k + 1..].bytes().take_while(u8::is_ascii_digit).count();
        let colon = k + 1 + digits;
        let kind = text[colon..].strip_prefix(':').map(|r| {
            r.bytes()
                .take_while(|b| b.is_ascii_uppercase() || *b == b'_')
                .count()
        });
        if kind.is_some_and(|n| n > 0 && text[colon + 1 + n..].starts_with(':')) {
            let weight = text[k + 1..colon].parse().unwrap_or(1);
            return Some((k, weight, colon + 1));
        }
        from = k + 1;
    }
    None
}

/// Moodle's html_entity_decode, for the entities the writer uses.
fn decode(s: &str) -> String {
    let mut out = String::new();
    let mut rest = s;
    while let Some(k) = rest.find('&') {
        out.push_str(&rest[..k]);
        rest = &rest[k..];
        let end = rest.find(';').expect("an entity ends with ;");
        let ent = &rest[1..end];
        out.push(match ent {
            "amp" => '&',
            "lt" => '<',
            "gt" => '>',
            _ => {
                let n: u32 = ent
                    .strip_prefix('#')
                    .expect("numeric entity")
                    .parse()
                    .unwrap();
                char::from_u32(n).unwrap()
            }
        });
        rest = &rest[end + 1..];
    }
    out + rest
}

/// The blanks of a Cloze text, read as Moodle does: an alternative's answer
/// ends at the first `#` not after `&`, alternatives part at `~`, a blank
/// ends at `}`; the feedback is entity-decoded once (what Moodle stores as
/// HTML) and once more here (what a student reads).
fn cloze_blanks(text: &str) -> Vec<Blank> {
    let mut out = Vec::new();
    let mut rest = text;
    while let Some((_, weight, start)) = next_blank(rest) {
        let body = &rest[start..];
        let end = body.find('}').expect("a blank ends");
        let (kind, alts) = body[..end].split_once(':').expect("a type");
        let alts = alts
            .split('~')
            .map(|a| {
                let (fraction, a) = match a.strip_prefix('=') {
                    Some(a) => (1.0, a),
                    None => {
                        let a = a.strip_prefix('%').expect("a fraction");
                        let (f, a) = a.split_once('%').unwrap();
                        (f.parse::<f64>().unwrap() / 100.0, a)
                    }
                };
                let cut = (0..a.len())
                    .find(|&i| a[i..].starts_with('#') && !a[..i].ends_with('&'))
                    .unwrap_or(a.len());
                Alt {
                    fraction,
                    answer: decode(&a[..cut]),
                    feedback: decode(&decode(a.get(cut + 1..).unwrap_or(""))),
                }
            })
            .collect();
        out.push(Blank {
            weight,
            kind: kind.to_string(),
            alts,
        });
        rest = &body[end + 1..];
    }
    out
}

/// `x:t` as numbers.
fn num_tol(answer: &str) -> (f64, f64) {
    let (x, t) = answer.split_once(':').expect("value:tolerance");
    (x.parse().unwrap(), t.parse().unwrap())
}

/// The (category, name, question text, general feedback) of each question
/// of a Moodle XML file, in order; a category has no texts.
fn xml_questions(xml: &str) -> Vec<(String, String, String, String)> {
    let doc = roxmltree::Document::parse(xml).expect("well-formed XML");
    let quiz = doc.root_element();
    assert_eq!(quiz.tag_name().name(), "quiz");
    let text_of = |q: roxmltree::Node, tag: &str| -> String {
        q.children()
            .find(|c| c.has_tag_name(tag))
            .and_then(|c| c.children().find(|t| t.has_tag_name("text")))
            .and_then(|t| t.text())
            .unwrap_or("")
            .to_string()
    };
    quiz.children()
        .filter(|c| c.has_tag_name("question"))
        .map(|q| {
            let kind = q.attribute("type").unwrap_or("").to_string();
            let label = if kind == "category" {
                text_of(q, "category")
            } else {
                assert_eq!(kind, "cloze");
                text_of(q, "name")
            };
            (
                kind,
                label,
                text_of(q, "questiontext"),
                text_of(q, "generalfeedback"),
            )
        })
        .collect()
}

fn generated(toml: &str) -> Generated {
    let problem = ProblemIn::parse(toml, "test").expect("parses");
    let report = solve::solve::<Real>(&problem).expect("solves");
    let order = grafika::tutor::keys::ordered_keys(&report.result);
    let scheme = Scheme::of(&problem, &report.result, &order).expect("a scheme");
    let keys = scheme.keys().cloned().collect();
    // The problem's own words stand for the drawn title and statement.
    Generated {
        title: Msg::Math(problem.title.clone()),
        statement: Msg::Math(problem.statement.clone().unwrap_or_default()),
        body: toml.to_string(),
        problem,
        report,
        keys,
        scheme,
    }
}

/// The questions of a one-problem Moodle XML file for a problem file's text.
fn one_problem_xml(toml: &str, lang: Lang) -> Vec<(String, String, String, String)> {
    xml_questions(&one_problem_file(toml, lang, Decimal::Point))
}

/// The Moodle XML file of one problem.
fn one_problem_file(toml: &str, lang: Lang, decimal: Decimal) -> String {
    let quiz = Quiz::new(vec![vec![generated(toml)]], &[Topic::View], R);
    let style = Style::new(4, true, lang);
    moodle_xml(&quiz, &Written::new(&style, decimal))
}

const CAMERA: &str = "title = 'Camera'\nstatement = 'The camera example.'\nask = ['view']\n\n[camera]\neye = [4, 4, 4]\nlook = [0, 1, 4]\nup = [0, 1, 0]\n\n[points]\nPref = [0, 1, 4]\n";

/// Pe − Pr = (4, 3, 0), |.| = 5: n = (0.8, 0.6, 0); Vup × n = (0, 0, −0.8),
/// u = (0, 0, −1); v = n × u = (−0.6, 0.8, 0); Pref' = (0, 0, −5).
/// Mistakes by hand: u = n × Vup flips u and v; n from Pr − Pe flips n and
/// u (v = n × u stays); n not normalized is (4, 3, 0) and v = n × u then
/// (−3, 4, 0); u not normalized is Vup × n = (0, 0, −0.8) and v (−0.48, 0.64, 0);
/// u and v swapped writes u = (−0.6, 0.8, 0) and v = (0, 0, −1).
#[test]
fn the_camera_example_has_the_keys_tolerances_and_mistakes_derived_by_hand() {
    let qs = one_problem_xml(CAMERA, Lang::En);
    assert_eq!(qs[0].0, "category");
    assert_eq!(qs[0].1, "$course$/grafika/view/01");
    let blanks = cloze_blanks(&qs[1].2);
    // view.u, view.v, view.n, view.points.Pref: 12 numbers
    assert_eq!(blanks.len(), 12);
    let expect: [(f64, f64); 12] = [
        (0.0, 0.001),
        (0.0, 0.001),
        (-1.0, 0.001),
        (-0.6, 0.0006),
        (0.8, 0.0008),
        (0.0, 0.0008),
        (0.8, 0.0008),
        (0.6, 0.0006),
        (0.0, 0.0008),
        (0.0, 0.005),
        (0.0, 0.005),
        (-5.0, 0.005),
    ];
    for (b, (x, t)) in blanks.iter().zip(expect) {
        assert_eq!(b.kind, "NUMERICAL");
        assert_eq!(b.alts[0].fraction, 1.0);
        assert_eq!(num_tol(&b.alts[0].answer), (x, t), "{b:?}");
    }
    let wrong = |i: usize, x: f64, code: &str| {
        let m = Code::all()
            .into_iter()
            .find(|m| m.as_str() == code)
            .unwrap();
        let alt = blanks[i]
            .alts
            .iter()
            .find(|a| (num_tol(&a.answer).0 - x).abs() < 1e-12)
            .unwrap_or_else(|| panic!("no 0 % answer {x} in blank {i}: {:?}", blanks[i]));
        assert_eq!(alt.fraction, 0.0);
        assert!(
            (num_tol(&alt.answer).1 - R * x.abs()).abs() < 1e-15,
            "{alt:?}"
        );
        assert!(
            alt.feedback.starts_with("Known mistake: "),
            "{}",
            alt.feedback
        );
        assert!(
            alt.feedback.contains(&typeable(mistake_text(m, Lang::En))),
            "{code}: {}",
            alt.feedback
        );
    };
    wrong(2, 1.0, "cross_order");
    wrong(2, 1.0, "n_reversed");
    wrong(2, -0.8, "u_not_normalized");
    wrong(3, 0.6, "cross_order");
    wrong(3, -3.0, "n_not_normalized");
    wrong(3, -0.48, "u_not_normalized");
    wrong(4, -0.8, "cross_order");
    wrong(4, 4.0, "n_not_normalized");
    wrong(4, 0.64, "u_not_normalized");
    wrong(6, -0.8, "n_reversed");
    wrong(6, 4.0, "n_not_normalized");
    wrong(7, -0.6, "n_reversed");
    wrong(7, 3.0, "n_not_normalized");
    wrong(0, -0.6, "uv_swapped");
    wrong(1, 0.8, "uv_swapped");
    wrong(5, -1.0, "uv_swapped");
    // n's zero, that every mistake keeps zero, has no wrong answers
    assert_eq!(blanks[8].alts.len(), 1, "{:?}", blanks[8]);
    // the general feedback holds the answers, named as the steps name
    // them, with a minus Moodle reads, and the worked solution
    assert!(qs[1].3.contains("<li>u = (0, 0, -1)</li>"), "{}", qs[1].3);
    assert!(qs[1].3.contains("Worked solution"));
}

#[test]
fn indonesian_feedback_names_the_mistake_in_indonesian() {
    let qs = one_problem_xml(CAMERA, Lang::Id);
    let blanks = cloze_blanks(&qs[1].2);
    let fb = &blanks[2].alts[1].feedback;
    assert!(fb.starts_with("Kesalahan yang dikenal: "), "{fb}");
    assert!(fb.contains("bukan Vup × n"), "{fb}");
    assert!(qs[1].2.contains("angka penting"));
    assert!(qs[1].3.contains("Penyelesaian"));
}

#[test]
fn markup_and_syntax_in_a_statement_are_escaped() {
    let nasty = "A & B <i>x</i> ]]> {1:NUMERICAL:=5} ~ = # : \\\\ end";
    let toml = CAMERA
        .replace("title = 'Camera'", "title = \"T & <b> ]]> { }\"")
        .replace("'The camera example.'", &format!("\"{nasty}\""));
    let qs = one_problem_xml(&toml, Lang::En);
    assert!(qs[1].1.ends_with("T & <b> ]]> { }"), "{}", qs[1].1);
    let text = &qs[1].2;
    assert!(
        text.contains(
            "A &amp; B &lt;i&gt;x&lt;/i&gt; ]]&gt; &#123;1:NUMERICAL:=5&#125; ~ = # : \\ end"
        ),
        "{text}"
    );
    // the statement's braces make no blank: still the 12 of the answers
    assert_eq!(cloze_blanks(text).len(), 12);
}

/// Generates into a fresh directory; returns it.
fn generate(name: &str, format: &str, extra: &[&str]) -> PathBuf {
    let out = tmp(name);
    let mut args = vec![
        "generate",
        "--topic",
        "basis,view,project,window,clip,shade,pipeline",
        "--count",
        "7",
        "--variants",
        "2",
        "--seed",
        "11",
        "--format",
        format,
        "--out",
    ];
    let o = out.display().to_string();
    args.push(&o);
    args.extend(extra);
    let run = grafika().args(&args).output().unwrap();
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    out
}

/// A key file's answers, in order: (key, leaves as written).
fn key_leaves(path: &Path) -> Vec<(String, Vec<String>)> {
    fn leaves(v: &toml::Value, out: &mut Vec<String>) {
        match v {
            toml::Value::Array(a) => a.iter().for_each(|x| leaves(x, out)),
            toml::Value::String(s) => out.push(s.clone()),
            other => out.push(other.to_string()),
        }
    }
    (common::key_entries(path).into_iter())
        .map(|(k, v)| {
            let mut l = Vec::new();
            leaves(&v, &mut l);
            (k, l)
        })
        .collect()
}

/// The leaves of a value a mistake gives, as numbers or texts.
fn tree_leaf(v: &grafika::stages::trace::Val, out: &mut Vec<String>) {
    use grafika::stages::trace::Val;
    match v {
        Val::Num(s) => out.push(format!("{:e}", s.value)),
        Val::List(items) => items.iter().for_each(|x| tree_leaf(x, out)),
        Val::Map(kv) => kv.iter().for_each(|(_, x)| tree_leaf(x, out)),
        Val::Text(t) => out.push(t.clone()),
        Val::Bool(b) => out.push(b.to_string()),
        Val::Null => out.push("none".into()),
        Val::Said(_) => {}
    }
}

/// Checks one Cloze question against its key file and problem file.
fn check_question(text: &str, key: &Path, problem: &Path) {
    let p = ProblemIn::read(problem).unwrap();
    let blanks = cloze_blanks(text);
    let keys = key_leaves(key);
    let total: usize = keys.iter().map(|(_, l)| l.len()).sum();
    assert_eq!(blanks.len(), total, "{}", key.display());
    let mut blanks = blanks.iter();
    for (k, leaves) in &keys {
        let all: Vec<f64> = leaves
            .iter()
            .filter_map(|s| parse_expr(s).ok()?.eval::<f64>().ok())
            .collect();
        let scale = answer_scale(k, &all);
        for (idx, leaf) in leaves.iter().enumerate() {
            let b = blanks.next().unwrap();
            let right = &b.alts[0];
            assert_eq!(right.fraction, 1.0);
            if b.kind == "SHORTANSWER" {
                assert_eq!(&right.answer, leaf, "{k}");
            } else {
                let want = parse_expr(leaf).unwrap().eval::<f64>().unwrap();
                let (x, t) = num_tol(&right.answer);
                // shown to 5 significant figures (4 asked, plus one); below
                // the resolution r·S a student works to, asked as 0
                let five: f64 = format!("{want:.4e}").parse().unwrap();
                let tiny = want.abs() < R * scale;
                assert_eq!(x, if tiny { 0.0 } else { five }, "{k}: {x} for {leaf}");
                let floor = if tiny { R * scale } else { R * want.abs() };
                // a pixel position takes at least half a pixel, as in check
                let pixel = k.starts_with("viewport.pixels");
                let floor = if pixel { floor.max(0.5) } else { floor };
                // every number check accepts is accepted, and little more
                let slack = 1e-12 * want.abs().max(1.0);
                assert!(
                    x - t <= want - floor + slack && x + t >= want + floor - slack,
                    "{k}: {x} ± {t} does not cover {want} ± {floor}"
                );
                assert!(
                    t <= floor * 1.01 + (x - want).abs() + slack,
                    "{k}: tolerance {t} for {want}"
                );
                if pixel {
                    let whole = want.round();
                    assert!((whole - x).abs() <= t, "{k}: whole pixel {whole}");
                    assert!(text_has_pixel_rule(text), "{k}: the rule is stated");
                }
            }
            for w in &b.alts[1..] {
                check_wrong(&p, (k, idx), b, w, scale);
            }
        }
    }
}

/// The scale S of an answer by hand: its largest magnitude; a colour's (a
/// lighting term, the colour before or after clamping) at least 1, full
/// intensity; 1 for an answer all zero.
fn answer_scale(key: &str, leaves: &[f64]) -> f64 {
    let largest = leaves.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let colour = [
        "ambient",
        "diffuse",
        "specular",
        "emissive",
        "unclamped",
        "color",
    ]
    .iter()
    .any(|c| key.ends_with(&format!(".{c}")));
    if colour {
        largest.max(1.0)
    } else if largest > 0.0 {
        largest
    } else {
        1.0
    }
}

/// Whether a question's instruction states the half-pixel rule.
fn text_has_pixel_rule(text: &str) -> bool {
    text.contains("a pixel position within half a pixel, so a whole pixel is right")
}

/// A 0 % answer: apart from the key's, and given by each mistake it names
/// (in the words of the catalog, with the minus a student can type back).
fn check_wrong(p: &ProblemIn, (key, idx): (&str, usize), b: &Blank, w: &Alt, scale: f64) {
    assert_eq!(w.fraction, 0.0);
    let names = w
        .feedback
        .strip_prefix("Known mistake: ")
        .expect("names a mistake");
    for name in names.split("; or: ") {
        let m = Code::all()
            .into_iter()
            .find(|m| typeable(mistake_text(*m, Lang::En)) == name)
            .unwrap_or_else(|| panic!("not in the catalog: {name}"));
        let trees = m.apply(p).expect("the mistake applies");
        let given = trees.iter().any(|t| {
            let mut l = Vec::new();
            if let Some(v) = t.lookup(key).map(|v| v.into_owned()) {
                tree_leaf(&v, &mut l);
            }
            match (b.kind.as_str(), l.get(idx)) {
                ("NUMERICAL", Some(s)) => {
                    let (x, t) = num_tol(&w.answer);
                    (s.parse::<f64>().unwrap() - x).abs() <= t
                }
                (_, Some(s)) => *s == w.answer,
                _ => false,
            }
        });
        assert!(given, "{} does not give {} at {key}[{idx}]", m, w.answer);
    }
    if b.kind == "NUMERICAL" {
        let ((x, t), (y, u)) = (num_tol(&b.alts[0].answer), num_tol(&w.answer));
        assert!(
            (x - y).abs() > t + u,
            "{key}: wrong {y} overlaps the key {x}"
        );
        // nothing absurd: finite, at most 10³ times the larger of the
        // key's magnitude and its answer's scale
        assert!(
            y.is_finite() && y.abs() <= 1e3 * x.abs().max(scale),
            "{key}: {y} for {x} (scale {scale})"
        );
    }
    // Moodle sizes a box by its longest answer: none is long
    let value = w.answer.split(':').next().unwrap_or("");
    assert!(value.chars().count() <= 12, "{key}: {}", w.answer);
}

#[test]
fn moodle_xml_agrees_with_the_keys_and_the_catalog() {
    let quiz = generate("xml", "moodle", &[]);
    let keys = generate("keys", "toml", &[]);
    let xml = std::fs::read_to_string(quiz.join("quiz.xml")).unwrap();
    let qs = xml_questions(&xml);
    let topics = [
        "basis", "view", "project", "window", "clip", "shade", "pipeline",
    ];
    assert_eq!(qs.len(), 7 * 3, "a category and two variants per problem");
    for (i, chunk) in qs.chunks(3).enumerate() {
        assert_eq!(chunk[0].0, "category", "the category comes first");
        assert_eq!(
            chunk[0].1,
            format!("$course$/grafika/{}/{:02}", topics[i], i + 1)
        );
        for (v, q) in chunk[1..].iter().enumerate() {
            assert!(q
                .1
                .starts_with(&format!("Problem {:02}, variant {:02}: ", i + 1, v + 1)));
            let dir = keys.join(format!("variant-{:02}", v + 1));
            check_question(
                &q.2,
                &dir.join(format!("problem-{:02}.key.toml", i + 1)),
                &dir.join(format!("problem-{:02}.toml", i + 1)),
            );
        }
    }
    // some mistakes are there to be named
    assert!(xml.contains("~%0%"));
}

/// A GIFT question as Moodle's import reads it: escaped characters set
/// aside, the name between `::`, the answers between the first `{` and `}`
/// (the general feedback after `####` dropped), each answer split at `=`,
/// its weight `%n%`, its feedback after `#`.
#[derive(Debug)]
enum Gift {
    Category(String),
    Question {
        name: String,
        text: String,
        numerical: bool,
        alts: Vec<Alt>,
    },
}

fn protect(s: &str) -> String {
    const SPECIALS: [char; 6] = [':', '#', '=', '{', '}', '~'];
    let mut out = String::new();
    let mut it = s.chars();
    while let Some(c) = it.next() {
        if c == '\\' {
            match it.next() {
                Some('\\') => out.push('\u{E05C}'),
                Some('n') => out.push('\n'),
                Some(d) if SPECIALS.contains(&d) => {
                    out.push(char::from_u32(0xE000 + d as u32).unwrap())
                }
                other => panic!("unknown escape \\{other:?}"),
            }
        } else {
            out.push(c);
        }
    }
    out
}

fn restore(s: &str) -> String {
    s.chars()
        .map(|c| match c as u32 {
            0xE000..=0xE0FF => char::from_u32(c as u32 - 0xE000).unwrap(),
            _ => c,
        })
        .collect()
}

fn gift_alts(answers: &str) -> (bool, Vec<Alt>) {
    let (numerical, answers) = match answers.strip_prefix('#') {
        Some(a) => (true, a),
        None => (false, answers),
    };
    let alts = answers
        .split('=')
        .map(str::trim)
        .filter(|a| !a.is_empty())
        .map(|a| {
            let (fraction, a) = match a.strip_prefix("%0%") {
                Some(a) => (0.0, a),
                None => (1.0, a),
            };
            let (answer, feedback) = a.split_once('#').unwrap_or((a, ""));
            Alt {
                fraction,
                answer: restore(answer.trim()),
                feedback: decode(&restore(feedback.trim())),
            }
        })
        .collect();
    (numerical, alts)
}

fn gift_questions(text: &str) -> Vec<Gift> {
    let mut out = Vec::new();
    for block in text.split("\n\n").filter(|b| !b.trim().is_empty()) {
        assert!(!block.contains('\n'), "one line per question: {block}");
        let t = protect(block);
        if let Some(cat) = t.strip_prefix("$CATEGORY: ") {
            out.push(Gift::Category(restore(cat)));
            continue;
        }
        let t = t.strip_prefix("::").expect("a name");
        let (name, rest) = t.split_once("::").expect("the name ends");
        let open = rest.find('{').expect("answers");
        let close = rest.find('}').expect("answers end");
        assert_eq!(close, rest.len() - 1, "the answers end the question");
        let answers = rest[open + 1..close].split("####").next().unwrap().trim();
        let (numerical, alts) = gift_alts(answers);
        out.push(Gift::Question {
            name: restore(name),
            text: restore(&rest[..open]),
            numerical,
            alts,
        });
    }
    out
}

#[test]
fn gift_has_the_moodle_blanks_one_question_each() {
    let xml_dir = generate("gx", "moodle", &["--tolerance", "0.005"]);
    let gift_dir = generate("gg", "gift", &["--tolerance", "0.005"]);
    let xml = std::fs::read_to_string(xml_dir.join("quiz.xml")).unwrap();
    let gift = std::fs::read_to_string(gift_dir.join("quiz.gift")).unwrap();
    let cloze: Vec<Blank> = xml_questions(&xml)
        .iter()
        .filter(|q| q.0 == "cloze")
        .flat_map(|q| cloze_blanks(&q.2))
        .collect();
    let mut blanks = cloze.iter();
    let mut category = String::new();
    let mut named = 0;
    for q in gift_questions(&gift) {
        match q {
            Gift::Category(c) => category = c,
            Gift::Question {
                name,
                text,
                numerical,
                alts,
            } => {
                // "Problem 03, variant 02: … — key" is in category …/03/02
                let (p, v) = (&name[8..10], &name[20..22]);
                assert!(
                    category.ends_with(&format!("/{p}/{v}")),
                    "{category} before {name}"
                );
                assert!(text.starts_with("[html]<p>"), "{text}");
                let b = blanks.next().expect("as many questions as blanks");
                assert_eq!(numerical, b.kind == "NUMERICAL", "{name}");
                assert_eq!(&alts, &b.alts, "{name}");
                named += alts.len() - 1;
            }
        }
    }
    assert!(blanks.next().is_none(), "as many questions as blanks");
    assert!(named > 0, "some mistakes are named");
    // the tolerance asked for, 0.5 %, on every nonzero number (half a
    // pixel where that is more: a pixel position, as in check), widened by
    // the rounding of the key to 4 significant figures (3 asked, plus one)
    for b in cloze.iter().filter(|b| b.kind == "NUMERICAL") {
        let (x, t) = num_tol(&b.alts[0].answer);
        let pixel = t >= 0.5 && 0.005 * x.abs() < 0.5;
        let (low, high) = (0.005 * x.abs(), 0.005 * x.abs() * 1.01 + 5e-4 * x.abs());
        assert!(
            x == 0.0 || pixel || (t >= low * (1.0 - 1e-9) && t <= high),
            "{x} ± {t}"
        );
    }
}

#[test]
fn a_tolerance_outside_zero_to_one_is_an_error_naming_it() {
    for bad in ["0", "-0.1", "1", "nan"] {
        let out = grafika()
            .args(["generate", "--topic", "view", "--format", "moodle", "--out"])
            .arg(tmp("bad"))
            .arg(format!("--tolerance={bad}"))
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(2), "{bad}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains("tolerance"), "{err}");
        assert_eq!(err.trim().lines().count(), 1, "{err}");
    }
}

/// fovy = 90°, aspect 1, near 1: top = tan 45° = 1. Taking tan(fovy)
/// instead gives tan 90°, 1.6·10¹⁶ in floating point: no student types it,
/// so the blank leaves it out (and its width with it); the degrees read as
/// radians give tan(45 rad) = 1.6198 and stay.
const FOVY_90: &str = "title = 'Window'\nstatement = 'fovy 90.'\nask = ['window']\n\n[perspective]\nnear = 1\nfovy = 90\naspect = 1\n";

#[test]
fn an_absurd_mistaken_value_is_left_out() {
    let qs = one_problem_xml(FOVY_90, Lang::En);
    let blanks = cloze_blanks(&qs[1].2);
    let top = &blanks[0];
    assert_eq!(num_tol(&top.alts[0].answer), (1.0, 0.001));
    let fovy = Code::FovyNotHalved;
    for b in &blanks {
        for a in &b.alts[1..] {
            assert!(
                !a.feedback.contains(&typeable(mistake_text(fovy, Lang::En))),
                "{a:?}"
            );
            assert!(num_tol(&a.answer).0.abs() < 1e6, "{a:?}");
        }
    }
    let radians = 45f64.tan();
    assert!(
        top.alts
            .iter()
            .any(|a| (num_tol(&a.answer).0 - radians).abs() < 1e-4),
        "{top:?}"
    );
}

#[test]
fn the_instruction_names_the_decimal_mark_and_asks_for_decimals() {
    let text = |lang, d| {
        xml_questions(&one_problem_file(CAMERA, lang, d))[1]
            .2
            .clone()
    };
    let en = text(Lang::En, Decimal::Point);
    assert!(en.contains("with a decimal point (0.5, not 0,5)"), "{en}");
    assert!(en.contains("not as an exact form such as (√2−1)/2"), "{en}");
    assert!(en.contains("with at least 4 significant figures"), "{en}");
    // no pixel, outcode or status blank: their rules are not stated
    assert!(!text_has_pixel_rule(&en) && !en.contains("outcode"), "{en}");
    let en_comma = text(Lang::En, Decimal::Comma);
    assert!(
        en_comma.contains("with a decimal comma (0,5)"),
        "{en_comma}"
    );
    let id = text(Lang::Id, Decimal::Comma);
    assert!(id.contains("dengan koma desimal (0,5)"), "{id}");
    assert!(id.contains("bukan sebagai bentuk eksak"), "{id}");
    let id_point = text(Lang::Id, Decimal::Point);
    assert!(
        id_point.contains("dengan titik desimal (0.5, bukan 0,5)"),
        "{id_point}"
    );
    // the answers Moodle reads are plain decimals with a point either way
    let b = cloze_blanks(&id)[3].alts[0].answer.clone();
    assert_eq!(b, "-0.6:0.0006");
}

#[test]
fn the_decimal_flag_is_checked_and_reaches_the_quiz() {
    let out = tmp("comma");
    let run = grafika()
        .args([
            "--lang", "id", "generate", "--topic", "window", "--count", "1",
        ])
        .args(["--format", "gift", "--decimal", "comma", "--out"])
        .arg(&out)
        .output()
        .unwrap();
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    let gift = std::fs::read_to_string(out.join("quiz.gift")).unwrap();
    assert!(gift.contains("dengan koma desimal (0,5)"), "{gift}");
    let bad = grafika()
        .args(["generate", "--topic", "window", "--format", "moodle"])
        .args(["--decimal", "koma", "--out"])
        .arg(tmp("koma"))
        .output()
        .unwrap();
    assert_eq!(bad.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&bad.stderr).contains("--decimal"));
}

/// The `<file>` elements of each question's general feedback: (name,
/// decoded bytes).
fn feedback_files(xml: &str) -> Vec<Vec<(String, Vec<u8>)>> {
    use base64::Engine as _;
    let doc = roxmltree::Document::parse(xml).unwrap();
    doc.root_element()
        .children()
        .filter(|q| q.attribute("type") == Some("cloze"))
        .map(|q| {
            let gf = q
                .children()
                .find(|c| c.has_tag_name("generalfeedback"))
                .unwrap();
            gf.children()
                .filter(|c| c.has_tag_name("file"))
                .map(|f| {
                    assert_eq!(f.attribute("encoding"), Some("base64"));
                    assert_eq!(f.attribute("path"), Some("/"));
                    let bytes = base64::engine::general_purpose::STANDARD
                        .decode(f.text().unwrap_or(""))
                        .expect("base64");
                    (f.attribute("name").unwrap().to_string(), bytes)
                })
                .collect()
        })
        .collect()
}

#[test]
fn embedded_figures_decode_to_the_svg_solve_writes() {
    let args = ["--topic", "view,window,clip", "--count", "3", "--seed", "3"];
    let quiz = tmp("fig-quiz");
    let keys = tmp("fig-keys");
    // an Indonesian quiz typed with decimal commas: its figures are those
    // of `solve --lang id` (with the mark of --decimal, as every number of
    // the quiz)
    for (dir, format) in [(&quiz, "moodle"), (&keys, "toml")] {
        let run = grafika()
            .args(["--lang", "id", "generate"])
            .args(args)
            .args(["--decimal", "comma", "--format", format, "--out"])
            .arg(dir)
            .output()
            .unwrap();
        assert!(
            run.status.success(),
            "{}",
            String::from_utf8_lossy(&run.stderr)
        );
    }
    let xml = std::fs::read_to_string(quiz.join("quiz.xml")).unwrap();
    let files = feedback_files(&xml);
    let qs: Vec<_> = xml_questions(&xml)
        .into_iter()
        .filter(|q| q.0 == "cloze")
        .collect();
    assert_eq!(files.len(), 3);
    for (i, (embedded, q)) in files.iter().zip(&qs).enumerate() {
        let svg = keys.join(format!("fig-{}.svg", i + 1));
        let run = grafika()
            .args(["--lang", "id", "solve"])
            .arg(keys.join(format!("problem-{:02}.toml", i + 1)))
            .arg("--figure")
            .arg(&svg)
            .output()
            .unwrap();
        assert!(
            run.status.success(),
            "{}",
            String::from_utf8_lossy(&run.stderr)
        );
        assert!(!embedded.is_empty(), "problem {} has a figure", i + 1);
        for (name, bytes) in embedded {
            // figure-1-view.svg is what solve names fig-1-1-view.svg
            let part = name.strip_prefix("figure-").unwrap();
            let written = std::fs::read(keys.join(format!("fig-{}-{part}", i + 1))).unwrap();
            assert!(bytes == &written, "{name} of problem {}", i + 1);
            // and the feedback shows it, where Moodle puts the file
            assert!(
                q.3.contains(&format!("src=\"@@PLUGINFILE@@/{name}\"")),
                "{name}"
            );
            assert!(
                !q.2.contains("@@PLUGINFILE@@"),
                "no figure gives answers away"
            );
        }
    }
}

/// The blocks of a worked solution's steps (the writer's `body_html`):
/// each line a `<div>` of its own, a matrix's lines together in a `<div>`
/// that does not wrap; returns (text lines, matrices).
fn step_blocks(feedback: &str) -> (Vec<String>, Vec<Vec<String>>) {
    let (mut lines, mut tables) = (Vec::new(), Vec::new());
    for body in feedback
        .split("<div style=\"font-family:monospace;white-space:pre-wrap\">")
        .skip(1)
    {
        for block in body.split("<div style=\"").skip(1) {
            let (style, rest) = block.split_once("\">").unwrap();
            let text = decode(rest.split("</div>").next().unwrap());
            if style == "white-space:pre;overflow-x:auto" {
                tables.push(text.lines().map(str::to_string).collect());
            } else {
                assert!(style.ends_with("ch;text-indent:-2ch"), "{style}");
                assert!(!text.contains('\n'), "one line per block: {text}");
                lines.push(text);
            }
        }
    }
    (lines, tables)
}

#[test]
fn what_students_see_is_laid_out_by_the_browser_and_in_one_language() {
    let en = std::fs::read_to_string(generate("see-en", "moodle", &[]).join("quiz.xml")).unwrap();
    let id_dir = generate("see-id", "moodle", &["--lang", "id"]);
    let id = std::fs::read_to_string(id_dir.join("quiz.xml")).unwrap();
    let mut matrices = 0;
    for (xml, lang) in [(&en, Lang::En), (&id, Lang::Id)] {
        for (_, _, text, feedback) in xml_questions(xml).iter().filter(|q| q.0 == "cloze") {
            // no "= ≈": a value without an exact form is "top ≈ 0.04663"
            assert!(!feedback.contains("= ≈"), "{feedback}");
            // no line is broken by the writer: a step's lines are blocks the
            // browser wraps, and a matrix's borders are whole (every line of
            // its table as wide as the others, its corners where they belong)
            // (only an answer that is a matrix is a <pre> of its own)
            let pres = feedback.matches("<pre>").count();
            assert_eq!(pres, feedback.matches("<li><pre>").count(), "{feedback}");
            let (lines, tables) = step_blocks(feedback);
            assert!(!lines.is_empty());
            for t in &tables {
                let width = t[0].chars().count();
                assert!(t.iter().all(|l| l.chars().count() == width), "{t:?}");
                let (first, last) = (t[0].trim(), t[t.len() - 1].trim());
                assert!(first.starts_with('┌') && first.ends_with('┐'), "{t:?}");
                assert!(last.starts_with('└') && last.ends_with('┘'), "{t:?}");
                matrices += 1;
            }
            // the parts are numbered within the question, from 1
            let part = if lang == Lang::En { "Part" } else { "Bagian" };
            assert!(feedback.contains(&format!("<h4>{part} 1: ")), "{feedback}");
            assert!(!feedback.contains("Step 4:") && !feedback.contains("Tahap 4:"));
            // the quiz's own words are the language's
            let other = match lang {
                Lang::En => ["Jawaban", "Bagian", "Langkah", "Gambar", "Tulis"],
                Lang::Id => ["Answers", "Part ", "Step ", "Figures", "Type "],
            };
            for w in other {
                assert!(!text.contains(w) && !feedback.contains(w), "{w}");
            }
            // the correct answer Moodle shows has 5 significant figures
            for b in cloze_blanks(text).iter().filter(|b| b.kind == "NUMERICAL") {
                let x = b.alts[0].answer.split(':').next().unwrap();
                let digits = x.trim_start_matches(['-', '0', '.']).replace('.', "");
                assert!(digits.len() <= 5, "{x}");
            }
            // every number typed back reads as written: no U+2212 minus (no
            // number to Moodle) and no exponent with one (1.6e−10 is 1.6)
            assert!(!feedback.contains('−'), "{feedback}");
            for b in cloze_blanks(text) {
                assert!(b.alts.iter().all(|a| !a.feedback.contains('−')), "{b:?}");
            }
        }
    }
    assert!(matrices > 0, "the pipeline's matrices are drawn");
}

/// The labels before the blanks of every Cloze question (`<p>n = (…`) and
/// after the dash of every GIFT question's name.
fn cloze_labels(xml: &str) -> Vec<String> {
    let mut out = Vec::new();
    for (_, _, text, _) in xml_questions(xml).iter().filter(|q| q.0 == "cloze") {
        for p in text.split("<p>").skip(1) {
            let p = p.split("</p>").next().unwrap();
            if let Some((label, _)) = p.split_once(" = ").filter(|(_, r)| {
                let r = r.trim_start_matches('(');
                next_blank(r).is_some_and(|(k, ..)| k == 0) || r.starts_with("<table>")
            }) {
                out.push(decode(label));
            }
        }
    }
    out
}

/// Whether a label spells a JSON key or a key's name: `view.points.A`,
/// `cos_alpha`, `code0`, `N_dot_H`.
fn spells_a_key(label: &str) -> bool {
    let dotted = label.split(' ').any(|w| {
        let parts: Vec<&str> = w.split('.').collect();
        parts.len() > 1
            && parts
                .iter()
                .all(|p| !p.is_empty() && p.chars().all(|c| c.is_alphanumeric() || c == '_'))
    });
    dotted || label.contains('_') || label.contains("code0") || label.contains("code1")
}

#[test]
fn no_label_spells_a_json_key_and_indonesian_labels_are_the_texts() {
    for lang in ["en", "id"] {
        let dir = generate(&format!("labels-{lang}"), "moodle", &["--lang", lang]);
        let xml = std::fs::read_to_string(dir.join("quiz.xml")).unwrap();
        let labels = cloze_labels(&xml);
        // 7 problems, 2 variants, every answer asked labelled
        assert!(labels.len() >= 14 * 3, "{labels:?}");
        for l in &labels {
            assert!(!spells_a_key(l), "{lang}: {l}");
        }
        let gift_dir = generate(&format!("labels-g-{lang}"), "gift", &["--lang", lang]);
        let gift = std::fs::read_to_string(gift_dir.join("quiz.gift")).unwrap();
        for q in gift_questions(&gift) {
            if let Gift::Question { name, text, .. } = q {
                let label = name.split(" — ").nth(1).unwrap();
                assert!(!spells_a_key(label), "{lang}: {name}");
                assert!(
                    text.ends_with(&format!("{} = ?</p>", escaped(label))),
                    "{text}"
                );
            }
        }
        let has = |l: &str| labels.iter().any(|x| x == l);
        match lang {
            "en" => {
                for l in [
                    "n",
                    "A'",
                    "A''",
                    "A pixel",
                    "top",
                    "width",
                    "outcode of P0",
                    "cos α",
                ] {
                    assert!(has(l), "{l}: {labels:?}");
                }
            }
            _ => {
                for l in [
                    "n",
                    "A'",
                    "piksel A",
                    "batas atas (top)",
                    "tinggi",
                    "lebar",
                    "region code P0",
                    "cos α",
                    "komponen diffuse",
                    "warna",
                ] {
                    assert!(has(l), "{l}: {labels:?}");
                }
                // no English word where the text has its own
                for l in ["top", "height", "width", "diffuse", "color"] {
                    assert!(!has(l), "{l}: {labels:?}");
                }
            }
        }
    }
}

/// A label as the question text escapes it.
fn escaped(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

#[test]
fn gift_names_its_blanks_as_the_steps_do_and_speaks_to_students_only() {
    let out = tmp("names");
    let run = grafika()
        .args(["--lang", "id", "generate", "--topic"])
        .args([
            "basis,view,project,window,clip,shade,pipeline",
            "--count",
            "7",
        ])
        .args([
            "--variants",
            "2",
            "--seed",
            "11",
            "--format",
            "gift",
            "--out",
        ])
        .arg(&out)
        .output()
        .unwrap();
    assert!(run.status.success());
    let gift = std::fs::read_to_string(out.join("quiz.gift")).unwrap();
    let mut names = 0;
    for q in gift_questions(&gift) {
        if let Gift::Question { name, .. } = q {
            assert!(!name.contains('['), "{name}");
            names += 1;
        }
    }
    assert!(names > 0);
    assert!(
        gift.contains("— n, komponen y::"),
        "view.n[2] is named n, komponen y"
    );
    // students read the feedback: no word to the lecturer, no command
    for lecturer in ["grafika generate", "--format", "Moodle XML", "GIFT"] {
        assert!(!gift.contains(lecturer), "{lecturer}");
    }
    // the lecturer is told where the figures are, when the file is written
    let said = String::from_utf8_lossy(&run.stdout);
    assert!(said.contains("GIFT tidak dapat membawa berkas"), "{said}");
    assert!(said.contains("--format moodle"), "{said}");
}

/// The Cloze blanks of every question whose key says `key` (`clip.status`),
/// by the label the language gives it.
fn blanks_labelled(xml: &str, label: &str) -> Vec<Blank> {
    let mut out = Vec::new();
    for (_, _, text, _) in xml_questions(xml).iter().filter(|q| q.0 == "cloze") {
        for p in text.split("<p>").skip(1) {
            let p = p.split("</p>").next().unwrap();
            if let Some(rest) = p.strip_prefix(&format!("{label} = ")) {
                out.extend(cloze_blanks(rest));
            }
        }
    }
    out
}

#[test]
fn a_clip_question_accepts_the_words_of_its_language_and_the_codes() {
    // three clipping problems of one exam take the three statuses
    // (`--clip mixed`; the default asks a clipped segment in every one)
    let args = [
        "--topic",
        "clip",
        "--count",
        "3",
        "--variants",
        "4",
        "--clip",
        "mixed",
    ];
    for (lang, words) in [
        (
            "id",
            [
                ("clipped", "di-clip"),
                ("accepted", "diterima"),
                ("rejected", "ditolak"),
            ],
        ),
        (
            "en",
            [
                ("clipped", "clipped"),
                ("accepted", "accepted"),
                ("rejected", "rejected"),
            ],
        ),
    ] {
        let out = tmp(&format!("words-{lang}"));
        let run = grafika()
            .args(["--lang", lang, "generate"])
            .args(args)
            .args(["--format", "moodle", "--out"])
            .arg(&out)
            .output()
            .unwrap();
        assert!(run.status.success());
        let xml = std::fs::read_to_string(out.join("quiz.xml")).unwrap();
        let status = blanks_labelled(&xml, "status");
        assert_eq!(status.len(), 12, "3 problems, 4 variants");
        for (code, word) in words {
            let right: Vec<&Blank> = status.iter().filter(|b| b.alts[0].answer == word).collect();
            assert!(!right.is_empty(), "{lang}: {word}");
            for b in right {
                let full: Vec<&str> = (b.alts.iter())
                    .filter(|a| a.fraction == 1.0)
                    .map(|a| a.answer.as_str())
                    .collect();
                // the language's word first (the answer Moodle shows), then
                // the code when it differs
                let want = if code == word {
                    vec![code]
                } else {
                    vec![word, code]
                };
                assert_eq!(full, want, "{lang}");
            }
        }
        // a rejected segment leaves none: "tidak ada" or "none"
        let segment = if lang == "id" {
            "segmen garis hasil clipping"
        } else {
            "clipped segment"
        };
        let none: Vec<Blank> = blanks_labelled(&xml, segment)
            .into_iter()
            .filter(|b| b.kind == "SHORTANSWER")
            .collect();
        assert!(!none.is_empty(), "{lang}");
        for b in none {
            let full: Vec<&str> = (b.alts.iter())
                .filter(|a| a.fraction == 1.0)
                .map(|a| a.answer.as_str())
                .collect();
            let want = if lang == "id" {
                vec!["tidak ada", "none"]
            } else {
                vec!["none"]
            };
            assert_eq!(full, want);
        }
        // the instruction names the words it takes
        let texts: Vec<String> = xml_questions(&xml).into_iter().map(|q| q.2).collect();
        if lang == "id" {
            assert!(texts
                .iter()
                .all(|t| t.is_empty() || t.contains("diterima, ditolak atau di-clip")));
            assert!(texts
                .iter()
                .all(|t| t.is_empty() || t.contains("tidak ada (atau none)")));
        }
    }
}

#[test]
fn a_fixed_seed_gives_the_same_bytes() {
    let a = generate("same-a", "moodle", &[]);
    let b = generate("same-b", "moodle", &[]);
    let read = |d: &Path| std::fs::read(d.join("quiz.xml")).unwrap();
    assert!(read(&a) == read(&b));
}

/// The statement (first paragraph) of each question of a quiz.
fn statements(xml: &str) -> Vec<String> {
    xml_questions(xml)
        .into_iter()
        .filter(|q| q.0 == "cloze")
        .map(|q| {
            let t = q.2;
            let end = t.find("</p>").unwrap_or(t.len());
            t[..end].trim_start_matches("<p>").to_string()
        })
        .collect()
}

/// Whether `s` holds a digit, `mark`, digit (a decimal written with `mark`).
fn has_decimal(s: &str, mark: char) -> bool {
    let c: Vec<char> = s.chars().collect();
    c.windows(3)
        .any(|w| w[0].is_ascii_digit() && w[1] == mark && w[2].is_ascii_digit())
}

/// Everything a student reads of a quiz with its numbers: each question's
/// text but its blanks' answers (Moodle's, always with a point) and the
/// instruction's "not 0,5", its general feedback, each 0 % answer's
/// feedback, and the text of its figures (the SVG files embedded).
fn read_by_students(xml: &str) -> Vec<String> {
    let mut out = Vec::new();
    for (_, _, text, feedback) in xml_questions(xml).iter().filter(|q| q.0 == "cloze") {
        let mut t = text
            .replace("(0.5, not 0,5)", "")
            .replace("(0.5, bukan 0,5)", "");
        while let Some((k, ..)) = next_blank(&t) {
            let end = k + t[k..].find('}').unwrap();
            t.replace_range(k..=end, "_");
        }
        out.push(t);
        out.push(feedback.clone());
        for b in cloze_blanks(text) {
            out.extend(b.alts.iter().map(|a| a.feedback.clone()));
        }
    }
    for files in feedback_files(xml) {
        for (_, bytes) in files {
            out.push(String::from_utf8(bytes).unwrap());
        }
    }
    // the text, not the markup (an SVG's points="1,2 3,4"); the Direct3D
    // page's own "(0,0,1)", quoted, is no decimal
    out.iter()
        .map(|s| without_tags(s).replace("(0,0,1)", ""))
        .collect()
}

/// `s` without its tags (`<…>`).
fn without_tags(s: &str) -> String {
    let mut out = String::new();
    let mut inside = false;
    for c in s.chars() {
        match c {
            '<' => inside = true,
            '>' if inside => {
                inside = false;
                out.push(' ');
            }
            c if !inside => out.push(c),
            _ => {}
        }
    }
    out
}

/// One exam, one decimal mark: whatever the language, every number of the
/// statement, the blanks, the answers, the worked solution and the figures
/// is written with the mark of `--decimal`, and a comma quiz separates the
/// blanks of a vector with `;`, as its statement separates components.
#[test]
fn a_quiz_writes_every_number_with_the_mark_it_tells_students_to_type() {
    for lang in ["id", "en"] {
        for (flag, mark, other, pct, sep) in [
            ("point", '.', ',', "0.1 %", "}, {"),
            ("comma", ',', '.', "0,1 %", "}; {"),
        ] {
            let dir = generate(
                &format!("marks-{lang}-{flag}"),
                "moodle",
                &["--lang", lang, "--decimal", flag],
            );
            let xml = std::fs::read_to_string(dir.join("quiz.xml")).unwrap();
            assert_eq!(statements(&xml).len(), 14, "7 problems, 2 variants");
            let read = read_by_students(&xml);
            // every problem of seed 11 has decimals (a near plane, a
            // coefficient, the worked steps), all written the same way
            assert!(read.iter().any(|s| has_decimal(s, mark)));
            for s in &read {
                assert!(
                    !has_decimal(s, other),
                    "--lang {lang} --decimal {flag}: {s}"
                );
            }
            let texts: Vec<String> = xml_questions(&xml).into_iter().map(|q| q.2).collect();
            assert!(texts.iter().any(|t| t.contains(pct)), "--decimal {flag}");
            // a vector's blanks are parted as its components are
            let other_sep = if sep == "}, {" { "}; {" } else { "}, {" };
            assert!(texts.iter().any(|t| t.contains(sep)), "{flag}");
            assert!(texts.iter().all(|t| !t.contains(other_sep)), "{flag}");
        }
    }
}

/// Hard windows rest on tan 20°, 25°, 35° or 40°, with no exact form:
/// bottom = −top is then worked as `bottom ≈ −0.0364`, never `bottom = ≈
/// −0.0364` with an empty exact form between.
#[test]
fn a_hard_window_has_no_empty_exact_form() {
    let out = tmp("hard-window");
    let run = grafika()
        .args(["generate", "--topic", "window", "--difficulty", "hard"])
        .args(["--count", "10", "--variants", "6", "--seed", "2026"])
        .args(["--format", "moodle", "--out"])
        .arg(&out)
        .output()
        .unwrap();
    assert!(run.status.success());
    let xml = std::fs::read_to_string(out.join("quiz.xml")).unwrap();
    let qs: Vec<_> = xml_questions(&xml)
        .into_iter()
        .filter(|q| q.0 == "cloze")
        .collect();
    assert_eq!(qs.len(), 60);
    // some of them have no exact form (their answers are marked ≈)
    assert!(qs.iter().any(|q| q.3.contains("bottom ≈ ")));
    for q in &qs {
        assert!(!q.3.contains("= ≈"), "{}", q.3);
        // a window asked alone is headed by what it asks
        assert!(q.3.contains("<h4>Part 1: viewing window</h4>"), "{}", q.3);
        assert!(!q.3.contains("clipping"), "{}", q.1);
    }
}

/// specular = ks·max(R·V, 0)ⁿ with L = N = (0, 0, 1), so R = (0, 0, 1),
/// and V = (1, 0, 1)/√2: R·V = 1/√2, and with n = 64 and ks = 0.5 the
/// term is 0.5·2⁻³² = 1.164·10⁻¹⁰ in each channel (white specular): below
/// what a student computes by hand (r·S = 0.001 of full intensity), so it
/// is asked as 0 ± 0.001, and 0 and the value itself are both right (the
/// problem asks the term: a lighting problem asks only its colour unless
/// its `[check] keys` say more).
const TINY: &str = "title = 'Tiny'\nstatement = 'A far highlight.'\nask = ['shade']\n\n[shade]\nmodel = 'specular'\nlight = [0, 0, 1]\nnormal = [0, 0, 1]\nview = [1, 0, 1]\ncolor = [1, 1, 1]\nks = 0.5\nshininess = 64\n\n[check]\nkeys = ['shade.specular', 'shade.color']\n";

#[test]
fn a_number_below_what_a_student_computes_by_hand_is_asked_as_zero() {
    let xml = one_problem_file(TINY, Lang::En, Decimal::Point);
    let qs = xml_questions(&xml);
    let text = &qs[1].2;
    let specular = blanks_labelled(&xml, "specular term");
    assert_eq!(specular.len(), 3, "{text}");
    let exact = 0.5 * 2f64.powi(-32);
    for b in &specular {
        assert_eq!(num_tol(&b.alts[0].answer), (0.0, 0.001), "{b:?}");
        let (x, t) = num_tol(&b.alts[0].answer);
        assert!((exact - x).abs() <= t && (0.0 - x).abs() <= t);
        // every wrong answer is apart from it, and none absurd for a
        // channel of colour: at most 1,000 times full intensity
        for a in &b.alts[1..] {
            let (y, u) = num_tol(&a.answer);
            assert!((y - x).abs() > t + u && y.abs() <= 1e3, "{a:?}");
        }
    }
    // the feedback shows no exponent Moodle misreads: 1.164e-10 if any,
    // never 1.164e−10
    assert!(!qs[1].3.contains("e−"), "{}", qs[1].3);
}

/// A zero key's mistaken values are kept within 1,000 times its answer's
/// scale: easy shading exams of seed 2026 had 661,230 and 58,465 for a
/// specular term of 0 (a normal not divided by |N| raised to the nth).
#[test]
fn a_zero_key_gets_no_absurd_mistaken_value() {
    let out = tmp("zero-keys");
    let run = grafika()
        .args(["generate", "--topic", "shade", "--difficulty", "easy"])
        .args(["--count", "7", "--variants", "20", "--seed", "2026"])
        .args(["--format", "moodle", "--out"])
        .arg(&out)
        .output()
        .unwrap();
    assert!(run.status.success());
    let xml = std::fs::read_to_string(out.join("quiz.xml")).unwrap();
    let mut zeros = 0;
    for (_, _, text, _) in xml_questions(&xml).iter().filter(|q| q.0 == "cloze") {
        for p in text.split("<p>").skip(1) {
            let blanks = cloze_blanks(p.split("</p>").next().unwrap());
            let keys: Vec<f64> = (blanks.iter())
                .filter(|b| b.kind == "NUMERICAL")
                .map(|b| num_tol(&b.alts[0].answer).0)
                .collect();
            // every shading answer here is a colour or at most a unit
            // vector's: a scale of at least 1
            let scale = keys.iter().fold(1.0f64, |m, x| m.max(x.abs()));
            for b in blanks.iter().filter(|b| b.kind == "NUMERICAL") {
                let x = num_tol(&b.alts[0].answer).0;
                zeros += (x == 0.0) as usize;
                for a in &b.alts[1..] {
                    let y = num_tol(&a.answer).0;
                    assert!(y.abs() <= 1e3 * x.abs().max(scale), "{y} for {x}");
                }
            }
        }
    }
    assert!(zeros > 0);
}

/// `--split-mb`: files under the size, every question once, in order, each
/// file naming the category before its first question.
#[test]
fn a_quiz_split_under_a_size_holds_the_same_questions() {
    let whole = generate("split-whole", "moodle", &[]);
    let split = generate("split", "moodle", &["--split-mb", "0.1"]);
    let xml = std::fs::read_to_string(whole.join("quiz.xml")).unwrap();
    let mut names: Vec<String> = std::fs::read_dir(&split)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| !n.starts_with('.') && !n.starts_with("blueprint."))
        .collect();
    names.sort();
    assert!(names.len() > 2, "{names:?}");
    let mut questions = Vec::new();
    for (k, n) in names.iter().enumerate() {
        assert_eq!(n, &format!("quiz-{:02}.xml", k + 1));
        let text = std::fs::read_to_string(split.join(n)).unwrap();
        assert!(text.len() <= 100_000, "{n}: {} bytes", text.len());
        let qs = xml_questions(&text);
        assert_eq!(qs[0].0, "category", "{n} names its category first");
        questions.extend(qs.into_iter().filter(|q| q.0 == "cloze"));
    }
    let all: Vec<_> = xml_questions(&xml)
        .into_iter()
        .filter(|q| q.0 == "cloze")
        .collect();
    assert!(questions == all, "the same questions, in order");
    // GIFT too
    let gift = generate("split-gift", "gift", &["--split-mb", "0.2"]);
    let files = std::fs::read_dir(&gift).unwrap().count();
    assert!(files > 2, "{files}");
    // a question that cannot fit, a size that is no size, a format that is
    // no quiz: one-line errors naming the flag, exit status 2
    for (format, mb) in [
        ("moodle", "0.001"),
        ("moodle", "0"),
        ("moodle", "-1"),
        ("md", "2"),
    ] {
        let out = grafika()
            .args(["generate", "--topic", "view", "--format", format])
            .arg(format!("--split-mb={mb}"))
            .arg("--out")
            .arg(tmp(&format!("bad-split-{format}-{mb}")))
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(2), "{format} {mb}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains("split-mb"), "{err}");
        assert_eq!(err.trim().lines().count(), 1, "{err}");
    }
    // a split quiz refuses to write over an earlier quiz file unless
    // --force, which replaces it (and no more of the earlier files stay)
    let run_split = |force: &[&str]| {
        grafika()
            .args(["generate", "--topic"])
            .arg("basis,view,project,window,clip,shade,pipeline")
            .args(["--count", "7", "--variants", "2", "--seed", "11"])
            .args(["--format", "moodle", "--split-mb", "0.5"])
            .args(force)
            .arg("--out")
            .arg(&split)
            .output()
            .unwrap()
    };
    let again = run_split(&[]);
    assert_eq!(again.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&again.stderr).contains("quiz-01.xml"));
    let forced = run_split(&["--force"]);
    assert!(
        forced.status.success(),
        "{}",
        String::from_utf8_lossy(&forced.stderr)
    );
    let left = std::fs::read_dir(&split).unwrap().count();
    assert!(
        left < names.len() + 1,
        "{left} entries: the stale files are gone"
    );
}

/// Marks by hand: the camera example with `"view.n" = 3` and
/// `"view.points.Pref" = 2` (u and v 1 each) is worth 1 + 1 + 3 + 2 = 7.
/// Each answer has 3 blanks; m·L/3 must be whole for m = 1, 1, 3, 2, so
/// L = 3 and the blanks weigh 1 (u, v), 3 (n), 2 (Pref′): each answer's
/// blanks together weigh 3·m, its marks in a total of 21 = 3·7. Without
/// `[marks]`, every blank weighs 1. The statement says "(7 marks)".
#[test]
fn a_blank_weighs_its_share_of_the_answers_marks() {
    let marked = format!("{CAMERA}\n[marks]\n\"view.n\" = 3\n\"view.points.Pref\" = 2\n");
    let qs = one_problem_xml(&marked, Lang::En);
    let weights: Vec<u32> = cloze_blanks(&qs[1].2).iter().map(|b| b.weight).collect();
    assert_eq!(weights, [1, 1, 1, 1, 1, 1, 3, 3, 3, 2, 2, 2]);
    assert!(
        qs[1].2.contains("The camera example. (7 marks)"),
        "{}",
        qs[1].2
    );
    let plain = one_problem_xml(CAMERA, Lang::Id);
    assert!(cloze_blanks(&plain[1].2).iter().all(|b| b.weight == 1));
    assert!(plain[1].2.contains("(4 poin)"));
}
