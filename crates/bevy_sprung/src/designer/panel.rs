//! The designer's panel, on Bevy's own editor widgets (`bevy_feathers`): the fields of every
//! parametrisation, the presets, the plot and its readouts, A/B, the preview and its
//! controls, the spring of the game being tuned, save and copy-as-code.

use bevy::clipboard::Clipboard;
use bevy::feathers::controls::{
    FeathersButton, FeathersNumberInput, FeathersRadio, FeathersSlider, NumberInputValue,
    UpdateNumberInput,
};
use bevy::feathers::display::{label, label_dim};
use bevy::feathers::theme::{ThemeBackgroundColor, ThemedText};
use bevy::feathers::tokens;
use bevy::input_focus::tab_navigation::TabGroup;
use bevy::prelude::*;
use bevy::ui::Checked;
use bevy::ui_widgets::{
    Activate, RadioGroup, SliderPrecision, SliderStep, ValueChange, radio_self_update,
    slider_self_update,
};
use sprung::{Parameter, Regime, Spring};

use super::attach::{DesignerStatus, SaveSpringDesign, Tunables, TuneSpring, TunedSpring};
use super::model::{Parametrisation, SpringDesign};
use super::plot::{PLOT_SIZE, ResponsePlot};
use super::preview::{Playhead, PreviewThing, ShowsReference, TRAVEL};

/// The frame rates the preview offers.
const FRAME_RATES: [u16; 4] = [30, 60, 144, 240];

/// The designer's root node.
#[derive(Component, Clone, Copy, Debug, Default)]
pub(super) struct DesignerPanel;

/// A number field: which parameter of which group it edits.
#[derive(Component, Clone, Copy, Debug)]
pub(super) struct FieldInput {
    group: Parametrisation,
    parameter: Parameter,
}

impl Default for FieldInput {
    fn default() -> Self {
        Self {
            group: Parametrisation::Physical,
            parameter: Parameter::Mass,
        }
    }
}

/// The settle tolerance field, in percent of the distance.
#[derive(Component, Clone, Copy, Debug, Default)]
pub(super) struct ToleranceInput;

/// A frame-rate choice of the preview.
#[derive(Component, Clone, Copy, Debug, Default, PartialEq)]
pub(super) struct FrameRate(u16);

/// Texts the panel rewrites.
#[derive(Component, Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(super) enum Readout {
    /// Regime, overshoot, settle time, period and half-life.
    #[default]
    Numbers,
    /// The code that makes the spring.
    Code,
    /// The spring of the game being tuned.
    Tuned,
    /// What the designer last did.
    Status,
}

/// The plot's image node.
#[derive(Component, Clone, Copy, Debug, Default)]
pub(super) struct PlotView;

/// What a button does.
#[derive(Component, Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(super) enum Action {
    /// Start from the preset at this index of [`Spring::presets`].
    Preset(u8),
    /// Keep the spring as the reference (B).
    #[default]
    KeepAsReference,
    /// Swap A and B.
    Swap,
    /// Drop B.
    ClearReference,
    /// Restart the preview.
    Replay,
    /// Tune the previous or the next spring of the game.
    Cycle(i8),
    /// Save the `*.spring.ron`.
    Save,
    /// Copy the code to the clipboard.
    CopyCode,
}

fn button(caption: &'static str, action: Action) -> impl Scene {
    bsn! {
        @FeathersButton { @caption: bsn! { Text(caption) ThemedText } }
        template_value(action)
        on(act)
    }
}

fn row(children: impl SceneList) -> impl Scene {
    bsn! {
        Node {
            flex_direction: FlexDirection::Row,
            align_items: AlignItems::Center,
            column_gap: px(6),
            flex_wrap: FlexWrap::Wrap,
            row_gap: px(4),
        }
        Children [ {children} ]
    }
}

fn column(width: f32, children: impl SceneList) -> impl Scene {
    bsn! {
        Node {
            flex_direction: FlexDirection::Column,
            row_gap: px(5),
            width: px(width),
        }
        Children [ {children} ]
    }
}

fn field(group: Parametrisation, parameter: Parameter) -> impl Scene {
    let input = FieldInput { group, parameter };
    row(bsn_list![
        (label_dim(parameter_label(group, parameter)) Node { width: px(118) }),
        (
            @FeathersNumberInput
            Node { flex_grow: 1.0 }
            template_value(input)
            on(edit_field)
        ),
    ])
}

