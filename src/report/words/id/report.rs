use super::Id;

impl super::super::report::ReportWords for Id {}
