//! One-dimensional meshes of two-node linear bar elements.
//!
//! ```text
//!   node 0      node 1            node N-1     node N
//!     o-----------o-----  ...  ------o-----------o
//!     |<-- h_0 -->|                  |<-h_{N-1}->|
//!     x_0 = 0                                  x_N = L
//! ```

use crate::error::InputError;

/// Node positions of a 1D mesh, strictly increasing. Element `e` joins nodes `e` and `e + 1`.
///
/// Element lengths are stored, not re-derived from rounded node positions: on a uniform mesh
/// every `h_e` is exactly `L/N`, which keeps Co = 1 exactness at round-off level for large N.
#[derive(Debug, Clone, PartialEq)]
pub struct Mesh {
    nodes: Vec<f64>,
    lengths: Vec<f64>,
}

/// Largest number of elements a mesh may have (memory: about 110 bytes per element in a lumped
/// `courant run` with one profile time, measured: `benches/RESULTS.md`).
pub const MAX_ELEMENTS: usize = 10_000_000;

/// Smallest element length relative to the bar length a graded mesh may produce.
pub const MIN_RELATIVE_ELEMENT_LENGTH: f64 = 1e-12;

impl Mesh {
    /// Uniform mesh of `elements` elements on `[0, length]`: `x_i = i L / N`.
    pub fn uniform(length: f64, elements: usize) -> Result<Self, InputError> {
        Self::geometric(length, elements, 1.0)
    }

    /// Graded mesh on `[0, length]` whose element lengths form a geometric progression,
    /// `h_{e+1} = ratio * h_e`, so `h_e = L ratio^e (ratio - 1)/(ratio^N - 1)`
    /// (`ratio = 1` is the uniform mesh).
    pub fn geometric(length: f64, elements: usize, ratio: f64) -> Result<Self, InputError> {
        positive("length", length)?;
        positive("grading ratio", ratio)?;
        check_element_count(elements)?;
        // The smallest element relative to L: (r - 1)/(r^N - 1) for r > 1, and the mirror image
        // for r < 1; it must stay representable and above the floor.
        let big = ratio.max(1.0 / ratio);
        let smallest = if ratio == 1.0 {
            1.0 / elements as f64
        } else {
            (big - 1.0) / (big.powf(elements as f64) - 1.0)
        };
        if smallest.is_nan() || smallest < MIN_RELATIVE_ELEMENT_LENGTH {
            return Err(InputError::Parameter {
                field: "grading ratio",
                value: ratio,
                rule: "makes the smallest element shorter than 1e-12 of the bar for this many elements",
            });
        }
        let mut nodes = Vec::with_capacity(elements + 1);
        if ratio == 1.0 {
            nodes.extend((0..=elements).map(|i| length * i as f64 / elements as f64));
            let mut mesh = Self::from_nodes(nodes)?;
            mesh.lengths
                .iter_mut()
                .for_each(|h| *h = length / elements as f64);
            return Ok(mesh);
        } else {
            // Partial sums of the progression, normalised so the last node is exactly L.
            let mut x = 0.0;
            let mut h = 1.0;
            nodes.push(0.0);
            for _ in 0..elements {
                x += h;
                h *= ratio;
                nodes.push(x);
            }
            let total = x;
            for xi in &mut nodes {
                *xi *= length / total;
            }
            nodes[elements] = length;
        }
        Self::from_nodes(nodes)
    }

