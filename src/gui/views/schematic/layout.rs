//! Where each element of the schematic goes: a pure function of the model, so that tests
//! can compute an element's screen position without drawing.
//!
//! The driveline is laid out as a tree on a grid of columns and lanes. Each connected
//! part is spanned by a breadth-first tree from its first node (the reference node for
//! the part that has it). The main line, on lane 0, runs from the node farthest from the
//! load to the load node on the right; without a load node it is the tree's longest path,
//! with the reference node near the left end. Every other branch
//! leaves its node downwards or upwards (alternately) on a lane of its own and then runs to
//! the right; branches are placed from the right end of the main line to the left, and a
//! branch's own side branches after its continuation, so a branch's vertical drop never
//! crosses a node. Connections to `ground` end at a frame symbol in a cell of their own.
//! Connections outside the tree (loops) are drawn as arcs.

use crate::gui::views::schematic::tree::{Vertex, bfs, farthest, graph_of};
use std::collections::VecDeque;
use torsim::model::{Model, graph};

/// A cell of the grid: column (along the driveline) and lane (from 0 at the top; a part's
/// branches lie on lanes below and above its main line).
pub type Cell = [i32; 2];

/// One connection in the schematic.
#[derive(Debug, Clone, PartialEq)]
pub struct Link {
    /// Index in `model.connections`.
    pub connection: usize,
    /// Cell of the end nearer the main line (the tree parent).
    pub from: Cell,
    /// Cell of the other end (a node or the frame).
    pub to: Cell,
    /// True for a tree connection (straight or one elbow); false for a loop, drawn as an arc.
    pub tree: bool,
}

/// The schematic on its grid.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Layout {
    /// Cell of each inertia, in model order; `None` for none (no inertias are left out).
    pub nodes: Vec<Option<Cell>>,
    /// Drawn connections (those whose ends name known nodes or `ground`).
    pub links: Vec<Link>,
    /// Cells of frame symbols: (connection, cell).
    pub grounds: Vec<(usize, Cell)>,
    /// Number of columns used.
    pub columns: i32,
    /// Lowest and highest lane used.
    pub lanes: [i32; 2],
}

struct Placer<'a> {
    tree: &'a [Vec<(Vertex, usize)>],
    cell: Vec<Option<Cell>>,
    links: Vec<Link>,
    /// Next free lane below (positive) and above (negative) the main line.
    below: i32,
    above: i32,
}

impl Placer<'_> {
    fn next_lane(&mut self, down: bool) -> i32 {
        if down {
            self.below += 1;
            self.below
        } else {
            self.above -= 1;
            self.above
        }
    }

    /// Places `v` at `cell` and its subtree (away from `parent`) to the right.
    fn subtree(&mut self, v: Vertex, parent: Vertex, cell: Cell, down: bool) {
        self.cell[v] = Some(cell);
        let children: Vec<(Vertex, usize)> = self.tree[v]
            .iter()
            .copied()
            .filter(|&(w, _)| w != parent)
            .collect();
        for (k, (w, j)) in children.into_iter().enumerate() {
            let lane = if k == 0 {
                cell[1]
            } else {
                self.next_lane(down)
            };
            let to = [cell[0] + 1, lane];
            self.links.push(Link {
                connection: j,
                from: cell,
                to,
                tree: true,
            });
            self.subtree(w, v, to, down);
        }
    }
}

