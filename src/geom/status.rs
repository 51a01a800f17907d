//! The status of a plane sweep: an ordered set whose elements are reached by handle, with their
//! neighbours in constant time.
//!
//! A sweep keeps the edges cut by the sweep line in order and, at every event, asks for the
//! neighbours of an edge it inserts or removes. With `BTreeSet` each of those questions is a
//! search from the root, and each comparison of a search is an exact orientation test, the
//! costly part. Here an element is found once, when inserted; the handle it gets gives its
//! neighbours (a doubly linked list in key order) and removes it, with no comparison at all.
//!
//! Structure: a treap (Seidel & Aragon, "Randomized search trees", Algorithmica 1996) in an
//! arena, with parent links, plus the in-order list. Invariants, kept by every operation:
//! - search order: every key in a node's left subtree is less than the node's, every key in its
//!   right subtree greater (by the key's `Ord`, which the caller keeps consistent over the
//!   elements present at a time, as a sweep status does);
//! - heap order: a node's priority is at most its children's (priorities from a fixed-seed
//!   generator, so runs are reproducible), which makes the expected depth O(log n);
//! - `prev` / `next` link the elements in key order.
//!
//! Complexity: `insert` and `below` O(log n) expected comparisons; `prev`, `next`, `key` O(1);
//! `remove` O(log n) expected rotations and no comparison. Memory: one node per element ever
//! inserted and not yet removed (freed slots are reused).

use std::cmp::Ordering;

/// A handle to an element of a [`Status`], valid until that element is removed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Handle(u32);

const NIL: u32 = u32::MAX;

#[derive(Clone, Debug)]
struct Node<K> {
    key: K,
    priority: u32,
    parent: u32,
    left: u32,
    right: u32,
    prev: u32,
    next: u32,
}

/// An ordered set of keys reached by [`Handle`]: see the module documentation.
#[derive(Clone, Debug)]
pub struct Status<K> {
    nodes: Vec<Node<K>>,
    free: Vec<u32>,
    root: u32,
    seed: u32,
}

impl<K: Ord> Default for Status<K> {
    fn default() -> Self {
        Status::new()
    }
}

impl<K: Ord> Status<K> {
    /// An empty status.
    pub fn new() -> Self {
        Status {
            nodes: Vec::new(),
            free: Vec::new(),
            root: NIL,
            seed: 0x9e37_79b9,
        }
    }

    /// The key of a present element.
    pub fn key(&self, h: Handle) -> &K {
        &self.nodes[h.0 as usize].key
    }

    /// The next smaller element, if any.
    pub fn prev(&self, h: Handle) -> Option<Handle> {
        wrap(self.nodes[h.0 as usize].prev)
    }

    /// The next greater element, if any.
    pub fn next(&self, h: Handle) -> Option<Handle> {
        wrap(self.nodes[h.0 as usize].next)
    }

    /// The greatest element less than `probe`, if any.
    pub fn below(&self, probe: &K) -> Option<Handle> {
        let (mut at, mut best) = (self.root, NIL);
        while at != NIL {
            let node = &self.nodes[at as usize];
            if node.key < *probe {
                best = at;
                at = node.right;
            } else {
                at = node.left;
            }
        }
        wrap(best)
    }

    /// Inserts `key`, which must differ (by `Ord`) from every element present, and returns its
    /// handle.
    pub fn insert(&mut self, key: K) -> Handle {
        // Descend to the leaf position, remembering the neighbours in key order: the last node
        // left of the path (we went right from it) and the last one right of it.
        let (mut parent, mut at, mut went_left) = (NIL, self.root, false);
        let (mut prev, mut next) = (NIL, NIL);
        while at != NIL {
            parent = at;
            let node = &self.nodes[at as usize];
            went_left = key.cmp(&node.key) == Ordering::Less;
            if went_left {
                next = at;
                at = node.left;
            } else {
                prev = at;
                at = node.right;
            }
        }
        let node = Node {
            key,
            priority: self.random(),
            parent,
            left: NIL,
            right: NIL,
            prev,
            next,
        };
        let x = match self.free.pop() {
            Some(slot) => {
                self.nodes[slot as usize] = node;
                slot
            }
            None => {
                let slot = u32::try_from(self.nodes.len()).expect("fewer than 2^32 elements");
                assert!(slot != NIL, "fewer than 2^32 - 1 elements");
                self.nodes.push(node);
                slot
            }
        };
        if parent == NIL {
            self.root = x;
        } else if went_left {
            self.nodes[parent as usize].left = x;
        } else {
            self.nodes[parent as usize].right = x;
        }
        if prev != NIL {
            self.nodes[prev as usize].next = x;
        }
        if next != NIL {
            self.nodes[next as usize].prev = x;
        }
        // Restore heap order.
        loop {
            let p = self.nodes[x as usize].parent;
            if p == NIL || self.nodes[p as usize].priority <= self.nodes[x as usize].priority {
                break;
            }
            self.rotate_up(x);
        }
        Handle(x)
    }

