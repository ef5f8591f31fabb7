//! INTERIM: replaced by the exact surd type before this lands.
use super::{Precision, Scalar, Shown};
use std::ops::*;

#[derive(Clone, Debug, PartialEq, PartialOrd)]
pub enum Real {
    Approx(f64),
}
impl Real {
    pub fn from_decimal(s: &str) -> Option<Real> {
        s.parse::<f64>().ok().map(Real::Approx)
    }
    pub fn from_f64(x: f64) -> Real {
        Real::Approx(x)
    }
    pub fn to_f64(&self) -> f64 {
        match self {
            Real::Approx(x) => *x,
        }
    }
    pub fn exact_ascii(&self) -> Option<String> {
        None
    }
    pub fn signum(&self) -> i8 {
        let x = self.to_f64();
        if x > 0.0 {
            1
        } else if x < 0.0 {
            -1
        } else {
            0
        }
    }
}
macro_rules! op {
    ($tr:ident, $m:ident, $tra:ident, $ma:ident, $o:tt) => {
        impl $tr for Real { type Output = Real; fn $m(self, o: Real) -> Real { Real::Approx(self.to_f64() $o o.to_f64()) } }
        impl $tra for Real { fn $ma(&mut self, o: Real) { *self = Real::Approx(self.to_f64() $o o.to_f64()) } }
    };
}
op!(Add, add, AddAssign, add_assign, +);
op!(Sub, sub, SubAssign, sub_assign, -);
op!(Mul, mul, MulAssign, mul_assign, *);
op!(Div, div, DivAssign, div_assign, /);
impl Neg for Real {
    type Output = Real;
    fn neg(self) -> Real {
        Real::Approx(-self.to_f64())
    }
}
impl num_traits::Zero for Real {
    fn zero() -> Self {
        Real::Approx(0.0)
    }
    fn is_zero(&self) -> bool {
        self.to_f64() == 0.0
    }
}
impl num_traits::One for Real {
    fn one() -> Self {
        Real::Approx(1.0)
    }
}
impl Scalar for Real {
    const PRECISION: Precision = Precision::Exact;
    fn from_real(x: &Real) -> Self {
        x.clone()
    }
    fn from_f64(x: f64) -> Self {
        Real::Approx(x)
    }
    fn from_i64(x: i64) -> Self {
        Real::Approx(x as f64)
    }
    fn to_f64(&self) -> f64 {
        Real::to_f64(self)
    }
    fn to_real(&self) -> Real {
        self.clone()
    }
    fn sqrt(&self) -> Self {
        Real::Approx(self.to_f64().sqrt())
    }
    fn pi() -> Self {
        Real::Approx(std::f64::consts::PI)
    }
    fn tan_deg(&self) -> Self {
        Real::Approx(self.to_f64().to_radians().tan())
    }
    fn sin_deg(&self) -> Self {
        Real::Approx(self.to_f64().to_radians().sin())
    }
    fn cos_deg(&self) -> Self {
        Real::Approx(self.to_f64().to_radians().cos())
    }
    fn is_finite(&self) -> bool {
        self.to_f64().is_finite()
    }
    fn is_exact(&self) -> bool {
        false
    }
    fn shown(&self) -> Shown {
        Shown {
            value: self.to_f64(),
            exact: None,
            pretty: None,
        }
    }
}
