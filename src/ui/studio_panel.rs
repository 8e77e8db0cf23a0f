//! The teacher's studio on screen: the *Teacher's studio* button and window,
//! the H / L / ? toggles beside every control while it is open, *Share with
//! class* (the student link and its QR code), the question card, and the one
//! check every panel's controls go through ([`control`]).
//!
//! The rules themselves, their validation and their masking are in
//! `settings/studio.rs`. Each frame the app hands this module the studio
//! ([`begin_frame`]); the panels draw each control through [`control`] (or
//! [`control_block`] for a group of widgets), which hides it, greys it, puts
//! "? (mystery value)" in its place, or, while the studio is open on the
//! teacher's page, draws the toggles beside it; the app takes the toggles'
//! edits back ([`end_frame`]).

use eframe::egui;

use super::WidgetRects;
use super::scene_panel::Notice;
use crate::i18n::ts;
use crate::settings::Settings;
use crate::settings::names::setting_text;
use crate::settings::studio::{ControlRule, Studio};
use crate::tr;

/// The rules of this frame, kept in egui's memory so every panel reaches them
/// without a new argument.
#[derive(Clone, Debug, Default)]
struct StudioFrame {
    studio: Studio,
    /// The studio is open on the teacher's page: draw the toggles.
    editing: bool,
}

fn frame_id() -> egui::Id {
    egui::Id::unique("shoal_studio_frame")
}

fn open_id() -> egui::Id {
    egui::Id::unique("shoal_studio_open")
}

/// Before the panels are drawn: the studio in force this frame.
pub fn begin_frame(ctx: &egui::Context, studio: &Studio) {
    let editing = !studio.student_view && ctx.data(|d| d.get_temp::<bool>(open_id()) == Some(true));
    ctx.data_mut(|d| {
        d.insert_temp(
            frame_id(),
            StudioFrame {
                studio: studio.clone(),
                editing,
            },
        );
    });
}

/// After the panels: the studio as the toggles left it.
pub fn end_frame(ctx: &egui::Context) -> Option<Studio> {
    ctx.data(|d| d.get_temp::<StudioFrame>(frame_id()))
        .map(|f| f.studio)
}

fn current(ui: &egui::Ui) -> Option<StudioFrame> {
    ui.data(|d| d.get_temp::<StudioFrame>(frame_id()))
}

/// Is `key`'s value a mystery to whoever looks at this page (a student)?
/// Panels ask before they print a value elsewhere (a legend, a table).
pub fn is_mystery(ui: &egui::Ui, key: &str) -> bool {
    current(ui).is_some_and(|f| f.studio.for_student(key).mystery)
}

/// Does this page keep any value a mystery (the student view)? Views that
/// would print every setting (the experiment's table) then stay closed.
pub fn has_mystery(ui: &egui::Ui) -> bool {
    current(ui).is_some_and(|f| f.studio.has_mystery_for_student())
}

/// Draws one control (a slider, a checkbox, a count, a row of buttons) named
/// by its setting `key` through the studio: hidden, greyed, replaced by
/// "? (mystery value)", or, while the studio is open, with its toggles beside
/// it. Returns what `add` returned, or `None` when the control was not drawn.
pub fn control<R>(
    ui: &mut egui::Ui,
    rects: &mut WidgetRects,
    key: &str,
    add: impl FnOnce(&mut egui::Ui, &mut WidgetRects) -> R,
) -> Option<R> {
    let Some(frame) = current(ui) else {
        return Some(add(ui, rects));
    };
    if frame.editing {
        return Some(
            ui.horizontal(|ui| {
                let r = add(ui, rects);
                toggles(ui, rects, key, &frame.studio);
                r
            })
            .inner,
        );
    }
    student_control(ui, rects, key, frame.studio.for_student(key), add)
}

