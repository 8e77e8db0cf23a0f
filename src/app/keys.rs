//! Shoal's keys: one table ([`SHORTCUTS`]) that the key handler and the
//! *Keyboard* window (`?`) both read, so what the window says is what the
//! keys do.
//!
//! The keys work while the tank or a control has the focus (a control in the
//! page's accessible mirror passes them on, see `web/a11y_dom.rs`), never while
//! the student types in a text field. Space and Enter press the control with
//! the focus; arrows change a focused slider, and turn the camera when no
//! control has the focus.

use eframe::egui;

use crate::i18n::ts;
use crate::settings::{SPEED_MAX, SPEED_MIN, Scene, Settings};

/// Something a key asks of the app.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum KeyAction {
    PlayPause,
    Step,
    Reset,
    ResetView,
    /// The scene at this place in [`Scene::ALL`].
    Scene(usize),
    /// Halve (−1) or double (+1) the speed.
    Speed(i8),
    /// Turn the camera by this many points of drag (right, down).
    Turn(f32, f32),
    /// Zoom the camera by this factor.
    Zoom(f32),
    /// Select the next (+1) or previous (−1) animal, and say what it does.
    NextAnimal(i8),
    /// Turn the camera's following of the selected animal on or off.
    Follow,
    /// Read the whole tank in words.
    Describe,
    /// Open or close the *Keyboard* window.
    Help,
}

/// One shortcut as the *Keyboard* window lists it: the catalogue's ids of
/// its keys' names and of what it does.
pub struct Shortcut {
    pub keys: &'static str,
    pub does: &'static str,
}

impl Shortcut {
    /// The keys' names in the language in force (the keys stay the same).
    pub fn keys_text(&self) -> String {
        if self.keys == "keys-speed" {
            // A message cannot start with "[": the brackets come as variables.
            crate::tr!("keys-speed", slower = "[", faster = "]")
        } else {
            ts(self.keys).to_owned()
        }
    }

    /// What the keys do, in the language in force.
    pub fn does_text(&self) -> &'static str {
        ts(self.does)
    }
}

/// Every key, in the order the *Keyboard* window lists them.
pub const SHORTCUTS: &[Shortcut] = &[
    Shortcut {
        keys: "keys-play",
        does: "keys-play.does",
    },
    Shortcut {
        keys: "keys-step",
        does: "keys-step.does",
    },
    Shortcut {
        keys: "keys-reset",
        does: "keys-reset.does",
    },
    Shortcut {
        keys: "keys-scenes",
        does: "keys-scenes.does",
    },
    Shortcut {
        keys: "keys-speed",
        does: "keys-speed.does",
    },
    Shortcut {
        keys: "keys-arrows",
        does: "keys-arrows.does",
    },
    Shortcut {
        keys: "keys-zoom",
        does: "keys-zoom.does",
    },
    Shortcut {
        keys: "keys-view",
        does: "keys-view.does",
    },
    Shortcut {
        keys: "keys-next",
        does: "keys-next.does",
    },
    Shortcut {
        keys: "keys-follow",
        does: "keys-follow.does",
    },
    Shortcut {
        keys: "keys-describe",
        does: "keys-describe.does",
    },
    Shortcut {
        keys: "keys-tab",
        does: "keys-tab.does",
    },
    Shortcut {
        keys: "keys-help",
        does: "keys-help.does",
    },
];

/// Points of drag one arrow press turns the camera by.
const TURN_PER_PRESS: f32 = 40.0;
/// Zoom factor of one + press (− divides by it).
const ZOOM_PER_PRESS: f32 = 0.8;

