use super::Id;

impl super::super::MsgWords for Id {}
