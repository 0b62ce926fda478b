//! Fixed-width lanes of `f64` for the fusion's lockstep kernels: several landmarks computed at
//! once, one per lane, each lane doing exactly the operations the scalar code does in its order
//! (so it rounds alike). Plain arrays and loops that the compiler turns into vector instructions —
//! 4 wide where a kernel is compiled with AVX2 (the triangulation's lanes), 2 wide on the
//! baseline x86-64 target.

// The lane helpers must be inlined into a kernel compiled with AVX2 to be compiled with AVX2 at all
// (a function not inlined is compiled for the baseline target): `inline(always)` is the point here.
#![allow(clippy::inline_always)]

use nalgebra::Matrix3;

/// One `f64` per lane.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Lanes<const N: usize>(pub(crate) [f64; N]);

/// One flag per lane: all bits set or none (so a select is three bit operations).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct LaneMask<const N: usize>(pub(crate) [u64; N]);

macro_rules! lane_op {
    ($trait:ident, $f:ident, $op:tt) => {
        impl<const N: usize> std::ops::$trait for Lanes<N> {
            type Output = Self;
            #[inline(always)]
            fn $f(self, o: Self) -> Self {
                let mut r = [0.0; N];
                for l in 0..N {
                    r[l] = self.0[l] $op o.0[l];
                }
                Lanes(r)
            }
        }
    };
}
lane_op!(Add, add, +);
lane_op!(Sub, sub, -);
lane_op!(Mul, mul, *);
lane_op!(Div, div, /);

impl<const N: usize> std::ops::Neg for Lanes<N> {
    type Output = Self;
    #[inline(always)]
    fn neg(self) -> Self {
        Lanes(self.0.map(|x| -x))
    }
}

impl<const N: usize> Lanes<N> {
    #[inline(always)]
    pub(crate) fn splat(x: f64) -> Lanes<N> {
        Lanes([x; N])
    }
    #[inline(always)]
    pub(crate) fn sqrt(self) -> Lanes<N> {
        Lanes(self.0.map(f64::sqrt))
    }
    #[inline(always)]
    pub(crate) fn cmp(self, o: Lanes<N>, f: impl Fn(f64, f64) -> bool) -> LaneMask<N> {
        let mut r = [0u64; N];
        for l in 0..N {
            r[l] = if f(self.0[l], o.0[l]) { u64::MAX } else { 0 };
        }
        LaneMask(r)
    }
    #[inline(always)]
    pub(crate) fn gt(self, o: Lanes<N>) -> LaneMask<N> {
        self.cmp(o, |a, b| a > b)
    }
    #[inline(always)]
    pub(crate) fn le(self, o: Lanes<N>) -> LaneMask<N> {
        self.cmp(o, |a, b| a <= b)
    }
    #[inline(always)]
    pub(crate) fn lt(self, o: Lanes<N>) -> LaneMask<N> {
        self.cmp(o, |a, b| a < b)
    }
    #[inline(always)]
    pub(crate) fn finite(self) -> LaneMask<N> {
        // |x| < ∞ is false for ±∞ and NaN
        self.cmp(Lanes::splat(f64::INFINITY), |a, b| a.abs() < b)
    }
}

impl<const N: usize> LaneMask<N> {
    pub(crate) const NONE: Self = LaneMask([0; N]);
    #[inline(always)]
    pub(crate) fn from_fn(f: impl Fn(usize) -> bool) -> LaneMask<N> {
        let mut r = [0u64; N];
        for (l, x) in r.iter_mut().enumerate() {
            *x = if f(l) { u64::MAX } else { 0 };
        }
        LaneMask(r)
    }
    #[inline(always)]
    pub(crate) fn get(self, l: usize) -> bool {
        self.0[l] != 0
    }
    #[inline(always)]
    pub(crate) fn set(&mut self, l: usize, v: bool) {
        self.0[l] = if v { u64::MAX } else { 0 };
    }
    #[inline(always)]
    pub(crate) fn and(self, o: LaneMask<N>) -> LaneMask<N> {
        let mut r = [0u64; N];
        for l in 0..N {
            r[l] = self.0[l] & o.0[l];
        }
        LaneMask(r)
    }
    #[inline(always)]
    pub(crate) fn or(self, o: LaneMask<N>) -> LaneMask<N> {
        let mut r = [0u64; N];
        for l in 0..N {
            r[l] = self.0[l] | o.0[l];
        }
        LaneMask(r)
    }
    #[inline(always)]
    pub(crate) fn not(self) -> LaneMask<N> {
        LaneMask(self.0.map(|x| !x))
    }
    #[inline(always)]
    pub(crate) fn any(self) -> bool {
        self.0.iter().fold(0, |a, &x| a | x) != 0
    }
    /// `a` where set, `b` elsewhere.
    #[inline(always)]
    pub(crate) fn select(self, a: Lanes<N>, b: Lanes<N>) -> Lanes<N> {
        let mut r = [0.0; N];
        for l in 0..N {
            r[l] = f64::from_bits((a.0[l].to_bits() & self.0[l]) | (b.0[l].to_bits() & !self.0[l]));
        }
        Lanes(r)
    }
}

