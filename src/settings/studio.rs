//! The teacher's studio: rules on the controls a student sees, and the
//! teacher's own question, carried with the settings (and so in share links).
//!
//! Each rule names a control by its setting key, the name `shoal.set` and the
//! share links use (`left.alignment`, `speed`, `physics.current_m_per_s`):
//!
//! - **hidden**: the student does not see the control;
//! - **locked**: the student sees it greyed and cannot change it;
//! - **mystery**: the student sees that the control exists and what the fish
//!   do, but not its value (the panel shows "? (mystery value)", and the value
//!   is masked in `settings()`, `state()` and the CSV's settings link). A
//!   mystery value is locked too.
//!
//! The rules apply in the **student view** (`student_view`), which the
//! studio's *Share with class* link opens; the teacher's own page shows every
//! control and edits the rules. In the student view the values the rules
//! cover keep the link's values whatever the panel, the keyboard or
//! `shoal.set` try ([`Studio::enforce`], [`Studio::check_unchanged`]).
//!
//! The rules are a classroom convention, not a secret: the link itself carries
//! the values, as it must for the fish to use them. The mystery values travel
//! scrambled (`share_link::seal`), so decoding the link shows no number, but a
//! student with developer tools and Shoal's source can still unscramble them.

use std::collections::BTreeMap;

use serde::{Deserialize, Serialize};
use serde_json::Value;

use super::range::SettingError;
use super::tank::TankSettings;
use super::{Scene, Settings, Side};
use crate::i18n::tr;
use crate::tr;

/// Longest question, in characters (default 1,000: a paragraph or two; the
/// link, and the QR code drawn from it, stay small enough to scan).
pub const QUESTION_MAX_CHARS: usize = 1_000;

/// Most rules in one studio (default 200: more than every control of every
/// scene, so never a limit for a teacher; a bound on what a link can carry).
pub const RULES_MAX: usize = 200;

/// What is masked in place of a mystery value in `settings()`, `state()`.
pub const MYSTERY: &str = "mystery";

/// The keys of the five urge weights of a tank, whose mix a preset's name
/// gives away.
fn weight_keys() -> impl Iterator<Item = &'static str> {
    TankSettings::WEIGHTS.iter().map(|w| w.range.key)
}

/// What a student may do with one control.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct ControlRule {
    /// Students do not see the control.
    #[serde(skip_serializing_if = "is_false")]
    pub hidden: bool,
    /// Students see it greyed and cannot change it.
    #[serde(skip_serializing_if = "is_false")]
    pub locked: bool,
    /// Students see the control but not its value (and cannot change it).
    #[serde(skip_serializing_if = "is_false")]
    pub mystery: bool,
}

fn is_false(b: &bool) -> bool {
    !*b
}

impl ControlRule {
    /// No rule at all.
    pub fn is_none(self) -> bool {
        !(self.hidden || self.locked || self.mystery)
    }

    /// The student cannot change the value (hidden, locked or mystery).
    pub fn keeps_value(self) -> bool {
        !self.is_none()
    }
}

/// The teacher's studio: rules per control, the question, and whether this
/// page is the student view.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Studio {
    /// The page is the student view: the rules apply and the studio is closed.
    pub student_view: bool,
    /// The teacher's question, shown to the students in a card at the top of
    /// the side panel (empty: no card).
    pub question: String,
    /// Rules by setting key; a control without a rule is free.
    pub rules: BTreeMap<String, ControlRule>,
}

impl Studio {
    /// No rules, no question, the teacher's view: nothing to carry.
    pub fn is_empty(&self) -> bool {
        *self == Self::default()
    }

    /// The rule written for `key` (none if not written).
    pub fn rule(&self, key: &str) -> ControlRule {
        self.rules.get(key).copied().unwrap_or_default()
    }

    /// Sets the rule of `key`, removing it when it is empty.
    pub fn set_rule(&mut self, key: &str, rule: ControlRule) {
        if rule.is_none() {
            self.rules.remove(key);
        } else {
            self.rules.insert(key.to_owned(), rule);
        }
    }

