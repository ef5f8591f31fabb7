//! A part's results as its fields: what each part's struct of results
//! ([`super::view::ViewResult`], …) says of itself, beneath the list of
//! them ([`super::result`]).

use crate::stages::trace::Val;
use crate::tutor::key::Field;

/// A part's results as its fields.
pub trait Fields {
    /// Its fields in the order the results show them (docs/spec.md §3).
    const ORDER: &'static [Field];
    /// The value of field `f`, if the part holds it: an exhaustive match
    /// over the part's fields.
    fn field(&self, f: Field) -> Option<&Val>;
    /// [`Fields::field`], to change it.
    fn field_mut(&mut self, f: Field) -> Option<&mut Val>;
}

/// The fields a part holds, in order, with their values.
pub fn entries<P: Fields>(p: &P) -> Vec<(Field, &Val)> {
    (P::ORDER.iter())
        .filter_map(|f| Some((*f, p.field(*f)?)))
        .collect()
}
