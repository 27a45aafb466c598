//! The choices of Park's scheme: the blend `theta`, the element acceleration variant and local
//! time stepping (module docs of [`crate::kernels::park`]).

/// The element acceleration of step 1.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum ParkVariant {
    /// `a~_e = M_e^-1 (f_e - K_e u~_e)`: the seed's literal formula.
    #[default]
    Free,
    /// `a~_e = a_e^n + M_e^-1 (df_e - K_e (u~_e - u_e^n))`: interface forces frozen at `t^n`;
    /// keeps a static state static on heterogeneous meshes.
    Incremental,
}

impl ParkVariant {
    /// Name in outputs.
    pub fn name(self) -> &'static str {
        match self {
            ParkVariant::Free => "free",
            ParkVariant::Incremental => "incremental",
        }
    }
}

/// Parameters of Park's scheme.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ParkOptions {
    /// Blend of the pulled-back and CD predictions, `0 <= theta <= 1` (default 1/2).
    pub theta: f64,
    /// Element acceleration variant (default `free`).
    pub variant: ParkVariant,
    /// Each element steps with its own `dt_e` (default); otherwise all use the stiffest one's.
    pub local_stepping: bool,
}

impl Default for ParkOptions {
    fn default() -> Self {
        Self {
            theta: 0.5,
            variant: ParkVariant::Free,
            local_stepping: true,
        }
    }
}

impl ParkOptions {
    /// Short name, e.g. `park-lts-free`.
    pub fn label(&self) -> String {
        format!(
            "park-{}-{}",
            if self.local_stepping { "lts" } else { "global" },
            self.variant.name()
        )
    }
}
