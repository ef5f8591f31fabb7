use super::Id;

impl super::super::errors::ErrorWords for Id {}