    /// The rule that applies to `key`: the one written, with what follows from
    /// others. A mystery value is locked; a tank's preset is a mystery when one
    /// of its five urge weights is (its name would give the mix away), and each
    /// weight is when the preset is.
    pub fn effective(&self, key: &str) -> ControlRule {
        let mut rule = self.rule(key);
        if let Some((side, name)) = key.split_once('.')
            && (side == Side::Left.name() || side == Side::Right.name())
        {
            if name == "preset" {
                rule.mystery |= weight_keys().any(|w| self.rule(&format!("{side}.{w}")).mystery);
            } else if weight_keys().any(|w| w == name) {
                rule.mystery |= self.rule(&format!("{side}.preset")).mystery;
            }
        }
        rule.locked |= rule.mystery;
        rule
    }

    /// The rule a student meets for `key`: none outside the student view.
    pub fn for_student(&self, key: &str) -> ControlRule {
        if self.student_view {
            self.effective(key)
        } else {
            ControlRule::default()
        }
    }

    /// Is any value a mystery to this page's user (student view only)?
    pub fn has_mystery_for_student(&self) -> bool {
        self.student_view && self.rules.values().any(|r| r.mystery)
    }

    /// Every key whose value a student cannot change: the rules' keys, and a
    /// mystery preset's five weights. (A preset that is a mystery only because
    /// a weight is follows the weights: its label changes with them.)
    fn kept_keys(&self) -> Vec<String> {
        let mut keys: Vec<String> = self.rules.keys().cloned().collect();
        for side in Side::BOTH {
            if self.rule(&format!("{}.preset", side.name())).mystery {
                keys.extend(weight_keys().map(|w| format!("{}.{w}", side.name())));
            }
        }
        keys.sort();
        keys.dedup();
        keys.retain(|k| self.effective(k).keeps_value());
        keys
    }

    /// Every key whose value a student does not see (a preset included when
    /// one of its weights is a mystery).
    pub fn mystery_keys(&self) -> Vec<String> {
        let mut keys = self.kept_keys();
        keys.extend(Side::BOTH.map(|side| format!("{}.preset", side.name())));
        keys.sort();
        keys.dedup();
        keys.retain(|k| self.effective(k).mystery);
        keys
    }

    /// The mystery values a link carries sealed (`share_link`): every
    /// [`Self::mystery_keys`] but a preset that is a mystery only because one
    /// of its weights is (its label follows the weights the link carries).
    pub fn sealed_keys(&self) -> Vec<String> {
        let mut keys = self.mystery_keys();
        keys.retain(|k| !k.ends_with(".preset") || self.rule(k).mystery);
        keys
    }

    /// In the student view, puts back into `after` every value the rules keep
    /// from `before` (a locked slider the keyboard or a preset moved, a hidden
    /// Pause pressed with Space). The teacher's page changes nothing.
    pub fn enforce(&self, before: &Settings, after: &mut Settings) {
        if !self.student_view {
            return;
        }
        let (Ok(old), Ok(mut new)) = (serde_json::to_value(before), serde_json::to_value(&*after))
        else {
            return;
        };
        let mut changed = false;
        for key in self.kept_keys() {
            let path: Vec<&str> = key.split('.').collect();
            if let (Some(was), Some(slot)) = (value_at(&old, &path), value_at_mut(&mut new, &path))
                && slot != was
            {
                *slot = was.clone();
                changed = true;
            }
        }
        if changed && let Ok(kept) = serde_json::from_value::<Settings>(new) {
            *after = kept;
        }
        // The studio itself stays as the link made it.
        after.studio.clone_from(&before.studio);
    }