/// [`control`] for a group of widgets laid out top to bottom (the control
/// modes' radio buttons): while the studio is open, its toggles sit on a line
/// of their own above it, after `label`.
pub fn control_block<R>(
    ui: &mut egui::Ui,
    rects: &mut WidgetRects,
    key: &str,
    label: &str,
    add: impl FnOnce(&mut egui::Ui, &mut WidgetRects) -> R,
) -> Option<R> {
    let Some(frame) = current(ui) else {
        return Some(add(ui, rects));
    };
    if frame.editing {
        ui.horizontal(|ui| {
            ui.label(egui::RichText::new(label).small().weak());
            toggles(ui, rects, key, &frame.studio);
        });
        return Some(add(ui, rects));
    }
    student_control(ui, rects, key, frame.studio.for_student(key), add)
}

/// One row of a two-column grid (a label, then the control) through the
/// studio: a hidden control's row, label included, is not drawn at all.
pub fn control_row<R>(
    ui: &mut egui::Ui,
    rects: &mut WidgetRects,
    key: &str,
    label: impl FnOnce(&mut egui::Ui),
    add: impl FnOnce(&mut egui::Ui, &mut WidgetRects) -> R,
) -> Option<R> {
    if is_hidden(ui, key) {
        return None;
    }
    label(ui);
    let r = control(ui, rects, key, add);
    ui.end_row();
    r
}

/// Is `key`'s control hidden from whoever looks at this page (a student)?
pub fn is_hidden(ui: &egui::Ui, key: &str) -> bool {
    current(ui).is_some_and(|f| !f.editing && f.studio.for_student(key).hidden)
}

fn student_control<R>(
    ui: &mut egui::Ui,
    rects: &mut WidgetRects,
    key: &str,
    rule: ControlRule,
    add: impl FnOnce(&mut egui::Ui, &mut WidgetRects) -> R,
) -> Option<R> {
    if rule.hidden {
        return None;
    }
    if rule.mystery {
        let r = ui
            .label(egui::RichText::new(ts("studio-mystery-value")).italics())
            .on_hover_text(ts("studio-mystery-value.help"));
        rects.insert(&format!("mystery_{key}"), r.rect);
        return None;
    }
    if rule.locked {
        let r = ui
            .add_enabled_ui(false, |ui| add(ui, rects))
            .response
            .on_disabled_hover_text(ts("studio-locked"));
        rects.insert(&format!("locked_{key}"), r.rect);
        return None;
    }
    Some(add(ui, rects))
}

/// Smallest side of an H / L / ? toggle, in points (24: WCAG 2.5.8's
/// smallest target for a pointer).
pub const TOGGLE_MIN_SIDE: f32 = 24.0;

/// The H / L / ? toggles of `key`, which edit the frame's studio. Each is at
/// least [`TOGGLE_MIN_SIDE`] square, and its accessible name says which rule
/// on which control ("Hide Alignment (left tank)").
fn toggles(ui: &mut egui::Ui, rects: &mut WidgetRects, key: &str, studio: &Studio) {
    let rule = studio.rule(key);
    let mut next = rule;
    let name = key.replace('.', "_");
    let setting = setting_text(key, true);
    for (flag, text, help, what, accessible) in [
        (
            &mut next.hidden,
            ts("studio-toggle-hide"),
            ts("studio-toggle-hide.help"),
            "hide",
            tr!("studio-toggle-hide-name", key = setting.as_str()),
        ),
        (
            &mut next.locked,
            ts("studio-toggle-lock"),
            ts("studio-toggle-lock.help"),
            "lock",
            tr!("studio-toggle-lock-name", key = setting.as_str()),
        ),
        (
            &mut next.mystery,
            ts("studio-toggle-mystery"),
            ts("studio-toggle-mystery.help"),
            "mystery",
            tr!("studio-toggle-mystery-name", key = setting.as_str()),
        ),
    ] {
        let r = ui
            .add(
                egui::Button::selectable(*flag, text)
                    .min_size(egui::vec2(TOGGLE_MIN_SIDE, TOGGLE_MIN_SIDE)),
            )
            .on_hover_text(tr!(
                "studio-toggle-help",
                help = help,
                key = setting.as_str()
            ))
            .accessible_name(accessible);
        rects.insert(&format!("studio_{what}_{name}"), r.rect);
        if r.clicked() {
            *flag = !*flag;
        }
    }
    if next != rule {
        ui.data_mut(|d| {
            d.get_temp_mut_or_default::<StudioFrame>(frame_id())
                .studio
                .set_rule(key, next);
        });
    }
}

