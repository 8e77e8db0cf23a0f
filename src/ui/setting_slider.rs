//! One row of a settings grid drawn from the setting's table entry
//! ([`NumberSetting`], `settings/number.rs`): its label with hover help, then
//! its control (a slider, a number field or a count with − and +) and the
//! buttons of its named values, through the studio's rules (hidden, locked,
//! mystery, the teacher's toggles), its widget rectangles recorded under the
//! entry's name for the browser tests.

use eframe::egui;
use egui::emath::Numeric;

use super::WidgetRects;
use super::studio_panel::control_row;
use crate::settings::number::{NumberSetting, Widget};
use crate::settings::range::SettingValue;
use crate::tr;

/// Draws `setting`'s row of `settings` (the keys under `prefix`, as in
/// "left."). Returns whether the control changed the value this frame.
pub fn setting_row<S, T>(
    ui: &mut egui::Ui,
    rects: &mut WidgetRects,
    prefix: &str,
    setting: &NumberSetting<S, T>,
    settings: &mut S,
) -> bool
where
    T: SettingValue + Numeric,
{
    let no_more = None::<fn(&mut egui::Ui, &mut WidgetRects, &mut S)>;
    row(ui, rects, prefix, setting, settings, no_more)
}

/// [`setting_row`] with `more` drawn after the control on the same line, under
/// the same studio rule (the *New* seed button, the *Turn* button); `more` sees
/// the settings with the value already changed.
pub fn setting_row_with<S, T>(
    ui: &mut egui::Ui,
    rects: &mut WidgetRects,
    prefix: &str,
    setting: &NumberSetting<S, T>,
    settings: &mut S,
    more: impl FnOnce(&mut egui::Ui, &mut WidgetRects, &mut S),
) -> bool
where
    T: SettingValue + Numeric,
{
    row(ui, rects, prefix, setting, settings, Some(more))
}

fn row<S, T>(
    ui: &mut egui::Ui,
    rects: &mut WidgetRects,
    prefix: &str,
    setting: &NumberSetting<S, T>,
    settings: &mut S,
    more: Option<impl FnOnce(&mut egui::Ui, &mut WidgetRects, &mut S)>,
) -> bool
where
    T: SettingValue + Numeric,
{
    let edit = |ui: &mut egui::Ui, rects: &mut WidgetRects, settings: &mut S| {
        let before = setting.value(settings);
        let mut value = before;
        let picked = if setting.named.is_empty() {
            control(ui, rects, setting, &mut value);
            false
        } else {
            // The named values' buttons under the control.
            ui.vertical(|ui| {
                control(ui, rects, setting, &mut value);
                named_values(ui, rects, setting, &mut value)
            })
            .inner
        };
        // A named value picked is set even when it is the value shown.
        let changed = picked || value != before;
        if changed {
            setting.set(settings, value);
        }
        changed
    };
    control_row(
        ui,
        rects,
        &setting.full_key(prefix),
        |ui| {
            ui.label(setting.label()).on_hover_text(setting.help());
        },
        |ui, rects| match more {
            None => edit(ui, rects, settings),
            Some(more) => {
                ui.horizontal(|ui| {
                    let changed = edit(ui, rects, settings);
                    more(ui, rects, settings);
                    changed
                })
                .inner
            }
        },
    )
    .unwrap_or(false)
}

