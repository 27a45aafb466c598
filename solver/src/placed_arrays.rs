//! Arrays that one sweep streams side by side, placed in one allocation so that their addresses
//! keep chosen distances modulo 4096 bytes (their offsets in a page).
//!
//! Why. Where an allocator puts separate arrays is chance: a fresh large allocation is mapped
//! at offset 16 of a page (all of them then coincide), a reused one anywhere. The matrix-mass
//! step's speed depended on it. Measured here (benches/RESULTS.md, fifth session): at N = 1e5,
//! `u`, `v`, `r` and `k` at one offset made the CMM step 0.945 ns per node-step and the RMM
//! step 0.733, against 0.867-0.919 and 0.591-0.701 with 16 spread placements; at N = 1e6 one
//! run loop's RMM steps took 1.18-1.22 ms with the allocator's first placement and 0.81-0.95 with
//! its second, in the same process. The likely mechanism is 4K aliasing (a load whose address
//! matches an older store's low 12 bits waits for it, as if dependent): the step's passes store
//! one array while loading others a little ahead. Here the arrays start a quarter page apart
//! whatever the allocator does: among the fastest placements at 1e5 (CMM 0.867, RMM 0.663). At
//! 1e6 the spread placements' RMM steps ranged 0.76-1.46 ns in one (noisy) sweep, the quarter
//! spacing 1.03-1.11 in three; the one placement fastest there (0.76-0.91, three runs) was
//! among the slowest at 1e5.
//!
//! The lumped kernel keeps its own arrays: it ran faster with coinciding offsets (0.53-0.60
//! against 0.61-0.63 ns at 1e5), its loads and stores all at the same row.

/// `K` arrays of `f64` in one allocation, array `k` starting at byte `k 4096 / K` modulo 4096
/// (an offset of its page; the page is the allocator's).
#[derive(Debug)]
pub(crate) struct PlacedArrays<const K: usize> {
    buffer: Vec<f64>,
    /// Where each array starts in `buffer` (increasing).
    starts: [usize; K],
    lens: [usize; K],
}

/// A page: the low 12 bits of an address that 4K aliasing compares.
const PAGE: usize = 4096;

impl<const K: usize> PlacedArrays<K> {
    /// The arrays, copied in (lengths as given).
    pub(crate) fn new(arrays: [&[f64]; K]) -> Self {
        let lens = arrays.map(<[f64]>::len);
        // Room for every array and a page of padding before each.
        let words = lens.iter().sum::<usize>() + K * PAGE / 8;
        let mut buffer = vec![0.0; words];
        let base = buffer.as_ptr() as usize;
        let mut starts = [0; K];
        let mut next = 0;
        for (k, start) in starts.iter_mut().enumerate() {
            // The first word at or after `next` whose address is `k PAGE / K` modulo PAGE (the
            // allocation is 8-byte aligned, so a word boundary reaches every multiple of 8).
            let target = k * PAGE / K;
            let address = base + 8 * next;
            let gap = (target + PAGE - address % PAGE) % PAGE;
            *start = next + gap / 8;
            next = *start + lens[k];
        }
        for ((array, &start), &len) in arrays.iter().zip(&starts).zip(&lens) {
            buffer[start..start + len].copy_from_slice(array);
        }
        Self {
            buffer,
            starts,
            lens,
        }
    }

    /// Array `k`.
    pub(crate) fn get(&self, k: usize) -> &[f64] {
        &self.buffer[self.starts[k]..self.starts[k] + self.lens[k]]
    }

    /// Every array, mutable, at once.
    pub(crate) fn split_mut(&mut self) -> [&mut [f64]; K] {
        let mut rest: &mut [f64] = &mut self.buffer;
        let mut taken = 0;
        let mut arrays = [(); K].map(|_| <&mut [f64]>::default());
        for (array, (&start, &len)) in arrays.iter_mut().zip(self.starts.iter().zip(&self.lens)) {
            let (_, tail) = std::mem::take(&mut rest).split_at_mut(start - taken);
            let (this, tail) = tail.split_at_mut(len);
            *array = this;
            rest = tail;
            taken = start + len;
        }
        arrays
    }
}

impl<const K: usize> Clone for PlacedArrays<K> {
    /// The same values, placed anew in the new allocation.
    fn clone(&self) -> Self {
        Self::new(std::array::from_fn(|k| self.get(k)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn arrays_keep_their_values_and_start_a_quarter_page_apart() {
        let (a, b, c, d) = (vec![1.0; 1000], vec![2.0; 3], vec![], vec![4.0; 5000]);
        let mut placed = PlacedArrays::new([&a[..], &b, &c, &d]);
        for copy in [placed.clone(), placed.clone()] {
            for (k, array) in [&a, &b, &c, &d].into_iter().enumerate() {
                assert_eq!(copy.get(k), &array[..]);
                assert_eq!(
                    copy.get(k).as_ptr() as usize % PAGE,
                    k * PAGE / 4,
                    "array {k}"
                );
            }
        }
        let [w, x, _, z] = placed.split_mut();
        (w[999], x[0], z[4999]) = (-1.0, -2.0, -4.0);
        assert_eq!(
            (placed.get(0)[999], placed.get(1)[0], placed.get(3)[4999]),
            (-1.0, -2.0, -4.0)
        );
        assert_eq!(placed.get(1), &[-2.0, 2.0, 2.0]);
    }
}