/// Lays out the model's schematic (see the module docs).
pub fn layout(model: &Model) -> Layout {
    let g = graph_of(model);
    let n = model.inertias.len();
    let total = g.adjacent.len();
    let mut out = Layout {
        nodes: vec![None; n],
        ..Layout::default()
    };
    let mut seen = vec![false; total];
    let mut tree: Vec<Vec<(Vertex, usize)>> = vec![Vec::new(); total];
    let mut in_tree = vec![false; model.connections.len()];
    let reference = graph::reference_node(model).unwrap_or(0);
    // The node that holds the mean speed, when something does (not the frame).
    let holds = model.load.is_some() || (model.engine.is_some() && !model.is_grounded());
    let load_anchor = holds
        .then(|| model.load_node().and_then(|name| model.node_index(name)))
        .flatten();
    let roots = std::iter::once(reference).chain(0..n).filter(|&r| r < n);
    let mut lane_offset = 0;
    for root in roots.collect::<Vec<_>>() {
        if seen[root] {
            continue;
        }
        // Spanning tree of this part, breadth first from its root.
        let mut members = vec![root];
        seen[root] = true;
        let mut queue = VecDeque::from([root]);
        while let Some(v) = queue.pop_front() {
            for &(w, j) in &g.adjacent[v] {
                if !seen[w] {
                    seen[w] = true;
                    in_tree[j] = true;
                    tree[v].push((w, j));
                    tree[w].push((v, j));
                    members.push(w);
                    queue.push_back(w);
                }
            }
        }
        // Main line: from the load node to the node farthest from it (the load on the
        // right), or else the tree's longest path, the root's end to the left.
        let dist_root = bfs(&tree, root).0;
        let load = load_anchor.filter(|l| members.contains(l));
        let a = load.unwrap_or_else(|| farthest(&dist_root, root));
        let (dist_a, parent) = bfs(&tree, a);
        let b = farthest(&dist_a, a);
        let mut path = vec![b];
        while let Some(&last) = path.last()
            && last != a
        {
            path.push(parent[last]);
        }
        // The path's vertex nearest the root goes to the left half; on a tie the end with
        // the lower index (file order; frame ends come last) goes left.
        let attach = (0..path.len())
            .min_by_key(|&p| dist_root[path[p]].unwrap_or(usize::MAX))
            .unwrap_or(0);
        let keep = if load.is_some() {
            true
        } else if 2 * attach + 1 == path.len() {
            path[0] <= path[path.len() - 1]
        } else {
            2 * attach < path.len()
        };
        if !keep {
            path.reverse();
        }
        let mut placer = Placer {
            tree: &tree,
            cell: vec![None; total],
            links: Vec::new(),
            below: 0,
            above: 0,
        };
        for (x, &v) in path.iter().enumerate() {
            placer.cell[v] = Some([x as i32, 0]);
        }
        for (x, pair) in path.windows(2).enumerate() {
            if let Some(&(_, j)) = tree[pair[0]].iter().find(|&&(w, _)| w == pair[1]) {
                placer.links.push(Link {
                    connection: j,
                    from: [x as i32, 0],
                    to: [x as i32 + 1, 0],
                    tree: true,
                });
            }
        }
        let mut down = true;
        for (x, &v) in path.iter().enumerate().rev() {
            let branches: Vec<(Vertex, usize)> = tree[v]
                .iter()
                .copied()
                .filter(|(w, _)| !path.contains(w))
                .collect();
            for (w, j) in branches {
                let lane = placer.next_lane(down);
                let from = [x as i32, 0];
                let to = [x as i32 + 1, lane];
                placer.links.push(Link {
                    connection: j,
                    from,
                    to,
                    tree: true,
                });
                placer.subtree(w, v, to, down);
                down = !down;
            }
        }
        // Stack this part below the previous ones.
        let shift = lane_offset - placer.above;
        let (mut links, cells) = (placer.links, placer.cell);
        let moved = |c: Cell| [c[0], c[1] + shift];
        for link in &mut links {
            link.from = moved(link.from);
            link.to = moved(link.to);
        }
        for &v in &members {
            let Some(c) = cells[v] else { continue };
            out.columns = out.columns.max(c[0] + 1);
            if v < n {
                out.nodes[v] = Some(moved(c));
            } else {
                out.grounds.push((g.ground_connection[v - n], moved(c)));
            }
        }
        out.links.extend(links);
        lane_offset = shift + placer.below + 2;
    }
    // Loops: connections between placed nodes that the trees left out.
    for (j, c) in model.connections.iter().enumerate() {
        if in_tree[j] {
            continue;
        }
        let cell = |name: &str| model.node_index(name).and_then(|i| out.nodes[i]);
        if let (Some(from), Some(to)) = (cell(&c.from), cell(&c.to))
            && from != to
        {
            out.links.push(Link {
                connection: j,
                from,
                to,
                tree: false,
            });
        }
    }
    let lanes = out
        .nodes
        .iter()
        .flatten()
        .chain(out.grounds.iter().map(|g| &g.1));
    out.lanes = lanes.fold([i32::MAX, i32::MIN], |[lo, hi], c| {
        [lo.min(c[1]), hi.max(c[1])]
    });
    if out.lanes[0] > out.lanes[1] {
        out.lanes = [0, 0];
    }
    out.links.sort_by_key(|l| l.connection);
    out
}