/// The entries of a [`LaneSym3`], by name.
pub(crate) struct S3Parts<const N: usize> {
    pub(crate) xx: Lanes<N>,
    pub(crate) xy: Lanes<N>,
    pub(crate) xz: Lanes<N>,
    pub(crate) yy: Lanes<N>,
    pub(crate) yz: Lanes<N>,
    pub(crate) zz: Lanes<N>,
}

/// A symmetric 3×3 matrix per lane (as `triangulation::Sym3`).
#[derive(Debug, Clone, Copy)]
pub(crate) struct LaneSym3<const N: usize> {
    xx: Lanes<N>,
    xy: Lanes<N>,
    xz: Lanes<N>,
    yy: Lanes<N>,
    yz: Lanes<N>,
    zz: Lanes<N>,
}

impl<const N: usize> LaneSym3<N> {
    #[inline(always)]
    pub(crate) fn zero() -> Self {
        let z = Lanes::splat(0.0);
        LaneSym3 {
            xx: z,
            xy: z,
            xz: z,
            yy: z,
            yz: z,
            zz: z,
        }
    }
    /// `Sym3::add_outer`.
    #[inline(always)]
    pub(crate) fn add_outer(&mut self, v: [Lanes<N>; 3], w: Lanes<N>) {
        let (a, b, c) = (v[0] * w, v[1] * w, v[2] * w);
        self.xx = self.xx + a * v[0];
        self.xy = self.xy + a * v[1];
        self.xz = self.xz + a * v[2];
        self.yy = self.yy + b * v[1];
        self.yz = self.yz + b * v[2];
        self.zz = self.zz + c * v[2];
    }
    /// `Sym3::add_outer` with unit weight (`x·1 = x` exactly).
    #[inline(always)]
    pub(crate) fn add_outer_unit(&mut self, v: [Lanes<N>; 3]) {
        self.xx = self.xx + v[0] * v[0];
        self.xy = self.xy + v[0] * v[1];
        self.xz = self.xz + v[0] * v[2];
        self.yy = self.yy + v[1] * v[1];
        self.yz = self.yz + v[1] * v[2];
        self.zz = self.zz + v[2] * v[2];
    }
    #[inline(always)]
    pub(crate) fn select(m: LaneMask<N>, a: &Self, b: &Self) -> Self {
        LaneSym3 {
            xx: m.select(a.xx, b.xx),
            xy: m.select(a.xy, b.xy),
            xz: m.select(a.xz, b.xz),
            yy: m.select(a.yy, b.yy),
            yz: m.select(a.yz, b.yz),
            zz: m.select(a.zz, b.zz),
        }
    }
    /// The six distinct entries.
    #[inline(always)]
    pub(crate) fn parts(&self) -> S3Parts<N> {
        S3Parts {
            xx: self.xx,
            xy: self.xy,
            xz: self.xz,
            yy: self.yy,
            yz: self.yz,
            zz: self.zz,
        }
    }
    pub(crate) fn lane(&self, l: usize) -> Matrix3<f64> {
        let (a, b, c) = (self.xx.0[l], self.xy.0[l], self.xz.0[l]);
        let (d, e, f) = (self.yy.0[l], self.yz.0[l], self.zz.0[l]);
        Matrix3::new(a, b, c, b, d, e, c, e, f)
    }
    /// `triangulation::solve_normal3`: the solution, and where it exists.
    #[inline(always)]
    pub(crate) fn solve(&self, b: [Lanes<N>; 3]) -> ([Lanes<N>; 3], LaneMask<N>) {
        let (a, bb, c, d, e, f) = (self.xx, self.xy, self.xz, self.yy, self.yz, self.zz);
        let c00 = d * f - e * e;
        let c01 = c * e - bb * f;
        let c02 = bb * e - c * d;
        let c11 = a * f - c * c;
        let c12 = bb * c - a * e;
        let c22 = a * d - bb * bb;
        let det = a * c00 + bb * c01 + c * c02;
        let scale = a * d * f;
        let ok = det
            .finite()
            .and(scale.finite())
            .and(scale.gt(Lanes::splat(0.0)))
            .and(det.gt(Lanes::splat(1e-12) * scale));
        let (i00, i01, i02) = (c00 / det, c01 / det, c02 / det);
        let (i11, i12, i22) = (c11 / det, c12 / det, c22 / det);
        (
            [
                i00 * b[0] + i01 * b[1] + i02 * b[2],
                i01 * b[0] + i11 * b[1] + i12 * b[2],
                i02 * b[0] + i12 * b[1] + i22 * b[2],
            ],
            ok,
        )
    }
}