    /// Equal-transit-time mesh on `[0, length]`: nodes at equal travel times `tau(x_i) = i T/N`,
    /// `tau(x) = int_0^x slowness`, so every element takes the same time `T/N` for a wave to cross
    /// (methods.md §4). `breaks` are the positions where the slowness jumps (layer interfaces): the
    /// travel time is integrated piece by piece between them with 3-point Gauss-Legendre on
    /// max(8192, 4N) panels (exact for piecewise-constant layers, sixth order for smooth ones) and
    /// inverted by bisection. Returns the mesh and the element transit `T/N`.
    pub fn equal_transit(
        length: f64,
        elements: usize,
        slowness: &dyn Fn(f64) -> f64,
        breaks: &[f64],
    ) -> Result<(Self, f64), InputError> {
        positive("length", length)?;
        check_element_count(elements)?;
        const GAUSS: [(f64, f64); 3] = [
            (-0.774_596_669_241_483_4, 5.0 / 9.0),
            (0.0, 8.0 / 9.0),
            (0.774_596_669_241_483_4, 5.0 / 9.0),
        ];
        let integral = |a: f64, b: f64| -> f64 {
            let (mid, half) = (0.5 * (a + b), 0.5 * (b - a));
            GAUSS
                .iter()
                .map(|&(x, w)| w * slowness(mid + half * x))
                .sum::<f64>()
                * half
        };
        // Panel edges: every piece between breaks split into panels of about L/(64 N).
        let mut cuts: Vec<f64> = breaks
            .iter()
            .copied()
            .filter(|&b| b > 0.0 && b < length)
            .collect();
        cuts.sort_by(f64::total_cmp);
        cuts.insert(0, 0.0);
        cuts.push(length);
        // Panels independent of N for accuracy (at least 8192), growing with N only to resolve
        // the node spacing: memory stays O(N).
        let target_width = length / (8192.max(4 * elements)) as f64;
        let mut edges = vec![0.0];
        for piece in cuts.windows(2) {
            let panels = ((piece[1] - piece[0]) / target_width).ceil().max(1.0) as usize;
            edges.extend(
                (1..=panels).map(|k| piece[0] + (piece[1] - piece[0]) * k as f64 / panels as f64),
            );
        }
        let mut tau = vec![0.0];
        for w in edges.windows(2) {
            let s = integral(w[0], w[1]);
            if !(s.is_finite() && s > 0.0) {
                return Err(InputError::Parameter {
                    field: "slowness",
                    value: s,
                    rule: "must be positive and finite along the bar",
                });
            }
            tau.push(tau[tau.len() - 1] + s);
        }
        let total = tau[tau.len() - 1];
        let mut nodes = Vec::with_capacity(elements + 1);
        nodes.push(0.0);
        for i in 1..elements {
            let target = total * i as f64 / elements as f64;
            let p = tau
                .partition_point(|&t| t < target)
                .clamp(1, edges.len() - 1)
                - 1;
            let (mut lo, mut hi) = (edges[p], edges[p + 1]);
            for _ in 0..64 {
                let mid = 0.5 * (lo + hi);
                if tau[p] + integral(edges[p], mid) < target {
                    lo = mid
                } else {
                    hi = mid
                }
            }
            nodes.push(0.5 * (lo + hi));
        }
        nodes.push(length);
        Ok((Self::from_nodes(nodes)?, total / elements as f64))
    }

    /// Mesh from arbitrary node positions; they must be finite and strictly increasing, and
    /// there must be at least two.
    pub fn from_nodes(nodes: Vec<f64>) -> Result<Self, InputError> {
        if nodes.len() < 2 {
            return Err(InputError::Length {
                field: "node positions",
                expected: 2,
                actual: nodes.len(),
            });
        }
        for (i, &x) in nodes.iter().enumerate() {
            if !x.is_finite() {
                return Err(InputError::NodeValue {
                    field: "position",
                    node: i,
                    value: x,
                    rule: "must be finite",
                });
            }
            if i > 0 && x <= nodes[i - 1] {
                return Err(InputError::NodeValue {
                    field: "position",
                    node: i,
                    value: x,
                    rule: "must be greater than the previous node's position",
                });
            }
        }
        check_element_count(nodes.len() - 1)?;
        let lengths = nodes.windows(2).map(|w| w[1] - w[0]).collect();
        Ok(Self { nodes, lengths })
    }

    /// Node positions.
    pub fn nodes(&self) -> &[f64] {
        &self.nodes
    }

    /// Number of nodes, `N + 1`.
    pub fn node_count(&self) -> usize {
        self.nodes.len()
    }

    /// Number of elements, `N`.
    pub fn element_count(&self) -> usize {
        self.nodes.len() - 1
    }