/// The side panel's *Teacher's studio* button (not in the student view).
pub fn studio_button(ui: &mut egui::Ui, studio: &Studio, rects: &mut WidgetRects) {
    if studio.student_view {
        return;
    }
    let open = ui.data(|d| d.get_temp::<bool>(open_id()) == Some(true));
    let r = ui
        .add(egui::Button::selectable(open, ts("studio-button")))
        .on_hover_text(ts("studio-button.help"));
    rects.insert("studio_open", r.rect);
    if r.clicked() {
        ui.data_mut(|d| d.insert_temp(open_id(), !open));
    }
}

/// The teacher's question, in a card at the top of the side panel.
pub fn question_card(ui: &mut egui::Ui, studio: &Studio, rects: &mut WidgetRects) {
    let question = studio.question.trim();
    if question.is_empty() {
        return;
    }
    let r = egui::Frame::group(ui.style())
        .fill(ui.visuals().faint_bg_color)
        .show(ui, |ui| {
            ui.set_width(ui.available_width());
            ui.label(egui::RichText::new(ts("studio-teacher-asks")).strong());
            ui.add(egui::Label::new(egui::RichText::new(question).size(15.0)).wrap());
        });
    rects.insert("studio_question_card", r.response.rect);
}

/// The link a class opens: the settings as they are now, with the studio's
/// rules in force (the student view).
pub fn student_link(settings: &Settings, page_url: &str) -> String {
    let mut student = settings.clone();
    student.studio.student_view = true;
    format!(
        "{page_url}#{}",
        crate::settings::share_link::encode(&student)
    )
}

/// The studio's windows and the QR code of the last link shown.
#[derive(Default)]
pub struct StudioPanel {
    share_open: bool,
    /// The link the QR code was made for, and the code (or why none).
    qr: Option<(String, Result<qrcodegen::QrCode, String>)>,
    /// The settings and page the last student link was made from, and the link (made
    /// again only when they change: making one checks that it reopens them).
    link: Option<(Settings, String, String)>,
}

