//! Springs and choreography as assets: RON files loaded with Bevy's `AssetServer`, referenced by
//! handle from components, reloaded live with Bevy's `file_watcher` feature.
//!
//! - `*.spring.ron` is a [`SpringPreset`]: spring parameters in any parametrisation and
//!   optionally rest tolerances. An entity with [`UseSpringPreset`] gives them to every spring
//!   it has, and one with [`UsePropertyPreset<P>`] to its spring on property `P` only (that one
//!   wins for `P`), when the file loads and each time it changes.
//! - `*.sequence.ron` is a [`SequencePreset`]: a choreography (steps, delay, repeats). An
//!   entity with [`UseSequencePreset<P>`] gets the [`SpringSequence<P>`] it describes, its
//!   targets read as property `P`'s values; edited, it restarts.
//!
//! An invalid file fails to load with an error that names the file, the line and column, and
//! what is wrong (an unknown field, an invalid spring, a target that is not the property's
//! type); it never panics, and a spring keeps what it had.

use core::fmt;
use core::marker::PhantomData;

use bevy::asset::io::Reader;
use bevy::asset::{AssetLoader, LoadContext};
use bevy::prelude::*;
use serde::Deserialize;
use serde::de::DeserializeOwned;
use sprung::{RestThreshold, Spring};

use crate::choreography::{Advance, OnInterrupt, Repeat, SpringSequence};
use crate::property::{SpringProperty, ValueOf};
use crate::spring::{
    PropertySpring, PropertySystems, SpringPhase, SpringUpdate, add_property_systems,
    add_systems_on_first_use, first_use,
};

/// The RON dialect the files are read in: `Some(…)` may be left out of optional fields.
fn ron_options() -> ron::Options {
    ron::Options::default().with_default_extension(ron::extensions::Extensions::IMPLICIT_SOME)
}

/// Spring parameters (and optionally rest tolerances) in a `*.spring.ron` file:
///
/// ```ron
/// (
///     spring: (duration: 0.35, bounce: 0.2),   // any parametrisation, or (preset: snappy)
///     rest: (offset: 0.5, speed: 5.0),         // optional, in the property's units
/// )
/// ```
///
/// # Example
/// ```
/// use bevy_sprung::asset::SpringPreset;
///
/// let preset = SpringPreset::from_ron(b"(spring: (half_life: 0.1))").unwrap();
/// assert!((preset.spring.half_life().unwrap() - 0.1).abs() < 1e-6);
/// let error = SpringPreset::from_ron(b"(spring: (half_life: -1.0))").unwrap_err();
/// assert!(error.to_string().contains("half-life must be positive"));
/// ```
#[derive(Asset, TypePath, Debug, Clone, Copy, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SpringPreset {
    /// The spring parameters.
    pub spring: Spring<f32>,
    /// Rest tolerances, if the file sets them.
    #[serde(default)]
    pub rest: Option<RestThreshold<f32>>,
}

impl SpringPreset {
    /// Reads a preset from RON.
    ///
    /// # Errors
    /// [`SpringAssetError::Ron`] for text that is not a valid preset (syntax, an unknown field,
    /// invalid spring parameters), with its position.
    pub fn from_ron(bytes: &[u8]) -> Result<Self, SpringAssetError> {
        ron_options()
            .from_bytes(bytes)
            .map_err(SpringAssetError::Ron)
    }
}

/// One step of a [`SequencePreset`], its target not yet read as any property's value.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SequenceStepPreset {
    /// The target, read as the property's value when the sequence is made.
    pub target: ron::Value,
    /// When the sequence moves on (on settle unless the file says otherwise).
    #[serde(default = "on_settle")]
    pub advance: Advance,
    /// Spring parameters for this step.
    #[serde(default)]
    pub spring: Option<Spring<f32>>,
}

fn on_settle() -> Advance {
    Advance::OnSettle
}

fn once() -> Repeat {
    Repeat::Once
}

fn cancel() -> OnInterrupt {
    OnInterrupt::Cancel
}