    /// In the student view, refuses `after` (a `shoal.set` result) if it
    /// changes a value the rules keep, or the studio, naming the first one.
    pub fn check_unchanged(&self, before: &Settings, after: &Settings) -> Result<(), SettingError> {
        if !self.student_view {
            return Ok(());
        }
        if after.studio != before.studio {
            return Err(SettingError {
                key: "studio".to_owned(),
                reason: tr("studio-error-student-view"),
            });
        }
        let (Ok(old), Ok(new)) = (serde_json::to_value(before), serde_json::to_value(after)) else {
            return Ok(());
        };
        for key in self.kept_keys() {
            let path: Vec<&str> = key.split('.').collect();
            if value_at(&old, &path) != value_at(&new, &path) {
                let how = match self.effective(&key) {
                    r if r.mystery => "mystery",
                    r if r.hidden => "hidden",
                    _ => "locked",
                };
                return Err(SettingError {
                    key,
                    reason: tr!("studio-error-kept", how = how),
                });
            }
        }
        Ok(())
    }

    /// In the student view, replaces every mystery value in `settings` (the
    /// JSON of [`Settings`], as `shoal.settings()` gives it) by `"mystery"`.
    pub fn mask_settings_json(&self, settings: &mut Value) {
        if !self.student_view {
            return;
        }
        for key in self.mystery_keys() {
            let path: Vec<&str> = key.split('.').collect();
            if let Some(slot) = value_at_mut(settings, &path) {
                *slot = Value::String(MYSTERY.to_owned());
            }
        }
    }

    /// In the student view, masks in `state` (the JSON of `shoal.state()`) what
    /// would give a mystery value away: a mystery urge's weight and strength in
    /// the selected fish's attention, the fish count of a mystery count.
    pub fn mask_state_json(&self, state: &mut Value) {
        if !self.student_view {
            return;
        }
        let mystery = |key: String| self.effective(&key).mystery;
        let masked = || Value::String(MYSTERY.to_owned());
        for (field, side) in [("metrics", Side::Left), ("metrics_right", Side::Right)] {
            let Some(urges) = state
                .get_mut(field)
                .and_then(|m| m.get_mut("attention"))
                .and_then(|a| a.get_mut("urges"))
                .and_then(Value::as_array_mut)
            else {
                continue;
            };
            for urge in urges {
                let name = urge.get("urge").and_then(Value::as_str).unwrap_or_default();
                if mystery(format!("{}.{name}", side.name())) {
                    for masked_field in ["weight", "strength_m_per_s2", "vector_m_per_s2"] {
                        if let Some(slot) = urge.get_mut(masked_field) {
                            *slot = masked();
                        }
                    }
                }
            }
        }
        let scene = state
            .get("scene")
            .and_then(Value::as_str)
            .and_then(|name| Scene::ALL.into_iter().find(|s| s.name() == name));
        if scene.is_some_and(|scene| self.count_is_mystery_for_student(scene))
            && let Some(slot) = state.get_mut("fish_count")
        {
            *slot = masked();
        }
    }

    /// Would the number of fish in `scene` (the status line's "40 fish",
    /// `state().fish_count`) give a mystery value away to a student: the count
    /// of either tank, the physics tank's fish or sharks, the reef's prey?
    pub fn count_is_mystery_for_student(&self, scene: Scene) -> bool {
        scene
            .class()
            .facts()
            .count_keys
            .iter()
            .any(|key| self.for_student(key).mystery)
    }

    /// Checks the question and every rule's key (the rest is checked by type).
    pub fn validate(&self) -> Result<(), SettingError> {
        let chars = self.question.chars().count();
        if chars > QUESTION_MAX_CHARS {
            return Err(SettingError {
                key: "studio.question".to_owned(),
                reason: tr!(
                    "studio-error-question-long",
                    count = chars,
                    max = QUESTION_MAX_CHARS
                ),
            });
        }
        if self.rules.len() > RULES_MAX {
            return Err(SettingError {
                key: "studio.rules".to_owned(),
                reason: tr!(
                    "studio-error-too-many-rules",
                    count = self.rules.len(),
                    max = RULES_MAX
                ),
            });
        }
        for key in self.rules.keys() {
            check_control_key(key)?;
        }
        Ok(())
    }

