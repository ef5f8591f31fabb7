//! The tutor: a whole problem solved through the text's steps ([`solve`]),
//! the result keys shared with the calculator ([`keys`]), answers marked
//! ([`check`]) against the catalog of known mistakes ([`diagnose`]),
//! exams drawn from a seed ([`generate`]), and one rendered pixel worked
//! through the renderer's own stages ([`pixel`]).

pub mod check;
pub mod diagnose;
pub mod follow;
pub mod generate;
pub mod keys;
pub mod pixel;
pub mod practice;
pub mod solve;
