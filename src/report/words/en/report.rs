use super::En;

impl super::super::report::ReportWords for En {}
