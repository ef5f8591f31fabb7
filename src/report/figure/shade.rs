//! The lighting figure of `shade` and `solve`'s shade part: the surface
//! patch at the point, the unit vectors N, L, V, R (and H for Blinn) from
//! the steps and results, and the angles α (L to N) and β (R to V) marked,
//! all under the cabinet projection.

use super::builders::{arrow3, num_val, panel, result, say, vec_of, Part};
use super::{cabinet, label_at, labelled, short, Figure, Item, Pen, Place};
use crate::msg::{FigWord, FigureMsg, Panel};
use crate::report::Style;
use crate::stages::trace::Val;

/// The length every unit vector is drawn with (page units).
pub const LENGTH: f64 = 1.5;

/// The first step result with this name that is a 3-vector (N, L, V).
fn step_vector<'a>(p: &'a Part, name: &str) -> Option<&'a Val> {
    p.steps
        .iter()
        .flat_map(|s| &s.result)
        .find(|(k, v)| k == name && vec_of(v).is_some())
        .map(|(_, v)| v)
}

fn unit(a: [f64; 3]) -> [f64; 3] {
    let n = a.iter().map(|c| c * c).sum::<f64>().sqrt().max(1e-300);
    [a[0] / n, a[1] / n, a[2] / n]
}

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// The square patch of the surface, perpendicular to N, centred at the
/// point.
fn patch(n: [f64; 3]) -> Vec<[f64; 2]> {
    let k = (0..3)
        .min_by(|i, j| n[*i].abs().total_cmp(&n[*j].abs()))
        .unwrap_or(0);
    let mut a = [0.0; 3];
    a[k] = 1.0;
    let t1 = unit(cross(n, a));
    let t2 = cross(n, t1);
    let s = 0.6 * LENGTH;
    [(1.0, 1.0), (-1.0, 1.0), (-1.0, -1.0), (1.0, -1.0)]
        .iter()
        .map(|(x, y)| {
            cabinet([
                s * (x * t1[0] + y * t2[0]),
                s * (x * t1[1] + y * t2[1]),
                s * (x * t1[2] + y * t2[2]),
            ])
        })
        .collect()
}

/// The arc from direction a to direction b at radius r, and its label
/// `name: cos name = … (name = …°)`; nothing when the angle is under 1°.
fn angle(a: [f64; 3], b: [f64; 3], name: &str, cos: Option<&Val>, st: &Style) -> Vec<Item> {
    let (a, b) = (unit(a), unit(b));
    let c = (a[0] * b[0] + a[1] * b[1] + a[2] * b[2]).clamp(-1.0, 1.0);
    let Some(cos) = cos else { return vec![] };
    if c.acos().to_degrees() < 1.0 || c < -0.999 {
        return vec![];
    }
    let r = 0.45 * LENGTH;
    let at = |t: f64| {
        let m = unit([
            (1.0 - t) * a[0] + t * b[0],
            (1.0 - t) * a[1] + t * b[1],
            (1.0 - t) * a[2] + t * b[2],
        ]);
        cabinet([r * m[0], r * m[1], r * m[2]])
    };
    let pts: Vec<[f64; 2]> = (0..=16).map(|i| at(i as f64 / 16.0)).collect();
    let deg = match cos {
        Val::Num(s) => s.value.clamp(-1.0, 1.0).acos().to_degrees(),
        _ => c.acos().to_degrees(),
    };
    let mid = at(0.5);
    let text = format!(
        "{name}: cos {name} = {} ({name} = {}°)",
        short(st, cos),
        st.val_inline(&num_val((deg * 100.0).round() / 100.0))
    );
    vec![
        Item::Path {
            pts,
            pen: Pen::Other,
        },
        label_at(mid, text, Place::beyond(mid)),
    ]
}

/// How far a vector that coincides with one drawn before is moved
/// sideways on the page (page units; a twentieth of [`LENGTH`]).
pub const BESIDE: f64 = 0.075;

