//! Exact references for heterogeneous bars: the linearly graded bar (methods.md §4) and
//! piecewise-constant layered bars, both free-fixed under a Heaviside end traction.
//!
//! ```text
//!   sigma(0,t) = sigma0 H(t)                                   u(L,t) = 0
//!        <==|==========================================|//
//!           | E(x) = E1 + (E2 - E1) x/L, rho, A          |//  fixed end
//!           x = 0 (E1)                            x = L (E2)
//! ```
//!
//! # Problem and notation
//!
//! `rho u_tt = (E(x) u_x)_x` on `0 <= x <= L`, `sigma = E u_x`, `v = u_t`, at rest at t = 0,
//! `sigma(0, t) = sigma0 H(t)` with `H(0) = 1`, `u(L, t) = 0`. The gradient is
//! `b = (E2 - E1)/L`, the wave speed `c(x) = sqrt(E/rho)` and the impedance per unit area
//! `z(x) = sqrt(rho E(x)) = rho c` (the bar impedance is `Z = A z`; only ratios `Z/Z1 = z/z1`
//! enter the fields, A only forces and energies). Stresses and velocities are per unit area.
//!
//! **Enters:** the bar's data (lengths, moduli, density, area, load amplitude) and evaluation
//! points `(x, t)`. **Leaves:** stresses, velocities, element averages, fronts, passes and
//! energies, or a [`ReferenceError`](crate::ReferenceError) for invalid data. It must not know any
//! solver (this crate is the independent yardstick), meshes of a solver, or files.
//!
//! Files, lowest first: `bar` ([`GradedBar`], closed forms and the jump law), `bessel` and
//! `series` (normalised Bessel functions, front expansions in `1/s`), `de_hoog` (Laplace
//! inversion), `laplace` (route (a)), `characteristics` (route (b)), `cost` (the work of an evaluation, known up front), `field` (the default
//! evaluation, choosing the route), `averages` (element averages), `layer` and `layered`
//! ([`LayeredBar`]).
//!
//! Sources: courant's methods.md §1-4 (conventions, the travel time, the jump law and the
//! Bessel substitution; it wins over the seed paper); de Hoog, Knight & Stokes, *An improved
//! method for numerical inversion of Laplace transforms*, SIAM J. Sci. Stat. Comput. 3 (1982)
//! 357-366; Abramowitz & Stegun 9.7.1-9.7.2 (Hankel expansions of I and K); Graff, *Wave
//! Motion in Elastic Solids* (1975), ch. 2 (transmission and reflection at an interface,
//! d'Alembert).

mod averages;
mod bar;
mod bessel;
mod characteristics;
mod cost;
mod de_hoog;
mod field;
mod laplace;
mod layer;
mod layered;
mod series;

pub use bar::{Direction, FieldPoint, GradedBar, Pass};
pub use characteristics::{
    CHARACTERISTIC_CELLS, CHARACTERISTIC_LEVELS, CHARACTERISTIC_LEVELS_MAX,
    CHARACTERISTIC_TRANSITS_MAX,
};
pub use cost::ROUTE_A_WORK;
pub use field::LAPLACE_DIFFICULTY_LIMIT;
pub use laplace::DE_HOOG_TERMS;
pub use layer::{Layer, reflection_coefficient, transmission_coefficient};
pub(crate) use layered::TimeKey;
pub use layered::{DEFAULT_MAX_WAVES, LayeredBar, LayeredField};
pub use series::FRONT_SERIES_ORDER;
