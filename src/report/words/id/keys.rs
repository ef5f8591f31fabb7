use super::Id;

impl super::super::keys::KeyWords for Id {}
