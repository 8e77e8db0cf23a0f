//! This folder's measurement scripts (see [`crate::census`]).

use crate::census::Census;

/// The scripts, in the order `shoal-census` lists them.
pub const CENSUSES: &[Census] = &[];