    /// Applies the `studio` part of a `shoal.set` patch (or a link):
    /// `student_view` and `question` replace theirs; `rules` merges by key, a
    /// rule object replacing that control's rule (flags left out are false)
    /// and `null` removing it. Refuses, naming the field, anything else.
    pub fn apply_patch(&mut self, patch: &Value) -> Result<(), SettingError> {
        let bad = |key: &str, reason: String| SettingError {
            key: key.to_owned(),
            reason,
        };
        let Value::Object(fields) = patch else {
            return Err(bad(
                "studio",
                tr!("studio-error-not-an-object", value = patch.to_string()),
            ));
        };
        let mut next = self.clone();
        for (field, value) in fields {
            match field.as_str() {
                "student_view" => {
                    next.student_view = value.as_bool().ok_or_else(|| {
                        bad(
                            "studio.student_view",
                            tr!("studio-error-expected-bool", value = value.to_string()),
                        )
                    })?;
                }
                "question" => {
                    value.as_str().ok_or_else(|| {
                        bad(
                            "studio.question",
                            tr!("studio-error-expected-text", value = value.to_string()),
                        )
                    })?;
                    next.question = value.as_str().unwrap_or_default().to_owned();
                }
                "rules" => {
                    let Value::Object(rules) = value else {
                        return Err(bad(
                            "studio.rules",
                            tr!(
                                "studio-error-rules-not-an-object",
                                value = value.to_string()
                            ),
                        ));
                    };
                    for (key, rule) in rules {
                        let full = format!("studio.rules.{key}");
                        check_control_key(key)?;
                        if rule.is_null() {
                            next.rules.remove(key);
                            continue;
                        }
                        let rule: ControlRule = parse_rule(rule).map_err(|r| bad(&full, r))?;
                        next.set_rule(key, rule);
                    }
                }
                other => {
                    return Err(bad(
                        &format!("studio.{other}"),
                        tr("studio-error-unknown-field"),
                    ));
                }
            }
        }
        next.validate()?;
        *self = next;
        Ok(())
    }
}

/// One rule's object, with a message a teacher reads.
fn parse_rule(value: &Value) -> Result<ControlRule, String> {
    let Value::Object(flags) = value else {
        return Err(tr!(
            "studio-error-rule-not-an-object",
            value = value.to_string()
        ));
    };
    let mut rule = ControlRule::default();
    for (flag, on) in flags {
        let slot = match flag.as_str() {
            "hidden" => &mut rule.hidden,
            "locked" => &mut rule.locked,
            "mystery" => &mut rule.mystery,
            other => {
                return Err(tr!("studio-error-unknown-flag", flag = other));
            }
        };
        *slot = on.as_bool().ok_or_else(|| {
            tr!(
                "studio-error-flag-not-bool",
                flag = flag.as_str(),
                value = on.to_string()
            )
        })?;
    }
    Ok(rule)
}

/// Is `key` a control a rule can name: a setting of [`Settings`] that is not
/// a group of settings (`left`) and not the studio itself?
fn check_control_key(key: &str) -> Result<(), SettingError> {
    let defaults = serde_json::to_value(Settings::default()).unwrap_or_default();
    let path: Vec<&str> = key.split('.').collect();
    let ok = path[0] != "studio"
        && value_at(&defaults, &path).is_some_and(|v| !v.is_object())
        && !key.is_empty();
    if ok {
        Ok(())
    } else {
        Err(SettingError {
            key: format!("studio.rules.{key}"),
            reason: tr!("studio-error-no-control", key = key),
        })
    }
}

fn value_at<'a>(root: &'a Value, path: &[&str]) -> Option<&'a Value> {
    path.iter()
        .try_fold(root, |v, key| v.as_object()?.get(*key))
}

fn value_at_mut<'a>(root: &'a mut Value, path: &[&str]) -> Option<&'a mut Value> {
    path.iter()
        .try_fold(root, |v, key| v.as_object_mut()?.get_mut(*key))
}

#[cfg(test)]
#[path = "studio_tests.rs"]
pub(crate) mod tests;
