//! The nearest-node index of [`super::Rrt`]: a bucket quadtree over the unit square whose
//! [`NearestIndex::nearest`] is exactly [`super::nearest_linear`] (numpy's `argmin`: the
//! recipe's distance `sqrt(dx * dx + dy * dy)`, the first index among equal ones), only
//! without looking at cells that cannot hold the answer.
//!
//! Layout: cells in one array (a cell is a leaf or the parent of 4 consecutive cells; bounds
//! are not stored but derived on the way down from the root [0, 1]^2), and the leaves' points
//! in one pool of fixed-size blocks (positions and ids in two parallel arrays), so that a
//! search reads a leaf as one contiguous run of memory and no leaf owns an allocation. Within
//! a leaf the ids increase (nodes are added in id order and a split keeps the order), so a
//! truncation pops leaves' tails.
//!
//! A search goes down to the leaf holding the query, scans it, then climbs back: at each
//! level it visits the siblings that may hold a nearer (or equally near, smaller) node, and
//! it stops as soon as the query lies farther inside the current cell than the best distance
//! (nothing outside can win).

use super::geometry::distance;

/// Points per leaf before it splits (one block of the pool).
const LEAF_CAPACITY: usize = 64;
/// Deepest level (cells of 2^-24): beyond it a leaf just grows (coincident nodes), into a
/// block twice as big.
const MAX_DEPTH: u8 = 24;
/// Slack on the pruning bounds: a cell is skipped only when every point in it is farther than
/// the best distance by more than any rounding of the recipe's distance (< 1e-15 in the unit
/// square), so a tie with a smaller index is never skipped.
const PRUNE_SLACK: f64 = 1e-9;
/// `Cell::len` of a cell that has children.
const INTERNAL: u32 = u32::MAX;
/// `Cell::first` of a leaf that has no block yet (it never held a point).
const NO_BLOCK: u32 = u32::MAX;

/// A cell: the parent of the 4 cells from `first` (`len == INTERNAL`), or a leaf holding
/// `len` points in the pool from `first`.
#[derive(Debug, Clone, Copy)]
struct Cell {
    first: u32,
    len: u32,
}

const EMPTY_LEAF: Cell = Cell {
    first: NO_BLOCK,
    len: 0,
};

/// A cell's bounds `[x0, y0, x1, y1]`.
type Rect = [f64; 4];

const ROOT: Rect = [0.0, 0.0, 1.0, 1.0];

/// Which child (0..4) of cell `r` holds `p`, and that child's bounds.
#[inline]
fn child_of(r: &Rect, p: [f64; 2]) -> (u32, Rect) {
    let (mx, my) = (0.5 * (r[0] + r[2]), 0.5 * (r[1] + r[3]));
    let k = u32::from(p[0] >= mx) + 2 * u32::from(p[1] >= my);
    (k, child_rect(r, k))
}

/// The bounds of child `k` of cell `r`.
#[inline]
fn child_rect(r: &Rect, k: u32) -> Rect {
    let (mx, my) = (0.5 * (r[0] + r[2]), 0.5 * (r[1] + r[3]));
    let (x0, x1) = if k & 1 == 0 { (r[0], mx) } else { (mx, r[2]) };
    let (y0, y1) = if k & 2 == 0 { (r[1], my) } else { (my, r[3]) };
    [x0, y0, x1, y1]
}

/// Distance from `q` to cell `r` (0 inside).
#[inline]
fn gap(r: &Rect, q: [f64; 2]) -> f64 {
    let dx = (r[0] - q[0]).max(q[0] - r[2]).max(0.0);
    let dy = (r[1] - q[1]).max(q[1] - r[3]).max(0.0);
    (dx * dx + dy * dy).sqrt()
}

/// How far `q` lies inside cell `r`: the distance to its nearest side (negative outside).
#[inline]
fn depth_inside(r: &Rect, q: [f64; 2]) -> f64 {
    (q[0] - r[0])
        .min(r[2] - q[0])
        .min(q[1] - r[1])
        .min(r[3] - q[1])
}

