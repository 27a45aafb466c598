//! Arrays that one sweep streams side by side, placed in one allocation so that each starts at
//! a chosen offset of its page (its address modulo 4096), whatever the allocator does.
//!
//! Why. Where an allocator puts separate large arrays is chance: a fresh mapping starts at offset
//! 16 of a page with glibc (so all of them coincide), a reused block anywhere. The matrix-mass
//! step's speed depended on it: the same 300 RMM steps at N = 1e6 took 244-285 ms with one
//! placement and 354-366 ms with another (benches/RESULTS.md, heading "... the run's start, the
//! mass check, where the state lives ...", and [`crate::kernels::matrix_mass::kernel`]'s
//! placement). Probable mechanisms: 4K aliasing (a load whose address matches an older store's low
//! 12 bits waits for it as if dependent; the step's passes store one array while loading others a
//! little ahead) and, at sizes beyond the caches, how the memory's channels see the streams (the
//! low 12 bits of a physical address are the virtual ones). This machine has no performance
//! counters to tell them apart; the placements are chosen by measurement.

/// `K` arrays of `f64` in one allocation, each starting at a chosen byte offset modulo 4096 (an
/// offset of its page; the page is the allocator's).
#[derive(Debug)]
pub(crate) struct PlacedArrays<const K: usize> {
    buffer: Vec<f64>,
    /// Where each array starts in `buffer` (increasing).
    starts: [usize; K],
    lens: [usize; K],
    /// Each array's byte offset modulo 4096.
    offsets: [usize; K],
}

/// A page: the low 12 bits of an address that 4K aliasing compares.
const PAGE: usize = 4096;

impl<const K: usize> PlacedArrays<K> {
    /// The arrays, copied in (lengths as given), array `k` at byte `offsets[k]` (a multiple of
    /// 8) modulo 4096.
    pub(crate) fn new(arrays: [&[f64]; K], offsets: [usize; K]) -> Self {
        let mut placed = Self::zeroed(arrays.map(<[f64]>::len), offsets);
        for (to, from) in placed.split_mut().into_iter().zip(arrays) {
            to.copy_from_slice(from);
        }
        placed
    }

    /// Arrays of the given lengths, zero, array `k` at byte `offsets[k]` (a multiple of 8)
    /// modulo 4096.
    pub(crate) fn zeroed(lens: [usize; K], offsets: [usize; K]) -> Self {
        assert!(
            offsets.iter().all(|o| o.is_multiple_of(8)),
            "offsets of words"
        );
        // Room for every array and a page of padding before each.
        let words = lens.iter().sum::<usize>() + K * PAGE / 8;
        let buffer = vec![0.0; words];
        let base = buffer.as_ptr() as usize;
        let mut starts = [0; K];
        let mut next = 0;
        for (k, start) in starts.iter_mut().enumerate() {
            // The first word at or after `next` whose address is `offsets[k]` modulo PAGE (the
            // allocation is 8-byte aligned, so a word boundary reaches every multiple of 8).
            let target = offsets[k] % PAGE;
            let address = base + 8 * next;
            let gap = (target + PAGE - address % PAGE) % PAGE;
            *start = next + gap / 8;
            next = *start + lens[k];
        }
        Self {
            buffer,
            starts,
            lens,
            offsets,
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
        Self::new(std::array::from_fn(|k| self.get(k)), self.offsets)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn arrays_keep_their_values_and_start_at_their_offsets() {
        let (a, b, c, d) = (vec![1.0; 1000], vec![2.0; 3], vec![], vec![4.0; 5000]);
        let offsets = [2624, 8, 0, 4088];
        let mut placed = PlacedArrays::new([&a[..], &b, &c, &d], offsets);
        for copy in [placed.clone(), placed.clone()] {
            for (k, array) in [&a, &b, &c, &d].into_iter().enumerate() {
                assert_eq!(copy.get(k), &array[..]);
                assert_eq!(copy.get(k).as_ptr() as usize % PAGE, offsets[k], "{k}");
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
