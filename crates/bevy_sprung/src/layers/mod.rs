//! Layers: several springs on one property, their motions added up — a card that hovers, is
//! punched and squashes at once, each motion unbent by the others (SwiftUI's additive
//! animations).
//!
//! A property's value is its *base* (whatever writes the property: its
//! [`PropertySpring`], an animation, gameplay) with every layer applied on top, each a
//! [`LayerSpace::Layer`] offset: sums for vectors, products for rotations, factors (sums of
//! logarithms) for scales, sums in Oklab for colours. Each layer is a property of its own,
//! [`Layer<P, L>`], so it has a full spring ([`LayerSpring<P, L>`]) with a target, impulses,
//! [`punch`](PropertySpring::punch), sequences and
//! [`InteractionTargets`](crate::interaction::InteractionTargets) (feature `picking`).
//!
//! The layers are shown in `PostUpdate`, after the springs (in [`LayerSystems`]), and taken
//! off again in `PreUpdate`, so gameplay and the base spring always see and write the base
//! value; where nothing else wrote the property between, it comes back bit for bit. A layer
//! at rest sleeps like any spring. A stack whose layers are all zero is neither shown nor
//! taken off: it costs nothing a frame. One held still away from zero (a hover held) is taken
//! off and shown again each frame, two writes that do not mark the property changed: transform
//! propagation and `Changed` filters see a still value.

mod space;

use core::any::TypeId;
use core::fmt;
use core::marker::PhantomData;

use bevy::app::AnimationSystems;
use bevy::ecs::entity_disabling::Disabled;
use bevy::ecs::world::DeferredWorld;
use bevy::log::warn_once;
use bevy::math::NormedVectorSpace;
use bevy::prelude::*;
use bevy::reflect::TypePath;
use bevy::transform::TransformSystems;

pub use space::LayerSpace;

use crate::property::{SpringProperty, ValueOf};
use crate::property_plugin::SpringPropertyPlugin;
use crate::space::FastPath;
use crate::space::{Linear, LinearValue, SpringSpace};
use crate::spring::{
    PropertySpring, SpringSystems, add_systems_on_first_use, first_use, warn_missing,
};

/// A layer's value for property `P`.
pub type LayerOf<P> = <<P as SpringProperty>::Space as LayerSpace>::Layer;

/// The layer named `L` of property `P`, as a property of its own: its value is the layer's
/// offset (a [`LayerSpace::Layer`], zero when it does nothing), kept in the entity's
/// [`SpringLayers<P>`] and springing linearly. `L` is any type naming the layer (a marker:
/// `#[derive(TypePath)] struct Hover;`).
///
/// Add [`SpringLayerPlugin<P, L>`] for each layer an app uses.
#[derive(TypePath)]
pub struct Layer<P, L>(PhantomData<fn() -> (P, L)>);

impl<P, L> SpringProperty for Layer<P, L>
where
    P: SpringProperty<Space: LayerSpace>,
    L: TypePath + Send + Sync + 'static,
{
    type Component = SpringLayers<P>;
    type Space = Linear<LayerOf<P>>;
    const DEFAULT_REST: sprung::RestThreshold<f32> = P::DEFAULT_REST;

    #[inline]
    fn get(layers: &SpringLayers<P>) -> LayerOf<P> {
        layers.get::<L>()
    }

    #[inline]
    fn set(layers: &mut SpringLayers<P>, value: LayerOf<P>) {
        layers.write(TypeId::of::<L>(), value);
    }
}

/// A spring on the layer `L` of property `P`: `LayerSpring::<Scale, Hover>::new(spring,
/// Vec3::ZERO)` springs a hover's scale factor on top of whatever else scales the entity. It
/// brings the entity's [`SpringLayers<P>`].
pub type LayerSpring<P, L> = PropertySpring<Layer<P, L>>;

