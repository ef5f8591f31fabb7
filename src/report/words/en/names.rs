use super::En;

impl super::super::names::NameWords for En {}