/// The control of `setting`, editing `value`.
fn control<S, T>(
    ui: &mut egui::Ui,
    rects: &mut WidgetRects,
    setting: &NumberSetting<S, T>,
    value: &mut T,
) where
    T: SettingValue + Numeric,
{
    let NumberSetting { range, rect, .. } = *setting;
    let label = setting.label();
    let help = setting.help();
    let unit = setting.unit_text();
    match setting.widget {
        Widget::Slider {
            logarithmic,
            decimals,
        } => {
            let mut slider = egui::Slider::new(value, range.bounds()).logarithmic(logarithmic);
            // A whole number keeps egui's whole-number display ("10", not
            // "10.0"): only a decimal setting says how many decimals it shows.
            if let Some(decimals) = decimals {
                slider = slider.max_decimals(decimals);
            }
            if logarithmic && T::INTEGRAL {
                // A count from 0: its first step up is one.
                slider = slider.smallest_positive(1.0);
            }
            if !unit.is_empty() {
                slider = slider.suffix(unit);
            }
            if crate::i18n::decimal_comma() {
                slider = slider
                    .custom_formatter(localized_number)
                    .custom_parser(crate::i18n::parse_decimal);
            }
            // Named by the row's label (a screen reader reads the hover
            // help after it).
            let r = ui.add(slider).on_hover_text(help).accessible_name(label);
            rects.insert(rect, r.rect);
        }
        Widget::Field { drag_speed, .. } => {
            let mut field = egui::DragValue::new(value)
                .range(range.bounds())
                .speed(drag_speed);
            if !unit.is_empty() {
                field = field.suffix(unit);
            }
            if crate::i18n::decimal_comma() {
                field = field
                    .custom_formatter(localized_number)
                    .custom_parser(crate::i18n::parse_decimal);
            }
            let r = ui
                .add(field)
                .on_hover_text(setting.field_help())
                .accessible_name(label);
            rects.insert(rect, r.rect);
        }
        Widget::Count { step, typed } => {
            let step = f64::from(step);
            ui.horizontal(|ui| {
                let minus = ui
                    .add_enabled(*value > range.min, egui::Button::new(" − "))
                    .on_hover_text(setting.fewer_help())
                    .accessible_name(tr!("setting-count-fewer", label = label));
                rects.insert(&format!("{rect}_minus"), minus.rect);
                if minus.clicked() {
                    // A whole number below zero comes back as zero.
                    *value = range.clamp(T::from_f64(value.to_f64() - step));
                }
                if typed {
                    let field = ui
                        .add(
                            egui::DragValue::new(value)
                                .range(range.bounds())
                                .speed(step.max(1.0) * 0.2),
                        )
                        .on_hover_text(help)
                        .accessible_name(label);
                    rects.insert(&format!("{rect}_count"), field.rect);
                } else {
                    ui.label(value.to_string()).on_hover_text(help);
                }
                let plus = ui
                    .add_enabled(*value < range.max, egui::Button::new(" + "))
                    .on_hover_text(setting.more_help())
                    .accessible_name(tr!("setting-count-more", label = label));
                rects.insert(&format!("{rect}_plus"), plus.rect);
                if plus.clicked() {
                    *value = range.clamp(T::from_f64(value.to_f64() + step));
                }
            });
        }
        Widget::NamedOnly => {}
    }
}

/// The buttons of `setting`'s named values, the one `value` has selected;
/// returns whether one was picked (and put in `value`).
fn named_values<S, T>(
    ui: &mut egui::Ui,
    rects: &mut WidgetRects,
    setting: &NumberSetting<S, T>,
    value: &mut T,
) -> bool
where
    T: SettingValue + Numeric,
{
    ui.horizontal_wrapped(|ui| {
        let mut picked = false;
        for named in setting.named {
            let name = setting.named_label(named);
            let r = ui
                .selectable_label(*value == named.value, name)
                .on_hover_text(tr!(
                    "setting-named-value",
                    name = name,
                    help = setting.named_help(named)
                ))
                // Which setting it is a value of, for a screen reader.
                .accessible_name(tr!(
                    "setting-named-value.name",
                    setting = setting.label(),
                    name = name
                ));
            rects.insert(&named.rect(setting.rect), r.rect);
            if r.clicked() {
                *value = named.value;
                picked = true;
            }
        }
        picked
    })
    .inner
}

