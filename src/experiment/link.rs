//! Experiment links (issue 16): `?experiment=v1.…` after Shoal's address
//! reopens an experiment: its design, packed like a share link's settings (the
//! version tag, then URL-safe base64 of the DEFLATE-compressed JSON of the
//! [`Design`]). The page opens in the experiment's scene and runs it again;
//! since every run is deterministic for its settings and seed, the results are
//! the ones the link was made from.
//!
//! Nothing in a link is trusted: the packed text has the share link's size
//! limits, and the design is validated like a file given to `shoal-lab`, so a
//! damaged link or an impossible design is refused with a sentence naming the
//! field, and the rest of the page opens.

use super::design::{Design, DesignError, Plan};
use crate::settings::share_link::{
    ShareLinkError, pack_json, query_value, unpack_json, with_query, without_query,
};
use crate::tr;

/// The query parameter that carries an experiment.
pub const KEY: &str = "experiment";

/// Why an experiment link could not be opened.
#[derive(Debug, PartialEq)]
pub enum ExperimentLinkError {
    Damaged(ShareLinkError),
    Empty,
    Refused(DesignError),
}

impl std::fmt::Display for ExperimentLinkError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::Damaged(err) => err.fmt(f),
            Self::Empty => f.write_str(&tr!("experiment-link-empty")),
            Self::Refused(err) => {
                f.write_str(&tr!("experiment-link-refused", reason = err.to_string()))
            }
        }
    }
}

impl std::error::Error for ExperimentLinkError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            Self::Damaged(err) => Some(err),
            Self::Empty => None,
            Self::Refused(err) => Some(err),
        }
    }
}

impl From<ShareLinkError> for ExperimentLinkError {
    fn from(err: ShareLinkError) -> Self {
        Self::Damaged(err)
    }
}

impl From<DesignError> for ExperimentLinkError {
    fn from(err: DesignError) -> Self {
        Self::Refused(err)
    }
}

/// The link text (the value of `?experiment=`) that reopens `design`.
pub fn encode(design: &Design) -> String {
    // A design is plain data: serialising it cannot fail; an empty object
    // would be refused on opening, never run.
    pack_json(&serde_json::to_string(design).unwrap_or_else(|_| "{}".to_owned()))
}

/// The design a link text packs, validated into its plan.
pub fn decode(text: &str) -> Result<Plan, ExperimentLinkError> {
    let value = unpack_json(text)?.ok_or(ExperimentLinkError::Empty)?;
    let design = Design::from_json(&value.to_string())?;
    Ok(design.validate()?)
}

/// The experiment a page address asks for (`?experiment=…`), if it asks for one.
pub fn from_url(url: &str) -> Option<Result<Plan, ExperimentLinkError>> {
    query_value(url, KEY).map(decode)
}

/// The address without its `experiment` parameter.
pub fn without_experiment(url: &str) -> String {
    without_query(url, KEY)
}

/// `page` (an address without parameters of ours) with `design` in its query.
pub fn link(page: &str, design: &Design) -> String {
    with_query(page, KEY, &encode(design))
}

#[cfg(test)]
mod tests {
    use super::*;

    const FIXTURE: &str = include_str!("../../experiments/alignment-sweep.json");

    #[test]
    fn a_link_reopens_the_same_plan() {
        let plan = Design::from_json(FIXTURE).unwrap().validate().unwrap();
        let url = link("http://127.0.0.1:8080/", &plan.design);
        assert!(
            url.starts_with("http://127.0.0.1:8080/?experiment=v1."),
            "{url}"
        );
        assert!(
            url.len() < 2_000,
            "a link short enough to share: {}",
            url.len()
        );
        let reopened = from_url(&format!("{url}#v1.abc")).unwrap().unwrap();
        assert_eq!(reopened, plan);
        assert_eq!(without_experiment(&url), "http://127.0.0.1:8080/");
    }

    #[test]
    fn other_parameters_are_kept() {
        let plan = Design::from_json(FIXTURE).unwrap().validate().unwrap();
        let url = link("http://h/?bench", &plan.design);
        assert!(url.starts_with("http://h/?bench&experiment=v1."), "{url}");
        assert_eq!(without_experiment(&url), "http://h/?bench");
        assert!(from_url("http://h/?bench").is_none());
    }

    #[test]
    fn a_damaged_or_impossible_link_is_refused_with_a_reason() {
        let plan = Design::from_json(FIXTURE).unwrap().validate().unwrap();
        let text = encode(&plan.design);
        // Cut off when copied.
        let cut = &text[..text.len() / 2];
        let err = decode(cut).unwrap_err();
        assert!(err.to_string().contains("damaged"), "{err}");
        assert!(matches!(
            decode("v9.abc"),
            Err(ExperimentLinkError::Damaged(_))
        ));
        assert_eq!(decode(""), Err(ExperimentLinkError::Empty));
        // A well-packed design with an unknown factor names the field.
        let mut bad = plan.design.clone();
        bad.factors[0].key = "left.alignmnt".into();
        let err = decode(&encode(&bad)).unwrap_err();
        assert!(
            matches!(&err, ExperimentLinkError::Refused(e) if e.field == "factors[0].key"),
            "{err}"
        );
        assert!(
            err.to_string()
                .starts_with("its experiment cannot run: factors[0].key")
        );
    }
}