impl StudioPanel {
    /// The *Teacher's studio* and *Share with class* windows, editing
    /// `settings.studio`; a notice when a link was copied.
    pub fn windows_ui(
        &mut self,
        ctx: &egui::Context,
        settings: &mut Settings,
        page_url: &str,
        rects: &mut WidgetRects,
    ) -> Option<Notice> {
        if settings.studio.student_view {
            return None;
        }
        let mut open = ctx.data(|d| d.get_temp::<bool>(open_id()) == Some(true));
        let mut notice = None;
        if open {
            let screen = ctx.content_rect();
            let width = (screen.width() - 24.0).clamp(220.0, 420.0);
            // On a phone the window would cover the side panel whose H / L / ?
            // toggles it explains: it sits at the bottom, at most 40 % of the
            // screen high, and the panel above scrolls each toggle into reach.
            let narrow = super::screen::is_narrow(screen.width());
            let max_height = if narrow {
                (screen.height() * 0.4 - 60.0).max(120.0)
            } else {
                (screen.height() - 140.0).max(160.0)
            };
            let mut window = egui::Window::new(ts("studio-button"))
                .id(egui::Id::unique("studio_window"))
                .open(&mut open)
                .collapsible(false)
                .default_width(width)
                .constrain(true);
            window = if narrow {
                window.anchor(egui::Align2::CENTER_BOTTOM, egui::vec2(0.0, -8.0))
            } else {
                window.default_pos(screen.right_top() + egui::vec2(-width - 12.0, 48.0))
            };
            let shown = window.show(ctx, |ui| {
                // However many rules, every row can be scrolled to: the
                // window never runs past the bottom of the screen.
                egui::ScrollArea::vertical()
                    .id_salt("studio_window_scroll")
                    .max_height(max_height)
                    .auto_shrink([false, true])
                    .show(ui, |ui| self.studio_ui(ui, settings, rects));
            });
            if let Some(shown) = shown {
                rects.insert("studio_window", shown.response.rect);
            }
            ctx.data_mut(|d| d.insert_temp(open_id(), open));
        }
        if self.share_open {
            if self
                .link
                .as_ref()
                .is_none_or(|(s, p, _)| s != settings || p != page_url)
            {
                let link = student_link(settings, page_url);
                self.link = Some((settings.clone(), page_url.to_owned(), link));
            }
            let link = self
                .link
                .as_ref()
                .map(|(_, _, l)| l.clone())
                .unwrap_or_default();
            if self.qr.as_ref().is_none_or(|(l, _)| *l != link) {
                self.qr = Some((link.clone(), super::qr::encode(&link)));
            }
            let mut share_open = true;
            let screen = ctx.content_rect();
            let side = (screen.height() - 260.0).clamp(160.0, 520.0);
            let shown = egui::Window::new(ts("studio-share"))
                .id(egui::Id::unique("studio_share_window"))
                .open(&mut share_open)
                .collapsible(false)
                .resizable(false)
                .default_pos(screen.center() - egui::vec2(0.5 * side, 0.5 * side + 60.0))
                .constrain(true)
                .show(ctx, |ui| {
                    ui.set_max_width(side.max(260.0));
                    ui.label(ts("studio-share-intro"));
                    match self.qr.as_ref().map(|(_, qr)| qr) {
                        Some(Ok(code)) => {
                            let r = super::qr::draw(ui, code, side);
                            rects.insert("studio_qr", r.rect);
                        }
                        Some(Err(why)) => {
                            ui.colored_label(ui.visuals().warn_fg_color, why);
                        }
                        None => {}
                    }
                    ui.add(
                        egui::Label::new(egui::RichText::new(&link).small().monospace()).truncate(),
                    )
                    .on_hover_text(&link);
                    ui.horizontal(|ui| {
                        let copy = ui
                            .button(ts("studio-copy-link"))
                            .on_hover_text(ts("studio-copy-link.help"));
                        rects.insert("studio_copy_link", copy.rect);
                        if copy.clicked() {
                            ui.ctx().copy_text(link.clone());
                            notice = Some(Notice::info(ts("studio-link-copied")));
                        }
                        let try_it = ui
                            .add(
                                egui::Hyperlink::from_label_and_url(
                                    ts("studio-open-student-view"),
                                    &link,
                                )
                                .open_in_new_tab(true),
                            )
                            .on_hover_text(ts("studio-open-student-view.help"));
                        rects.insert("studio_try_link", try_it.rect);
                    });
                });
            if let Some(shown) = shown {
                rects.insert("studio_share_window", shown.response.rect);
            }
            self.share_open = share_open;
        }
        notice
    }