/// The key actions of this frame's input. Nothing while the student types in
/// a text field; no camera arrows while a control has the focus (they move
/// the control).
pub fn key_actions(ctx: &egui::Context) -> Vec<KeyAction> {
    if ctx.text_edit_focused() {
        return Vec::new();
    }
    let control_focused = ctx.memory(|m| m.focused().is_some());
    ctx.input(|input| {
        let mut actions = Vec::new();
        for event in &input.events {
            let egui::Event::Key {
                key,
                pressed: true,
                modifiers,
                ..
            } = event
            else {
                continue;
            };
            if modifiers.ctrl || modifiers.alt || modifiers.mac_cmd || modifiers.command {
                continue;
            }
            use egui::Key;
            let action = match key {
                Key::Space if !control_focused => Some(KeyAction::PlayPause),
                Key::P => Some(KeyAction::PlayPause),
                Key::S => Some(KeyAction::Step),
                Key::R => Some(KeyAction::Reset),
                Key::V => Some(KeyAction::ResetView),
                Key::Num1 | Key::Num2 | Key::Num3 | Key::Num4 | Key::Num5 => {
                    let digits = [Key::Num1, Key::Num2, Key::Num3, Key::Num4, Key::Num5];
                    digits.iter().position(|d| d == key).map(KeyAction::Scene)
                }
                Key::OpenBracket => Some(KeyAction::Speed(-1)),
                Key::CloseBracket => Some(KeyAction::Speed(1)),
                Key::ArrowLeft if !control_focused => Some(KeyAction::Turn(-TURN_PER_PRESS, 0.0)),
                Key::ArrowRight if !control_focused => Some(KeyAction::Turn(TURN_PER_PRESS, 0.0)),
                Key::ArrowUp if !control_focused => Some(KeyAction::Turn(0.0, -TURN_PER_PRESS)),
                Key::ArrowDown if !control_focused => Some(KeyAction::Turn(0.0, TURN_PER_PRESS)),
                Key::Plus | Key::Equals => Some(KeyAction::Zoom(ZOOM_PER_PRESS)),
                Key::Minus => Some(KeyAction::Zoom(1.0 / ZOOM_PER_PRESS)),
                Key::N => Some(KeyAction::NextAnimal(1)),
                Key::B => Some(KeyAction::NextAnimal(-1)),
                Key::D => Some(KeyAction::Describe),
                Key::F => Some(KeyAction::Follow),
                Key::Questionmark => Some(KeyAction::Help),
                Key::Slash if modifiers.shift => Some(KeyAction::Help),
                _ => None,
            };
            actions.extend(action);
        }
        actions
    })
}

/// Applies the actions that only change settings; returns the others.
pub fn apply_to_settings(actions: Vec<KeyAction>, settings: &mut Settings) -> Vec<KeyAction> {
    let mut rest = Vec::new();
    for action in actions {
        match action {
            KeyAction::PlayPause => settings.paused = !settings.paused,
            KeyAction::Scene(i) => {
                if let Some(scene) = Scene::ALL.get(i) {
                    settings.scene = *scene;
                }
            }
            KeyAction::Speed(direction) => {
                let factor = if direction > 0 { 2.0 } else { 0.5 };
                settings.speed = (settings.speed * factor).clamp(SPEED_MIN, SPEED_MAX);
            }
            other => rest.push(other),
        }
    }
    rest
}

/// The animal after (`direction` +1) or before (−1) `current` among `animals`
/// (indices), wrapping round; the first (or last) when none is selected.
pub fn next_animal(animals: &[usize], current: Option<u32>, direction: i8) -> Option<u32> {
    let mut sorted = animals.to_vec();
    sorted.sort_unstable();
    sorted.dedup();
    if sorted.is_empty() {
        return None;
    }
    let at = current.and_then(|c| sorted.iter().position(|&a| a == c as usize));
    let n = sorted.len();
    let next = match (at, direction >= 0) {
        (None, true) => 0,
        (None, false) => n - 1,
        (Some(i), true) => (i + 1) % n,
        (Some(i), false) => (i + n - 1) % n,
    };
    Some(sorted[next] as u32)
}

/// The *Keyboard* window: every key from [`SHORTCUTS`].
pub fn help_window(ctx: &egui::Context, open: &mut bool, rects: &mut crate::ui::WidgetRects) {
    let mut still_open = *open;
    egui::Window::new(ts("keys-title"))
        // The same window whatever the language.
        .id(egui::Id::unique("Keyboard")) // words: the window's id, never shown
        .open(&mut still_open)
        .collapsible(false)
        .resizable(false)
        .default_width(460.0)
        // Over the tank, not over the controls the focus ring may be on.
        .anchor(egui::Align2::CENTER_CENTER, egui::vec2(120.0, 0.0))
        .show(ctx, |ui| {
            egui::Grid::new("keys")
                .num_columns(2)
                .min_col_width(150.0)
                .spacing([16.0, 6.0])
                .striped(true)
                .show(ui, |ui| {
                    for shortcut in SHORTCUTS {
                        ui.label(egui::RichText::new(shortcut.keys_text()).strong());
                        ui.label(shortcut.does_text());
                        ui.end_row();
                    }
                });
            ui.add_space(6.0);
            ui.label(ts("keys-screen-reader"));
            let close = ui.button(ts("keys-close"));
            rects.insert("keys_close", close.rect);
            if close.clicked() {
                *open = false;
            }
        });
    if !still_open {
        *open = false;
    }
}

