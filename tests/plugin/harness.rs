//! Test helpers: headless apps with manual time, and the exact reference the plugin must match.

use std::time::Duration;

use bevy::prelude::*;
use bevy::time::TimeUpdateStrategy;
use bevy_sprung::prelude::*;
use bevy_sprung::property::SpringProperty;
use bevy_sprung::spring::{SpringAsleep, SpringMotion};
use sprung::SpringState;

/// A headless app with the spring plugin, advancing `1/fps` seconds per update. Like every
/// Bevy app, its first update has `dt = 0`.
pub(crate) fn app(fps: u32) -> App {
    app_with(fps, SpringPlugins::default())
}

/// [`app`] with a configured plugin.
pub(crate) fn app_with(fps: u32, plugin: SpringPlugins) -> App {
    let mut app = App::new();
    app.add_plugins((MinimalPlugins, TransformPlugin, plugin))
        .insert_resource(TimeUpdateStrategy::ManualDuration(frame(fps)));
    app
}

/// A primary window of `width × height` logical pixels (scale factor 1): what a camera's view
/// is measured in.
pub(crate) fn primary_window(world: &mut World, width: u32, height: u32) -> Entity {
    world
        .spawn((
            bevy::window::Window {
                resolution: bevy::window::WindowResolution::new(width, height)
                    .with_scale_factor_override(1.0),
                ..default()
            },
            bevy::window::PrimaryWindow,
        ))
        .id()
}

/// One frame at `fps`, as the `Duration` Bevy adds (whole nanoseconds).
pub(crate) fn frame(fps: u32) -> Duration {
    Duration::from_secs_f64(1.0 / f64::from(fps))
}

/// Runs frames whose times cycle through `pattern` (seconds) until `seconds` of game time have
/// passed, calling `each` after every frame with the game time elapsed.
pub(crate) fn run_pattern(
    app: &mut App,
    pattern: &[f64],
    seconds: f64,
    mut each: impl FnMut(&mut App, f64),
) {
    let elapsed = |app: &App| app.world().resource::<Time<Virtual>>().elapsed_secs_f64();
    for &dt in pattern.iter().cycle() {
        if elapsed(app) >= seconds {
            break;
        }
        app.insert_resource(TimeUpdateStrategy::ManualDuration(Duration::from_secs_f64(
            dt,
        )));
        app.update();
        let now = elapsed(app);
        each(app, now);
    }
}

/// Runs `frames` updates.
pub(crate) fn run(app: &mut App, frames: u32) {
    for _ in 0..frames {
        app.update();
    }
}

/// Spawns a `Transform` at `from` springing toward `to`.
pub(crate) fn spawn_translation(app: &mut App, spring: Spring, from: Vec3, to: Vec3) -> Entity {
    app.world_mut()
        .spawn((
            Transform::from_translation(from),
            TranslationSpring::new(spring, to),
        ))
        .id()
}

/// A thousand translation springs in one table (several of the blocks of rows whose change
/// ticks the step tests together), from `x = 0, 1, …` toward `target`.
pub(crate) fn many_translations(app: &mut App, spring: Spring, target: Vec3) -> Vec<Entity> {
    (0..1000_u16)
        .map(|i| spawn_translation(app, spring, Vec3::X * f32::from(i), target))
        .collect()
}

/// Asserts that the entity's translation is one exact 60 fps step of `spring` from `from`,
/// moving at `velocity`, toward `target` (within 1e-4).
pub(crate) fn assert_stepped_from(
    app: &App,
    entity: Entity,
    spring: Spring,
    (from, velocity): (Vec3, Vec3),
    target: Vec3,
) {
    let expected = spring
        .transition(1.0 / 60.0)
        .step(SpringState::new(from, velocity), target)
        .position;
    let moved = translation(app, entity);
    assert!(moved.distance(expected) < 1e-4, "{moved} vs {expected}");
}

/// The entity's translation.
pub(crate) fn translation(app: &App, entity: Entity) -> Vec3 {
    app.world().get::<Transform>(entity).unwrap().translation
}

/// The entity's translation spring.
pub(crate) fn translation_spring(app: &App, entity: Entity) -> TranslationSpring {
    *app.world().get::<TranslationSpring>(entity).unwrap()
}

/// Runs `frames` updates and returns the targets the entity's translation spring had, each
/// once, in the order they came.
pub(crate) fn targets_visited(app: &mut App, entity: Entity, frames: u32) -> Vec<Vec3> {
    let mut visited = Vec::new();
    for _ in 0..frames {
        app.update();
        let target = translation_spring(app, entity).target();
        if visited.last() != Some(&target) {
            visited.push(target);
        }
    }
    visited
}

/// Whether the entity's spring on `P` sleeps.
pub(crate) fn asleep<P: SpringProperty>(app: &App, entity: Entity) -> bool {
    app.world().get::<SpringAsleep<P>>(entity).is_some()
}

