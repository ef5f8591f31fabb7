//! Polygon meshes for the renderer: the text's primitives (cone, sphere,
//! cylinder, box, plane grid with a height formula), Wavefront OBJ models,
//! face and vertex normals, triangulation and the closed-mesh test that
//! decides whether back faces may be culled.
//!
//! Faces are kept as the polygons the text builds (quads on a sphere, one
//! n-gon for a cone's base) because per-face colours cycle by *polygon*
//! index (the text's `i%2`, `i%3`, `i%5`); triangles remember their polygon.

use crate::error::{Error, Result};
use crate::input::NotOpened;
use crate::msg::{ErrMsg, IoWhy, NumErr, ObjWhy};
use std::collections::HashMap;
use std::f64::consts::PI;
use std::path::Path;

/// A polygon mesh in model coordinates.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Mesh {
    /// Vertex positions.
    pub positions: Vec<[f32; 3]>,
    /// Per-vertex normals given by the model (an OBJ file's `vn`), if any.
    pub normals: Option<Vec<[f32; 3]>>,
    /// Polygon faces: indices into `positions`, counter-clockwise seen from
    /// outside (so that (v1 − v0) × (v2 − v0) points outward).
    pub faces: Vec<Vec<u32>>,
}

/// The triangles of a mesh, each with the polygon it came from.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Triangles {
    /// Vertex indices, counter-clockwise seen from outside.
    pub tris: Vec<[u32; 3]>,
    /// The polygon face each triangle belongs to.
    pub face: Vec<u32>,
}

fn p3(x: f64, y: f64, z: f64) -> [f32; 3] {
    [x as f32, y as f32, z as f32]
}

/// The text's cone `createCone(n, r, h)`: base circle of radius r in the
/// plane y = 0, apex at (0, h, 0). Faces 0..n are the sides (triangles
/// `base[i]`, `base[i+1]`, apex), face n is the base (one n-gon with its own
/// vertices, so the rim stays a crease under smooth shading).
pub fn cone(n: u32, r: f64, h: f64) -> Mesh {
    let mut m = Mesh::default();
    let ring = |k: u32| {
        let a = 2.0 * PI * k as f64 / n as f64;
        p3(r * a.cos(), 0.0, -r * a.sin())
    };
    for k in 0..n {
        m.positions.push(ring(k));
    }
    let apex = n;
    m.positions.push(p3(0.0, h, 0.0));
    for k in 0..n {
        m.faces.push(vec![k, (k + 1) % n, apex]);
    }
    let base0 = m.positions.len() as u32;
    for k in 0..n {
        m.positions.push(ring(k));
    }
    // Seen from below (outside the base), the ring runs the other way.
    m.faces.push((0..n).rev().map(|k| base0 + k).collect());
    m
}

/// A cylinder of radius r from y = 0 to y = h with n sides: faces 0..n the
/// side quads, then the bottom and the top n-gons (own vertices: creases).
pub fn cylinder(n: u32, r: f64, h: f64) -> Mesh {
    let mut m = Mesh::default();
    let ring = |k: u32, y: f64| {
        let a = 2.0 * PI * k as f64 / n as f64;
        p3(r * a.cos(), y, -r * a.sin())
    };
    for y in [0.0, h] {
        for k in 0..n {
            m.positions.push(ring(k, y));
        }
    }
    for k in 0..n {
        let k1 = (k + 1) % n;
        m.faces.push(vec![k, k1, n + k1, n + k]);
    }
    for (y, flip) in [(0.0, true), (h, false)] {
        let b = m.positions.len() as u32;
        for k in 0..n {
            m.positions.push(ring(k, y));
        }
        let mut f: Vec<u32> = (0..n).map(|k| b + k).collect();
        if flip {
            f.reverse();
        }
        m.faces.push(f);
    }
    m
}

