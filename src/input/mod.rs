//! What users type, read and validated: flag values ([`values`]), problem
//! files ([`problem`]), scene files ([`scene`]), lights files and the
//! `[shade]` set-up ([`lights`]) and meshes ([`mesh`]). Every error names the
//! field (and, for files, the line and column).

pub mod fields;
pub mod lights;
pub mod mesh;
pub mod problem;
pub mod scene;
pub mod values;

pub use values::*;