/// A vector `names[1]` along the unit direction `d` that coincides with
/// `names[0]` drawn before (and with k − 1 others since): its arrow moved
/// sideways by k·[`BESIDE`] (perpendicular on the page), the earlier
/// label rewritten `L = V = (…)`, and a note saying they coincide.
fn beside(items: &mut Vec<Item>, names: [&str; 2], d: [f64; 3], pen: Pen, st: &Style) {
    let tip = cabinet([LENGTH * d[0], LENGTH * d[1], LENGTH * d[2]]);
    let len = tip[0].hypot(tip[1]).max(1e-300);
    let head = format!("{}, ", names[0]);
    let k = 1 + items
        .iter()
        .filter_map(|it| match it {
            Item::Note { text } if text.starts_with(&head) => Some(text.matches(", ").count()),
            _ => None,
        })
        .sum::<usize>();
    let s = k as f64 * BESIDE;
    let off = [-tip[1] / len * s, tip[0] / len * s];
    items.push(Item::Arrow {
        a: off,
        b: [tip[0] + off[0], tip[1] + off[1]],
        pen,
    });
    let (eq, approx) = (format!("{} = ", names[0]), format!("{} ≈ ", names[0]));
    let word = say(st, FigureMsg::Word(FigWord::Coincide));
    let mut noted = false;
    for it in items.iter_mut() {
        match it {
            // `N = L = (…)` → `N = L = V = (…)`: the name goes before the
            // value (which starts at its bracket, after `= ` or `≈ `).
            Item::Label { text, .. } if text.starts_with(&eq) || text.starts_with(&approx) => {
                if let Some(at) = text.find('(') {
                    let (names_part, value) = text.split_at(at);
                    for sign in ["= ", "≈ "] {
                        if let Some(before) = names_part.strip_suffix(sign) {
                            *text = format!("{before}= {} {sign}{value}", names[1]);
                            break;
                        }
                    }
                }
            }
            Item::Note { text } if text.starts_with(&head) => {
                *text = text.replacen(':', &format!(", {}:", names[1]), 1);
                noted = true;
            }
            _ => {}
        }
    }
    if !noted {
        items.push(Item::Note {
            text: format!("{}, {}: {word}", names[0], names[1]),
        });
    }
}

/// The lighting panel. With several lights, the first light's L is
/// labelled L and the others L2, L3, …; R, H and the angles are drawn for
/// one light only (the results name them for one light).
pub fn figure(p: &Part, st: &Style) -> Option<Figure> {
    let nv = step_vector(p, "N")?;
    let n = vec_of(nv)?;
    let mut items = vec![Item::Polygon {
        pts: patch(unit(n)),
        pen: Pen::Frame,
    }];
    let surface = say(st, FigureMsg::Word(FigWord::Surface));
    items.push(label_at(patch(unit(n))[2], surface, Place::BelowLeft));
    let mut drawn: Vec<(&str, [f64; 3])> = vec![];
    let vectors: [(&str, Option<&Val>, Pen); 5] = [
        ("N", Some(nv), Pen::Frame),
        ("L", step_vector(p, "L"), Pen::Given),
        ("V", step_vector(p, "V"), Pen::Vector),
        ("R", result(p.res, "R"), Pen::Other),
        ("H", result(p.res, "H"), Pen::Tried),
    ];
    for (name, v, pen) in vectors {
        let Some(d) = v.and_then(vec_of) else {
            continue;
        };
        let text = labelled(st, name, v?);
        let same = drawn.iter().find(|(_, e)| unit(*e) == unit(d)).map(|x| x.0);
        match same {
            Some(first) => beside(&mut items, [first, name], unit(d), pen, st),
            None => items.extend(arrow3([0.0; 3], unit(d), LENGTH, pen, text)),
        }
        drawn.push((name, d));
    }
    // With several lights, each light's L after the first (L2, L3, …).
    let ls: Vec<&Val> = p
        .steps
        .iter()
        .flat_map(|s| &s.result)
        .filter(|(k, v)| k == "L" && vec_of(v).is_some())
        .map(|(_, v)| v)
        .collect();
    for (i, v) in ls.iter().enumerate().skip(1) {
        let text = labelled(st, &format!("L{}", i + 1), v);
        let d = vec_of(v).unwrap_or_default();
        items.extend(arrow3([0.0; 3], unit(d), LENGTH, Pen::Given, text));
    }
    let get = |k: &str| drawn.iter().find(|(n, _)| *n == k).map(|(_, d)| *d);
    if let (Some(l), Some(n)) = (get("L"), get("N")) {
        items.extend(angle(l, n, "α", result(p.res, "cos_alpha"), st));
    }
    if let (Some(r), Some(v)) = (get("R"), get("V")) {
        items.extend(angle(r, v, "β", result(p.res, "cos_beta"), st));
    }
    items.push(Item::Dot {
        at: [0.0, 0.0],
        pen: Pen::Frame,
    });
    Some(panel(st, Panel::Shade, items))
}
