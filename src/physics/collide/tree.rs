//! The dynamic bounding-volume tree of the broad phase (`broad_phase =
//! "bvh"`), kept from call to call: each body a leaf holding a *fat* box
//! (its box grown by a tenth of its largest half extent), each inner node
//! the box around its two children. A body whose box leaves its fat box is
//! removed and inserted again (descending to the sibling whose box grows
//! least in surface area, the ancestors refitted); a body that is new is
//! inserted, one that lost its box removed. The first call, or a tree
//! grown too deep, is built top-down (halves by the median along the axis
//! of largest spread). Pairs: each body's box queried down the tree, a
//! pair tested at the leaf of its higher body. A box that is not finite is
//! loose: tested against every other box.

use super::bounds::{loose_pairs, Bounds};

const NONE: usize = usize::MAX;

#[derive(Debug, Clone, Copy)]
struct Node {
    fat: Bounds,
    parent: usize,
    children: [usize; 2],
    /// The body of a leaf; `NONE` for an inner node.
    body: usize,
    /// 0 for a leaf.
    height: u32,
}

/// The tree and its last call's counts.
#[derive(Debug, Clone)]
pub(super) struct Tree {
    nodes: Vec<Node>,
    free: Vec<usize>,
    root: usize,
    /// Each body's leaf (`NONE`: not in the tree).
    leaf_of: Vec<usize>,
    loose: Vec<usize>,
    is_loose: Vec<bool>,
    stack: Vec<usize>,
    /// Nodes the last call's queries visited.
    pub(super) visited: usize,
    /// Box-against-box tests at the leaves (each pair once).
    pub(super) tests: usize,
    /// Bodies inserted again in the last call (their box left the fat box).
    pub(super) moved: usize,
    /// Whether the last call built the tree anew.
    pub(super) rebuilt: bool,
}

impl Default for Tree {
    fn default() -> Self {
        Tree {
            nodes: Vec::new(),
            free: Vec::new(),
            root: NONE,
            leaf_of: Vec::new(),
            loose: Vec::new(),
            is_loose: Vec::new(),
            stack: Vec::new(),
            visited: 0,
            tests: 0,
            moved: 0,
            rebuilt: false,
        }
    }
}

impl Tree {
    /// Brings the tree to `boxes`, then appends every pair (i, j), i < j,
    /// whose boxes overlap or touch to `out`, each once, unsorted.
    pub(super) fn pairs(&mut self, boxes: &[Option<Bounds>], out: &mut Vec<(usize, usize)>) {
        self.update(boxes);
        self.visited = 0;
        self.tests = 0;
        for (i, b) in boxes.iter().enumerate() {
            let Some(q) = b else { continue };
            if self.leaf_of[i] == NONE || self.root == NONE {
                continue;
            }
            self.stack.clear();
            self.stack.push(self.root);
            while let Some(n) = self.stack.pop() {
                self.visited += 1;
                let node = self.nodes[n];
                if !node.fat.overlaps(q) {
                    continue;
                }
                if node.body == NONE {
                    self.stack.extend_from_slice(&node.children);
                } else if node.body > i {
                    self.tests += 1;
                    if boxes[node.body].as_ref().is_some_and(|p| p.overlaps(q)) {
                        out.push((i, node.body));
                    }
                }
            }
        }
        self.tests += loose_pairs(&self.loose, &self.is_loose, boxes, out);
    }

    /// Leaves in the tree.
    pub(super) fn leaves(&self) -> usize {
        self.leaf_of.iter().filter(|&&l| l != NONE).count()
    }

    /// The tree's height (0: one leaf or none).
    pub(super) fn height(&self) -> u32 {
        if self.root == NONE {
            0
        } else {
            self.nodes[self.root].height
        }
    }

    /// The last call's loose bodies.
    pub(super) fn loose(&self) -> usize {
        self.loose.len()
    }

