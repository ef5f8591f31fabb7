//! The tutor: a whole problem solved through the text's steps ([`solve`]),
//! the result keys shared with the calculator ([`keys`]), answers marked
//! ([`check`]) against the catalog of known mistakes ([`diagnose`]), a
//! class's answers and the lecturer's statistics of them ([`class`]),
//! exams drawn from a seed ([`generate`]), and one rendered pixel worked
//! through the renderer's own stages ([`pixel`]).

pub mod check;
pub mod class;
pub mod diagnose;
pub mod follow;
pub mod generate;
pub mod given;
pub mod key;
pub mod keys;
pub mod parts;
pub mod pixel;
pub mod practice;
pub mod run;
pub mod solution;
pub mod solve;
pub mod topic;
