//! Exact profiles evaluated once for all cases of a scene.

use super::exact::ExactOnMesh;
use crate::scene::reference::Reference;
use courant_solver::Mesh;
use rayon::prelude::*;
use std::sync::Arc;

/// A reference, the index of a mesh and a time: what an exact profile is a function of.
type ProfileKey = (Reference, usize, f64);

/// Exact element averages and the extreme of the field.
type ExactProfile = (Vec<f64>, f64);

/// Exact profiles (element averages and extreme) evaluated once for all cases of a scene: the
/// cases share their reference, so a Courant or scheme sweep needs each exact profile once. A
/// profile is keyed by value: the reference's parameters, the mesh's node coordinates and the
/// time, bit for bit. The cache is filled before any comparison, every distinct profile
/// evaluated in parallel, and only read afterwards; each value is a pure function of its key (the
/// references use no threads), so results are bit-identical whatever the thread count and
/// whether or not a value came from the cache.
#[derive(Default)]
pub struct ProfileCache {
    /// The distinct meshes (each kept once, shared with the records: never copied).
    meshes: Vec<Arc<Mesh>>,
    /// `(reference, index into meshes, time)` and the exact profile.
    entries: Vec<(ProfileKey, ExactProfile)>,
}

/// Same node coordinates, bit for bit.
fn same_mesh(a: &Mesh, b: &Mesh) -> bool {
    let (a, b) = (a.nodes(), b.nodes());
    a.len() == b.len() && a.iter().zip(b).all(|(x, y)| x.to_bits() == y.to_bits())
}

impl ProfileCache {
    /// Evaluate every distinct exact profile that `runs` (each a reference, the mesh of its
    /// record and the times of its profiles) needs, in parallel, in the order of first
    /// appearance.
    pub fn for_runs(runs: &[(&Reference, &Arc<Mesh>, Vec<f64>)]) -> Self {
        let mut meshes: Vec<Arc<Mesh>> = Vec::new();
        let mut keys: Vec<ProfileKey> = Vec::new();
        for (reference, mesh, times) in runs {
            let m = match meshes.iter().position(|m| same_mesh(m, mesh)) {
                Some(m) => m,
                None => {
                    meshes.push(Arc::clone(mesh));
                    meshes.len() - 1
                }
            };
            for &time in times {
                let seen = keys
                    .iter()
                    .any(|(r, k, t)| *k == m && t.to_bits() == time.to_bits() && r == *reference);
                if !seen {
                    keys.push(((*reference).clone(), m, time));
                }
            }
        }
        let values: Vec<ExactProfile> = keys
            .par_iter()
            .map(|(r, m, t)| evaluate(r, &meshes[*m], *t))
            .collect();
        Self {
            entries: keys.into_iter().zip(values).collect(),
            meshes,
        }
    }

    /// The exact profile: from the cache, or evaluated now when it is not there.
    pub fn exact(&self, reference: &Reference, mesh: &Mesh, t: f64) -> ExactProfile {
        self.entries
            .iter()
            .find(|((r, m, time), _)| {
                time.to_bits() == t.to_bits() && same_mesh(&self.meshes[*m], mesh) && r == reference
            })
            .map_or_else(|| evaluate(reference, mesh, t), |(_, v)| v.clone())
    }
}

/// Exact element averages of the stress at `t` and the extreme stress of the field.
fn evaluate(reference: &Reference, mesh: &Mesh, t: f64) -> ExactProfile {
    (reference.element_averages(mesh, t), reference.extreme(t))
}