    /// Inserts, moves and removes leaves so that every finite box is inside
    /// its body's fat box.
    fn update(&mut self, boxes: &[Option<Bounds>]) {
        self.moved = 0;
        self.rebuilt = false;
        if self.leaf_of.len() != boxes.len() {
            *self = Tree::default();
            self.leaf_of.resize(boxes.len(), NONE);
        }
        self.loose.clear();
        self.is_loose.clear();
        self.is_loose.resize(boxes.len(), false);
        let fresh = self.root == NONE;
        for (i, b) in boxes.iter().enumerate() {
            let fat = b.as_ref().and_then(fat_of);
            let leaf = self.leaf_of[i];
            if b.is_some() && fat.is_none() {
                self.loose.push(i);
                self.is_loose[i] = true;
            }
            match (fat, leaf) {
                (None, NONE) => {}
                (None, leaf) => {
                    self.remove(leaf);
                    self.free.push(leaf);
                    self.leaf_of[i] = NONE;
                }
                (Some(fat), NONE) => {
                    self.leaf_of[i] = self.new_leaf(i, fat);
                    if !fresh {
                        self.insert(self.leaf_of[i]);
                    }
                }
                (Some(fat), leaf) => {
                    let held = b.as_ref().is_some_and(|b| self.nodes[leaf].fat.holds(b));
                    if !held {
                        self.remove(leaf);
                        self.nodes[leaf].fat = fat;
                        self.insert(leaf);
                        self.moved += 1;
                    }
                }
            }
        }
        let leaves = self.leaves();
        let limit = 2 * (usize::BITS - leaves.leading_zeros()) + 8;
        if fresh || self.height() > limit {
            self.rebuild();
        }
    }

    fn new_leaf(&mut self, body: usize, fat: Bounds) -> usize {
        self.alloc(Node {
            fat,
            parent: NONE,
            children: [NONE; 2],
            body,
            height: 0,
        })
    }

    fn alloc(&mut self, node: Node) -> usize {
        match self.free.pop() {
            Some(n) => {
                self.nodes[n] = node;
                n
            }
            None => {
                self.nodes.push(node);
                self.nodes.len() - 1
            }
        }
    }

    /// Takes a leaf out (it stays allocated, to be inserted again or freed).
    fn remove(&mut self, leaf: usize) {
        if leaf == self.root {
            self.root = NONE;
            return;
        }
        let parent = self.nodes[leaf].parent;
        let [l, r] = self.nodes[parent].children;
        let sibling = if l == leaf { r } else { l };
        let grand = self.nodes[parent].parent;
        self.nodes[sibling].parent = grand;
        if grand == NONE {
            self.root = sibling;
        } else {
            let c = &mut self.nodes[grand].children;
            c[usize::from(c[1] == parent)] = sibling;
            self.refit(grand);
        }
        self.free.push(parent);
        self.nodes[leaf].parent = NONE;
    }

    /// Puts a leaf in beside the node whose box it grows least.
    fn insert(&mut self, leaf: usize) {
        if self.root == NONE {
            self.root = leaf;
            self.nodes[leaf].parent = NONE;
            return;
        }
        let b = self.nodes[leaf].fat;
        let mut at = self.root;
        while self.nodes[at].body == NONE {
            let node = self.nodes[at];
            let joined = area(&union(&node.fat, &b));
            let here = 2.0 * joined;
            let inherited = 2.0 * (joined - area(&node.fat));
            let cost = |c: usize| {
                let fat = &self.nodes[c].fat;
                let grown = area(&union(fat, &b));
                let own = if self.nodes[c].body == NONE {
                    area(fat)
                } else {
                    0.0
                };
                grown - own + inherited
            };
            let [l, r] = node.children;
            let (cl, cr) = (cost(l), cost(r));
            if here < cl && here < cr {
                break;
            }
            at = if cl <= cr { l } else { r };
        }
        let old_parent = self.nodes[at].parent;
        let parent = self.alloc(Node {
            fat: union(&self.nodes[at].fat, &b),
            parent: old_parent,
            children: [at, leaf],
            body: NONE,
            height: 0,
        });
        self.nodes[at].parent = parent;
        self.nodes[leaf].parent = parent;
        if old_parent == NONE {
            self.root = parent;
        } else {
            let c = &mut self.nodes[old_parent].children;
            c[usize::from(c[1] == at)] = parent;
        }
        self.refit(parent);
    }

    /// Recomputes the boxes and heights from `n` up to the root.
    fn refit(&mut self, mut n: usize) {
        while n != NONE {
            let [l, r] = self.nodes[n].children;
            let (a, b) = (self.nodes[l], self.nodes[r]);
            self.nodes[n].fat = union(&a.fat, &b.fat);
            self.nodes[n].height = 1 + a.height.max(b.height);
            n = self.nodes[n].parent;
        }
    }