/// Virtual seconds elapsed.
pub(crate) fn elapsed(app: &App) -> f64 {
    app.world().resource::<Time<Virtual>>().elapsed_secs_f64()
}

/// The exact state, in `f64`, of a 1D spring released at rest at `from` toward `to` after
/// `seconds`: what every frame rate must reproduce.
pub(crate) fn exact(spring: &Spring, from: f32, to: f32, seconds: f64) -> SpringState<f64> {
    sprung::Spring::<f64>::from(*spring)
        .transition(seconds)
        .step(SpringState::new(f64::from(from), 0.0), f64::from(to))
}

/// Runs `frames` updates, asserting after each that the translation springs of `a` and `b` are
/// in the same state, bit for bit: the same translation and the same velocity.
pub(crate) fn assert_move_alike(app: &mut App, (a, b): (Entity, Entity), frames: u32) {
    for frame in 0..frames {
        app.update();
        assert_eq!(translation(app, a), translation(app, b), "frame {frame}");
        assert_eq!(
            motion::<Translation>(app, a).velocity(),
            motion::<Translation>(app, b).velocity(),
            "frame {frame}"
        );
    }
}

/// The motion of the entity's spring on property `P`.
pub(crate) fn motion<P: SpringProperty>(app: &App, entity: Entity) -> SpringMotion<P> {
    *app.world().get::<SpringMotion<P>>(entity).unwrap()
}

/// A small, seeded generator (`SplitMix64`): the randomized tests are deterministic.
pub(crate) struct Random(pub(crate) u64);

impl Random {
    pub(crate) fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in `[0, 1)`.
    pub(crate) fn unit(&mut self) -> f32 {
        #[expect(clippy::cast_precision_loss, reason = "24 random bits")]
        let unit = (self.next() >> 40) as f32 / (1_u32 << 24) as f32;
        unit
    }

    /// Uniform in `[-scale, scale)`.
    pub(crate) fn symmetric(&mut self, scale: f32) -> f32 {
        scale * (2.0 * self.unit() - 1.0)
    }

    /// Uniform in `0..n` (`n > 0`).
    pub(crate) fn below(&mut self, n: usize) -> usize {
        usize::try_from(self.next() % n as u64).unwrap()
    }

    /// True with probability `p`.
    pub(crate) fn chance(&mut self, p: f32) -> bool {
        self.unit() < p
    }

    /// One of `items`, uniformly.
    pub(crate) fn pick<T: Copy>(&mut self, items: &[T]) -> T {
        items[self.below(items.len())]
    }
}

/// Loads the test skin (`assets/models/tail.gltf`: four bones in a chain, one skinned mesh,
/// one clip that turns the second bone) into `app`, adding the asset, scene, mesh, animation
/// and glTF plugins, and updates until its scene has spawned. Returns the clip and the four
/// bones, root first, with their animation target ids.
pub(crate) fn load_tail(
    app: &mut App,
) -> (
    Handle<bevy::animation::AnimationClip>,
    [(Entity, bevy::animation::AnimationTargetId); 4],
) {
    use bevy::animation::{AnimationClip, AnimationPlugin, AnimationTargetId};
    use bevy::gltf::{GltfAssetLabel, GltfPlugin};
    use bevy::mesh::MeshPlugin;
    use bevy::world_serialization::{WorldAssetRoot, WorldSerializationPlugin};

    app.add_plugins((
        AssetPlugin::default(),
        WorldSerializationPlugin,
        MeshPlugin,
        AnimationPlugin,
        GltfPlugin::default(),
    ));
    app.finish();
    app.cleanup();
    let server = app.world().resource::<AssetServer>().clone();
    let scene = server.load(GltfAssetLabel::Scene(0).from_asset("models/tail.gltf"));
    let clip: Handle<AnimationClip> =
        server.load(GltfAssetLabel::Animation(0).from_asset("models/tail.gltf"));
    app.world_mut().spawn(WorldAssetRoot(scene.clone()));
    let bones = |app: &mut App| {
        let mut named = app
            .world_mut()
            .query::<(Entity, &Name, &AnimationTargetId)>();
        let found = ["bone", "bone.001", "bone.002", "bone.003"].map(|name| {
            named
                .iter(app.world())
                .find_map(|(entity, found, &id)| (found.as_str() == name).then_some((entity, id)))
        });
        found
            .iter()
            .all(Option::is_some)
            .then(|| found.map(Option::unwrap))
    };
    let start = std::time::Instant::now();
    loop {
        if let Some(bones) = bones(app)
            && server.is_loaded(&clip)
        {
            return (clip, bones);
        }
        assert!(
            start.elapsed().as_secs() < 10,
            "the glTF did not load: scene {:?}, clip {:?}",
            server.load_state(&scene),
            server.load_state(&clip)
        );
        app.update();
        std::thread::sleep(Duration::from_millis(2));
    }
}
