//! Determinism and the world's bookkeeping: a seed replays bit for bit, the
//! fish count changes without touching the fish that stay, and a reset
//! rebuilds from the seed.

use super::{assert_all_fish_legal, positions, world};

#[test]
fn same_seed_gives_bit_identical_fish_and_another_seed_does_not() {
    let mut a = world(42, 50);
    let mut b = world(42, 50);
    let mut c = world(43, 50);
    for _ in 0..1_000 {
        a.step();
        b.step();
        c.step();
    }
    assert_eq!(positions(&a), positions(&b));
    assert_ne!(positions(&a), positions(&c));
    assert_ne!(a.obstacles(), c.obstacles());
}

#[test]
fn set_fish_count_grows_and_shrinks_keeping_existing_fish() {
    let mut w = world(9, 10);
    for _ in 0..10 {
        w.step();
    }
    let first_ten = w.fish().to_vec();
    w.set_fish_count(25);
    assert_eq!(w.fish().len(), 25);
    assert_eq!(&w.fish()[..10], &first_ten[..]);
    assert_all_fish_legal(&w);
    w.set_fish_count(4);
    assert_eq!(w.fish(), &first_ten[..4]);
    w.set_fish_count(0);
    assert!(w.fish().is_empty());
    w.step();
    assert_eq!(w.steps(), 11);
}

#[test]
fn reset_rebuilds_from_the_seed_and_keeps_the_fish_count() {
    let mut w = world(1, 7);
    w.step();
    w.set_fish_count(12);
    w.reset(77);
    assert_eq!((w.seed(), w.steps(), w.fish().len()), (77, 0, 12));
    let fresh = world(77, 12);
    assert_eq!(positions(&w), positions(&fresh));
    assert_eq!(w.obstacles(), fresh.obstacles());
}