    fn studio_ui(&mut self, ui: &mut egui::Ui, settings: &mut Settings, rects: &mut WidgetRects) {
        ui.label(ts("studio-intro"));
        ui.label(egui::RichText::new(ts("studio-intro-note")).small().weak());
        ui.add_space(4.0);
        ui.label(egui::RichText::new(ts("studio-question")).strong());
        let question = ui.add(
            egui::TextEdit::multiline(&mut settings.studio.question)
                .char_limit(crate::settings::studio::QUESTION_MAX_CHARS)
                .desired_rows(3)
                .desired_width(f32::INFINITY)
                .hint_text(ts("studio-question-hint")),
        );
        rects.insert("studio_question", question.rect);

        ui.add_space(4.0);
        ui.label(egui::RichText::new(ts("studio-rules")).strong());
        if settings.studio.rules.is_empty() {
            ui.label(egui::RichText::new(ts("studio-no-rules")).weak());
        }
        let mut remove = None;
        egui::Grid::new("studio_rules")
            .num_columns(2)
            .striped(true)
            .show(ui, |ui| {
                for (key, rule) in &settings.studio.rules {
                    let mut what = Vec::new();
                    if rule.hidden {
                        what.push(ts("studio-rule-hidden"));
                    }
                    if rule.locked {
                        what.push(ts("studio-rule-locked"));
                    }
                    if rule.mystery {
                        what.push(ts("studio-rule-mystery"));
                    }
                    ui.label(tr!(
                        "studio-rule",
                        key = setting_text(key, true),
                        what = what.join(", ")
                    ));
                    let r = ui.small_button(ts("studio-remove"));
                    rects.insert(&format!("studio_remove_{}", key.replace('.', "_")), r.rect);
                    if r.clicked() {
                        remove = Some(key.clone());
                    }
                    ui.end_row();
                }
            });
        if let Some(key) = remove {
            settings.studio.rules.remove(&key);
        }
        ui.add_space(6.0);
        let share = ui
            .add(egui::Button::new(
                egui::RichText::new(ts("studio-share")).strong(),
            ))
            .on_hover_text(ts("studio-share.help"));
        rects.insert("studio_share", share.rect);
        if share.clicked() {
            self.share_open = true;
        }
    }
}