    /// Builds the tree anew over its leaves, top-down by median splits.
    fn rebuild(&mut self) {
        self.rebuilt = true;
        let mut leaves: Vec<usize> = self
            .leaf_of
            .iter()
            .copied()
            .filter(|&l| l != NONE)
            .collect();
        let kept: Vec<Node> = leaves.iter().map(|&l| self.nodes[l]).collect();
        self.nodes.clear();
        self.free.clear();
        for (k, node) in kept.into_iter().enumerate() {
            self.leaf_of[node.body] = k;
            leaves[k] = k;
            self.nodes.push(Node {
                parent: NONE,
                ..node
            });
        }
        self.root = if leaves.is_empty() {
            NONE
        } else {
            self.build(&mut leaves)
        };
    }

    fn build(&mut self, leaves: &mut [usize]) -> usize {
        if leaves.len() == 1 {
            return leaves[0];
        }
        let centre = |n: &Node, k: usize| n.fat.min[k] + n.fat.max[k];
        let mut low = [f64::INFINITY; 3];
        let mut high = [f64::NEG_INFINITY; 3];
        for &l in leaves.iter() {
            for k in 0..3 {
                low[k] = low[k].min(centre(&self.nodes[l], k));
                high[k] = high[k].max(centre(&self.nodes[l], k));
            }
        }
        let axis = (1..3).fold(0, |a, k| {
            if high[k] - low[k] > high[a] - low[a] {
                k
            } else {
                a
            }
        });
        let nodes = &self.nodes;
        leaves.sort_unstable_by(|&p, &q| {
            (centre(&nodes[p], axis).total_cmp(&centre(&nodes[q], axis)))
                .then(nodes[p].body.cmp(&nodes[q].body))
        });
        let (left, right) = leaves.split_at_mut(leaves.len() / 2);
        let (l, r) = (self.build(left), self.build(right));
        let n = self.alloc(Node {
            fat: union(&self.nodes[l].fat, &self.nodes[r].fat),
            parent: NONE,
            children: [l, r],
            body: NONE,
            height: 1 + self.nodes[l].height.max(self.nodes[r].height),
        });
        self.nodes[l].parent = n;
        self.nodes[r].parent = n;
        n
    }

    /// Checks the tree's shape (for tests): every inner node's box holds its
    /// children's, parents and heights agree, every body's leaf is its own.
    #[cfg(test)]
    pub(super) fn check(&self) {
        for (body, &leaf) in self.leaf_of.iter().enumerate() {
            if leaf != NONE {
                assert_eq!(self.nodes[leaf].body, body);
            }
        }
        if self.root == NONE {
            return;
        }
        assert_eq!(self.nodes[self.root].parent, NONE);
        let mut stack = vec![self.root];
        let mut leaves = 0;
        while let Some(n) = stack.pop() {
            let node = self.nodes[n];
            if node.body != NONE {
                leaves += 1;
                continue;
            }
            for c in node.children {
                assert_eq!(self.nodes[c].parent, n);
                assert!(node.fat.holds(&self.nodes[c].fat));
                assert!(node.height > self.nodes[c].height);
                stack.push(c);
            }
        }
        assert_eq!(leaves, self.leaves());
    }
}

/// A box grown by a tenth of its largest half extent; `None` when not finite.
fn fat_of(b: &Bounds) -> Option<Bounds> {
    let half = (0..3).fold(0.0f64, |m, k| m.max(0.5 * (b.max[k] - b.min[k])));
    let m = 0.1 * half;
    let fat = Bounds {
        min: b.min.map(|x| x - m),
        max: b.max.map(|x| x + m),
    };
    let finite = fat.min.iter().chain(&fat.max).all(|x| x.is_finite());
    (finite && m.is_finite() && fat.holds(b)).then_some(fat)
}

fn union(a: &Bounds, b: &Bounds) -> Bounds {
    Bounds {
        min: [0, 1, 2].map(|k| a.min[k].min(b.min[k])),
        max: [0, 1, 2].map(|k| a.max[k].max(b.max[k])),
    }
}

/// Half the surface area.
fn area(b: &Bounds) -> f64 {
    let d = [0, 1, 2].map(|k| b.max[k] - b.min[k]);
    d[0] * d[1] + d[1] * d[2] + d[2] * d[0]
}
