//! The seal on the plugin's fast-path hooks of [`SpringVector`](super::SpringVector) and
//! [`SpringSpace`](super::SpringSpace).

/// The token every fast-path hook of [`SpringVector`](super::SpringVector) and
/// [`SpringSpace`](super::SpringSpace) takes as its last argument. It is a public type in a
/// private module: code outside this crate cannot name it, so it can neither call those hooks
/// nor override their defaults, which are right for any vector or space. Zero-sized: passing it
/// costs nothing.
#[derive(Clone, Copy, Debug)]
pub struct FastPath;