/// Slots of the block of a leaf holding `len` points: [`LEAF_CAPACITY`], or the power of two
/// a deepest-level leaf has grown to.
#[inline]
fn block_slots(len: usize) -> usize {
    len.max(LEAF_CAPACITY).next_power_of_two()
}

/// The best node so far: id and distance.
type Best = (u32, f64);

/// The nearest-node index of [`super::Rrt`] (see the module's docs).
#[derive(Debug, Clone)]
pub struct NearestIndex {
    cells: Vec<Cell>,
    /// The leaves' blocks: positions, and ids in a parallel array.
    points: Vec<[f64; 2]>,
    ids: Vec<u32>,
    /// Blocks of [`LEAF_CAPACITY`] slots that splits gave back.
    free: Vec<u32>,
    /// The search's way down: cell and bounds per level.
    path: Vec<(u32, Rect)>,
}

impl Default for NearestIndex {
    fn default() -> Self {
        NearestIndex::new()
    }
}

impl NearestIndex {
    /// An empty index over [0, 1]^2 (points outside still work, in the border cells).
    pub fn new() -> NearestIndex {
        NearestIndex {
            cells: vec![EMPTY_LEAF],
            points: Vec::new(),
            ids: Vec::new(),
            free: Vec::new(),
            path: Vec::new(),
        }
    }

    /// An index of every node.
    pub fn of(nodes: &[[f64; 2]]) -> NearestIndex {
        let mut index = NearestIndex::new();
        for id in 0..nodes.len() {
            index.insert(nodes, id);
        }
        index
    }

    /// The leaf holding `p`, its bounds and depth.
    #[inline]
    fn leaf_of(&self, p: [f64; 2]) -> (usize, Rect, u8) {
        let (mut c, mut r, mut depth) = (0, ROOT, 0);
        while self.cells[c].len == INTERNAL {
            let (k, child) = child_of(&r, p);
            c = (self.cells[c].first + k) as usize;
            r = child;
            depth += 1;
        }
        (c, r, depth)
    }

    /// A block of [`LEAF_CAPACITY`] slots: a freed one, or a new one at the pool's end.
    fn new_block(&mut self) -> u32 {
        if let Some(b) = self.free.pop() {
            return b;
        }
        self.grow_pool(LEAF_CAPACITY)
    }

    /// `slots` new slots at the pool's end; returns the first.
    fn grow_pool(&mut self, slots: usize) -> u32 {
        let first = self.points.len();
        self.points.resize(first + slots, [0.0; 2]);
        self.ids.resize(first + slots, 0);
        first as u32
    }

    /// Adds node `id` (at `nodes[id]`), which must be the largest id in the index.
    pub fn insert(&mut self, nodes: &[[f64; 2]], id: usize) {
        let Some(&p) = nodes.get(id) else {
            return;
        };
        loop {
            let (c, r, depth) = self.leaf_of(p);
            let Cell { first, len } = self.cells[c];
            let len = len as usize;
            if first == NO_BLOCK {
                self.cells[c].first = self.new_block();
            } else if len == block_slots(len) {
                if depth < MAX_DEPTH {
                    self.split(c, r);
                    continue;
                }
                // Coincident nodes at the deepest level: move to a block twice as big.
                let moved = self.grow_pool(2 * len);
                let (from, to) = (first as usize, moved as usize);
                self.points.copy_within(from..from + len, to);
                self.ids.copy_within(from..from + len, to);
                if len == LEAF_CAPACITY {
                    self.free.push(first);
                }
                self.cells[c].first = moved;
            }
            let slot = (self.cells[c].first as usize) + len;
            self.points[slot] = p;
            self.ids[slot] = id as u32;
            self.cells[c].len += 1;
            return;
        }
    }

