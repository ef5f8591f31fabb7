//! Refusals whose reason comes from a crate (the TOML reader, serde, the
//! OBJ reader) or from the size of an exact result, in both languages:
//! the English as the crate words it, the Indonesian from the reason's key.

mod common;

use common::{grafika, refusal, scratch};
use std::path::Path;

/// `grafika --lang LANG ARGS` in `dir`: exit status 2 and one line on
/// stderr, which is returned.
fn refused(dir: &Path, lang: &str, args: &[&str]) -> String {
    let mut cmd = grafika();
    cmd.current_dir(dir).args(["--lang", lang]);
    refusal(cmd, args).trim_end().to_string()
}

#[test]
fn an_exact_result_beyond_f64_has_its_own_reason() {
    // xp = x·d/z = 1e300 · (−1e300) / (−1e−300) = 1e900, beyond f64's
    // largest (about 1.8e308): exact, but with no decimal to print; in f64
    // the image itself is too large.
    let d = common::root();
    let args = [
        "project",
        "--d",
        "-1e300",
        "--point",
        "A=1e300,1e300,-1e-300",
    ];
    assert_eq!(
        refused(&d, "en", &args),
        "error: points.A: the result is exact but beyond the range of f64 (about 1.8e308), \
         so it has no decimal or JSON number to give (scale the inputs)"
    );
    assert_eq!(
        refused(&d, "id", &args),
        "kesalahan: points.A: hasilnya eksak tetapi di luar jangkauan f64 (sekitar 1,8e308), \
         jadi tidak ada desimal atau bilangan JSON untuknya (skalakan masukan)"
    );
    let f64 = [&["--precision", "f64"][..], &args].concat();
    assert!(refused(&d, "en", &f64).ends_with("the image of A is too large for f64 precision (the point is too near the plane of the centre of projection)"));
}

#[test]
fn the_toml_readers_reasons_in_both_languages() {
    let d = scratch("refusals-toml");
    let camera = "look = [0, 0, 0]\nup = [0, 1, 0]\n";
    // two values on one line: the reader wants the line to end there
    std::fs::write(d.join("a.toml"), "[camera]\neye = 1 look = 2\n").expect("writes");
    let (en, id) = (
        refused(&d, "en", &["solve", "a.toml"]),
        refused(&d, "id", &["solve", "a.toml"]),
    );
    assert!(en.starts_with("error: eye: a.toml:2:"), "{en}");
    assert!(
        en.ends_with(": unexpected key or value, expected newline, `#`"),
        "{en}"
    );
    assert!(
        id.ends_with(": sintaks TOML tidak sah: kunci atau nilai yang tidak diharapkan, seharusnya akhir baris, `#`"),
        "{id}"
    );
    // a point with two components: serde's words, said in Indonesian
    std::fs::write(
        d.join("b.toml"),
        format!("[camera]\neye = [1, 2]\n{camera}"),
    )
    .expect("writes");
    assert_eq!(
        refused(&d, "en", &["solve", "b.toml"]),
        "error: eye: b.toml:2:7: invalid length 2, expected an array of length 3"
    );
    assert_eq!(
        refused(&d, "id", &["solve", "b.toml"]),
        "kesalahan: eye: b.toml:2:7: panjang salah: 2, seharusnya array dengan panjang 3"
    );
    // a description the reader's number decoder gives (`1.` has no fraction)
    std::fs::write(d.join("c.toml"), format!("[camera]\neye = 1.\n{camera}")).expect("writes");
    let id = refused(&d, "id", &["solve", "c.toml"]);
    assert!(
        id.ends_with(": sintaks TOML tidak sah: bagian pecahan tidak sah, seharusnya angka"),
        "{id}"
    );
}

/// A number field of the wrong kind or out of what it takes: serde names
/// the Rust type (`u32`, `i64`); a student reads what the field takes.
#[test]
fn a_number_field_says_what_it_takes_not_a_rust_type() {
    let d = scratch("refusals-serde-types");
    let sphere = "[[object]]\ntype = \"sphere\"\n";
    let cases = [
        (
            "w.toml",
            format!("[image]\nwidth = -5\nheight = 10\n{sphere}n = 8\nr = 1\n"),
        ),
        (
            "h.toml",
            format!("[image]\nwidth = 10\nheight = 1.5\n{sphere}n = 8\nr = 1\n"),
        ),
        ("n.toml", format!("{sphere}n = \"x\"\nr = 1\n")),
    ];
    for (file, text) in &cases {
        std::fs::write(d.join(file), text).expect("writes");
    }
    let said = |lang, file| refused(&d, lang, &["render", file, "-o", "o.png"]);
    assert_eq!(
        said("en", "w.toml"),
        "error: width: w.toml:2:9: invalid value: integer `-5`, \
         expected a whole number from 0 to 4294967295"
    );
    assert_eq!(
        said("id", "w.toml"),
        "kesalahan: width: w.toml:2:9: nilai tidak sah: bilangan bulat `-5`, \
         seharusnya bilangan bulat dari 0 sampai 4294967295"
    );
    assert_eq!(
        said("id", "h.toml"),
        "kesalahan: height: h.toml:3:10: jenis nilai salah: bilangan desimal `1.5`, \
         seharusnya bilangan bulat dari 0 sampai 4294967295"
    );
    assert_eq!(
        said("en", "n.toml"),
        "error: n: n.toml:3:5: invalid type: string \"x\", expected a whole number"
    );
    assert!(!d.join("o.png").exists(), "nothing is drawn");
}

#[test]
fn the_obj_readers_reasons_in_both_languages() {
    let d = scratch("refusals-obj");
    let scene = "[[object]]\ntype = \"obj\"\npath = \"m.obj\"\n";
    std::fs::write(d.join("s.toml"), scene).expect("writes");
    // a vertex with w = 0 (x/w, y/w, z/w would divide by zero)
    std::fs::write(d.join("m.obj"), "v 0 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").expect("writes");
    let args = ["render", "s.toml", "-o", "s.png"];
    let (en, id) = (refused(&d, "en", &args), refused(&d, "id", &args));
    assert!(
        en.ends_with("m.obj is not a valid OBJ file: scaling (w) by zero"),
        "{en}"
    );
    assert!(
        id.ends_with("m.obj bukan berkas OBJ yang sah: koordinat w sebuah verteks bernilai nol"),
        "{id}"
    );
    assert!(!d.join("s.png").exists());
}

#[test]
fn a_path_through_a_file_is_said_in_the_readers_language() {
    // `solve notes.txt/view.toml`: the system's reason is ENOTDIR, which
    // each language words itself (before, the system's English was quoted
    // under --lang id too).
    let d = scratch("path-through-a-file");
    std::fs::write(d.join("notes.txt"), "not a folder").expect("writes");
    let en = refused(&d, "en", &["solve", "notes.txt/view.toml"]);
    assert!(en.ends_with("a folder on its path is a file"), "{en}");
    let id = refused(&d, "id", &["solve", "notes.txt/view.toml"]);
    assert!(
        id.ends_with("sebuah folder pada jalurnya adalah berkas"),
        "{id}"
    );
}
