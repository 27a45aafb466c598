//! Ordered collection of parallel work.

/// The values in order, or the first error in order (not whichever thread failed first): collect
/// a parallel map into a `Vec` of results first, then this. With it, what a command returns and
/// prints does not depend on the thread count.
pub fn in_order<T, E>(results: Vec<Result<T, E>>) -> Result<Vec<T>, E> {
    results.into_iter().collect()
}
