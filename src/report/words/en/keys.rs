use super::En;

impl super::super::keys::KeyWords for En {}
