pub mod handle_defs;
mod handle_impls;
pub mod iterators;
mod public_handles;

pub use public_handles::*;