/// Draws `controls` in a side panel under `studio` (the studio window open
/// or not) for two frames, as the app does, and returns the widgets drawn and
/// the studio the frame ended with (tests of the panels' controls).
#[cfg(test)]
pub fn draw_controls_for_test(
    studio: &Studio,
    open: bool,
    mut controls: impl FnMut(&mut egui::Ui, &mut WidgetRects),
) -> (WidgetRects, Option<Studio>) {
    let ctx = egui::Context::default();
    ctx.data_mut(|d| d.insert_temp(open_id(), open));
    let mut rects = WidgetRects::new();
    for frame in 0..2 {
        rects.clear();
        let input = egui::RawInput {
            screen_rect: Some(egui::Rect::from_min_size(
                egui::Pos2::ZERO,
                egui::vec2(1280.0, 2000.0),
            )),
            time: Some(f64::from(frame) / 60.0),
            ..Default::default()
        };
        let mut output = ctx.run_ui(input, |ui| {
            begin_frame(ui.ctx(), studio);
            egui::Panel::left("controls").show(ui, |ui| controls(ui, &mut rects));
        });
        output.textures_delta.clear();
    }
    (rects, end_frame(&ctx))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::settings::Side;
    use serde_json::json;

    /// Draws the schooling lab's tank controls once under `studio`, with the
    /// studio window open or not, and returns the widgets drawn.
    fn draw_tank(studio: &Studio, open: bool) -> (WidgetRects, Option<Studio>) {
        let mut settings = Settings::default();
        draw_controls_for_test(studio, open, |ui, rects| {
            super::super::tank_panel::tank_ui(ui, &mut settings.left, Side::Left, rects);
        })
    }

    fn lesson(student_view: bool) -> Studio {
        let mut settings = Settings::default();
        settings
            .apply_patch(&json!({"studio": {
                "student_view": student_view,
                "rules": {
                    "left.alignment": {"mystery": true},
                    "left.stingrays": {"hidden": true},
                    "left.wander": {"locked": true}
                }
            }}))
            .unwrap();
        settings.studio
    }

    #[test]
    fn a_student_sees_no_hidden_control_no_mystery_number_and_greyed_locks() {
        let (rects, _) = draw_tank(&lesson(true), false);
        assert!(rects.get("stingrays_count").is_none(), "hidden");
        assert!(
            rects.get("sharks_count").is_some(),
            "a free control is drawn"
        );
        assert!(rects.get("weight_alignment").is_none(), "no mystery slider");
        assert!(rects.get("mystery_left.alignment").is_some());
        assert!(
            rects.get("mystery_left.preset").is_some(),
            "the preset with it"
        );
        assert!(rects.get("preset_group").is_none());
        assert!(rects.get("wander").is_some(), "a locked control is drawn…");
        assert!(rects.get("locked_left.wander").is_some(), "…greyed");
        assert!(
            rects.iter().all(|(name, _)| !name.starts_with("studio_")),
            "no toggles for a student"
        );
    }

    #[test]
    fn the_teacher_sees_everything_and_the_toggles_while_the_studio_is_open() {
        let (closed, _) = draw_tank(&lesson(false), false);
        assert!(closed.get("weight_alignment").is_some());
        assert!(closed.get("stingrays_count").is_some());
        assert!(closed.get("studio_hide_left_stingrays").is_none());
        let (open, studio) = draw_tank(&lesson(false), true);
        for name in [
            "studio_hide_left_stingrays",
            "studio_lock_left_wander",
            "studio_mystery_left_alignment",
            "studio_hide_left_mode",
            "studio_lock_left_preset",
        ] {
            assert!(open.get(name).is_some(), "{name}");
        }
        assert!(
            open.get("weight_alignment").is_some(),
            "the teacher sets it"
        );
        assert_eq!(studio, Some(lesson(false)), "no click, no change");
        // A student's page never shows the toggles, even with the flag set.
        let (student, _) = draw_tank(&lesson(true), true);
        assert!(student.get("studio_hide_left_stingrays").is_none());
    }

    #[test]
    fn the_studio_speaks_spanish() {
        use crate::i18n::{Lang, with_lang};
        with_lang(Lang::Es, || {
            assert_eq!(ts("studio-mystery-value"), "? (valor misterioso)");
            // A rule names its control as the panel does, with its tank.
            assert_eq!(
                tr!(
                    "studio-rule",
                    key = setting_text("left.alignment", true),
                    what = "oculto, bloqueado"
                ),
                "Alineación (tanque izquierdo): oculto, bloqueado"
            );
            assert_eq!(
                setting_text("physics.show_body", true),
                "Mostrar masas y resortes"
            );
            let mut settings = Settings::default();
            let err = settings
                .apply_patch(&json!({"studio": {"rules": {"speed": {"secret": true}}}}))
                .expect_err("an unknown flag")
                .to_string();
            assert!(err.contains("marca desconocida 'secret'"), "{err}");
            let studio = lesson(true);
            let before = Settings {
                studio: studio.clone(),
                ..Settings::default()
            };
            let mut after = before.clone();
            after.left.wander = 0.25;
            let err = studio
                .check_unchanged(&before, &after)
                .expect_err("locked")
                .to_string();
            assert!(
                err.contains("está bloqueado por el estudio del maestro"),
                "{err}"
            );
        });
    }

    #[test]
    fn the_student_link_opens_the_student_view_with_the_same_settings() {
        let mut settings = Settings {
            studio: lesson(false),
            ..Settings::default()
        };
        settings.left.alignment = 37.0;
        let link = student_link(&settings, "https://example.org/shoal/");
        let fragment = link.split_once('#').unwrap().1;
        let opened = crate::settings::share_link::decode(fragment)
            .unwrap()
            .unwrap();
        assert!(opened.studio.student_view);
        assert_eq!(opened.studio.rules, settings.studio.rules);
        assert_eq!(opened.left.alignment, 37.0);
        assert!(!settings.studio.student_view, "the teacher's page stays");
    }
}