/// The layers of property `P` on an entity, in the order they were first written, and what
/// they were last shown on. Springs ([`LayerSpring`]) write their layers here; other effects
/// (a [`SquashStretch`](crate::juice::SquashStretch)) write theirs with
/// [`set`](Self::set).
///
/// # Example
/// ```
/// use bevy::prelude::*;
/// use bevy_sprung::layers::{LayerSpring, SpringLayerPlugin, SpringLayers};
/// use bevy_sprung::prelude::*;
///
/// /// The hover lift, on top of the card's own motion.
/// #[derive(TypePath)]
/// struct Hover;
///
/// let mut app = App::new();
/// app.add_plugins((MinimalPlugins, SpringPlugins::default()))
///     .add_plugins(SpringLayerPlugin::<Translation, Hover>::default());
/// app.insert_resource(bevy::time::TimeUpdateStrategy::ManualDuration(
///     std::time::Duration::from_secs_f64(1.0 / 60.0),
/// ));
/// let card = app
///     .world_mut()
///     .spawn((
///         Transform::default(),
///         // The card deals to x = 300...
///         TranslationSpring::new(Spring::smooth(), Vec3::new(300.0, 0.0, 0.0)),
///         // ...and lifts by 20 while it travels, each motion unbent by the other.
///         LayerSpring::<Translation, Hover>::new(Spring::bouncy(), Vec3::new(0.0, 20.0, 0.0)),
///     ))
///     .id();
/// for _ in 0..240 {
///     app.update();
/// }
/// let transform = app.world().get::<Transform>(card).unwrap();
/// assert_eq!(transform.translation, Vec3::new(300.0, 20.0, 0.0));
/// let layers = app.world().get::<SpringLayers<Translation>>(card).unwrap();
/// assert_eq!(layers.get::<Hover>(), Vec3::new(0.0, 20.0, 0.0));
/// ```
#[derive(Component, Reflect)]
#[component(on_add = first_use::<Self>)]
#[reflect(Component, Default)]
pub struct SpringLayers<P: SpringProperty<Space: LayerSpace>> {
    /// Each layer's name and offset.
    #[reflect(ignore)]
    layers: Vec<(TypeId, LayerOf<P>)>,
    /// The base the layers were last shown on, and the value shown, until taken off.
    #[reflect(ignore)]
    shown: Option<Shown<P>>,
    /// The value shown at the end of the last frame, kept while taken off: showing it again
    /// changes nothing anyone downstream sees.
    #[reflect(ignore)]
    last: Option<ValueOf<P>>,
    #[reflect(ignore)]
    property: PhantomData<fn() -> P>,
}

/// What a stack of layers put on its property: the base under it, and the value written.
struct Shown<P: SpringProperty> {
    base: ValueOf<P>,
    value: ValueOf<P>,
}

impl<P: SpringProperty> Clone for Shown<P> {
    fn clone(&self) -> Self {
        *self
    }
}

impl<P: SpringProperty> Copy for Shown<P> {}

impl<P: SpringProperty<Space: LayerSpace>> Default for SpringLayers<P> {
    fn default() -> Self {
        Self {
            layers: Vec::new(),
            shown: None,
            last: None,
            property: PhantomData,
        }
    }
}

impl<P: SpringProperty<Space: LayerSpace>> fmt::Debug for SpringLayers<P> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("SpringLayers")
            .field("property", &P::short_type_path())
            .field(
                "layers",
                &self.layers.iter().map(|(_, v)| v).collect::<Vec<_>>(),
            )
            .finish_non_exhaustive()
    }
}

impl<P: SpringProperty<Space: LayerSpace>> SpringLayers<P> {
    /// The offset of layer `L`: zero if it has none.
    #[must_use]
    pub fn get<L: 'static>(&self) -> LayerOf<P> {
        let name = TypeId::of::<L>();
        self.layers
            .iter()
            .find_map(|&(layer, value)| (layer == name).then_some(value))
            .unwrap_or_default()
    }

    /// Sets the offset of layer `L` (an effect that is not a spring, or a jump). A NaN or
    /// infinite offset is refused, with one warning: the layer keeps its value.
    pub fn set<L: 'static>(&mut self, value: LayerOf<P>) {
        if !value.to_offset().norm_squared().is_finite() {
            warn_once!(
                "bevy_sprung: refused a non-finite offset for a layer of {}",
                P::short_type_path()
            );
            return;
        }
        self.write(TypeId::of::<L>(), value);
    }

    /// All layers together: the base `value` with every layer applied in order.
    #[must_use]
    pub fn apply(&self, value: ValueOf<P>) -> ValueOf<P> {
        let zero = LayerOf::<P>::default();
        self.layers
            .iter()
            .filter(|(_, layer)| *layer != zero)
            .fold(value, |value, &(_, layer)| P::Space::apply(value, layer))
    }

    /// The base under `value`: every layer taken off, in reverse order.
    #[must_use]
    pub fn remove(&self, value: ValueOf<P>) -> ValueOf<P> {
        let zero = LayerOf::<P>::default();
        self.layers
            .iter()
            .rev()
            .filter(|(_, layer)| *layer != zero)
            .fold(value, |value, &(_, layer)| P::Space::remove(value, layer))
    }

    fn write(&mut self, name: TypeId, value: LayerOf<P>) {
        match self.layers.iter_mut().find(|(layer, _)| *layer == name) {
            Some((_, slot)) => *slot = value,
            None => self.layers.push((name, value)),
        }
    }

    /// Forgets layer `name`, and returns its offset.
    fn forget(&mut self, name: TypeId) -> Option<LayerOf<P>> {
        let index = self.layers.iter().position(|(layer, _)| *layer == name)?;
        Some(self.layers.remove(index).1)
    }
}

