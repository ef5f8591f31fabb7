//! The one solver's entry points: a typed problem ([`Problem`]: a
//! calculator command's one part, or a problem file's parts) solved part
//! by part through the text's steps — modeling, viewing transformation,
//! projection onto the near plane, window and clipping, viewport — by one
//! exhaustive match over the typed part, each part solved by its module
//! of [`crate::tutor::parts`]. What a part takes from earlier parts is
//! worked once, when first needed (`Earlier`); a problem file's results
//! are nested under each part's key, with its section headers and a
//! comparison with the answers the source printed; a command's are not.

use crate::error::{Error, Result};
use crate::input::eval3;
use crate::input::part::Problem;
use crate::input::problem::ProblemIn;
use crate::msg::ErrMsg;
use crate::num::Scalar;
use crate::stages::trace::Recorder;
use crate::tutor::check::{named_leaves, printed_agrees, settings_for, written};
use crate::tutor::key::Part;
use crate::tutor::parts::{Earlier, Out, Solver};
use crate::tutor::run::{Hooks, Named};
use crate::tutor::solution::{Asked, Compared, Comparison, Given, Report, Results};
use std::borrow::Cow;

/// Solves a typed problem at precision `T`: a calculator command's one
/// part or a problem file's parts.
pub fn solve_problem<T: Scalar>(p: &Problem) -> Result<Report> {
    solve_typed::<T>(p, &Hooks::default())
}

/// Solves a parsed problem file at precision `T`.
pub fn solve<T: Scalar>(p: &ProblemIn) -> Result<Report> {
    solve_with::<T>(p, &Hooks::default())
}

/// Solves a parsed problem file at precision `T`, with stage results
/// altered by `hooks` (the mistake catalog, follow-through).
pub fn solve_with<T: Scalar>(p: &ProblemIn, hooks: &Hooks<T>) -> Result<Report> {
    solve_typed::<T>(&Problem::of_file(p.clone())?, hooks)
}

/// Solves a typed problem at precision `T`, with stage results altered by
/// `hooks`: each part asked, in [`Part::all`]'s order, by one exhaustive
/// match over the typed part (`Solver::part`: a new part stops the
/// build there). The view is worked before the projection reads near,
/// which is read whatever is asked (a near that does not evaluate is
/// refused).
pub fn solve_typed<T: Scalar>(p: &Problem, hooks: &Hooks<T>) -> Result<Report> {
    let points: Vec<Named<T>> = (p.shared.points.iter())
        .map(|(n, field, v)| Ok((n.clone(), eval3(field, v)?)))
        .collect::<Result<_>>()?;
    let mut s = Solver {
        p,
        hooks,
        out: Out {
            sections: p.file.is_some(),
            rec: Recorder::quiet(hooks.quiet),
            result: Results::new(p.file.is_some()),
            parts: Vec::new(),
        },
        earlier: Earlier {
            points,
            based: None,
            viewed: None,
            near: None,
            projected: None,
            window: None,
        },
    };
    for part in Part::all() {
        if part == Part::Project {
            if s.projects() {
                s.viewed()?;
            }
            s.near()?;
        }
        for typed in p.parts.iter().filter(|t| t.part() == part) {
            s.part(typed)?;
        }
    }
    let Out {
        rec, result, parts, ..
    } = s.out;
    match &p.file {
        None => Ok(Report::from_recorder::<T>(
            Asked::Command,
            parts,
            result,
            rec,
        )),
        Some(file) => file_report::<T>(file, (rec, result, parts)),
    }
}

/// A problem file's report: lights without a `[shade]` table are refused
/// whatever is asked, and so is a file that asks nothing it can solve;
/// the printed answers compared with the results.
fn file_report<T: Scalar>(
    p: &ProblemIn,
    (rec, result, parts): (Recorder, Results, Vec<Given>),
) -> Result<Report> {
    if !p.light.is_empty() && p.shade.is_none() {
        return Err(Error::why("shade", ErrMsg::LightsNeedShade));
    }
    if result.parts.is_empty() {
        return Err(Error::why("ask", ErrMsg::NothingToSolve));
    }
    let comparison = compare_printed(p, &result);
    let asked = Asked::File(Box::new(p.clone()));
    let mut report = Report::from_recorder::<T>(asked, parts, result, rec);
    report.comparison = comparison;
    report.source_notes = p.source_notes.clone();
    Ok(report)
}