/// The text's sphere `createSphere(n, r)` generalised to `slices` around the
/// y axis and `stacks` from the north pole (0, r, 0) to the south pole:
/// x = r·sin θ·cos φ, y = r·cos θ, z = −r·sin θ·sin φ with θ = π·i/stacks,
/// φ = 2π·j/slices. Face index = i·slices + j (stack i, slice j), as in the
/// text, so per-face colours cycle the same way; the faces touching a pole
/// are triangles (one pole vertex each, no degenerate quads).
pub fn sphere(slices: u32, stacks: u32, r: f64) -> Mesh {
    let mut m = Mesh::default();
    m.positions.push(p3(0.0, r, 0.0));
    for i in 1..stacks {
        let th = PI * i as f64 / stacks as f64;
        for j in 0..slices {
            let ph = 2.0 * PI * j as f64 / slices as f64;
            m.positions.push(p3(
                r * th.sin() * ph.cos(),
                r * th.cos(),
                -r * th.sin() * ph.sin(),
            ));
        }
    }
    let south = m.positions.len() as u32;
    m.positions.push(p3(0.0, -r, 0.0));
    // Ring i (1..stacks) vertex j.
    let at = |i: u32, j: u32| 1 + (i - 1) * slices + j % slices;
    for i in 0..stacks {
        for j in 0..slices {
            let f = if i == 0 {
                vec![0, at(1, j), at(1, j + 1)]
            } else if i == stacks - 1 {
                vec![at(i, j), south, at(i, j + 1)]
            } else {
                vec![at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)]
            };
            m.faces.push(f);
        }
    }
    m
}

/// An axis-aligned box of size w × h × d centred at the origin; faces
/// +x, −x, +y, −y, +z, −z, each with its own four vertices.
pub fn cuboid(w: f64, h: f64, d: f64) -> Mesh {
    let (a, b, c) = (w / 2.0, h / 2.0, d / 2.0);
    let mut m = Mesh::default();
    // For each face: normal axis and sign; corners counter-clockwise from outside.
    let quads: [[[f64; 3]; 4]; 6] = [
        [[a, -b, c], [a, -b, -c], [a, b, -c], [a, b, c]],
        [[-a, -b, -c], [-a, -b, c], [-a, b, c], [-a, b, -c]],
        [[-a, b, c], [a, b, c], [a, b, -c], [-a, b, -c]],
        [[-a, -b, -c], [a, -b, -c], [a, -b, c], [-a, -b, c]],
        [[-a, -b, c], [a, -b, c], [a, b, c], [-a, b, c]],
        [[a, -b, -c], [-a, -b, -c], [-a, b, -c], [a, b, -c]],
    ];
    for q in quads {
        let b0 = m.positions.len() as u32;
        for v in q {
            m.positions.push(p3(v[0], v[1], v[2]));
        }
        m.faces.push(vec![b0, b0 + 1, b0 + 2, b0 + 3]);
    }
    m
}

/// The text's plane `createPlane(nx, nz, dx, dz)`: nx × nz vertices at
/// (i·dx, y, k·dz), vertex index i·nz + k (the text's loop order), y given by
/// `height(i, k)`; (nx − 1)(nz − 1) quads, face index i·(nz − 1) + k, facing +y.
pub fn plane(nx: u32, nz: u32, dx: f64, dz: f64, height: impl Fn(f64, f64) -> f64) -> Mesh {
    let mut m = Mesh::default();
    for i in 0..nx {
        for k in 0..nz {
            let y = height(i as f64, k as f64);
            m.positions.push(p3(i as f64 * dx, y, k as f64 * dz));
        }
    }
    plane_faces(&mut m, nx, nz);
    m
}

/// [`plane`] whose every vertex must be finite (as f32): `None` at the
/// first that is not, without evaluating the rest (a 1410² grid whose last
/// row is infinite was evaluated whole, 23 s, before its error).
pub fn finite_plane(
    nx: u32,
    nz: u32,
    dx: f64,
    dz: f64,
    height: impl Fn(f64, f64) -> f64,
) -> Option<Mesh> {
    let mut m = Mesh::default();
    for i in 0..nx {
        for k in 0..nz {
            let p = p3(i as f64 * dx, height(i as f64, k as f64), k as f64 * dz);
            if !p.iter().all(|v| v.is_finite()) {
                return None;
            }
            m.positions.push(p);
        }
    }
    plane_faces(&mut m, nx, nz);
    Some(m)
}

