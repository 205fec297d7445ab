//! What springs: a field of a component, and how its value springs.

use bevy::ecs::component::{Component, Mutable};
use bevy::reflect::TypePath;
use sprung::RestThreshold;

use crate::space::SpringSpace;

/// A field of a component that a [`PropertySpring`](crate::spring::PropertySpring) moves toward
/// a target: which component, how to read and write the field, and the
/// [`SpringSpace`] its value springs in.
///
/// Write one with [`spring_property!`](crate::spring_property) — one line per field; every
/// built-in property is written that way — and add its
/// [`SpringPropertyPlugin`](crate::SpringPropertyPlugin).
pub trait SpringProperty: TypePath + Send + Sync + 'static {
    /// The component the field is on.
    type Component: Component<Mutability = Mutable>;
    /// How the field's value springs.
    type Space: SpringSpace;

    /// The tolerances at which a spring on this property counts as at rest, in its units. The
    /// space's own unless the property says otherwise (a scale rests ten times finer than a
    /// position).
    const DEFAULT_REST: RestThreshold<f32> = <Self::Space as SpringSpace>::DEFAULT_REST;

    /// Reads the field.
    #[must_use]
    fn get(component: &Self::Component) -> ValueOf<Self>;

    /// Writes the field.
    fn set(component: &mut Self::Component, value: ValueOf<Self>);
}

/// The value type of property `P` (what its target is).
pub type ValueOf<P> = <<P as SpringProperty>::Space as SpringSpace>::Value;

/// The offset type of property `P` (what the step computes with).
pub type OffsetOf<P> = <<P as SpringProperty>::Space as SpringSpace>::Offset;

/// The velocity type of property `P`, as its spring's getters return it (`Vec3` for a `Vec3`
/// value).
pub type VelocityOf<P> = <<P as SpringProperty>::Space as SpringSpace>::Velocity;

/// Declares that a field of a component springs: defines a marker type naming the property and
/// implements [`SpringProperty`] for it, in one line — the spring-side counterpart of Bevy's
/// `animated_field!`.
///
/// ```text
/// spring_property!(/// docs
///     pub Name: Component::field as Space);
/// spring_property!(pub Name: Component::field as Space, rest: RestThreshold { offset: .., speed: .. });
/// spring_property!(pub Name: Component { get: |c| .., set: |c, value| .. } as Space);
/// ```
///
/// `field` is a named or tuple field (`Transform::translation`, `BackgroundColor::0`); the
/// second form overrides the space's rest tolerances; the third reads and writes through
/// expressions, for a value spread over several fields. `Space` is a
/// [`SpringSpace`]: [`Linear<V>`](crate::space::Linear) for a vector `V`,
/// [`NeverThroughZero<Linear<V>>`](crate::space::NeverThroughZero) for a scale,
/// [`ShortestArc`](crate::space::ShortestArc) for a `Quat`, `OklabColor` for a `Color`,
/// `Length` for a `Val`. Then add `SpringPropertyPlugin::<Name>` and spawn
/// `PropertySpring::<Name>`.
///
/// # Example
/// ```
/// use bevy::prelude::*;
/// use bevy_sprung::prelude::*;
/// use bevy_sprung::space::Linear;
///
/// #[derive(Component, Default)]
/// struct Engine { throttle: f32 }
///
/// spring_property!(
///     /// `Engine::throttle`.
///     Throttle: Engine::throttle as Linear<f32>
/// );
///
/// let mut app = App::new();
/// app.add_plugins((MinimalPlugins, SpringPlugins::default(), SpringPropertyPlugin::<Throttle>::default()));
/// // 60 fps of game time, whatever the wall clock does.
/// app.insert_resource(bevy::time::TimeUpdateStrategy::ManualDuration(
///     std::time::Duration::from_secs_f64(1.0 / 60.0),
/// ));
/// let engine = app
///     .world_mut()
///     .spawn((Engine::default(), PropertySpring::<Throttle>::new(Spring::snappy(), 1.0)))
///     .id();
/// for _ in 0..120 {
///     app.update();
/// }
/// assert_eq!(app.world().get::<Engine>(engine).unwrap().throttle, 1.0);
/// ```
// The field form is the accessor form with a field's accessors: one expansion to maintain.
#[macro_export]
macro_rules! spring_property {
    (
        $(#[$attribute:meta])*
        $visibility:vis $name:ident : $component:ident :: $field:tt as $space:ty
        $(, rest: $rest:expr)? $(,)?
    ) => {
        $crate::spring_property! {
            $(#[$attribute])*
            $visibility $name : $component {
                get: |component| component.$field,
                set: |component, value| component.$field = value,
            } as $space
            $(, rest: $rest)?
        }
    };
    (
        $(#[$attribute:meta])*
        $visibility:vis $name:ident : $component:ty {
            get: |$get:ident| $read:expr,
            set: |$set:ident, $value:ident| $write:expr $(,)?
        } as $space:ty
        $(, rest: $rest:expr)? $(,)?
    ) => {
        $(#[$attribute])*
        #[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Hash)]
        $visibility struct $name;

        impl $crate::property::__macro::TypePath for $name {
            fn type_path() -> &'static str {
                concat!(module_path!(), "::", stringify!($name))
            }

            fn short_type_path() -> &'static str {
                stringify!($name)
            }

            fn type_ident() -> Option<&'static str> {
                Some(stringify!($name))
            }

            fn module_path() -> Option<&'static str> {
                Some(module_path!())
            }

            fn crate_name() -> Option<&'static str> {
                module_path!().split("::").next()
            }
        }

        impl $crate::property::SpringProperty for $name {
            type Component = $component;
            type Space = $space;
            $(const DEFAULT_REST: $crate::property::__macro::RestThreshold<f32> = $rest;)?

            #[inline]
            fn get($get: &$component) -> $crate::property::ValueOf<Self> {
                $read
            }

            #[inline]
            fn set($set: &mut $component, $value: $crate::property::ValueOf<Self>) {
                $write;
            }
        }
    };
}

/// What [`spring_property!`] expands to needs these, from this crate whatever the caller's
/// dependencies are called.
#[doc(hidden)]
pub mod __macro {
    pub use bevy::reflect::TypePath;
    pub use sprung::RestThreshold;
}
