//! The words of an answer's keys (`view.points.A`, …).

/// The words of an answer's keys (`view.points.A`, …).
pub trait KeyWords {}
