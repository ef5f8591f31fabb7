use super::En;

impl super::super::MsgWords for En {}
