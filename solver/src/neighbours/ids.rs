//! Neighbour indices stored as 16-bit differences.
//!
//! Particles are sorted by cell, so consecutive entries of a list — in candidate order, row by
//! row — are a few indices apart, and the first is within a few cell layers of the particle
//! itself. A list is stored as the differences of its entries, each from the previous one (the
//! first from an *origin*, the particle's own index), as signed 16-bit words; a difference
//! outside ±32767 (the jump to the wall particles, a list in a scene wider than about 170
//! spacings across) is written as the escape word followed by the index in two words. Lists
//! take 2 bytes per entry instead of 4, and decode in order with one add per entry.

/// The word that announces an index written in full (the two words after it, low half first).
const ESCAPE: u16 = 0x8000;
/// The largest difference written in one word.
const SHORT: i64 = 32767;

/// Appends `ids` to `words` as differences from `origin`, then from each entry.
pub(super) fn encode(words: &mut Vec<u16>, origin: u32, ids: &[u32]) {
    let mut prev = origin;
    for &j in ids {
        let d = j as i64 - prev as i64;
        if (-SHORT..=SHORT).contains(&d) {
            words.push(d as i16 as u16);
        } else {
            words.extend_from_slice(&[ESCAPE, j as u16, (j >> 16) as u16]);
        }
        prev = j;
    }
}

/// The indices of one encoded list, in list order.
#[derive(Clone, Debug)]
pub struct Ids<'a> {
    words: std::slice::Iter<'a, u16>,
    prev: u32,
}

impl<'a> Ids<'a> {
    /// Decodes `words`, written by [`encode`] from `origin`.
    #[inline(always)]
    pub(super) fn new(words: &'a [u16], origin: u32) -> Self {
        Ids {
            words: words.iter(),
            prev: origin,
        }
    }

    /// Decodes the rest of the list into `out` (cleared first).
    #[inline]
    pub fn decode_into(self, out: &mut Vec<u32>) {
        out.clear();
        let words = self.words.as_slice();
        if all_short(words) {
            out.resize(words.len(), 0);
            prefix_sums(self.prev, words, out);
        } else {
            out.extend(self.map(|j| j as u32));
        }
    }

    /// Decodes the next entries into `out`, as many as fit; returns how many were written
    /// (fewer than `out.len()` only at the end of the list).
    #[inline(always)]
    pub fn fill(&mut self, out: &mut [u32]) -> usize {
        let words = self.words.as_slice();
        let m = out.len().min(words.len());
        if all_short(&words[..m]) {
            self.prev = prefix_sums(self.prev, &words[..m], &mut out[..m]);
            self.words = words[m..].iter();
            return m;
        }
        let mut n = 0;
        while n < out.len() {
            match self.next() {
                Some(j) => out[n] = j as u32,
                None => break,
            }
            n += 1;
        }
        n
    }

    /// Whether the list has no entries.
    #[inline]
    pub fn is_empty(&self) -> bool {
        self.words.len() == 0
    }
}

impl Iterator for Ids<'_> {
    type Item = usize;

    #[inline(always)]
    fn next(&mut self) -> Option<usize> {
        let w = *self.words.next()?;
        self.prev = if w == ESCAPE {
            let lo = *self.words.next()? as u32;
            let hi = *self.words.next()? as u32;
            lo | (hi << 16)
        } else {
            self.prev.wrapping_add(w as i16 as i32 as u32)
        };
        Some(self.prev as usize)
    }

    #[inline]
    fn size_hint(&self) -> (usize, Option<usize>) {
        let n = self.words.len();
        (n.div_ceil(3), Some(n))
    }
}

/// Whether no word of `words` is an escape: each is a difference (branch-free, vectorised: most
/// lists have no escape, and they then decode without a test per entry).
#[inline(always)]
fn all_short(words: &[u16]) -> bool {
    !words.iter().fold(false, |any, &w| any | (w == ESCAPE))
}

/// Writes into `out` the running sums of the differences `words` (no escapes) from `prev`;
/// returns the last index (`prev` for none).
#[inline(always)]
fn prefix_sums(mut prev: u32, words: &[u16], out: &mut [u32]) -> u32 {
    for (o, &w) in out.iter_mut().zip(words) {
        prev = prev.wrapping_add(w as i16 as i32 as u32);
        *o = prev;
    }
    prev
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_difference_round_trips() {
        // short steps either way, the largest short ones, the first escaped ones, jumps to the
        // top of the index range and back, repeats
        let ids: Vec<u32> = vec![
            5,
            0,
            32767,
            0,
            32768,
            1,
            65_536 + 1,
            70_000,
            37_233,
            37_232,
            u32::MAX >> 1,
            3,
            3,
            4_000_000_000,
            4_000_000_001,
        ];
        for origin in [0u32, 7, 40_000, u32::MAX >> 1] {
            let mut words = vec![9u16]; // a previous list's word, left alone
            encode(&mut words, origin, &ids);
            let back: Vec<usize> = Ids::new(&words[1..], origin).collect();
            assert_eq!(back, ids.iter().map(|&j| j as usize).collect::<Vec<_>>());
            assert_eq!(words[0], 9);
        }
        // one word per entry when every step is short; three for an escaped one
        let mut words = Vec::new();
        encode(&mut words, 100, &[90, 95, 32_862, 32_863]);
        assert_eq!(words.len(), 1 + 1 + 1 + 1);
        encode(&mut words, 0, &[32_768]);
        assert_eq!(words.len(), 4 + 3);
        assert!(Ids::new(&[], 5).is_empty() && Ids::new(&[], 5).next().is_none());
    }

    #[test]
    fn decoding_in_bulk_gives_the_entries_one_by_one() {
        // lists without escapes (the fast path) and with them at the start, middle and end,
        // decoded whole and in pieces of every size around a chunk (an escape straddling one)
        let short: Vec<u32> = (0..40).map(|k| 1000 + 7 * k - (k % 3) * 5).collect();
        let mut lists = vec![short.clone(), vec![], vec![3]];
        for at in [0, 17, 39] {
            let mut l = short.clone();
            l.insert(at, 900_000 + at as u32);
            lists.push(l);
        }
        for ids in &lists {
            let mut words = Vec::new();
            encode(&mut words, 1003, ids);
            let one_by_one: Vec<u32> = Ids::new(&words, 1003).map(|j| j as u32).collect();
            assert_eq!(&one_by_one, ids);
            let mut whole = vec![77];
            Ids::new(&words, 1003).decode_into(&mut whole);
            assert_eq!(&whole, ids);
            for piece in [1, 2, 15, 16, 17, 64] {
                let mut it = Ids::new(&words, 1003);
                let (mut got, mut buf) = (Vec::new(), vec![0u32; piece]);
                loop {
                    let m = it.fill(&mut buf);
                    got.extend_from_slice(&buf[..m]);
                    if m < piece {
                        break;
                    }
                }
                assert_eq!(&got, ids, "pieces of {piece}");
            }
        }
    }
}
