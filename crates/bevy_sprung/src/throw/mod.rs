//! What a throw is made of, shared by everything that flings: the pointer's velocity at
//! release ([`ReleaseVelocity`]), the box a throw stays in ([`DragBounds`]) and where it snaps
//! ([`Snap`]). Below drags ([`SpringDrag`](crate::interaction::SpringDrag)),
//! [`Inertia`](crate::inertia::Inertia) and momentum scrolling, which use them and not each
//! other's.

mod bounds;
mod release;

pub use bounds::{DragBounds, Snap, SnapLine};
pub use release::ReleaseVelocity;