fn group(group: Parametrisation) -> impl Scene {
    let fields: Vec<_> = group.fields().iter().map(|&p| field(group, p)).collect();
    column(270.0, bsn_list![label(group.title()), { fields }])
}

/// What a field is called in its group (SwiftUI calls the damping ratio its damping fraction).
fn parameter_label(group: Parametrisation, parameter: Parameter) -> &'static str {
    match (group, parameter) {
        (Parametrisation::Response, Parameter::DampingRatio) => "damping fraction",
        (_, parameter) => parameter.name(),
    }
}

fn presets() -> impl Scene {
    let buttons: Vec<_> = Spring::<f32>::presets()
        .iter()
        .zip(0_u8..)
        .map(|((name, _), index)| button(name, Action::Preset(index)))
        .collect();
    row(buttons)
}

fn left_column() -> impl Scene {
    let groups: Vec<_> = Parametrisation::ALL.into_iter().map(group).collect();
    column(
        270.0,
        bsn_list![
            label("Presets"),
            presets(),
            { groups },
            row(bsn_list![
                button("Save .spring.ron", Action::Save),
                button("Copy code", Action::CopyCode),
            ]),
        ],
    )
}

fn lane(thing: PreviewThing, caption: &'static str) -> impl Scene {
    let (size, round) = match thing {
        PreviewThing::Sprite => (18.0, 9.0),
        PreviewThing::Button => (64.0, 6.0),
        PreviewThing::Camera => (64.0, 2.0),
    };
    let marker = |reference: bool| {
        let color = match (thing, reference) {
            (_, true) => Color::srgba(0.6, 0.6, 0.65, 0.45),
            (PreviewThing::Camera, false) => Color::NONE,
            (_, false) => Color::srgb(0.43, 0.75, 1.0),
        };
        let outline = if thing == PreviewThing::Camera && !reference {
            Color::srgb(1.0, 0.67, 0.31)
        } else {
            Color::NONE
        };
        let left = if thing == PreviewThing::Button {
            TRAVEL * 0.5
        } else {
            0.0
        };
        bsn! {
            Node {
                position_type: PositionType::Absolute,
                left: px(left),
                width: px(size),
                height: px(size * 0.6),
                border: px(2),
                border_radius: BorderRadius::all(px(round)),
            }
            BackgroundColor(color)
            BorderColor::all(outline)
            UiTransform
            template_value(thing)
        }
    };
    let target = bsn! {
        Node {
            position_type: PositionType::Absolute,
            left: px(TRAVEL + if thing == PreviewThing::Camera { 29.0 } else { 6.0 }),
            width: px(6),
            height: px(6),
        }
        BackgroundColor(Color::srgb(0.35, 0.63, 0.43))
    };
    column(
        560.0,
        bsn_list![
            label_dim(caption),
            (
                Node { height: px(size * 0.6), align_items: AlignItems::Center }
                Children [
                    {target},
                    ({marker(true)} ShowsReference),
                    {marker(false)},
                ]
            ),
        ],
    )
}

fn frame_rates() -> impl Scene {
    let radios: Vec<_> = FRAME_RATES
        .into_iter()
        .map(|fps| {
            bsn! {
                @FeathersRadio { @caption: bsn! { Text({format!("{fps} fps")}) ThemedText } }
                template_value(FrameRate(fps))
            }
        })
        .collect();
    bsn! {
        Node { flex_direction: FlexDirection::Row, column_gap: px(10) }
        RadioGroup
        on(radio_self_update)
        on(pick_frame_rate)
        Children [ {radios} ]
    }
}