/// A choreography in a `*.sequence.ron` file:
///
/// ```ron
/// (
///     delay: 0.2,                                  // optional
///     repeat: Forever,                             // Once (default), Times(3), Forever
///     ping_pong: true,                             // optional
///     on_interrupt: Pause,                         // Cancel (default) or Pause
///     steps: [
///         (target: (1.08, 1.08, 1.0), advance: After(0.45), spring: (preset: gentle)),
///         (target: (1.0, 1.0, 1.0), advance: OnSettle),
///     ],
/// )
/// ```
///
/// The targets are read as the property's values ([`UseSequencePreset<P>`]), so one file can
/// drive any property whose values it spells (a `Vec3` is `(x, y, z)`, a `Color` is
/// `Srgba((red: 1.0, green: 0.5, blue: 0.0, alpha: 1.0))`, a `Val` is `Px(200.0)`).
///
/// # Example
/// ```
/// use bevy::prelude::*;
/// use bevy_sprung::asset::SequencePreset;
/// use bevy_sprung::prelude::*;
///
/// let preset = SequencePreset::from_ron(b"(steps: [(target: (0.0, 10.0, 0.0)), (target: (0.0, 0.0, 0.0))])").unwrap();
/// let sequence = preset.sequence::<Translation>().unwrap();
/// assert_eq!(sequence.steps()[0].target, Vec3::new(0.0, 10.0, 0.0));
/// // A target the property cannot read is an error that says which step.
/// let error = preset.sequence::<bevy_sprung::spin::SpinAngle>().unwrap_err();
/// assert!(error.to_string().contains("step 0"));
/// ```
#[derive(Asset, TypePath, Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SequencePreset {
    /// Seconds before the first step.
    #[serde(default)]
    pub delay: f32,
    /// How many times the steps play.
    #[serde(default = "once")]
    pub repeat: Repeat,
    /// Back and forth instead of cycling.
    #[serde(default)]
    pub ping_pong: bool,
    /// What an interruption does.
    #[serde(default = "cancel")]
    pub on_interrupt: OnInterrupt,
    /// The steps.
    pub steps: Vec<SequenceStepPreset>,
}

impl SequencePreset {
    /// Reads a choreography from RON.
    ///
    /// # Errors
    /// [`SpringAssetError::Ron`] for text that is not a valid choreography, with its position.
    pub fn from_ron(bytes: &[u8]) -> Result<Self, SpringAssetError> {
        ron_options()
            .from_bytes(bytes)
            .map_err(SpringAssetError::Ron)
    }

    /// The sequence this describes for property `P`, its targets read as `P`'s values.
    ///
    /// # Errors
    /// [`SpringAssetError::Target`] for a target that is not a valid value of `P`.
    pub fn sequence<P>(&self) -> Result<SpringSequence<P>, SpringAssetError>
    where
        P: SpringProperty,
        ValueOf<P>: DeserializeOwned,
    {
        let mut sequence = SpringSequence::<P>::new()
            .delayed(self.delay)
            .repeat(self.repeat)
            .on_interrupt(self.on_interrupt);
        if self.ping_pong {
            sequence = sequence.ping_pong();
        }
        for (index, step) in self.steps.iter().enumerate() {
            let target: ValueOf<P> =
                step.target
                    .clone()
                    .into_rust()
                    .map_err(|error| SpringAssetError::Target {
                        step: index,
                        property: P::short_type_path(),
                        message: error.to_string(),
                    })?;
            sequence = sequence.step(target, step.advance);
            if let Some(spring) = step.spring {
                sequence = sequence.with_spring(spring);
            }
        }
        Ok(sequence)
    }
}

/// Why a spring asset could not be read.
#[derive(Debug)]
#[non_exhaustive]
pub enum SpringAssetError {
    /// The file could not be read.
    Io(std::io::Error),
    /// The text is not a valid preset or choreography: syntax, an unknown field, invalid spring
    /// parameters.
    Ron(ron::error::SpannedError),
    /// A choreography's target is not a value of the property it drives.
    Target {
        /// The step.
        step: usize,
        /// The property.
        property: &'static str,
        /// What is wrong with the value.
        message: String,
    },
}

