//! The sweep status: an ordered set of small integer ids, kept as a treap in an arena. Used by the
//! simplicity sweep here and by the triangulation sweep of `polydist-separation`.
//!
//! Positions are decided by a caller-supplied comparator during insertion only (or given outright:
//! [`Treap::insert_after`], [`Treap::replace`]); removal and the neighbour queries follow parent
//! links and never compare. So whatever the comparator answers (even
//! inconsistently), the structure stays a valid binary tree, every operation terminates, and nothing
//! panics: insertion descends at most the tree's height, removal rotates the node down at most its
//! height, and the neighbour walks climb or descend at most the height.
//!
//! Priorities are a fixed hash of the id (splitmix64), so runs are reproducible; the expected height is
//! `O(log n)` as for a treap with random priorities, since the hash is unrelated to the geometric order.
//!
//! Reference: Seidel & Aragon, "Randomized search trees", Algorithmica 16 (1996).

use core::cmp::Ordering;

/// No node.
const NIL: usize = usize::MAX;

/// One id's node; ids index the arena directly.
#[derive(Clone, Copy, Debug)]
struct Node {
    left: usize,
    right: usize,
    parent: usize,
    priority: u64,
    linked: bool,
}

/// An ordered set of the ids `0..capacity`, each inserted at most once at a time.
#[derive(Debug)]
pub struct Treap {
    nodes: Vec<Node>,
    root: usize,
}