/// A slider's or field's number as egui would write it, the way of the
/// language in force (`0,25` in Spanish).
fn localized_number(value: f64, decimals: std::ops::RangeInclusive<usize>) -> String {
    crate::i18n::localize_decimal(&egui::emath::format_with_decimals_in_range(value, decimals))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::settings::learning::LearningSettings;
    use crate::settings::number::Number;
    use crate::settings::physics::PhysicsSettings;
    use crate::settings::reef::ReefSettings;
    use crate::settings::studio::{ControlRule, Studio};
    use crate::settings::tank::TankSettings;
    use crate::settings::{Settings, Side};
    use crate::sim::reef::mind::FishKind;
    use crate::sim::reef::mind::habits::MindTraits;
    use crate::ui::studio_panel::draw_controls_for_test;

    /// Draws every row of `table` of `settings` under `studio` and returns the
    /// widgets drawn.
    fn draw_table<S>(
        studio: &Studio,
        prefix: &str,
        table: &[Number<S>],
        settings: &mut S,
    ) -> WidgetRects {
        draw_controls_for_test(studio, false, |ui, rects| {
            egui::Grid::new("table").num_columns(2).show(ui, |ui| {
                for number in table {
                    match number {
                        Number::F32(s) => setting_row(ui, rects, prefix, s, settings),
                        Number::U32(s) => setting_row(ui, rects, prefix, s, settings),
                        Number::U64(s) => setting_row(ui, rects, prefix, s, settings),
                    };
                }
            });
        })
        .0
    }

    /// The names of the rectangles a row records.
    fn rect_names<S>(number: &Number<S>) -> Vec<String> {
        let (widget, rect, named): (_, _, Vec<String>) = match number {
            Number::F32(s) => (
                s.widget,
                s.rect,
                s.named.iter().map(|n| n.rect(s.rect)).collect(),
            ),
            Number::U32(s) => (
                s.widget,
                s.rect,
                s.named.iter().map(|n| n.rect(s.rect)).collect(),
            ),
            Number::U64(s) => (
                s.widget,
                s.rect,
                s.named.iter().map(|n| n.rect(s.rect)).collect(),
            ),
        };
        let mut names = match widget {
            Widget::Count { typed, .. } => {
                let mut names = vec![format!("{rect}_minus"), format!("{rect}_plus")];
                if typed {
                    names.push(format!("{rect}_count"));
                }
                names
            }
            Widget::Slider { .. } | Widget::Field { .. } => vec![rect.to_owned()],
            Widget::NamedOnly => vec![],
        };
        names.extend(named);
        names
    }

    /// Every row of `table` draws its named widgets, and none of them once the
    /// studio hides every setting from a student.
    fn check<S: Clone>(prefix: &str, table: &[Number<S>], settings: &S) {
        let drawn = draw_table(&Studio::default(), prefix, table, &mut settings.clone());
        for number in table {
            for name in rect_names(number) {
                assert!(
                    drawn.get(&name).is_some(),
                    "{prefix}{}: {name}",
                    number.key()
                );
            }
        }
        let mut hidden = Studio {
            student_view: true,
            ..Studio::default()
        };
        for number in table {
            let rule = ControlRule {
                hidden: true,
                ..ControlRule::default()
            };
            hidden.set_rule(&format!("{prefix}{}", number.key()), rule);
        }
        let drawn = draw_table(&hidden, prefix, table, &mut settings.clone());
        assert_eq!(drawn.iter().count(), 0, "{prefix}: nothing drawn");
    }

    #[test]
    fn every_setting_of_every_table_draws_its_named_widgets_through_the_studio() {
        let settings = Settings::default();
        check("", &Settings::NUMBERS, &settings);
        check(
            &Side::Right.prefix(),
            &TankSettings::NUMBERS,
            &settings.right,
        );
        check(
            PhysicsSettings::PREFIX,
            &PhysicsSettings::NUMBERS,
            &settings.physics,
        );
        check(ReefSettings::PREFIX, &ReefSettings::NUMBERS, &settings.reef);
        check(
            LearningSettings::PREFIX,
            &LearningSettings::NUMBERS,
            &settings.learning,
        );
        for kind in FishKind::ALL {
            check(
                &MindTraits::prefix(ReefSettings::PREFIX, kind),
                &MindTraits::NUMBERS,
                settings.reef.traits.of(kind),
            );
        }
    }

    #[test]
    fn the_minds_rows_keep_the_names_the_browser_tests_click() {
        let mut traits = MindTraits::default();
        let drawn = draw_table(
            &Studio::default(),
            "reef.traits.pacifist.",
            &MindTraits::NUMBERS,
            &mut traits,
        );
        for name in [
            "reef_minds_hunger",
            "reef_minds_hunger_calm",
            "reef_minds_libido_nominal",
            "reef_minds_libido_sexual_mania",
            "reef_minds_appetite",
            "reef_minds_fear_distance",
            "reef_minds_alarm",
            "reef_minds_panic",
            "reef_minds_urge",
            "reef_minds_box_courageous",
            "reef_minds_persistence_devoted",
        ] {
            assert!(drawn.get(name).is_some(), "{name}");
        }
        assert!(drawn.get("reef_minds_box").is_none(), "named values only");
        assert_eq!(traits, MindTraits::default(), "drawing leaves them unset");
    }

    #[test]
    fn an_unset_count_shows_the_demo_s_own_and_is_set_only_when_moved() {
        let mut reef = ReefSettings::default();
        let drawn = draw_table(
            &Studio::default(),
            "reef.",
            &ReefSettings::NUMBERS,
            &mut reef,
        );
        assert!(drawn.get("reef_prey").is_some());
        assert_eq!(reef.prey_count, None, "drawing leaves it unset");
        assert_eq!(
            ReefSettings::PREY_COUNT.value(&reef),
            reef.demo.default_prey_count() as u32
        );
    }
}
