use super::En;

impl super::super::errors::ErrorWords for En {}
