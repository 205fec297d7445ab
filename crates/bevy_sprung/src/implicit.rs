//! Implicit transitions: values written directly spring instead of jumping — CSS transitions,
//! SwiftUI's `.animation(_:value:)`.
//!
//! With an [`ImplicitSpring<P>`] on an entity, code that writes property `P` (a system setting
//! `BackgroundColor`, a `Node` width or a `UiTransform`) is not changed: the plugin sees the
//! write by its change tick, takes the written value as the spring's new target and puts the
//! shown value back, so that the spring carries it there with its velocity.

use core::any::TypeId;
use core::fmt;
use core::marker::PhantomData;

use bevy::ecs::lifecycle::HookContext;
use bevy::ecs::world::DeferredWorld;
use bevy::prelude::*;
use sprung::Spring;

use crate::property::SpringProperty;
use crate::space::SpringSpace;
use crate::spring::{
    PropertySpring, PropertySystems, SpringMotion, SpringPhase, SpringTargetMut, SpringUpdate,
    add_systems_on_first_use,
};

/// Makes writes to property `P` spring: when something other than the spring writes the
/// property, the written value becomes the spring's target and the property springs to it from
/// where it was shown, keeping its velocity. Writing the value it is already heading for changes
/// nothing; a NaN or infinite write is refused (the shown value is put back, one warning).
///
/// It brings a [`PropertySpring<P>`] with `spring`, resting at the property's value, unless the
/// entity already has one. Writes are seen through change detection, as every spring sees
/// them: one made with `bypass_change_detection` is not, nor one made in the frame the
/// `ImplicitSpring` or the spring was added (the spring starts from it).
///
/// # Example
/// ```
/// use bevy::prelude::*;
/// use bevy_sprung::prelude::*;
///
/// #[derive(Component)]
/// struct Piece {
///     cell: IVec2,
/// }
///
/// fn spawn_piece(mut commands: Commands) {
///     commands.spawn((
///         Piece { cell: IVec2::ZERO },
///         Transform::default(),
///         // Moves glide instead of jumping.
///         ImplicitSpring::<Translation>::new(Spring::snappy()),
///     ));
/// }
///
/// // Unchanged game code: it writes the translation, the spring animates it.
/// fn place(mut pieces: Query<(&Piece, &mut Transform), Changed<Piece>>) {
///     for (piece, mut transform) in &mut pieces {
///         transform.translation = (piece.cell.as_vec2() * 64.0).extend(0.0);
///     }
/// }
/// # let mut app = App::new();
/// # app.add_plugins((MinimalPlugins, SpringPlugins::default()))
/// #     .add_systems(Startup, spawn_piece)
/// #     .add_systems(Update, place);
/// # app.update();
/// ```
#[derive(Component, Reflect)]
#[component(on_add = Self::on_add)]
#[reflect(Component, Debug, Clone)]
pub struct ImplicitSpring<P: SpringProperty> {
    /// The spring a write is animated with (when the entity had no spring on `P`).
    pub spring: Spring,
    #[reflect(ignore)]
    property: PhantomData<fn() -> P>,
}

impl<P: SpringProperty> ImplicitSpring<P> {
    /// Writes to `P` spring with `spring`.
    #[must_use]
    pub fn new(spring: Spring) -> Self {
        Self {
            spring,
            property: PhantomData,
        }
    }

    /// The hook: the first implicit spring on `P` brings in its system, and an entity without a
    /// spring on `P` gets one resting where the property is.
    fn on_add(mut world: DeferredWorld, context: HookContext) {
        crate::spring::first_use::<Self>(world.reborrow(), context);
        let entity = context.entity;
        if world.get::<PropertySpring<P>>(entity).is_some() {
            return;
        }
        let Some(spring) = world.get::<Self>(entity).map(|implicit| implicit.spring) else {
            return;
        };
        let at = world
            .get::<P::Component>(entity)
            .map(P::get)
            .filter(|&value| P::Space::is_valid(value))
            .unwrap_or_default();
        world
            .commands()
            .entity(entity)
            .try_insert_if_new(PropertySpring::<P>::new(spring, at));
    }
}

impl<P: SpringProperty> Clone for ImplicitSpring<P> {
    fn clone(&self) -> Self {
        Self::new(self.spring)
    }
}

impl<P: SpringProperty> fmt::Debug for ImplicitSpring<P> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("ImplicitSpring")
            .field("property", &P::short_type_path())
            .field("spring", &self.spring)
            .finish()
    }
}

/// Before property `P`'s springs step: a value written by something else becomes the target,
/// and the property shows what the spring showed.
fn take_writes<P: SpringProperty>(
    mut written: Query<
        (
            &mut P::Component,
            &mut PropertySpring<P>,
            &SpringMotion<P>,
            Ref<ImplicitSpring<P>>,
        ),
        Changed<P::Component>,
    >,
) {
    for (mut component, mut spring, motion, implicit) in &mut written {
        // A spring that has not stepped yet starts from whatever the property holds.
        if implicit.is_added() || spring.is_added() {
            continue;
        }
        let value = P::get(&component);
        if motion.holds(value) {
            continue;
        }
        if P::Space::is_valid(value) {
            spring.set_target_if_neq(value);
        } else {
            warn_once!(
                "bevy_sprung: refused a non-finite value written to a sprung property: {value:?}"
            );
        }
        P::set(&mut component, motion.shown());
    }
}

/// What [`SpringPropertyPlugin<P>`](crate::SpringPropertyPlugin) adds of implicit transitions:
/// with the first [`ImplicitSpring<P>`], writes to `P` are taken as targets in
/// [`SpringPhase::Input`].
pub(crate) fn add_property<P: SpringProperty>(app: &mut App) {
    app.register_type::<ImplicitSpring<P>>();
    add_systems_on_first_use(
        app,
        &[TypeId::of::<ImplicitSpring<P>>()],
        SpringUpdate,
        |schedule| {
            schedule.add_systems(
                take_writes::<P>
                    .in_set(PropertySystems::<P>::phase(SpringPhase::Input))
                    .run_if(any_with_component::<ImplicitSpring<P>>),
            );
        },
    );
}