impl fmt::Display for SpringAssetError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Io(error) => write!(f, "could not read the file: {error}"),
            Self::Ron(error) => write!(f, "{error}"),
            Self::Target {
                step,
                property,
                message,
            } => write!(
                f,
                "the target of step {step} is not a value of property {property}: {message}"
            ),
        }
    }
}

impl core::error::Error for SpringAssetError {}

/// The whole file a loader reads.
async fn read_all(reader: &mut dyn Reader) -> Result<Vec<u8>, SpringAssetError> {
    let mut bytes = Vec::new();
    reader
        .read_to_end(&mut bytes)
        .await
        .map_err(SpringAssetError::Io)?;
    Ok(bytes)
}

/// Loads `*.spring.ron` files as [`SpringPreset`]s.
#[derive(Debug, Default, TypePath)]
pub struct SpringPresetLoader;

impl AssetLoader for SpringPresetLoader {
    type Asset = SpringPreset;
    type Settings = ();
    type Error = SpringAssetError;

    async fn load(
        &self,
        reader: &mut dyn Reader,
        _settings: &(),
        _context: &mut LoadContext<'_>,
    ) -> Result<SpringPreset, SpringAssetError> {
        SpringPreset::from_ron(&read_all(reader).await?)
    }

    fn extensions(&self) -> &[&str] {
        &["spring.ron"]
    }
}

/// Loads `*.sequence.ron` files as [`SequencePreset`]s.
#[derive(Debug, Default, TypePath)]
pub struct SequencePresetLoader;

impl AssetLoader for SequencePresetLoader {
    type Asset = SequencePreset;
    type Settings = ();
    type Error = SpringAssetError;

    async fn load(
        &self,
        reader: &mut dyn Reader,
        _settings: &(),
        _context: &mut LoadContext<'_>,
    ) -> Result<SequencePreset, SpringAssetError> {
        SequencePreset::from_ron(&read_all(reader).await?)
    }

    fn extensions(&self) -> &[&str] {
        &["sequence.ron"]
    }
}

/// Gives the [`SpringPreset`] at this handle to every spring of the entity (each property's
/// spring takes its parameters, and its rest tolerances if the preset sets them) when the
/// preset loads, and again each time it changes (live, with Bevy's `file_watcher`).
///
/// # Example
/// ```no_run
/// use bevy::prelude::*;
/// use bevy_sprung::asset::UseSpringPreset;
/// use bevy_sprung::prelude::*;
///
/// fn spawn(mut commands: Commands, assets: Res<AssetServer>) {
///     commands.spawn((
///         Transform::default(),
///         TranslationSpring::new(Spring::default(), Vec3::X * 100.0),
///         UseSpringPreset(assets.load("springs/snappy.spring.ron")),
///     ));
/// }
/// ```
#[derive(Component, Reflect, Debug, Clone, PartialEq, Eq)]
#[component(on_add = first_use::<Self>)]
#[reflect(Component, Debug, Clone)]
pub struct UseSpringPreset(pub Handle<SpringPreset>);

/// The preset asset `A` at `handle`, applied to what this entity springs on property `P`: when
/// it loads, and again each time it changes. Used by its two names,
/// [`UsePropertyPreset<P>`] (a [`SpringPreset`] for the spring on `P`) and
/// [`UseSequencePreset<P>`] (a [`SequencePreset`], the choreography of `P`).
#[derive(Component, Reflect)]
#[component(on_add = first_use::<Self>)]
#[reflect(Component)]
pub struct UsePreset<A: Asset, P: SpringProperty> {
    /// The preset.
    pub handle: Handle<A>,
    #[reflect(ignore)]
    property: PhantomData<fn() -> P>,
}

impl<A: Asset, P: SpringProperty> UsePreset<A, P> {
    /// The preset at `handle`, for property `P`.
    #[must_use]
    pub fn new(handle: Handle<A>) -> Self {
        Self {
            handle,
            property: PhantomData,
        }
    }
}

