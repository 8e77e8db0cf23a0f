//! Every student: what a screen reader and a keyboard get from Shoal.
//!
//! - [`mirror`]: egui's accessibility tree read as the page's HTML elements
//!   (the browser side, `web/a11y_dom.rs`, keeps them in the page and turns a
//!   screen reader's actions back into egui's);
//! - [`describe`]: the tank in words, per scene, for the live region and the
//!   *Describe the tank* key.

pub mod describe;
pub mod mirror;

#[cfg(test)]
mod tests;
