//! The words of the report writers' own headings, columns and notes (class report, practice, check, Moodle, GIFT, …).

/// The words of the report writers' own headings, columns and notes (class report, practice, check, Moodle, GIFT, …).
pub trait ReportWords {}