impl<A: Asset, P: SpringProperty> Clone for UsePreset<A, P> {
    fn clone(&self) -> Self {
        Self::new(self.handle.clone())
    }
}

impl<A: Asset, P: SpringProperty> fmt::Debug for UsePreset<A, P> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("UsePreset")
            .field("asset", &A::short_type_path())
            .field("property", &P::short_type_path())
            .field("handle", &self.handle)
            .finish()
    }
}

/// Gives the [`SpringPreset`] at this handle to the entity's spring on property `P` only (as
/// [`UseSpringPreset`] does for every spring of the entity, which it overrides for `P`): when
/// the preset loads, and again each time it changes.
///
/// # Example
/// ```no_run
/// use bevy::prelude::*;
/// use bevy_sprung::asset::{UsePropertyPreset, UseSpringPreset};
/// use bevy_sprung::prelude::*;
/// use bevy_sprung::transform::Scale;
///
/// fn spawn(mut commands: Commands, assets: Res<AssetServer>) {
///     commands.spawn((
///         Transform::default(),
///         TranslationSpring::new(Spring::default(), Vec3::X * 100.0),
///         ScaleSpring::new(Spring::default(), Vec3::ONE),
///         // Every spring smooth, but the scale bouncy.
///         UseSpringPreset(assets.load("springs/smooth.spring.ron")),
///         UsePropertyPreset::<Scale>::new(assets.load("springs/bouncy.spring.ron")),
///     ));
/// }
/// ```
pub type UsePropertyPreset<P> = UsePreset<SpringPreset, P>;

/// Gives this entity the [`SpringSequence<P>`] that the [`SequencePreset`] at this handle
/// describes, when it loads, and again (from the start) each time it changes.
pub type UseSequencePreset<P> = UsePreset<SequencePreset, P>;

/// Whether an asset changed this frame (loaded or modified), by id.
fn changed<A: Asset>(events: &mut MessageReader<AssetEvent<A>>) -> Vec<AssetId<A>> {
    events
        .read()
        .filter_map(|event| match event {
            AssetEvent::LoadedWithDependencies { id } | AssetEvent::Modified { id } => Some(*id),
            _ => None,
        })
        .collect()
}

/// Gives presets that loaded or changed to the springs on property `P` that use them (through
/// [`UsePropertyPreset<P>`], or else [`UseSpringPreset`]), and presets that are already loaded
/// to springs that started using them.
fn apply_presets<P>(
    mut events: MessageReader<AssetEvent<SpringPreset>>,
    presets: Res<Assets<SpringPreset>>,
    mut every_spring: Query<
        (Ref<UseSpringPreset>, &mut PropertySpring<P>),
        Without<UsePropertyPreset<P>>,
    >,
    mut this_property: Query<(Ref<UsePropertyPreset<P>>, &mut PropertySpring<P>)>,
) where
    P: SpringProperty,
{
    let changed = changed(&mut events);
    let uses = every_spring
        .iter_mut()
        .map(|(uses, spring)| (uses.is_changed(), uses.0.id(), spring))
        .chain(
            this_property
                .iter_mut()
                .map(|(uses, spring)| (uses.is_changed(), uses.handle.id(), spring)),
        );
    for (started, preset, mut spring) in uses {
        if !(started || changed.contains(&preset)) {
            continue;
        }
        if let Some(preset) = presets.get(preset) {
            spring.set_spring(preset.spring);
            if let Some(rest) = preset.rest {
                spring.set_rest(rest);
            }
        }
    }
}

