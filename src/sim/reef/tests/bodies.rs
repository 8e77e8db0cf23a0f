//! Bodies: the muscle fish's tail fins never fold in the reef.

use super::*;

#[test]
fn tail_fins_never_fold_in_the_reef_and_the_predator_demo() {
    // With the tips tied to ring 5 only, 9 of 18 fish of the reef and 7 of 15
    // of the predator demo (seed 1) folded their fins within 2 minutes, for
    // 34 % and 40 % of the fish-time (`shoal-census fold`, before the brace).
    for scene in [ReefScene::Reef, ReefScene::PredatorAndSchool] {
        let (share, fish, of) = folded_fins(scene, 1, 60.0);
        assert_eq!(
            fish, 0,
            "{scene:?}: {fish} of {of} fish, {share} of the time"
        );
    }
}