    /// Removes a present element; its handle becomes invalid.
    pub fn remove(&mut self, h: Handle) {
        let x = h.0;
        // Rotate it down until it is a leaf, always lifting the child of smaller priority.
        loop {
            let (l, r) = (self.nodes[x as usize].left, self.nodes[x as usize].right);
            let lift = match (l, r) {
                (NIL, NIL) => break,
                (c, NIL) | (NIL, c) => c,
                (l, r) => {
                    if self.nodes[l as usize].priority <= self.nodes[r as usize].priority {
                        l
                    } else {
                        r
                    }
                }
            };
            self.rotate_up(lift);
        }
        let node = &self.nodes[x as usize];
        let (parent, prev, next) = (node.parent, node.prev, node.next);
        self.replace_child(parent, x, NIL);
        if prev != NIL {
            self.nodes[prev as usize].next = next;
        }
        if next != NIL {
            self.nodes[next as usize].prev = prev;
        }
        self.free.push(x);
    }

    /// Whether the set is empty.
    pub fn is_empty(&self) -> bool {
        self.root == NIL
    }

    /// Makes `x` take its parent's place, its parent becoming its child (one rotation).
    fn rotate_up(&mut self, x: u32) {
        let p = self.nodes[x as usize].parent;
        let g = self.nodes[p as usize].parent;
        if self.nodes[p as usize].left == x {
            // x's right subtree becomes p's left subtree.
            let moved = self.nodes[x as usize].right;
            self.nodes[p as usize].left = moved;
            if moved != NIL {
                self.nodes[moved as usize].parent = p;
            }
            self.nodes[x as usize].right = p;
        } else {
            let moved = self.nodes[x as usize].left;
            self.nodes[p as usize].right = moved;
            if moved != NIL {
                self.nodes[moved as usize].parent = p;
            }
            self.nodes[x as usize].left = p;
        }
        self.nodes[p as usize].parent = x;
        self.nodes[x as usize].parent = g;
        self.replace_child(g, p, x);
    }

    /// Points `parent`'s link to `old` (or the root, when `parent` is NIL) at `new`.
    fn replace_child(&mut self, parent: u32, old: u32, new: u32) {
        if parent == NIL {
            self.root = new;
        } else if self.nodes[parent as usize].left == old {
            self.nodes[parent as usize].left = new;
        } else {
            self.nodes[parent as usize].right = new;
        }
    }

    /// xorshift32: priorities, reproducible from run to run.
    fn random(&mut self) -> u32 {
        let mut s = self.seed;
        s ^= s << 13;
        s ^= s >> 17;
        s ^= s << 5;
        self.seed = s;
        s
    }
}

fn wrap(x: u32) -> Option<Handle> {
    (x != NIL).then_some(Handle(x))
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::BTreeSet;

    /// Every invariant of the module documentation, checked from scratch.
    fn check<K: Ord + Copy + std::fmt::Debug>(s: &Status<K>, expected: &BTreeSet<K>) {
        fn walk<K: Ord + Copy>(s: &Status<K>, at: u32, parent: u32, out: &mut Vec<u32>) {
            if at == NIL {
                return;
            }
            let node = &s.nodes[at as usize];
            assert_eq!(node.parent, parent, "parent link");
            if parent != NIL {
                assert!(
                    s.nodes[parent as usize].priority <= node.priority,
                    "heap order"
                );
            }
            walk(s, node.left, at, out);
            out.push(at);
            walk(s, node.right, at, out);
        }
        let mut inorder = Vec::new();
        walk(s, s.root, NIL, &mut inorder);
        let keys: Vec<K> = inorder.iter().map(|&x| s.nodes[x as usize].key).collect();
        assert_eq!(
            keys,
            expected.iter().copied().collect::<Vec<_>>(),
            "search order"
        );
        for (k, &x) in inorder.iter().enumerate() {
            let prev = if k == 0 { NIL } else { inorder[k - 1] };
            let next = inorder.get(k + 1).copied().unwrap_or(NIL);
            assert_eq!(s.nodes[x as usize].prev, prev, "prev link");
            assert_eq!(s.nodes[x as usize].next, next, "next link");
        }
        assert_eq!(s.is_empty(), expected.is_empty());
    }

    #[test]
    fn random_inserts_and_removals_keep_every_invariant_and_match_a_btreeset() {
        let mut state = 12345u64;
        let mut rand = move |n: u64| {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state % n
        };
        let mut status = Status::new();
        let mut model = BTreeSet::new();
        let mut handles: Vec<(u64, Handle)> = Vec::new();
        for step in 0..4000 {
            if handles.is_empty() || rand(3) > 0 {
                let key = rand(1000);
                if model.insert(key) {
                    let h = status.insert(key);
                    assert_eq!(*status.key(h), key);
                    // Neighbours as the model has them.
                    let below = model.range(..key).next_back().copied();
                    let above = model.range(key + 1..).next().copied();
                    assert_eq!(status.prev(h).map(|p| *status.key(p)), below);
                    assert_eq!(status.next(h).map(|p| *status.key(p)), above);
                    handles.push((key, h));
                }
            } else {
                let (key, h) = handles.swap_remove(rand(handles.len() as u64) as usize);
                status.remove(h);
                model.remove(&key);
            }
            let probe = rand(1001);
            assert_eq!(
                status.below(&probe).map(|h| *status.key(h)),
                model.range(..probe).next_back().copied()
            );
            if step % 97 == 0 {
                check(&status, &model);
            }
        }
        check(&status, &model);
        for (key, h) in handles {
            status.remove(h);
            model.remove(&key);
        }
        check(&status, &model);
        assert!(status.nodes.len() <= 1000, "freed slots are reused");
    }
}
