use super::Id;

impl super::super::names::NameWords for Id {}