impl super::ShoalApp {
    /// Reads this frame's keys: settings they change are changed in
    /// `settings`; the rest act on the app now or come back as panel actions.
    pub(super) fn keys(&mut self, settings: &mut Settings) -> Vec<crate::ui::PanelAction> {
        use crate::ui::PanelAction;
        let mut panel_actions = Vec::new();
        let actions = apply_to_settings(key_actions(&self.ctx), settings);
        for action in actions {
            match action {
                KeyAction::Step => panel_actions.push(PanelAction::Step),
                KeyAction::Reset => panel_actions.push(PanelAction::Reset),
                KeyAction::ResetView => panel_actions.push(PanelAction::ResetView),
                KeyAction::Turn(dx, dy) => {
                    self.camera.rotate(dx, dy);
                    self.camera_is_default = false;
                }
                KeyAction::Zoom(factor) => {
                    self.camera.zoom(factor);
                    self.camera_is_default = false;
                }
                KeyAction::NextAnimal(direction) => {
                    let class = settings.scene.class();
                    let side = crate::settings::Side::Left;
                    let animals: Vec<usize> = self.lab.runs()[0]
                        .selectable_animals(self.lab.draw_alpha())
                        .into_iter()
                        .map(|a| a.0)
                        .collect();
                    let next = next_animal(&animals, class.selected(settings, side), direction);
                    class.select(settings, side, next);
                    if class.selected(settings, side).is_some() {
                        self.describe_selection = true;
                    } else {
                        self.say(crate::tr!(
                            "keys-cannot-pick",
                            scene = class.facts().label()
                        ));
                    }
                }
                KeyAction::Describe => panel_actions.push(PanelAction::Describe),
                KeyAction::Follow => {
                    let class = settings.scene.class();
                    let words = match class.toggle_camera_follow(settings) {
                        Some(true) => ts("keys-following").to_owned(),
                        Some(false)
                            if class
                                .selected(settings, crate::settings::Side::Left)
                                .is_none() =>
                        {
                            ts("keys-select-first").to_owned()
                        }
                        Some(false) => ts("keys-not-following").to_owned(),
                        None => crate::tr!("keys-cannot-follow", scene = class.facts().label()),
                    };
                    self.say(words);
                }
                KeyAction::Help => self.keys_open = !self.keys_open,
                KeyAction::PlayPause | KeyAction::Scene(_) | KeyAction::Speed(_) => {}
            }
        }
        panel_actions
    }

    /// Says the whole tank in words: the notice shows them, the live region
    /// reads them.
    pub(super) fn describe_tank(&mut self) {
        let state = self.state_report();
        let histories: Vec<(&str, &crate::metrics_history::MetricsHistory)> = self
            .lab
            .runs()
            .iter()
            .map(|run| {
                let name = match run.side() {
                    crate::settings::Side::Left => ts("keys-left-tank"),
                    crate::settings::Side::Right => ts("keys-right-tank"),
                };
                (name, run.history())
            })
            .collect();
        let words = crate::a11y::describe::full(&state, &histories);
        // Shown too, until closed or the world is rebuilt (it speaks of it).
        self.notice =
            Some(crate::ui::Notice::info(words.clone()).about_world(self.lab.world_generation()));
        self.notice_said = Some(words.clone());
        self.say(words);
    }

    /// The live region's words for this frame, if it is time to say any.
    pub(super) fn narrate(&mut self, status: &crate::automation::StateReport, now_secs: f64) {
        // A new notice (a link that could not be opened, a download, an
        // error) is read once, before anything else.
        if status.notice != self.notice_said {
            self.notice_said = status.notice.clone();
            if let Some(notice) = &status.notice {
                self.say(notice.clone());
                return;
            }
        }
        if std::mem::take(&mut self.describe_selection)
            && let Some(words) = crate::a11y::describe::selected(status)
        {
            self.say(words);
            return;
        }
        if let Some(words) = self.narrator.observe(status, now_secs) {
            self.say(words);
        }
    }