/// Where layers are shown: in `PostUpdate`, in `AnimationSystems` after the springs
/// ([`SpringSystems`]) and before transform propagation (and so before `bevy_ui`'s layout).
/// Effects that write a layer directly run before it. In `PreUpdate` the same set takes the
/// layers off again.
#[derive(SystemSet, Debug, Clone, PartialEq, Eq, Hash)]
pub struct LayerSystems;

/// Layer `L` of property `P`: the layer's spring ([`SpringPropertyPlugin<Layer<P, L>>`]), and
/// for the property, the systems that show and take off its layers (once however many layers
/// it has). A [`LayerSpring<P, L>`] then brings its [`SpringLayers<P>`]. Adding it twice is
/// harmless.
pub struct SpringLayerPlugin<P, L>(PhantomData<fn() -> (P, L)>);

impl<P, L> Default for SpringLayerPlugin<P, L> {
    fn default() -> Self {
        Self(PhantomData)
    }
}

impl<P, L> fmt::Debug for SpringLayerPlugin<P, L>
where
    P: SpringProperty<Space: LayerSpace>,
    L: TypePath + Send + Sync + 'static,
{
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "SpringLayerPlugin<{}, {}>",
            P::short_type_path(),
            L::short_type_path()
        )
    }
}

impl<P, L> Plugin for SpringLayerPlugin<P, L>
where
    P: SpringProperty<Space: LayerSpace>,
    L: TypePath + Send + Sync + 'static,
{
    fn build(&self, app: &mut App) {
        if crate::spring::is_registered::<Layer<P, L>>(app.world()) {
            return;
        }
        app.add_plugins(SpringPropertyPlugin::<Layer<P, L>>::default());
        app.try_register_required_components::<LayerSpring<P, L>, SpringLayers<P>>()
            .ok();
        app.add_observer(fold_into_base::<P, L>);
        add_layered_property::<P>(app);
    }

    fn is_unique(&self) -> bool {
        false
    }
}

/// The systems of property `P`'s layers, once.
pub(crate) fn add_layered_property<P: SpringProperty<Space: LayerSpace>>(app: &mut App) {
    #[derive(Resource)]
    struct Added<P>(PhantomData<fn() -> P>);
    if app.world().contains_resource::<Added<P>>() {
        return;
    }
    app.insert_resource(Added::<P>(PhantomData));
    app.add_observer(touch_on_return::<P>);
    app.configure_sets(PreUpdate, LayerSystems).configure_sets(
        PostUpdate,
        LayerSystems
            .in_set(AnimationSystems)
            .after(SpringSystems)
            .before(TransformSystems::Propagate),
    );
    let stacks = [TypeId::of::<SpringLayers<P>>()];
    add_systems_on_first_use(app, &stacks, PreUpdate, |schedule| {
        schedule.add_systems(
            take_off::<P>
                .in_set(LayerSystems)
                .run_if(any_with_component::<SpringLayers<P>>),
        );
    });
    add_systems_on_first_use(app, &stacks, PostUpdate, |schedule| {
        schedule.add_systems(
            (
                show::<P>,
                warn_missing::<SpringLayers<P>, P::Component>(
                    "layers are shown on the component their property is a field of; add it",
                ),
            )
                .in_set(LayerSystems)
                .run_if(any_with_component::<SpringLayers<P>>),
        );
    });
}

