//! [`StepEnergy`]: the energy sums every step kernel returns, which the shared time loop turns
//! into the energy balance and the blow-up guard (module docs of [`crate::integrator`]).

/// Energy sums of one step, at the new level `t^{n+1}`.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct StepEnergy {
    /// `1/2 v^{n+1/2} M v^{n+3/2}`.
    pub kinetic_staggered: f64,
    /// `1/2 v^{n+1} M v^{n+1}`, `v^{n+1} = (v^{n+1/2} + v^{n+3/2})/2`.
    pub kinetic: f64,
    /// `1/2 u^{n+1} K u^{n+1}`.
    pub strain: f64,
}
