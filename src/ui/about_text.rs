//! The words of *About this scene*: for each scene what it is, how it works,
//! things to notice, things to try and the references, written for a
//! 14-year-old; the equations one click deeper. Every number here is the
//! model's own (see `docs/`). The words themselves are in the catalogue
//! (`locales/<lang>/about.ftl`); a page here names its messages.

/// One scene's page: the ids of its messages in the catalogue, each shown
/// with [`crate::i18n::ts`].
pub struct About {
    /// A paragraph: what the scene is.
    pub what: &'static str,
    /// A paragraph: how it works.
    pub how: &'static str,
    /// Things to notice, one bullet each.
    pub notice: &'static [&'static str],
    /// Things to try, one bullet each.
    pub try_this: &'static [&'static str],
    /// Groups of (name, formula and what its letters mean), shown under *The
    /// equations*: a message and its `.formula` attribute.
    pub equations: &'static [&'static [(&'static str, &'static str)]],
    pub references: &'static [&'static str],
    /// The model's ODD description (Grimm et al. 2020): `docs/odd-<odd>.md`,
    /// published as `odd/<odd>.html` and linked under the references.
    pub odd: &'static str,
}

impl About {
    /// Every message id of the page, in the order the window shows them.
    pub fn ids(&self) -> impl Iterator<Item = &'static str> + '_ {
        [self.what, self.how]
            .into_iter()
            .chain(self.notice.iter().copied())
            .chain(self.try_this.iter().copied())
            .chain(
                self.equations
                    .iter()
                    .flat_map(|g| g.iter())
                    .flat_map(|(name, formula)| [*name, *formula]),
            )
            .chain(self.references.iter().copied())
    }
}

const TT_1994: &str = "about-ref-tu-terzopoulos";
const LIM_TAN: &str = "about-ref-lim-tan";
const REYNOLDS: &str = "about-ref-reynolds";
const COUZIN: &str = "about-ref-couzin";
const BALLERINI: &str = "about-ref-ballerini";
const PITCHER: &str = "about-ref-pitcher";
const LANDEAU: &str = "about-ref-landeau";
const VIDELER: &str = "about-ref-videler";
const KIRKPATRICK: &str = "about-ref-kirkpatrick";

const STEERING_EQUATIONS: &[(&str, &str)] = &[
    ("about-eq-seek", "about-eq-seek.formula"),
    ("about-eq-wander", "about-eq-wander.formula"),
    ("about-eq-containment", "about-eq-containment.formula"),
];

const URGE_EQUATIONS: &[(&str, &str)] = &[
    ("about-eq-alignment", "about-eq-alignment.formula"),
    ("about-eq-cohesion", "about-eq-cohesion.formula"),
    ("about-eq-separation", "about-eq-separation.formula"),
    ("about-eq-weights", "about-eq-weights.formula"),
];

const BOIDS_EQUATIONS: &[(&str, &str)] = &[
    ("about-eq-blended", "about-eq-blended.formula"),
    ("about-eq-classic", "about-eq-classic.formula"),
    (
        "about-eq-direct-alternate",
        "about-eq-direct-alternate.formula",
    ),
    ("about-eq-monte-carlo", "about-eq-monte-carlo.formula"),
    ("about-eq-polarization", "about-eq-polarization.formula"),
    ("about-eq-milling", "about-eq-milling.formula"),
    ("about-eq-nearest", "about-eq-nearest.formula"),
];

const BODY_EQUATIONS: &[(&str, &str)] = &[
    ("about-eq-springs", "about-eq-springs.formula"),
    ("about-eq-mass-motion", "about-eq-mass-motion.formula"),
    ("about-eq-muscles", "about-eq-muscles.formula"),
    ("about-eq-water", "about-eq-water.formula"),
    ("about-eq-fins", "about-eq-fins.formula"),
];

const MIND_EQUATIONS: &[(&str, &str)] = &[
    ("about-eq-hunger", "about-eq-hunger.formula"),
    ("about-eq-libido", "about-eq-libido.formula"),
    ("about-eq-fear", "about-eq-fear.formula"),
    ("about-eq-intention", "about-eq-intention.formula"),
    ("about-eq-shark-choice", "about-eq-shark-choice.formula"),
    ("about-eq-her-choice", "about-eq-her-choice.formula"),
];

const LEARNING_EQUATIONS: &[(&str, &str)] = &[
    ("about-eq-objective", "about-eq-objective.formula"),
    (
        "about-eq-muscle-controls",
        "about-eq-muscle-controls.formula",
    ),
    ("about-eq-annealing", "about-eq-annealing.formula"),
    ("about-eq-abstraction", "about-eq-abstraction.formula"),
];

/// The aquarium's page.
pub const AQUARIUM: About = About {
    what: "about-aquarium-what",
    how: "about-aquarium-how",
    notice: &[
        "about-aquarium-notice-1",
        "about-aquarium-notice-2",
        "about-aquarium-notice-3",
    ],
    try_this: &["about-aquarium-try-1", "about-aquarium-try-2"],
    equations: &[STEERING_EQUATIONS],
    references: &[REYNOLDS, LIM_TAN],
    odd: "schooling",
};

/// The schooling lab's page.
pub const SCHOOLING_LAB: About = About {
    what: "about-schooling-what",
    how: "about-schooling-how",
    notice: &[
        "about-schooling-notice-1",
        "about-schooling-notice-2",
        "about-schooling-notice-3",
    ],
    try_this: &[
        "about-schooling-try-1",
        "about-schooling-try-2",
        "about-schooling-try-3",
        "about-schooling-try-4",
    ],
    equations: &[STEERING_EQUATIONS, URGE_EQUATIONS, BOIDS_EQUATIONS],
    references: &[LIM_TAN, REYNOLDS, COUZIN, BALLERINI, PITCHER, LANDEAU],
    odd: "schooling",
};

/// The physics fish tank's page.
pub const PHYSICS_FISH: About = About {
    what: "about-physics-what",
    how: "about-physics-how",
    notice: &[
        "about-physics-notice-1",
        "about-physics-notice-2",
        "about-physics-notice-3",
    ],
    try_this: &[
        "about-physics-try-1",
        "about-physics-try-2",
        "about-physics-try-3",
    ],
    equations: &[BODY_EQUATIONS],
    references: &[TT_1994, VIDELER],
    odd: "physics",
};

/// The reef's page.
pub const REEF: About = About {
    what: "about-reef-what",
    how: "about-reef-how",
    notice: &[
        "about-reef-notice-1",
        "about-reef-notice-2",
        "about-reef-notice-3",
    ],
    try_this: &["about-reef-try-1", "about-reef-try-2", "about-reef-try-3"],
    equations: &[MIND_EQUATIONS],
    references: &[TT_1994, LANDEAU],
    odd: "reef",
};

/// The learning lab's page.
pub const LEARNING_LAB: About = About {
    what: "about-learning-what",
    how: "about-learning-how",
    notice: &[
        "about-learning-notice-1",
        "about-learning-notice-2",
        "about-learning-notice-3",
    ],
    try_this: &["about-learning-try-1", "about-learning-try-2"],
    equations: &[LEARNING_EQUATIONS],
    references: &[TT_1994, KIRKPATRICK],
    odd: "learning",
};