/// Compares every `[printed]` answer with the computed results, each
/// judged as `check` marks a student's answer, with the problem's
/// settings ([`printed_agrees`]), and shown as written ([`written`]).
fn compare_printed(p: &ProblemIn, result: &Results) -> Option<Comparison> {
    let flat = named_leaves(&p.printed);
    if flat.is_empty() {
        return None;
    }
    let settings = settings_for(p, None, None);
    let rows = flat
        .iter()
        .map(|(name, printed)| {
            let (k, key) = (name.key().ok(), name.to_string());
            let computed = k.as_ref().and_then(|k| result.get(k)).map(Cow::into_owned);
            let judged = k.as_ref().zip(computed.as_ref());
            let erratum = p.errata.iter().find(|e| e.key == key);
            Compared {
                key,
                printed: written(printed),
                agrees: judged.and_then(|(k, c)| printed_agrees(printed, c, k, &settings)),
                computed,
                kind: erratum.and_then(|e| e.kind),
                why: erratum.map(|e| e.why()),
            }
        })
        .collect();
    Some(Comparison {
        source: p.source.clone(),
        rows,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::input::part::{PartIn, ProjectIn, Table};
    use crate::input::problem::PerspectiveIn;
    use crate::msg::Msg;
    use crate::stages::trace::Val;
    use crate::tutor::key::Key;
    use crate::tutor::keys::ordered_keys;

    /// Every shipped problem (problems/*.toml), by file name, solved.
    fn shipped() -> Vec<(String, ProblemIn, Report)> {
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("problems");
        let mut files: Vec<_> = std::fs::read_dir(&dir)
            .expect("problems/ is read")
            .map(|e| e.expect("an entry of problems/").path())
            .filter(|f| f.extension().is_some_and(|x| x == "toml"))
            .collect();
        files.sort();
        let solved = files.into_iter().map(|f| {
            let name = f.display().to_string();
            let p = ProblemIn::read(&f).unwrap_or_else(|e| panic!("{name}: {e}"));
            let r = solve::<f64>(&p).unwrap_or_else(|e| panic!("{name}: {e}"));
            (name, p, r)
        });
        solved.collect()
    }

    /// The answer keys of `part` that practice asks and check follows
    /// through, in the results.
    fn keys_of(part: Part, result: &Results) -> Vec<Key> {
        let of_part = |k: &Key| k.part == Some(part);
        ordered_keys(result).into_iter().filter(of_part).collect()
    }

    /// A new part needs more than the solver's arm the compiler asks for:
    /// the problem file's table it is solved from, and a shipped problem
    /// that asks it. For every part: some shipped problem solves it to
    /// results under its key, with answer keys (`ordered_keys`) for it; and
    /// that problem asking the part alone gives the same results, under
    /// that key only (the part's dependencies on earlier ones are worked
    /// without their results).
    #[test]
    fn every_part_is_solved_by_a_shipped_problem_alone_or_with_others() {
        let shipped = shipped();
        for part in Part::all() {
            let mut solvers = (shipped.iter()).filter(|(_, _, r)| r.result.of(part).is_some());
            let Some((name, p, r)) = solvers.next() else {
                panic!("no problem in problems/ solves `{part}`: add one that asks it");
            };
            let keys = keys_of(part, &r.result);
            assert!(!keys.is_empty(), "{name}: no answer key of `{part}`");
            let mut alone = p.clone();
            alone.ask = Some(vec![part]);
            let a = solve::<f64>(&alone).unwrap_or_else(|e| panic!("{name}, {part} alone: {e}"));
            let mine = |t: &Results| t.of(part).cloned();
            assert_eq!(a.result.parts.len(), 1, "{name}, {part} alone");
            assert_eq!(mine(&a.result), mine(&r.result), "{name}, {part} alone");
            assert_eq!(keys_of(part, &a.result), keys, "{name}, {part} alone");
        }
    }

    /// A source's printed answers are judged as `check` marks a student's:
    /// the same reader (a decimal comma, `√` and `−`, an Indonesian status,
    /// a segment written as text), the same tolerance and rounding. By
    /// hand: fovy 45°, near 0.1, aspect 2: top = 0.1·tan 22.5° =
    /// 0.1(√2 − 1) = 0.0414214, right = 2·top = 0.0828427 = height, width
    /// = 2·right = 2(√2 − 1)/5 = 0.1656854. The clip example's segment is
    /// clipped to (3, 8/3, 11/6)–(1, 4, 3/2) (the hand working in
    /// problems/text-clip.toml).
    #[test]
    fn printed_answers_are_judged_as_a_students_answers_are() {
        let text = "title = 't'\nask = ['window']\n\
            [perspective]\nnear = 0.1\nfovy = 45\naspect = 2\n\
            [printed]\n\
            'window.top' = '0.041'\n\
            'window.right' = '0.0829'\n\
            'window.left' = '-0.082'\n\
            'window.bottom' = '0.0414'\n\
            'window.height' = '0,0828'\n\
            'window.width' = '2(√2 − 1)/5'\n\
            'window.nowhere' = '1'\n";
        let p = ProblemIn::parse(text, "t.toml").unwrap();
        let expected = [
            ("window.top", Some(true)),     // 0.0414 rounded to 3 decimals
            ("window.right", Some(true)),   // 0.07 % off: within 0.1 %
            ("window.left", Some(false)),   // 1 % off; rounded it is −0.083
            ("window.bottom", Some(false)), // the sign
            ("window.height", Some(true)),  // 0.05 % off, a decimal comma
            ("window.width", Some(true)),   // exactly
            ("window.nowhere", None),       // no such result
        ];
        let rows = |r: Report| r.comparison.expect("printed answers").rows;
        let agrees = |rows: Vec<Compared>| -> Vec<(String, Option<bool>)> {
            rows.into_iter().map(|c| (c.key, c.agrees)).collect()
        };
        let want: Vec<(String, Option<bool>)> = (expected.iter())
            .map(|(k, a)| (k.to_string(), *a))
            .collect();
        let exact = rows(solve::<crate::num::Real>(&p).unwrap());
        assert_eq!(agrees(exact), want, "exact");
        assert_eq!(agrees(rows(solve::<f32>(&p).unwrap())), want, "f32");

        let file = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("problems/text-clip.toml");
        let mut p = ProblemIn::read(&file).unwrap();
        p.printed = toml::from_str(
            "'clip.status' = 'di-clip'\n\
             'clip.segment' = '(3; 8/3; 11/6), (1; 4; 3/2)'\n\
             'clip.code0' = '000 010'\n\
             'clip.code1' = '001000'\n",
        )
        .unwrap();
        p.errata.clear();
        let got = agrees(rows(solve::<f64>(&p).unwrap()));
        let want = [Some(true), Some(true), Some(true), Some(false)];
        assert_eq!(
            got.iter().map(|(_, a)| *a).collect::<Vec<_>>(),
            want,
            "{got:?}"
        );
    }

    /// A command's flags as a table (fields unprefixed).
    fn flags<X>(table: X) -> Table<X> {
        Table { prefix: "", table }
    }

    /// The numbers of a result (a number, or a vector's or a matrix's).
    fn nums(v: Option<Cow<'_, Val>>) -> Vec<f64> {
        match v.as_deref() {
            Some(Val::Num(x)) => vec![x.value],
            Some(Val::List(xs)) => xs
                .iter()
                .flat_map(|x| nums(Some(Cow::Borrowed(x))))
                .collect(),
            other => panic!("not numbers: {other:?}"),
        }
    }

    /// A calculator command and the same part of a problem file run through
    /// the one solver and give the same results and inputs. By hand: eye
    /// (0, 0, 5) looking at the origin, up y: n = (Pe − Pr)/|Pe − Pr| =
    /// (0, 0, 1), u = Vup × n/|…| = (1, 0, 0), v = n × u = (0, 1, 0); the
    /// view matrix translates by −Pe·(u, v, n) = (0, 0, −5); P = (1, 2, 3)
    /// is (1, 2, 3 − 5) = (1, 2, −2) in eye coordinates. Projected onto
    /// z = d = −near = −1: (x·d/z, y·d/z, d) = (0.5, 1, −1). fovy 90°,
    /// aspect 2, near 1: top = near·tan 45° = 1, right = aspect·top = 2.
    #[test]
    fn a_command_and_a_file_give_the_same_part_by_the_one_solver() {
        use crate::input::part::{ProjectionIn, Shared};
        use crate::input::problem::CameraIn;
        use crate::input::{num, vec3};
        use crate::num::Real;
        let text = "title = 't'\nask = ['view', 'project', 'window']\n\
            [camera]\neye = '(0, 0, 5)'\nlook = [0, 0, 0]\nup = [0, 1, 0]\n\
            [points]\nP = [1, 2, 3]\n\
            [perspective]\nnear = 1\nfovy = 90\naspect = 2\n";
        let file = solve::<Real>(&ProblemIn::parse(text, "t.toml").unwrap()).unwrap();
        let of_file = |part| file.result.of(part).cloned();
        let of_command = |r: Results| r.parts.into_iter().next();
        let camera = CameraIn {
            eye: vec3("eye", "0,0,5").unwrap(),
            look: vec3("look", "0,0,0").unwrap(),
            up: vec3("up", "0,1,0").unwrap(),
        };
        let view = Shared {
            points: vec![(
                "P".into(),
                "point P".into(),
                vec3("point P", "1,2,3").unwrap(),
            )],
            camera: Some(flags(camera)),
            ..Shared::default()
        };
        let c = solve_problem::<Real>(&Problem::command(vec![PartIn::View], view)).unwrap();
        assert_eq!(nums(c.result.lookup("u")), [1.0, 0.0, 0.0]);
        assert_eq!(nums(c.result.lookup("v")), [0.0, 1.0, 0.0]);
        assert_eq!(nums(c.result.lookup("n")), [0.0, 0.0, 1.0]);
        let m = [1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, -5.0];
        assert_eq!(nums(c.result.lookup("matrix"))[..12], m);
        assert_eq!(nums(c.result.lookup("points.P")), [1.0, 2.0, -2.0]);
        assert_eq!(of_file(Part::View), of_command(c.result));
        assert_eq!(c.parts, file.parts[..1]);

        let d = ProjectionIn::Plane(("d".into(), num("d", "-1").unwrap()));
        let project = Shared {
            points: vec![(
                "P".into(),
                "point P".into(),
                vec3("point P", "1,2,-2").unwrap(),
            )],
            ..Shared::default()
        };
        let part = PartIn::Project(ProjectIn::Given(d));
        let c = solve_problem::<Real>(&Problem::command(vec![part], project)).unwrap();
        assert_eq!(nums(c.result.lookup("points.P")), [0.5, 1.0, -1.0]);
        assert_eq!(of_file(Part::Project), of_command(c.result));

        let table = PerspectiveIn {
            near: Some(num("near", "1").unwrap()),
            far: None,
            fovy: Some(crate::input::angle("fovy", "90").unwrap()),
            aspect: Some(num("aspect", "2").unwrap()),
            viewport: None,
            d: None,
        };
        let window = Shared {
            perspective: Some(flags(table)),
            on_window: Some(vec![]),
            ..Shared::default()
        };
        let c = solve_problem::<Real>(&Problem::command(vec![PartIn::Window], window)).unwrap();
        let edges = ["top", "bottom", "left", "right", "height", "width"];
        let got: Vec<f64> = edges
            .iter()
            .flat_map(|e| nums(c.result.lookup(e)))
            .collect();
        assert_eq!(got, [1.0, -1.0, -2.0, 2.0, 2.0, 4.0]);
        assert_eq!(of_file(Part::Window), of_command(c.result));
    }

    /// `ask` names the parts by their one spelling, in the file's order;
    /// any other name is refused in the field `ask`, listing every part.
    #[test]
    fn ask_reads_every_part_by_its_name_and_refuses_others() {
        let names: Vec<&str> = Part::all().into_iter().map(Part::name).collect();
        let listed = names.iter().rev().map(|n| format!("'{n}'"));
        let text = format!(
            "title = 't'\nask = [{}]\n",
            listed.collect::<Vec<_>>().join(", ")
        );
        let p = ProblemIn::parse(&text, "t.toml").expect("every part's name is read");
        let mut all = Part::all();
        all.reverse();
        assert_eq!(p.ask, Some(all));
        for bad in ["View", "camera", ""] {
            let text = format!("title = 't'\nask = ['view', '{bad}']\n");
            let e = ProblemIn::parse(&text, "t.toml").expect_err(bad);
            let why = ErrMsg::UnknownPart(bad.to_string(), names.join(", "));
            assert_eq!((e.field, e.message), ("ask".to_string(), Msg::Err(why)));
        }
    }
}