fn right_column() -> impl Scene {
    column(
        570.0,
        bsn_list![
            row(bsn_list![
                button("<", Action::Cycle(-1)),
                button(">", Action::Cycle(1)),
                (label("") template_value(Readout::Tuned)),
            ]),
            (
                Node { width: px(PLOT_SIZE.x as f32), height: px(PLOT_SIZE.y as f32) }
                PlotView
                Children [
                    (
                        Node {
                            position_type: PositionType::Absolute,
                            width: px(1),
                            height: percent(100),
                        }
                        BackgroundColor(Color::srgba(1.0, 1.0, 1.0, 0.5))
                        Playhead
                    )
                ]
            ),
            label_dim("blue: x(t) of A, orange: v(t) of A, grey: B, dots: the preview's frames, green: settled"),
            (label("") template_value(Readout::Numbers)),
            row(bsn_list![
                label_dim("settle within %"),
                (
                    @FeathersNumberInput
                    Node { width: px(70) }
                    ToleranceInput
                    on(edit_tolerance)
                ),
                button("Keep as B", Action::KeepAsReference),
                button("Swap A/B", Action::Swap),
                button("Clear B", Action::ClearReference),
            ]),
            row(bsn_list![
                frame_rates(),
                label_dim("time scale"),
                (
                    @FeathersSlider { @min: 0.1, @max: 2.0, @value: 1.0 }
                    Node { width: px(120) }
                    SliderStep(0.05)
                    SliderPrecision(2)
                    on(slider_self_update)
                    on(set_time_scale)
                ),
                button("Replay", Action::Replay),
            ]),
            lane(PreviewThing::Sprite, "A sprite moving to its target"),
            lane(PreviewThing::Button, "A button's scale"),
            lane(PreviewThing::Camera, "A camera following a target that jumped"),
            (label("") template_value(Readout::Code)),
            (label("") template_value(Readout::Status)),
        ],
    )
}

/// The whole panel.
pub(super) fn panel() -> impl Scene {
    bsn! {
        #SpringDesigner
        DesignerPanel
        Node {
            position_type: PositionType::Absolute,
            right: px(0),
            top: px(0),
            height: percent(100),
            flex_direction: FlexDirection::Row,
            column_gap: px(14),
            padding: px(10),
        }
        ThemeBackgroundColor(tokens::WINDOW_BG)
        TabGroup
        Children [ left_column(), right_column() ]
    }
}

/// Spawns the panel, and shows the plot in it.
pub(super) fn spawn(mut commands: Commands) {
    commands.spawn_scene(panel());
}

/// Puts the plot's image in its node once the node exists.
pub(super) fn show_plot(
    mut commands: Commands,
    plot: Res<ResponsePlot>,
    views: Query<Entity, Added<PlotView>>,
) {
    for view in &views {
        commands
            .entity(view)
            .insert(ImageNode::new(plot.image.clone()));
    }
}

fn edit_field(
    change: On<ValueChange<f32>>,
    inputs: Query<&FieldInput>,
    mut design: ResMut<SpringDesign>,
    mut status: ResMut<DesignerStatus>,
) {
    let Ok(input) = inputs.get(change.source) else {
        return;
    };
    if !change.is_final {
        return;
    }
    match design.set_field(input.group, input.parameter, change.value) {
        Ok(()) => status.0.clear(),
        Err(error) => {
            status.0 = format!("Not set: {error}");
            // Show the fields as they are again.
            design.set_changed();
        }
    }
}

fn edit_tolerance(change: On<ValueChange<f32>>, mut design: ResMut<SpringDesign>) {
    let tolerance = change.value / 100.0;
    if change.is_final && tolerance > 0.0 && tolerance < 1.0 {
        design.tolerance = tolerance;
    } else if change.is_final {
        design.set_changed();
    }
}

fn set_time_scale(change: On<ValueChange<f32>>, mut design: ResMut<SpringDesign>) {
    if change.value > 0.0 {
        design.preview.time_scale = change.value;
    }
}

fn pick_frame_rate(
    change: On<ValueChange<Entity>>,
    rates: Query<&FrameRate>,
    mut design: ResMut<SpringDesign>,
) {
    if let Ok(rate) = rates.get(change.value) {
        design.preview.fps = f32::from(rate.0);
    }
}

fn act(
    activate: On<Activate>,
    actions: Query<&Action>,
    mut design: ResMut<SpringDesign>,
    mut status: ResMut<DesignerStatus>,
    mut clipboard: Option<ResMut<Clipboard>>,
    mut commands: Commands,
) {
    let Ok(&action) = actions.get(activate.entity) else {
        return;
    };
    match action {
        Action::Preset(index) => {
            if let Some((name, spring)) = Spring::presets().get(usize::from(index)) {
                design.set_spring(*spring);
                status.0 = format!("Preset {name}");
            }
        }
        Action::KeepAsReference => design.keep_as_reference(),
        Action::Swap => design.swap(),
        Action::ClearReference => design.clear_reference(),
        Action::Replay => design.set_changed(),
        Action::Cycle(step) => commands.run_system_cached_with(cycle, step),
        Action::Save => commands.trigger(SaveSpringDesign),
        Action::CopyCode => {
            let code = design.code();
            let copied = clipboard
                .as_mut()
                .is_some_and(|clipboard| clipboard.set_text(code.clone()).is_ok());
            info!("{code}");
            status.0 = if copied {
                format!("Copied {code}")
            } else {
                format!("No clipboard here; the code is in the log: {code}")
            };
        }
    }
}

