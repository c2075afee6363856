//! An AABB tree over a mesh's triangles, built top-down by median split:
//! each node's triangles are split at the median of their centroids along
//! the longest axis of the centroids' box (`select_nth_unstable`, linear per
//! level, so O(n log n) in all), down to one triangle per leaf. A query
//! walks it from the root with a box and records each node it visits.

use nalgebra::Vector3;

/// An axis-aligned box `[min, max]`.
pub type Aabb = [Vector3<f64>; 2];

/// One node: its box, and its two children or its triangle.
#[derive(Debug, Clone, PartialEq)]
pub struct Node {
    pub bounds: Aabb,
    pub kind: NodeKind,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum NodeKind {
    Inner([usize; 2]),
    Leaf(usize),
}

/// The tree; node 0 is the root.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Bvh {
    nodes: Vec<Node>,
}

/// One node visited by a query: whether its box met the query's, and the
/// children it pushed (none for a leaf or a miss).
#[derive(Debug, Clone, PartialEq)]
pub struct Visit {
    pub node: usize,
    pub bounds: Aabb,
    pub overlap: bool,
    pub children: Vec<usize>,
    /// The leaf's triangle, when the node is a leaf.
    pub triangle: Option<usize>,
}

/// Whether two boxes overlap (touching counts).
pub fn overlaps(a: &Aabb, b: &Aabb) -> bool {
    (0..3).all(|i| a[0][i] <= b[1][i] && b[0][i] <= a[1][i])
}

fn union(a: &Aabb, b: &Aabb) -> Aabb {
    [a[0].inf(&b[0]), a[1].sup(&b[1])]
}

fn bounds_of(points: &[Vector3<f64>]) -> Aabb {
    let mut b = [points[0], points[0]];
    for p in &points[1..] {
        b = [b[0].inf(p), b[1].sup(p)];
    }
    b
}

impl Bvh {
    pub fn build(vertices: &[Vector3<f64>], triangles: &[[usize; 3]]) -> Bvh {
        if triangles.is_empty() {
            return Bvh::default();
        }
        let boxes: Vec<Aabb> = (triangles.iter())
            .map(|t| bounds_of(&t.map(|i| vertices[i])))
            .collect();
        let centres: Vec<Vector3<f64>> = boxes.iter().map(|b| (b[0] + b[1]) / 2.0).collect();
        let mut order: Vec<usize> = (0..triangles.len()).collect();
        let mut nodes = Vec::with_capacity(2 * triangles.len());
        build_node(&mut nodes, &mut order, &boxes, &centres);
        Bvh { nodes }
    }

    pub fn nodes(&self) -> &[Node] {
        &self.nodes
    }

    /// The root's box (the whole mesh's), if the tree has nodes.
    pub fn bounds(&self) -> Option<Aabb> {
        self.nodes.first().map(|n| n.bounds)
    }

    /// Depth-first walk with `query`: every node visited, in order, and
    /// the triangles of the leaves whose boxes met it (ascending).
    pub fn traverse(&self, query: &Aabb) -> (Vec<Visit>, Vec<usize>) {
        let mut visits = Vec::new();
        let mut candidates = Vec::new();
        let mut stack = if self.nodes.is_empty() {
            vec![]
        } else {
            vec![0]
        };
        while let Some(i) = stack.pop() {
            let node = &self.nodes[i];
            let overlap = overlaps(&node.bounds, query);
            let mut visit = Visit {
                node: i,
                bounds: node.bounds,
                overlap,
                children: vec![],
                triangle: None,
            };
            match node.kind {
                NodeKind::Inner(children) => {
                    if overlap {
                        visit.children = children.to_vec();
                        stack.push(children[1]);
                        stack.push(children[0]);
                    }
                }
                NodeKind::Leaf(t) => {
                    visit.triangle = Some(t);
                    if overlap {
                        candidates.push(t);
                    }
                }
            }
            visits.push(visit);
        }
        candidates.sort_unstable();
        (visits, candidates)
    }

    /// Depth of the tree (a leaf alone has depth 1).
    pub fn depth(&self) -> usize {
        fn depth(nodes: &[Node], i: usize) -> usize {
            match nodes[i].kind {
                NodeKind::Leaf(_) => 1,
                NodeKind::Inner([a, b]) => 1 + depth(nodes, a).max(depth(nodes, b)),
            }
        }
        if self.nodes.is_empty() {
            0
        } else {
            depth(&self.nodes, 0)
        }
    }
}

/// Builds the node for `order`'s triangles, returns its index.
fn build_node(
    nodes: &mut Vec<Node>,
    order: &mut [usize],
    boxes: &[Aabb],
    centres: &[Vector3<f64>],
) -> usize {
    let bounds = (order[1..].iter()).fold(boxes[order[0]], |b, &t| union(&b, &boxes[t]));
    let index = nodes.len();
    if order.len() == 1 {
        nodes.push(Node {
            bounds,
            kind: NodeKind::Leaf(order[0]),
        });
        return index;
    }
    nodes.push(Node {
        bounds,
        kind: NodeKind::Leaf(usize::MAX),
    });
    let spread = bounds_of(&order.iter().map(|&t| centres[t]).collect::<Vec<_>>());
    let axis = (spread[1] - spread[0]).imax();
    let mid = order.len() / 2;
    order.select_nth_unstable_by(mid, |&a, &b| {
        (centres[a][axis].total_cmp(&centres[b][axis])).then(a.cmp(&b))
    });
    let (left, right) = order.split_at_mut(mid);
    let l = build_node(nodes, left, boxes, centres);
    let r = build_node(nodes, right, boxes, centres);
    nodes[index].kind = NodeKind::Inner([l, r]);
    index
}