/// Gives entities the sequence their [`SequencePreset`] describes for property `P`, when it
/// loads or changes, or when they start using it.
pub(crate) fn apply_sequence_presets<P>(
    mut events: MessageReader<AssetEvent<SequencePreset>>,
    presets: Option<Res<Assets<SequencePreset>>>,
    uses: Query<(Entity, Ref<UseSequencePreset<P>>)>,
    mut commands: Commands,
) where
    P: SpringProperty,
    ValueOf<P>: DeserializeOwned,
{
    let Some(presets) = presets else {
        return;
    };
    let changed = changed(&mut events);
    for (entity, uses) in &uses {
        if !(uses.is_changed() || changed.contains(&uses.handle.id())) {
            continue;
        }
        let Some(preset) = presets.get(&uses.handle) else {
            continue;
        };
        match preset.sequence::<P>() {
            Ok(sequence) => {
                commands.entity(entity).try_insert(sequence);
            }
            Err(error) => {
                error!("bevy_sprung: a sequence preset cannot drive {entity}: {error}");
            }
        }
    }
}

/// The asset types and their loaders (part of [`SpringPlugins`](crate::SpringPlugins) with
/// feature `asset`). Presets apply to every property's springs; sequences from files need
/// [`SpringSequenceAssetPlugin<P>`] for their property (the built-in properties have it).
#[derive(Debug, Default, Clone, Copy)]
pub struct SpringAssetPlugin;

impl Plugin for SpringAssetPlugin {
    fn build(&self, app: &mut App) {
        app.register_type::<UseSpringPreset>();
    }

    /// The assets are registered once every plugin is built, so that `AssetPlugin` (from
    /// `DefaultPlugins`) may come before or after; an app without one has no assets to load
    /// and gets none.
    fn finish(&self, app: &mut App) {
        if !app.world().contains_resource::<AssetServer>()
            || app.world().contains_resource::<Assets<SpringPreset>>()
        {
            return;
        }
        app.init_asset::<SpringPreset>()
            .init_asset::<SequencePreset>()
            .init_asset_loader::<SpringPresetLoader>()
            .init_asset_loader::<SequencePresetLoader>();
    }

    fn is_unique(&self) -> bool {
        false
    }
}

/// Presets from files reach property `P`'s springs, in [`SpringPhase::Configure`]: what
/// [`SpringPropertyPlugin<P>`](crate::SpringPropertyPlugin) adds of assets. The system joins
/// with the first [`UseSpringPreset`] or [`UsePropertyPreset<P>`].
pub(crate) fn add_property<P: SpringProperty>(app: &mut App) {
    app.register_type::<UsePropertyPreset<P>>();
    let users = [
        core::any::TypeId::of::<UseSpringPreset>(),
        core::any::TypeId::of::<UsePropertyPreset<P>>(),
    ];
    add_systems_on_first_use(app, &users, SpringUpdate, |schedule| {
        schedule.add_systems(
            apply_presets::<P>
                .in_set(PropertySystems::<P>::phase(SpringPhase::Configure))
                .run_if(
                    resource_exists::<Assets<SpringPreset>>.and_then(
                        any_with_component::<UseSpringPreset>
                            .or_else(any_with_component::<UsePropertyPreset<P>>),
                    ),
                ),
        );
    });
}

/// Sequences from `*.sequence.ron` files for property `P`, whose values must be readable from
/// RON (`serde`). Adding it twice is harmless.
pub struct SpringSequenceAssetPlugin<P: SpringProperty>(PhantomData<fn() -> P>);

impl<P: SpringProperty> Default for SpringSequenceAssetPlugin<P> {
    fn default() -> Self {
        Self(PhantomData)
    }
}

impl<P> Plugin for SpringSequenceAssetPlugin<P>
where
    P: SpringProperty,
    ValueOf<P>: DeserializeOwned,
{
    fn build(&self, app: &mut App) {
        app.register_type::<UseSequencePreset<P>>();
        let springs = [core::any::TypeId::of::<PropertySpring<P>>()];
        add_property_systems(app, &springs, |schedule| {
            schedule.add_systems(
                apply_sequence_presets::<P>
                    .in_set(PropertySystems::<P>::phase(SpringPhase::Configure))
                    .run_if(any_with_component::<UseSequencePreset<P>>),
            );
        });
    }

    fn is_unique(&self) -> bool {
        false
    }
}

impl<P: SpringProperty> fmt::Debug for SpringSequenceAssetPlugin<P> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "SpringSequenceAssetPlugin<{}>", P::short_type_path())
    }
}