/// splitmix64: a fixed, well-mixed hash of the id, used as its priority.
fn priority(id: usize) -> u64 {
    let mut z = (id as u64).wrapping_add(0x9E37_79B9_7F4A_7C15);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

impl Treap {
    /// An empty set able to hold the ids `0..capacity`.
    #[must_use]
    pub fn new(capacity: usize) -> Treap {
        let nodes = (0..capacity)
            .map(|id| Node {
                left: NIL,
                right: NIL,
                parent: NIL,
                priority: priority(id),
                linked: false,
            })
            .collect();
        Treap { nodes, root: NIL }
    }

    /// Inserts `id` where the comparator puts it: at each node `other` on the way down, `cmp(other)`
    /// says whether `id` goes before (`Less`) or after (`Equal`, `Greater`) it. A comparator error stops
    /// the insertion, leaves the set unchanged and is returned. Inserting a present id does nothing.
    pub fn insert<E>(
        &mut self,
        id: usize,
        mut cmp: impl FnMut(usize) -> Result<Ordering, E>,
    ) -> Result<(), E> {
        if self.nodes[id].linked {
            return Ok(());
        }
        let mut parent = NIL;
        let mut go_left = false;
        let mut cur = self.root;
        while cur != NIL {
            parent = cur;
            go_left = cmp(cur)? == Ordering::Less;
            cur = if go_left {
                self.nodes[cur].left
            } else {
                self.nodes[cur].right
            };
        }
        self.link_leaf(id, parent, go_left);
        Ok(())
    }

    /// Hangs the unlinked `id` as a leaf below `parent` (or as the root when `parent` is `NIL`)
    /// and rotates it up to restore the heap order on priorities.
    fn link_leaf(&mut self, id: usize, parent: usize, go_left: bool) {
        self.nodes[id] = Node {
            left: NIL,
            right: NIL,
            parent,
            linked: true,
            ..self.nodes[id]
        };
        if parent == NIL {
            self.root = id;
        } else if go_left {
            self.nodes[parent].left = id;
        } else {
            self.nodes[parent].right = id;
        }
        // Each rotation lifts `id` one level.
        while self.nodes[id].parent != NIL
            && self.nodes[self.nodes[id].parent].priority < self.nodes[id].priority
        {
            self.rotate_up(id);
        }
    }

    /// Inserts `id` just after `anchor` in the order, without comparing: `O(height)` pointer steps
    /// and rotations. `false` (and nothing done) when `anchor` is absent or `id` present.
    pub fn insert_after(&mut self, anchor: usize, id: usize) -> bool {
        if !self.nodes[anchor].linked || self.nodes[id].linked {
            return false;
        }
        // The slot just after `anchor`: its right child, or the left end of its right subtree.
        let (mut parent, mut go_left) = (anchor, false);
        let mut cur = self.nodes[anchor].right;
        while cur != NIL {
            (parent, go_left) = (cur, true);
            cur = self.nodes[cur].left;
        }
        self.link_leaf(id, parent, go_left);
        true
    }

    /// Puts `new` in the place of `old` (same position in the order), in `O(1)`: `new` takes
    /// over `old`'s links and its priority, so the tree keeps its shape. For a sweep whose edge ends
    /// where the next begins. `false` (and nothing done) when `old` is absent or `new` present.
    ///
    /// A position keeps the priority of the id first inserted there; priorities stay a fixed hash of
    /// ids unrelated to the order, so the expected height is unchanged.
    pub fn replace(&mut self, old: usize, new: usize) -> bool {
        if old == new || !self.nodes[old].linked || self.nodes[new].linked {
            return false;
        }
        let node = self.nodes[old];
        self.nodes[new] = node;
        for child in [node.left, node.right] {
            if child != NIL {
                self.nodes[child].parent = new;
            }
        }
        self.replace_child(node.parent, old, new);
        self.nodes[old] = Node {
            left: NIL,
            right: NIL,
            parent: NIL,
            priority: priority(old),
            linked: false,
        };
        true
    }

    /// Removes `id`; `false` (and nothing done) when it was absent.
    pub fn remove(&mut self, id: usize) -> bool {
        if !self.nodes[id].linked {
            return false;
        }
        // Rotate `id` down until it is a leaf; each rotation shrinks its subtree, so this terminates.
        loop {
            let Node { left, right, .. } = self.nodes[id];
            let child = match (left != NIL, right != NIL) {
                (false, false) => break,
                (true, false) => left,
                (false, true) => right,
                (true, true) => {
                    if self.nodes[left].priority > self.nodes[right].priority {
                        left
                    } else {
                        right
                    }
                }
            };
            self.rotate_up(child);
        }
        let parent = self.nodes[id].parent;
        self.replace_child(parent, id, NIL);
        self.nodes[id] = Node {
            left: NIL,
            right: NIL,
            parent: NIL,
            priority: priority(id),
            linked: false,
        };
        true
    }

    /// The last id in the order for which `pred` holds, for a `pred` that holds on a prefix of the
    /// order (e.g. "this edge lies below the point"): one descent, at most the height in calls. A
    /// predicate error stops the search and is returned.
    pub fn last_where<E>(
        &self,
        mut pred: impl FnMut(usize) -> Result<bool, E>,
    ) -> Result<Option<usize>, E> {
        let (mut cur, mut best) = (self.root, None);
        while cur != NIL {
            if pred(cur)? {
                best = Some(cur);
                cur = self.nodes[cur].right;
            } else {
                cur = self.nodes[cur].left;
            }
        }
        Ok(best)
    }

    /// The id just before `id` in the order (`None` for the first, or when `id` is absent).
    #[must_use]
    pub fn prev(&self, id: usize) -> Option<usize> {
        self.neighbour(id, |n| n.left, |n| n.right)
    }

    /// The id just after `id` in the order (`None` for the last, or when `id` is absent).
    #[must_use]
    pub fn next(&self, id: usize) -> Option<usize> {
        self.neighbour(id, |n| n.right, |n| n.left)
    }

    /// The in-order neighbour on the side `toward` (its mirror is `away`).
    fn neighbour(
        &self,
        id: usize,
        toward: impl Fn(&Node) -> usize,
        away: impl Fn(&Node) -> usize,
    ) -> Option<usize> {
        if !self.nodes[id].linked {
            return None;
        }
        let sub = toward(&self.nodes[id]);
        if sub != NIL {
            // The extreme node of the subtree on that side.
            let mut cur = sub;
            while away(&self.nodes[cur]) != NIL {
                cur = away(&self.nodes[cur]);
            }
            return Some(cur);
        }
        // Climb until we arrive from the other side.
        let mut cur = id;
        let mut parent = self.nodes[cur].parent;
        while parent != NIL && toward(&self.nodes[parent]) == cur {
            cur = parent;
            parent = self.nodes[cur].parent;
        }
        (parent != NIL).then_some(parent)
    }

    /// Rotates `x` above its parent, keeping the in-order sequence.
    fn rotate_up(&mut self, x: usize) {
        let p = self.nodes[x].parent;
        if p == NIL {
            return;
        }
        let g = self.nodes[p].parent;
        if self.nodes[p].left == x {
            let moved = self.nodes[x].right;
            self.nodes[p].left = moved;
            if moved != NIL {
                self.nodes[moved].parent = p;
            }
            self.nodes[x].right = p;
        } else {
            let moved = self.nodes[x].left;
            self.nodes[p].right = moved;
            if moved != NIL {
                self.nodes[moved].parent = p;
            }
            self.nodes[x].left = p;
        }
        self.nodes[p].parent = x;
        self.nodes[x].parent = g;
        self.replace_child(g, p, x);
    }

    /// Makes `new` the child of `parent` that `old` was (or the root when `parent` is `NIL`).
    fn replace_child(&mut self, parent: usize, old: usize, new: usize) {
        if parent == NIL {
            self.root = new;
        } else if self.nodes[parent].left == old {
            self.nodes[parent].left = new;
        } else {
            self.nodes[parent].right = new;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The ids in order, by walking `next` from the first.
    fn in_order(t: &Treap) -> Vec<usize> {
        let Some(mut cur) = (0..t.nodes.len()).find(|&i| t.nodes[i].linked && t.prev(i).is_none())
        else {
            return Vec::new();
        };
        let mut out = vec![cur];
        while let Some(n) = t.next(cur) {
            out.push(n);
            cur = n;
        }
        out
    }

    #[test]
    fn keeps_order_of_keys_through_inserts_and_removes() {
        // Keys are a permutation; the treap must list present ids sorted by key.
        let n = 200;
        let key: Vec<usize> = (0..n).map(|i| (i * 73) % n).collect();
        let mut t = Treap::new(n);
        for id in 0..n {
            assert_eq!(
                t.insert::<()>(id, |other| Ok(key[id].cmp(&key[other]))),
                Ok(())
            );
        }
        for id in (0..n).step_by(3) {
            t.remove(id);
        }
        let mut expected: Vec<usize> = (0..n).filter(|id| id % 3 != 0).collect();
        expected.sort_by_key(|&id| key[id]);
        assert_eq!(in_order(&t), expected);
        for &id in &expected {
            let pos = expected.iter().position(|&x| x == id).unwrap_or(usize::MAX);
            assert_eq!(t.prev(id), pos.checked_sub(1).map(|p| expected[p]));
            assert_eq!(t.next(id), expected.get(pos + 1).copied());
        }
    }

    /// Checks the parent links and the heap order on the stored priorities.
    fn is_heap(t: &Treap) -> bool {
        (0..t.nodes.len()).filter(|&i| t.nodes[i].linked).all(|i| {
            let n = t.nodes[i];
            [n.left, n.right]
                .into_iter()
                .filter(|&c| c != NIL)
                .all(|c| {
                    t.nodes[c].linked && t.nodes[c].parent == i && t.nodes[c].priority <= n.priority
                })
                && (n.parent != NIL || t.root == i)
        })
    }

    #[test]
    fn positional_inserts_and_replacements_keep_order_and_heap() {
        // Build 0, 2, 4, … by comparisons, place each odd id after its even predecessor, then
        // replace every multiple of 4 by itself + 300: the order must follow the positions given.
        let mut t = Treap::new(600);
        for id in (0..200).step_by(2) {
            assert_eq!(t.insert::<()>(id, |other| Ok(id.cmp(&other))), Ok(()));
        }
        for id in (1..200).step_by(2) {
            assert!(t.insert_after(id - 1, id));
        }
        assert_eq!(in_order(&t), (0..200).collect::<Vec<_>>());
        assert!(is_heap(&t));
        for id in (0..200).step_by(4) {
            assert!(t.replace(id, id + 300));
        }
        let expected: Vec<usize> = (0..200)
            .map(|id| if id % 4 == 0 { id + 300 } else { id })
            .collect();
        assert_eq!(in_order(&t), expected);
        assert!(is_heap(&t));
        // Refused: an absent anchor or old id, a present new id.
        assert!(!t.insert_after(0, 500));
        assert!(!t.insert_after(1, 2));
        assert!(!t.replace(0, 501));
        assert!(!t.replace(1, 2));
        // A replaced position is removed like any other, and the old id can come back.
        assert!(t.remove(300));
        assert_eq!(t.insert::<()>(0, |_| Ok(Ordering::Less)), Ok(()));
        assert_eq!(in_order(&t)[0], 0);
        assert!(is_heap(&t));
    }

    #[test]
    fn survives_an_inconsistent_comparator() {
        let n = 300;
        let mut t = Treap::new(n);
        let mut coin = 12345u64;
        for id in 0..n {
            let inserted = t.insert::<()>(id, |_| {
                coin = priority(coin as usize);
                Ok(if coin % 2 == 0 {
                    Ordering::Less
                } else {
                    Ordering::Greater
                })
            });
            assert_eq!(inserted, Ok(()));
        }
        assert_eq!(in_order(&t).len(), n);
        for id in 0..n {
            t.remove(id);
        }
        assert!(in_order(&t).is_empty());
    }

    #[test]
    fn a_comparator_error_leaves_the_set_unchanged() {
        let mut t = Treap::new(3);
        assert_eq!(t.insert::<()>(0, |_| Ok(Ordering::Less)), Ok(()));
        assert_eq!(t.insert(1, Err), Err(0));
        assert_eq!(in_order(&t), vec![0]);
    }
}