    /// Leaf `c` (bounds `r`, full) gets 4 children that take its points, in order.
    fn split(&mut self, c: usize, r: Rect) {
        let Cell { first, len } = self.cells[c];
        let children = self.cells.len() as u32;
        self.cells.extend([EMPTY_LEAF; 4]);
        self.cells[c] = Cell {
            first: children,
            len: INTERNAL,
        };
        for slot in first as usize..(first + len) as usize {
            let (p, id) = (self.points[slot], self.ids[slot]);
            let (k, _) = child_of(&r, p);
            let child = (children + k) as usize;
            if self.cells[child].first == NO_BLOCK {
                self.cells[child].first = self.new_block();
            }
            let to = (self.cells[child].first + self.cells[child].len) as usize;
            self.points[to] = p;
            self.ids[to] = id;
            self.cells[child].len += 1;
        }
        self.free.push(first);
    }

    /// Removes every node from `len` on (`nodes` still holds them), as after
    /// `nodes.truncate(len)`.
    pub fn truncate(&mut self, nodes: &[[f64; 2]], len: usize) {
        for id in (len..nodes.len()).rev() {
            let (c, _, _) = self.leaf_of(nodes[id]);
            let Cell { first, len: n } = self.cells[c];
            if n == 0 || first == NO_BLOCK {
                continue;
            }
            let (from, n) = (first as usize, n as usize);
            if self.ids[from + n - 1] as usize == id {
                // The usual case: the largest id left is the leaf's last.
                self.cells[c].len -= 1;
            } else {
                let mut kept = 0;
                for slot in from..from + n {
                    if (self.ids[slot] as usize) < len {
                        self.points[from + kept] = self.points[slot];
                        self.ids[from + kept] = self.ids[slot];
                        kept += 1;
                    }
                }
                self.cells[c].len = kept as u32;
            }
        }
    }

    /// The index of the node nearest to `q`: exactly [`super::nearest_linear`] (0 when empty).
    pub fn nearest(&mut self, q: [f64; 2]) -> usize {
        let mut path = std::mem::take(&mut self.path);
        path.clear();
        let (mut c, mut r) = (0u32, ROOT);
        loop {
            path.push((c, r));
            let cell = self.cells[c as usize];
            if cell.len != INTERNAL {
                break;
            }
            let (k, child) = child_of(&r, q);
            c = cell.first + k;
            r = child;
        }
        let mut best: Best = (u32::MAX, f64::INFINITY);
        self.scan(c as usize, q, &mut best);
        // Climb: the siblings of each cell of the way down, the smallest first.
        for level in (1..path.len()).rev() {
            let (cell, r) = path[level];
            if depth_inside(&r, q) - PRUNE_SLACK > best.1 {
                // Every node outside this cell is farther than the best.
                break;
            }
            let (parent, pr) = path[level - 1];
            let children = self.cells[parent as usize].first;
            let own = cell - children;
            for k in [own ^ 1, own ^ 2, own ^ 3] {
                let sr = child_rect(&pr, k);
                if gap(&sr, q) - PRUNE_SLACK <= best.1 {
                    self.search(children + k, &sr, q, &mut best);
                }
            }
        }
        self.path = path;
        if best.0 == u32::MAX {
            0
        } else {
            best.0 as usize
        }
    }

    /// Searches the subtree of cell `c` (bounds `r`), the child nearest `q` first.
    fn search(&self, c: u32, r: &Rect, q: [f64; 2], best: &mut Best) {
        let cell = self.cells[c as usize];
        if cell.len != INTERNAL {
            self.scan(c as usize, q, best);
            return;
        }
        let (own, _) = child_of(r, q);
        for k in [own, own ^ 1, own ^ 2, own ^ 3] {
            let cr = child_rect(r, k);
            if gap(&cr, q) - PRUNE_SLACK <= best.1 {
                self.search(cell.first + k, &cr, q, best);
            }
        }
    }

    /// The points of leaf `c` against the best so far (ties: the smaller id).
    #[inline]
    fn scan(&self, c: usize, q: [f64; 2], best: &mut Best) {
        let Cell { first, len } = self.cells[c];
        if len == 0 {
            return;
        }
        let from = first as usize;
        let points = &self.points[from..from + len as usize];
        for (slot, p) in points.iter().enumerate() {
            let d = distance(*p, q);
            if d <= best.1 {
                let id = self.ids[from + slot];
                if d < best.1 || id < best.0 {
                    *best = (id, d);
                }
            }
        }
    }
}