/// The (nx − 1)(nz − 1) quads of a plane's grid, face i·(nz − 1) + k.
fn plane_faces(m: &mut Mesh, nx: u32, nz: u32) {
    let at = |i: u32, k: u32| i * nz + k;
    for i in 0..nx - 1 {
        for k in 0..nz - 1 {
            m.faces
                .push(vec![at(i, k), at(i, k + 1), at(i + 1, k + 1), at(i + 1, k)]);
        }
    }
}

/// The OBJ reader's reason as a key (one case per `tobj::LoadError`).
fn obj_why(e: tobj::LoadError) -> ObjWhy {
    use tobj::LoadError as L;
    match e {
        L::OpenFileFailed => ObjWhy::OpenFileFailed,
        L::ReadError => ObjWhy::ReadError,
        L::UnrecognizedCharacter => ObjWhy::UnrecognizedCharacter,
        L::PositionParseError => ObjWhy::PositionParse,
        L::ScalingByZeroError => ObjWhy::ScalingByZero,
        L::ColorParseError => ObjWhy::ColorParse,
        L::NormalParseError => ObjWhy::NormalParse,
        L::TexcoordParseError => ObjWhy::TexcoordParse,
        L::FaceParseError => ObjWhy::FaceParse,
        L::MaterialParseError => ObjWhy::MaterialParse,
        L::InvalidObjectName => ObjWhy::InvalidObjectName,
        L::InvalidPolygon => ObjWhy::InvalidPolygon,
        L::FaceVertexOutOfBounds => ObjWhy::FaceVertexOutOfBounds,
        L::FaceTexCoordOutOfBounds => ObjWhy::FaceTexCoordOutOfBounds,
        L::FaceNormalOutOfBounds => ObjWhy::FaceNormalOutOfBounds,
        L::FaceColorOutOfBounds => ObjWhy::FaceColorOutOfBounds,
        L::InvalidLoadOptionConfig => ObjWhy::LoadOptions,
        L::GenericFailure => ObjWhy::Generic,
    }
}

/// Loads a Wavefront OBJ file (all its objects, one mesh; normals when every
/// vertex has one). `field` names the scene entry in errors.
pub fn load_obj(path: &Path, field: &str) -> Result<Mesh> {
    let opts = tobj::LoadOptions {
        single_index: true,
        triangulate: false,
        ignore_points: true,
        ignore_lines: true,
    };
    let shown = path.display().to_string();
    let unreadable =
        |e: std::io::Error| Error::why(field, ErrMsg::ObjUnreadable(shown.clone(), IoWhy::of(&e)));
    // A regular file only: an OBJ path naming a FIFO would wait forever.
    let mut file = crate::input::open_regular(path).map_err(|e| match e {
        NotOpened::Io(e) => unreadable(e),
        NotOpened::NotRegular(k) => Error::why(field, ErrMsg::InputNotRegular(shown.clone(), k)),
    })?;
    let mut text = Vec::new();
    std::io::Read::read_to_end(&mut file, &mut text).map_err(unreadable)?;
    let (models, _) = tobj::load_obj_buf(&mut std::io::Cursor::new(text), &opts, |_| {
        Err(tobj::LoadError::OpenFileFailed)
    })
    .map_err(|e| Error::why(field, ErrMsg::ObjInvalid(shown.clone(), obj_why(e))))?;
    let mut m = Mesh::default();
    let mut normals = Vec::new();
    let mut all_normals = true;
    for model in &models {
        let t = &model.mesh;
        let base = m.positions.len() as u32;
        for p in t.positions.chunks_exact(3) {
            m.positions.push([p[0], p[1], p[2]]);
        }
        if t.normals.len() == t.positions.len() {
            normals.extend(t.normals.chunks_exact(3).map(|n| [n[0], n[1], n[2]]));
        } else {
            all_normals = false;
        }
        let mut start = 0usize;
        let arities: Vec<u32> = if t.face_arities.is_empty() {
            vec![3; t.indices.len() / 3]
        } else {
            t.face_arities.clone()
        };
        for a in arities {
            let a = a as usize;
            let f: Vec<u32> = t.indices[start..start + a]
                .iter()
                .map(|i| base + i)
                .collect();
            start += a;
            if f.len() >= 3 {
                m.faces.push(f);
            }
        }
    }
    if m.faces.is_empty() {
        return Err(Error::why(field, ErrMsg::ObjNoFaces(shown)));
    }
    if m.positions.iter().flatten().any(|x| !x.is_finite()) {
        return Err(Error::why(field, ErrMsg::ObjNotFinite(shown)));
    }
    if all_normals && !normals.is_empty() {
        m.normals = Some(normals);
    }
    Ok(m)
}

