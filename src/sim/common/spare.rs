//! Giving memory back after a count shrinks (issue 35).
//!
//! A `Vec` that is cleared and refilled every step or frame keeps the capacity
//! of the most it ever held. After 300 muscle fish, a tank back at 10 kept
//! about 4.5 MB of such room in the page (the renderer's copy of the last
//! frame's inputs, the fish's bodies, the drawn nodes): bounded, but held for
//! as long as the page lives. [`release_spare`] trims what is far beyond need.

/// Trims `v`'s spare room when it holds more than four times what it needs:
/// it keeps room for twice its length, and never less than `floor` elements.
/// Growing back to the old size takes a few doublings; a count that goes up and
/// down by less than a factor of two never reallocates.
pub fn release_spare<T>(v: &mut Vec<T>, floor: usize) {
    let keep = (2 * v.len()).max(floor);
    if v.capacity() > 2 * keep {
        v.shrink_to(keep);
    }
}

#[cfg(test)]
mod tests {
    use super::release_spare;

    #[test]
    fn a_vec_that_shrank_a_lot_gives_back_its_room_and_one_that_shrank_a_little_keeps_it() {
        let mut v: Vec<u64> = (0..10_000).collect();
        v.truncate(100);
        release_spare(&mut v, 16);
        assert!(v.capacity() <= 400, "kept {} for 100", v.capacity());
        assert!(v.capacity() >= 200);
        assert_eq!(v, (0..100).collect::<Vec<_>>());

        let mut w: Vec<u64> = Vec::with_capacity(1000);
        w.extend(0..400);
        release_spare(&mut w, 16);
        assert_eq!(w.capacity(), 1000, "a Vec at 40 % of its room keeps it");

        let mut empty: Vec<u64> = Vec::with_capacity(1000);
        release_spare(&mut empty, 64);
        assert!(empty.capacity() >= 64 && empty.capacity() <= 128);
    }
}