    /// Length of element `e`, `h_e = x_{e+1} - x_e`.
    pub fn element_length(&self, e: usize) -> f64 {
        self.lengths[e]
    }

    /// Midpoint of element `e`.
    pub fn midpoint(&self, e: usize) -> f64 {
        0.5 * (self.nodes[e] + self.nodes[e + 1])
    }

    /// Position of the left end.
    pub fn start(&self) -> f64 {
        self.nodes[0]
    }

    /// Length of the bar, `x_N - x_0`.
    pub fn length(&self) -> f64 {
        self.nodes[self.nodes.len() - 1] - self.nodes[0]
    }

    /// The node closest to `x` (ties go to the left node).
    pub fn nearest_node(&self, x: f64) -> usize {
        let i = self.nodes.partition_point(|&xi| xi < x);
        match i {
            0 => 0,
            i if i == self.nodes.len() => i - 1,
            i if (self.nodes[i] - x) < (x - self.nodes[i - 1]) => i,
            i => i - 1,
        }
    }
}

fn check_element_count(elements: usize) -> Result<(), InputError> {
    if (1..=MAX_ELEMENTS).contains(&elements) {
        Ok(())
    } else {
        Err(InputError::Parameter {
            field: "elements",
            value: elements as f64,
            rule: "must be between 1 and 10000000",
        })
    }
}

pub(crate) fn positive(field: &'static str, value: f64) -> Result<(), InputError> {
    if value.is_finite() && value > 0.0 {
        Ok(())
    } else {
        Err(InputError::Parameter {
            field,
            value,
            rule: "must be positive and finite",
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn uniform_mesh_hits_both_ends_exactly() {
        let m = Mesh::uniform(2.0, 7).unwrap();
        assert_eq!(m.node_count(), 8);
        assert_eq!(m.nodes()[0], 0.0);
        assert_eq!(m.nodes()[7], 2.0);
    }

    #[test]
    fn geometric_mesh_has_the_requested_ratio() {
        let m = Mesh::geometric(1.0, 10, 1.2).unwrap();
        for e in 1..10 {
            let r = m.element_length(e) / m.element_length(e - 1);
            assert!((r - 1.2).abs() < 1e-12, "ratio {r} at element {e}");
        }
        assert_eq!(m.nodes()[10], 1.0);
    }

    #[test]
    fn bad_meshes_are_refused_with_the_rule() {
        let err = Mesh::uniform(-1.0, 3).unwrap_err();
        assert_eq!(err.to_string(), "length = -1 must be positive and finite");
        assert!(Mesh::uniform(1.0, 0).is_err());
        let err = Mesh::from_nodes(vec![0.0, 0.5, 0.5]).unwrap_err();
        assert!(err.to_string().contains("node 2"), "{err}");
    }

    #[test]
    fn extreme_grading_and_huge_meshes_are_refused_by_rule() {
        let err = Mesh::geometric(1.0, 2000, 1.5).unwrap_err();
        assert!(
            err.to_string()
                .starts_with("grading ratio = 1.5 makes the smallest element"),
            "{err}"
        );
        assert!(Mesh::geometric(1.0, 2000, 1.0 / 1.5).is_err());
        assert!(Mesh::geometric(1.0, 100, 1.2).is_ok());
        assert!(
            Mesh::uniform(1.0, MAX_ELEMENTS + 1)
                .unwrap_err()
                .to_string()
                .contains("between 1 and")
        );
    }

    #[test]
    fn uniform_elements_are_exactly_l_over_n() {
        let m = Mesh::uniform(1.0, 3000).unwrap();
        assert!((0..3000).all(|e| m.element_length(e) == 1.0 / 3000.0));
    }

    #[test]
    fn nearest_node_snaps_to_the_closest_position() {
        let m = Mesh::uniform(1.0, 10).unwrap();
        assert_eq!(m.nearest_node(0.0), 0);
        assert_eq!(m.nearest_node(0.52), 5);
        assert_eq!(m.nearest_node(0.58), 6);
        assert_eq!(m.nearest_node(7.0), 10);
    }
}