/// The stacks to show or take off: those whose layers moved or were shown or taken off since,
/// and those whose property's component was put back (removed and inserted again).
type Moved<P> = Or<(
    Changed<SpringLayers<P>>,
    Added<<P as SpringProperty>::Component>,
)>;

/// An entity enabled again (Bevy's `Disabled` removed): the systems did not see its stack
/// meanwhile, so it is looked at afresh.
fn touch_on_return<P: SpringProperty<Space: LayerSpace>>(
    returning: On<Remove, Disabled>,
    mut world: DeferredWorld,
) {
    if let Some(mut layers) = world.get_mut::<SpringLayers<P>>(returning.entity) {
        layers.set_changed();
    }
}

/// `PostUpdate`: shows every stack whose layers moved, or that was taken off since it was last
/// shown, on its property's base value. Showing the value of the last frame again (layers held
/// still on a still base) does not mark the property changed: nothing downstream sees a change.
fn show<P: SpringProperty<Space: LayerSpace>>(
    mut stacks: Query<(&mut SpringLayers<P>, &mut P::Component), Moved<P>>,
) {
    for (mut layers, mut component) in &mut stacks {
        let base = P::get(&component);
        let value = layers.apply(base);
        if P::Space::same(value, base, FastPath) {
            // Nothing to show (every layer zero): nothing to take off either.
            layers.bypass_change_detection().last = None;
            continue;
        }
        if !P::Space::is_valid(value) {
            warn_once!(
                "bevy_sprung: layers of {} made a value that is not valid; not shown",
                P::short_type_path()
            );
            continue;
        }
        if layers
            .last
            .is_some_and(|last| P::Space::same(last, value, FastPath))
        {
            P::set(component.bypass_change_detection(), value);
        } else {
            P::set(&mut component, value);
        }
        layers.shown = Some(Shown { base, value });
        layers.last = Some(value);
    }
}

/// `PreUpdate`: takes the layers shown last frame off, without marking the property changed
/// (they are shown again before anything downstream reads it). Where nothing else wrote the
/// property since, the base comes back bit for bit; otherwise the layers are taken off what was
/// written.
fn take_off<P: SpringProperty<Space: LayerSpace>>(
    mut stacks: Query<(&mut SpringLayers<P>, &mut P::Component), Moved<P>>,
) {
    for (mut layers, mut component) in &mut stacks {
        let Some(shown) = layers.shown else {
            continue;
        };
        layers.shown = None;
        let current = P::get(&component);
        let base = if component.is_added() {
            // The component was put back since it was shown: what it holds is a base.
            current
        } else if P::Space::same(current, shown.value, FastPath) {
            shown.base
        } else {
            layers.remove(current)
        };
        if P::Space::is_valid(base) {
            P::set(component.bypass_change_detection(), base);
        }
    }
}

/// A layer's spring removed mid-flight: its offset joins the base, so that nothing jumps (a
/// base spring then carries the value home).
fn fold_into_base<P, L>(
    removed: On<Remove, LayerSpring<P, L>>,
    mut stacks: Query<(&mut SpringLayers<P>, &mut P::Component)>,
) where
    P: SpringProperty<Space: LayerSpace>,
    L: TypePath + Send + Sync + 'static,
{
    if let Ok((mut layers, mut component)) = stacks.get_mut(removed.entity) {
        layers.fold::<L>(&mut component);
    }
}

impl<P: SpringProperty<Space: LayerSpace>> SpringLayers<P> {
    /// Removes layer `L`, its offset joining the base so that the value shown does not jump
    /// (what an effect that writes a layer does when it is removed).
    pub fn fold<L: 'static>(&mut self, component: &mut P::Component) {
        let Some(offset) = self.forget(TypeId::of::<L>()) else {
            return;
        };
        match self.shown {
            // Shown: the value stays, and the base is what the other layers show as it.
            Some(shown) => {
                let base = self.remove(shown.value);
                self.shown = Some(Shown {
                    base,
                    value: shown.value,
                });
            }
            // Taken off (removed between `PreUpdate` and `PostUpdate`): the property holds the
            // base, which takes the offset.
            None if offset != LayerOf::<P>::default() => {
                let value = P::Space::apply(P::get(component), offset);
                if P::Space::is_valid(value) {
                    P::set(component, value);
                }
            }
            None => {}
        }
    }
}