fn sub(a: [f32; 3], b: [f32; 3]) -> [f32; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn cross(a: [f32; 3], b: [f32; 3]) -> [f32; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// v/|v|, or v itself when it is zero.
pub fn unit(v: [f32; 3]) -> [f32; 3] {
    let l = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    if l > 0.0 {
        [v[0] / l, v[1] / l, v[2] / l]
    } else {
        v
    }
}

impl Mesh {
    /// The (unnormalised) normal of polygon `f` by Newell's method:
    /// N = Σ (Pᵢ − P₀) × (Pᵢ₊₁ − P₀), which for a triangle is the text's
    /// (v1 − v0) × (v2 − v0) and for a non-planar quad the average plane.
    pub fn face_normal(&self, f: usize) -> [f32; 3] {
        let face = &self.faces[f];
        let p0 = self.positions[face[0] as usize];
        let mut n = [0.0f32; 3];
        for w in face[1..].windows(2) {
            let c = cross(
                sub(self.positions[w[0] as usize], p0),
                sub(self.positions[w[1] as usize], p0),
            );
            n = [n[0] + c[0], n[1] + c[1], n[2] + c[2]];
        }
        n
    }

    /// The axis-aligned bounding box of the positions, [lo, hi]:
    /// lo = min over vertices of each coordinate, hi = max (±∞ for no
    /// vertices). Serial, in vertex order: f32::min/max may pick either of
    /// ±0, so the order is fixed.
    pub fn bounds(&self) -> [[f32; 3]; 2] {
        let mut lo = [f32::INFINITY; 3];
        let mut hi = [f32::NEG_INFINITY; 3];
        for p in &self.positions {
            for k in 0..3 {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
        [lo, hi]
    }

    /// Vertex normals: the normalised average of the unit normals of the
    /// faces around each vertex (or the model's own normals when it has them).
    pub fn vertex_normals(&self) -> Vec<[f32; 3]> {
        if let Some(n) = &self.normals {
            return n.iter().map(|&v| unit(v)).collect();
        }
        let mut acc = vec![[0.0f32; 3]; self.positions.len()];
        for (f, face) in self.faces.iter().enumerate() {
            let n = unit(self.face_normal(f));
            for &v in face {
                let a = &mut acc[v as usize];
                *a = [a[0] + n[0], a[1] + n[1], a[2] + n[2]];
            }
        }
        acc.into_iter().map(unit).collect()
    }

    /// Fan triangulation of every polygon (convex polygons, as the
    /// primitives and OBJ files give).
    pub fn triangles(&self) -> Triangles {
        let mut t = Triangles::default();
        for (f, face) in self.faces.iter().enumerate() {
            for w in face[1..].windows(2) {
                t.tris.push([face[0], w[0], w[1]]);
                t.face.push(f as u32);
            }
        }
        t
    }

    /// Whether the surface is closed: after welding vertices at the same
    /// position, every edge is shared by exactly two faces that run it in
    /// opposite directions. Only then can no back face ever be seen, so
    /// only then are back faces culled.
    pub fn is_closed(&self) -> bool {
        let mut id: HashMap<[u32; 3], u32> = HashMap::new();
        let weld: Vec<u32> = self
            .positions
            .iter()
            .map(|p| {
                let key = p.map(|x| (x + 0.0).to_bits());
                let next = id.len() as u32;
                *id.entry(key).or_insert(next)
            })
            .collect();
        let mut edges: HashMap<(u32, u32), i32> = HashMap::new();
        for face in &self.faces {
            for k in 0..face.len() {
                let a = weld[face[k] as usize];
                let b = weld[face[(k + 1) % face.len()] as usize];
                if a == b {
                    continue;
                }
                let (key, dir) = if a < b { ((a, b), 1) } else { ((b, a), -1) };
                // Count uses (high bits) and the direction balance (low bits).
                *edges.entry(key).or_insert(0) += 1000 + dir;
            }
        }
        !edges.is_empty() && edges.values().all(|&v| v == 2000)
    }

    /// Checks that every face index names a vertex.
    pub fn validate(&self, field: &str) -> Result<()> {
        let n = self.positions.len() as u32;
        if self.faces.iter().flatten().any(|&i| i >= n) {
            return Err(Error::why(field, ErrMsg::FaceVertex));
        }
        Ok(())
    }
}

/// A height formula in the grid indices x and z: numbers, x, z, pi, the
/// operators `+ - * / ^`, parentheses and exp, sqrt, sin, cos, abs (the
/// text's landscape is `100*exp(-(x-6)^2/40 - (z-6)^2/40)`).
#[derive(Clone, Debug, PartialEq)]
pub enum Height {
    /// A number.
    Num(f64),
    /// The grid index along x.
    X,
    /// The grid index along z.
    Z,
    /// −a.
    Neg(Box<Height>),
    /// a op b.
    Bin(char, Box<Height>, Box<Height>),
    /// f(a).
    Call(String, Box<Height>),
}

impl Height {
    /// Parses a formula; the error names the column.
    pub fn parse(s: &str) -> std::result::Result<Height, NumErr> {
        let c: Vec<char> = s.chars().filter(|c| !c.is_whitespace()).collect();
        let mut p = HParser {
            c: &c,
            i: 0,
            depth: 0,
            ops: 0,
        };
        let e = p.sum()?;
        if p.i < c.len() {
            return Err(NumErr::Unexpected(c[p.i], p.i + 1));
        }
        Ok(e)
    }

    /// How many nodes the formula has (operations and operands): the work
    /// of one evaluation.
    pub fn size(&self) -> usize {
        match self {
            Height::Num(_) | Height::X | Height::Z => 1,
            Height::Neg(a) | Height::Call(_, a) => 1 + a.size(),
            Height::Bin(_, a, b) => 1 + a.size() + b.size(),
        }
    }

    /// The value at (x, z).
    pub fn eval(&self, x: f64, z: f64) -> f64 {
        match self {
            Height::Num(v) => *v,
            Height::X => x,
            Height::Z => z,
            Height::Neg(a) => -a.eval(x, z),
            Height::Bin(op, a, b) => {
                let (a, b) = (a.eval(x, z), b.eval(x, z));
                match op {
                    '+' => a + b,
                    '-' => a - b,
                    '*' => a * b,
                    '/' => a / b,
                    _ => a.powf(b),
                }
            }
            Height::Call(f, a) => {
                let a = a.eval(x, z);
                match f.as_str() {
                    "exp" => a.exp(),
                    "sqrt" => a.sqrt(),
                    "sin" => a.sin(),
                    "cos" => a.cos(),
                    _ => a.abs(),
                }
            }
        }
    }
}

struct HParser<'a> {
    c: &'a [char],
    i: usize,
    /// How deep the parser is in parentheses, signs and powers.
    depth: usize,
    /// How many operators it has read.
    ops: usize,
}

impl HParser<'_> {
    fn peek(&self) -> Option<char> {
        self.c.get(self.i).copied()
    }
    /// Counts one more operator, or refuses a formula with more than
    /// [`MAX_OPERATIONS`](crate::num::expr::MAX_OPERATIONS) of them (a tree
    /// that long would overflow the stack when it is evaluated or dropped).
    fn count(&mut self) -> std::result::Result<(), NumErr> {
        self.ops += 1;
        if self.ops > crate::num::expr::MAX_OPERATIONS {
            return Err(NumErr::FormulaOps(
                crate::num::expr::MAX_OPERATIONS,
                self.i + 1,
            ));
        }
        Ok(())
    }
    fn unary(&mut self) -> std::result::Result<Height, NumErr> {
        self.depth += 1;
        if self.depth > crate::num::expr::MAX_DEPTH {
            return Err(NumErr::FormulaDeep(crate::num::expr::MAX_DEPTH, self.i + 1));
        }
        let e = self.unary_inner();
        self.depth -= 1;
        e
    }
    fn sum(&mut self) -> std::result::Result<Height, NumErr> {
        let mut a = self.product()?;
        while let Some(op @ ('+' | '-' | '−')) = self.peek() {
            self.count()?;
            self.i += 1;
            let b = self.product()?;
            let op = if op == '+' { '+' } else { '-' };
            a = Height::Bin(op, Box::new(a), Box::new(b));
        }
        Ok(a)
    }
    fn product(&mut self) -> std::result::Result<Height, NumErr> {
        let mut a = self.unary()?;
        while let Some(op @ ('*' | '/' | '·')) = self.peek() {
            self.count()?;
            self.i += 1;
            let b = self.unary()?;
            let op = if op == '/' { '/' } else { '*' };
            a = Height::Bin(op, Box::new(a), Box::new(b));
        }
        Ok(a)
    }
    fn unary_inner(&mut self) -> std::result::Result<Height, NumErr> {
        if let Some('-' | '−') = self.peek() {
            self.count()?;
            self.i += 1;
            return Ok(Height::Neg(Box::new(self.unary()?)));
        }
        let base = self.atom()?;
        if self.peek() == Some('^') {
            self.count()?;
            self.i += 1;
            let e = self.unary()?;
            return Ok(Height::Bin('^', Box::new(base), Box::new(e)));
        }
        Ok(base)
    }
    fn atom(&mut self) -> std::result::Result<Height, NumErr> {
        let start = self.i;
        match self.peek() {
            Some('(') => {
                self.i += 1;
                let e = self.sum()?;
                if self.peek() != Some(')') {
                    return Err(NumErr::Expected(
                        crate::msg::Want::Close,
                        self.i + 1,
                        self.peek(),
                    ));
                }
                self.i += 1;
                Ok(e)
            }
            Some(c) if c.is_ascii_digit() || c == '.' => {
                while let Some(c) = self.peek() {
                    let exp_sign = matches!(c, '+' | '-')
                        && matches!(self.c.get(self.i.wrapping_sub(1)), Some('e' | 'E'));
                    if c.is_ascii_digit() || c == '.' || c == 'e' || c == 'E' || exp_sign {
                        self.i += 1;
                    } else {
                        break;
                    }
                }
                let s: String = self.c[start..self.i].iter().collect();
                s.parse()
                    .map(Height::Num)
                    .map_err(|_| NumErr::NotANumber(s))
            }
            Some(c) if c.is_ascii_alphabetic() => {
                while self.peek().is_some_and(|c| c.is_ascii_alphanumeric()) {
                    self.i += 1;
                }
                let name: String = self.c[start..self.i].iter().collect();
                match name.as_str() {
                    "x" => Ok(Height::X),
                    "z" => Ok(Height::Z),
                    "pi" => Ok(Height::Num(PI)),
                    "exp" | "sqrt" | "sin" | "cos" | "abs" => {
                        if self.peek() != Some('(') {
                            return Err(NumErr::OpenAfter(name));
                        }
                        let a = self.atom()?;
                        Ok(Height::Call(name, Box::new(a)))
                    }
                    _ => Err(NumErr::UnknownName(name)),
                }
            }
            Some(c) => Err(NumErr::Unexpected(c, self.i + 1)),
            None => Err(NumErr::EndsEarly),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_height_formula_nested_10000_deep_is_an_error_not_a_stack_overflow() {
        let deep = format!("{}x{}", "(".repeat(10_000), ")".repeat(10_000));
        let e = Height::parse(&deep).unwrap_err();
        assert!(matches!(e, NumErr::FormulaDeep(100, _)), "{e:?}");
        let signs = format!("{}x", "-".repeat(10_000));
        assert!(matches!(
            Height::parse(&signs),
            Err(NumErr::FormulaDeep(..))
        ));
        let chain = vec!["x"; 10_000].join("+");
        assert!(matches!(Height::parse(&chain), Err(NumErr::FormulaOps(..))));
        // Within the limits, as for flags: 100 levels and 500 operations.
        let ok = format!("{}x{}", "(".repeat(99), ")".repeat(99));
        assert_eq!(Height::parse(&ok).unwrap().eval(2.0, 0.0), 2.0);
        assert!(Height::parse(&vec!["x"; 500].join("+")).is_ok());
    }

    /// Σ over faces of N·(centroid): positive when every normal points out
    /// of a mesh around the origin.
    fn outward(m: &Mesh, centre: [f32; 3]) -> bool {
        (0..m.faces.len()).all(|f| {
            let n = m.face_normal(f);
            let face = &m.faces[f];
            let mut c = [0.0f32; 3];
            for &v in face {
                let p = m.positions[v as usize];
                c = [c[0] + p[0], c[1] + p[1], c[2] + p[2]];
            }
            let k = face.len() as f32;
            let d = [
                c[0] / k - centre[0],
                c[1] / k - centre[1],
                c[2] / k - centre[2],
            ];
            n[0] * d[0] + n[1] * d[1] + n[2] * d[2] > 0.0
        })
    }

    #[test]
    fn primitives_are_closed_and_face_outward() {
        let s = sphere(21, 21, 100.0);
        assert_eq!(s.faces.len(), 21 * 21); // the text's face count n·n
        assert!(s.is_closed() && outward(&s, [0.0; 3]));
        let c = cone(20, 90.0, 150.0);
        assert_eq!(c.faces.len(), 21);
        // The centroid of a cone of height h lies at h/4 above the base.
        assert!(c.is_closed() && outward(&c, [0.0, 37.5, 0.0]));
        let y = cylinder(12, 1.0, 2.0);
        assert!(y.is_closed() && outward(&y, [0.0, 1.0, 0.0]));
        let b = cuboid(1.0, 2.0, 3.0);
        assert!(b.is_closed() && outward(&b, [0.0; 3]));
    }

    #[test]
    fn bench_sphere_has_llvmpipes_triangle_count() {
        // 2·256·(128 − 1) = 65,024 non-degenerate triangles.
        assert_eq!(sphere(256, 128, 1.0).triangles().tris.len(), 65_024);
    }

    #[test]
    fn a_plane_is_open_and_faces_up() {
        let p = plane(3, 3, 1.0, 1.0, |_, _| 0.0);
        assert_eq!(p.faces.len(), 4);
        assert!(!p.is_closed());
        let n = unit(p.face_normal(0));
        assert_eq!(n, [0.0, 1.0, 0.0]);
        // A box with one face removed has a hole.
        let mut b = cuboid(1.0, 1.0, 1.0);
        b.faces.pop();
        assert!(!b.is_closed());
    }

    #[test]
    fn bounds_of_a_sphere_are_its_poles_and_rim() {
        // A sphere of radius 2 at the origin reaches ±2 on each axis (its
        // poles and equator), and every vertex lies within the box.
        let s = sphere(32, 16, 2.0);
        let [lo, hi] = s.bounds();
        for k in 0..3 {
            assert!(
                (lo[k] + 2.0).abs() < 1e-5 && (hi[k] - 2.0).abs() < 1e-5,
                "{lo:?} {hi:?}"
            );
        }
        for p in &s.positions {
            assert!((0..3).all(|k| lo[k] <= p[k] && p[k] <= hi[k]), "{p:?}");
        }
    }

    #[test]
    fn vertex_normals_of_a_sphere_point_outward() {
        // On a sphere at the origin the average of the faces around a vertex
        // is close to the radial direction P/|P|.
        let s = sphere(32, 32, 2.0);
        for (p, n) in s.positions.iter().zip(s.vertex_normals()) {
            let r = unit(*p);
            let d = r[0] * n[0] + r[1] * n[1] + r[2] * n[2];
            assert!(d > 0.99, "{p:?} {n:?}");
        }
    }

    #[test]
    fn height_formula_of_the_landscape() {
        let h = Height::parse("100*exp(-(x-6)^2/40 - (z-6)^2/40)").unwrap();
        assert_eq!(h.eval(6.0, 6.0), 100.0); // the peak: exp(0)
                                             // At (8, 6): 100·e^(−4/40) = 100·e^(−0.1).
        assert!((h.eval(8.0, 6.0) - 100.0 * (-0.1f64).exp()).abs() < 1e-12);
        assert!(Height::parse("y+1").is_err());
        assert!(Height::parse("exp(").is_err());
    }
}
