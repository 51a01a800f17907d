//! A fast hash for maps keyed by vertex numbers (the half-edges of `mesh.rs`).
//!
//! The keys are numbers the program makes itself (positions in a polygon, pairs of them), never
//! chosen by an adversary, so the standard SipHash, built to resist hash flooding, only costs
//! time: it was a tenth of the MIS's time on small polygons (when the MIS kept its values in
//! such a map). This is a multiplicative hash in the manner of rustc's FxHash, with the high
//! half of each word folded down first so that keys packed as `from << 32 | to` spread over the
//! table by both halves.

use std::collections::HashMap;
use std::hash::{BuildHasherDefault, Hasher};

/// The hasher; see the module docs.
#[derive(Default)]
pub(crate) struct NumberHasher(u64);

impl Hasher for NumberHasher {
    fn finish(&self) -> u64 {
        self.0
    }

    fn write(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.write_u64(u64::from(b));
        }
    }

    fn write_u64(&mut self, n: u64) {
        self.0 = (self.0.rotate_left(5) ^ n ^ (n >> 29)).wrapping_mul(0x517c_c1b7_2722_0a95);
    }

    fn write_usize(&mut self, n: usize) {
        self.write_u64(n as u64);
    }
}

/// A `HashMap` with [`NumberHasher`].
pub(crate) type NumberMap<K, V> = HashMap<K, V, BuildHasherDefault<NumberHasher>>;
