//! The batch planners: BIT\* (`bit_star.rs`), which searches batches of samples in order of the
//! solutions they could give, over the graph of samples and tree it grows (`graph.rs`).

pub mod bit_star;
pub(crate) mod graph;
