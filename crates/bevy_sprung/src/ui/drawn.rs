//! Drawing UI nodes away from where layout put them, after layout: the one subtree walk that
//! layout transitions and rubber-band scrolling share.

use alloc::vec::Vec;

use bevy::prelude::*;
use bevy::ui::UiGlobalTransform;

/// Moves the drawn transforms of `roots` and all their descendants by `by` (physical pixels, on
/// screen). `stack` is scratch space, kept by the caller across frames.
pub(super) fn shift_subtrees(
    globals: &mut Query<&mut UiGlobalTransform>,
    descendants: &Query<&Children>,
    stack: &mut Vec<Entity>,
    roots: impl IntoIterator<Item = Entity>,
    by: Vec2,
) {
    stack.clear();
    stack.extend(roots);
    while let Some(node) = stack.pop() {
        if let Ok(mut global) = globals.get_mut(node) {
            let mut affine = **global;
            affine.translation += by;
            *global = affine.into();
        }
        if let Ok(children) = descendants.get(node) {
            stack.extend(children.iter());
        }
    }
}