    /// Says `words` to a screen reader (the page's polite live region); kept
    /// for `shoal.state()` too.
    pub(super) fn say(&mut self, words: String) {
        #[cfg(target_arch = "wasm32")]
        crate::web::announce(&words);
        self.last_said = Some(words);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_next_animal_wraps_round_both_ways() {
        let animals = [4, 1, 9];
        assert_eq!(next_animal(&animals, None, 1), Some(1));
        assert_eq!(next_animal(&animals, None, -1), Some(9));
        assert_eq!(next_animal(&animals, Some(1), 1), Some(4));
        assert_eq!(next_animal(&animals, Some(9), 1), Some(1));
        assert_eq!(next_animal(&animals, Some(1), -1), Some(9));
        assert_eq!(next_animal(&[], Some(1), 1), None);
    }

    /// Presses `key` once in a fresh context and returns the actions read.
    fn press(key: egui::Key, shift: bool, focus_a_control: bool) -> Vec<KeyAction> {
        let ctx = egui::Context::default();
        let mut actions = Vec::new();
        for frame in 0..2 {
            let mut input = egui::RawInput::default();
            if frame == 1 {
                input.events.push(egui::Event::Key {
                    key,
                    physical_key: None,
                    pressed: true,
                    repeat: false,
                    modifiers: egui::Modifiers {
                        shift,
                        ..Default::default()
                    },
                });
            }
            let mut output = ctx.run_ui(input, |ui| {
                let button = ui.button("a control");
                if focus_a_control && frame == 0 {
                    button.request_focus();
                }
                if frame == 1 {
                    actions = key_actions(ui.ctx());
                }
            });
            output.textures_delta.clear();
        }
        actions
    }

    #[test]
    fn every_listed_key_does_what_the_list_says() {
        use egui::Key;
        assert_eq!(press(Key::P, false, false), [KeyAction::PlayPause]);
        assert_eq!(press(Key::Space, false, false), [KeyAction::PlayPause]);
        assert_eq!(press(Key::Num3, false, false), [KeyAction::Scene(2)]);
        assert_eq!(
            press(Key::CloseBracket, false, false),
            [KeyAction::Speed(1)]
        );
        assert_eq!(press(Key::N, false, false), [KeyAction::NextAnimal(1)]);
        assert_eq!(press(Key::D, false, false), [KeyAction::Describe]);
        assert_eq!(press(Key::F, false, false), [KeyAction::Follow]);
        assert_eq!(press(Key::Questionmark, false, false), [KeyAction::Help]);
        assert!(
            matches!(press(Key::ArrowLeft, false, false)[..], [KeyAction::Turn(x, _)] if x < 0.0)
        );
        assert!(matches!(press(Key::Plus, false, false)[..], [KeyAction::Zoom(f)] if f < 1.0));
    }

    #[test]
    fn a_focused_control_keeps_space_and_the_arrows() {
        use egui::Key;
        assert!(press(Key::Space, false, true).is_empty());
        assert!(press(Key::ArrowLeft, false, true).is_empty());
        // The letters still work.
        assert_eq!(press(Key::P, false, true), [KeyAction::PlayPause]);
    }

    #[test]
    fn the_keyboard_list_reads_in_spanish_with_the_same_keys() {
        use crate::i18n::{Lang, with_lang};
        let spanish: Vec<(String, &str)> = with_lang(Lang::Es, || {
            SHORTCUTS
                .iter()
                .map(|s| (s.keys_text(), s.does_text()))
                .collect()
        });
        for (keys, does) in &spanish {
            assert!(
                !keys.starts_with("[keys") && !does.starts_with("[keys"),
                "{spanish:?}"
            );
        }
        assert_eq!(spanish[0].0, "Espacio o P");
        assert_eq!(spanish[4].0, "[ y ]");
        assert!(spanish[2].1.contains("Reiniciar"), "{spanish:?}");
        assert_eq!(SHORTCUTS[4].keys_text(), "[ and ]");
        assert_eq!(SHORTCUTS[0].keys_text(), "Space or P");
    }

    #[test]
    fn speed_keys_halve_and_double_within_the_range() {
        let mut settings = Settings::default();
        let rest = apply_to_settings(
            vec![KeyAction::Speed(1), KeyAction::Speed(1)],
            &mut settings,
        );
        assert!(rest.is_empty());
        assert_eq!(settings.speed, 4.0);
        for _ in 0..10 {
            apply_to_settings(vec![KeyAction::Speed(-1)], &mut settings);
        }
        assert_eq!(settings.speed, SPEED_MIN);
        apply_to_settings(vec![KeyAction::Scene(3)], &mut settings);
        assert_eq!(settings.scene, Scene::ALL[3]);
    }
}