/// Tunes the spring `step` places after (or before) the one tuned now, among every spring of
/// the properties the designer tunes; past either end, none (the preview alone).
fn cycle(In(step): In<i8>, world: &mut World) {
    let Some(tunables) = world.get_resource::<Tunables>().cloned() else {
        return;
    };
    let springs = tunables.springs(world);
    let now = world.resource::<TunedSpring>().0;
    let position = now.and_then(|tuned| springs.iter().position(|s| *s == tuned));
    // Positions 0..n are springs, n is "none": cycling wraps through all n + 1.
    let count = springs.len() + 1;
    let from = position.unwrap_or(springs.len());
    let next = if step < 0 {
        (from + count - 1) % count
    } else {
        (from + 1) % count
    };
    let target = springs.get(next).copied();
    world.trigger(TuneSpring(target));
}

/// Shows the design's values in the fields after it changed (not in the one being typed in).
pub(super) fn refresh_fields(
    design: Res<SpringDesign>,
    fields: Query<(Entity, &FieldInput)>,
    tolerance: Query<Entity, With<ToleranceInput>>,
    rates: Query<(Entity, &FrameRate, Has<Checked>)>,
    mut commands: Commands,
) {
    if !design.is_changed() {
        return;
    }
    for (entity, input) in &fields {
        if let Some(value) = design.field(input.parameter) {
            commands.trigger(UpdateNumberInput {
                entity,
                value: NumberInputValue::F32(value),
            });
        }
    }
    for entity in &tolerance {
        commands.trigger(UpdateNumberInput {
            entity,
            value: NumberInputValue::F32(design.tolerance * 100.0),
        });
    }
    for (entity, rate, checked) in &rates {
        let chosen = (f32::from(rate.0) - design.preview.fps).abs() < 0.5;
        if chosen && !checked {
            commands.entity(entity).insert(Checked);
        } else if !chosen && checked {
            commands.entity(entity).remove::<Checked>();
        }
    }
}

/// Rewrites the readouts, the code, the tuned spring's name and the status line.
pub(super) fn refresh_texts(
    design: Res<SpringDesign>,
    tuned: Res<TunedSpring>,
    status: Res<DesignerStatus>,
    names: Query<&Name>,
    mut texts: Query<(&Readout, &mut Text)>,
) {
    if !(design.is_changed() || tuned.is_changed() || status.is_changed()) {
        return;
    }
    for (readout, mut text) in &mut texts {
        let new = match readout {
            Readout::Numbers => numbers(&design),
            Readout::Code => design.code(),
            Readout::Tuned => tuned_label(tuned.0, &names),
            Readout::Status => status.0.clone(),
        };
        if text.0 != new {
            text.0 = new;
        }
    }
}

fn tuned_label(tuned: Option<super::attach::SpringRef>, names: &Query<&Name>) -> String {
    match tuned {
        Some(target) => {
            let name = names
                .get(target.entity)
                .map_or_else(|_| target.entity.to_string(), ToString::to_string);
            format!("Tuning {} of {name}", target.property_name)
        }
        None => "Preview only (< > picks a spring of the game)".into(),
    }
}

fn numbers(design: &SpringDesign) -> String {
    let readouts = design.readouts();
    let regime = match readouts.regime {
        Regime::Underdamped => "underdamped",
        Regime::CriticallyDamped => "critically damped",
        Regime::Overdamped => "overdamped",
        Regime::Undamped => "undamped",
        Regime::Unsprung => "unsprung",
        Regime::Free => "free",
    };
    let seconds = |value: Option<f32>| value.map_or_else(|| "-".into(), |s| format!("{s:.3} s"));
    format!(
        "{regime}  overshoot {:.1} %  settles in {}  period {}  half-life {}",
        readouts.overshoot * 100.0,
        seconds(readouts.settle_time),
        seconds(readouts.period),
        seconds(readouts.half_life),
    )
}
