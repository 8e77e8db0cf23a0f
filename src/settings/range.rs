//! One numeric setting's valid range, written once: [`Range::check`] refuses a value
//! outside it (settings validation), [`Range::clamp`] brings a value into it (paths
//! that cannot refuse), [`Range::bounds`] is the slider's. Each numeric setting's
//! entry in its settings struct's table holds its `Range` (`number.rs`).

use std::fmt::{self, Display};
use std::ops::RangeInclusive;

use crate::i18n::Arg;
use crate::tr;

/// Why a setting was refused: the setting's full key ("left.cohesion") and the
/// reason a user reads (in the language in force when it was made).
#[derive(Clone, Debug, PartialEq)]
pub struct SettingError {
    pub key: String,
    pub reason: String,
}

impl Display for SettingError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let text = tr!(
            "setting-error",
            key = self.key.as_str(),
            reason = self.reason.as_str()
        );
        f.write_str(&text)
    }
}

impl std::error::Error for SettingError {}

/// `value` as a message variable: a number written the language's way, with
/// the digits its own display shows (an `f32`'s shortest form: 0.1, not
/// 0.10000000149).
pub fn number_arg(value: impl Display) -> Arg<'static> {
    let text = value.to_string();
    match text.parse::<f64>() {
        Ok(n) => Arg::from(n),
        Err(_) => Arg::from(text),
    }
}

impl SettingError {
    /// `value` outside `min..=max` for the setting `key`.
    pub fn out_of_range(
        key: String,
        value: impl Display,
        min: impl Display,
        max: impl Display,
    ) -> Self {
        Self {
            key,
            reason: tr!(
                "setting-error-out-of-range",
                value = number_arg(value),
                min = number_arg(min),
                max = number_arg(max)
            ),
        }
    }
}

/// A number a setting can hold.
pub trait SettingValue: Copy + PartialOrd + Display + 'static {
    /// False for NaN and the infinities, which no range holds.
    fn is_number(self) -> bool;
}

impl SettingValue for f32 {
    fn is_number(self) -> bool {
        self.is_finite()
    }
}

impl SettingValue for u32 {
    fn is_number(self) -> bool {
        true
    }
}

impl SettingValue for u64 {
    fn is_number(self) -> bool {
        true
    }
}

/// The valid values of one numeric setting.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Range<T> {
    /// The setting's name in the automation API and share links ("cohesion").
    pub key: &'static str,
    pub min: T,
    pub max: T,
    /// What [`Range::clamp`] puts in place of a value that is not a number.
    pub if_not_a_number: T,
}

impl<T: SettingValue> Range<T> {
    /// `min..=max`; a value that is not a number clamps to `min`.
    pub const fn new(key: &'static str, min: T, max: T) -> Self {
        Self {
            key,
            min,
            max,
            if_not_a_number: min,
        }
    }

    /// `min..=max`; a value that is not a number clamps to `if_not_a_number`.
    pub const fn or_else(key: &'static str, min: T, max: T, if_not_a_number: T) -> Self {
        Self {
            key,
            min,
            max,
            if_not_a_number,
        }
    }

    /// The slider's bounds.
    pub fn bounds(&self) -> RangeInclusive<T> {
        self.min..=self.max
    }

    pub fn contains(&self, value: T) -> bool {
        value.is_number() && self.min <= value && value <= self.max
    }

    /// Refuses a value outside the range, naming the setting as `prefix` + key.
    pub fn check(&self, prefix: &str, value: T) -> Result<(), SettingError> {
        if self.contains(value) {
            Ok(())
        } else {
            Err(SettingError::out_of_range(
                format!("{prefix}{}", self.key),
                value,
                self.min,
                self.max,
            ))
        }
    }

    /// The nearest value in the range.
    pub fn clamp(&self, value: T) -> T {
        if !value.is_number() {
            self.if_not_a_number
        } else if value < self.min {
            self.min
        } else if value > self.max {
            self.max
        } else {
            value
        }
    }
}
