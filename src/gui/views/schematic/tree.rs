//! The driveline as an undirected graph for the schematic, and breadth-first search on
//! trees of it.

use std::collections::VecDeque;
use torsim::model::{GROUND, Model};

/// An end of a connection in the graph: node index, or `n + k` for the k-th frame end.
pub type Vertex = usize;

/// Vertices and who is next to whom.
pub struct Graph {
    /// For each vertex: (neighbour, connection).
    pub adjacent: Vec<Vec<(Vertex, usize)>>,
    /// Connection of each frame vertex.
    pub ground_connection: Vec<usize>,
}

/// The model as a graph: nodes, plus one vertex per connection to the frame; connections
/// naming unknown nodes, or a node twice, are left out.
pub fn graph_of(model: &Model) -> Graph {
    let n = model.inertias.len();
    let mut g = Graph {
        adjacent: vec![Vec::new(); n],
        ground_connection: Vec::new(),
    };
    for (j, c) in model.connections.iter().enumerate() {
        let end = |name: &str| {
            if name == GROUND {
                Some(None)
            } else {
                model.node_index(name).map(Some)
            }
        };
        let (a, b) = match (end(&c.from), end(&c.to)) {
            (Some(Some(a)), Some(Some(b))) if a != b => (a, b),
            (Some(Some(a)), Some(None)) | (Some(None), Some(Some(a))) => {
                let v = n + g.ground_connection.len();
                g.ground_connection.push(j);
                g.adjacent.push(Vec::new());
                (a, v)
            }
            _ => continue,
        };
        g.adjacent[a].push((b, j));
        g.adjacent[b].push((a, j));
    }
    g
}

/// Breadth-first distances and parents from `root` over tree edges only.
pub fn bfs(tree: &[Vec<(Vertex, usize)>], root: Vertex) -> (Vec<Option<usize>>, Vec<Vertex>) {
    let mut dist = vec![None; tree.len()];
    let mut parent = vec![usize::MAX; tree.len()];
    dist[root] = Some(0);
    let mut queue = VecDeque::from([root]);
    while let Some(v) = queue.pop_front() {
        for &(w, _) in &tree[v] {
            if dist[w].is_none() {
                dist[w] = dist[v].map(|d| d + 1);
                parent[w] = v;
                queue.push_back(w);
            }
        }
    }
    (dist, parent)
}

/// The farthest vertex from `root` (the first found among equals).
pub fn farthest(dist: &[Option<usize>], root: Vertex) -> Vertex {
    let mut best = (root, 0);
    for (v, d) in dist.iter().enumerate() {
        if let Some(d) = *d
            && d > best.1
        {
            best = (v, d);
        }
    }
    best.0
}
