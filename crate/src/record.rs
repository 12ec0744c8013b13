//! The recorder: named series over the whole run in a fixed memory budget.
//!
//! Two resolutions. The most recent rows are kept at full rate in a ring buffer; every row
//! that falls out of the ring is folded into a min/max bucket of the older history, and when
//! the buckets run out, neighbouring buckets merge pairwise (each then covers twice as many
//! rows). So any run length fits the same memory, a plot of the whole run keeps every spike
//! (the minimum and maximum of each bucket, in the order they happened) and every gap (a
//! bucket that saw a missing value breaks the line), and the recent past is exact. Exports
//! that need every sample stream rows as they are made (`attlab run --csv`) or re-run the
//! simulation (the page), instead of keeping them here.
//!
//! Series 0 is the time axis `t_s`.

use crate::model::SeriesSpec;

/// Memory the page's recorder may use (bytes): the budget of the largest lab.
pub const DEFAULT_BUDGET_BYTES: usize = 16 << 20;

/// Buckets of older history kept per series (pairs merge when they run out).
const MAX_BUCKETS: usize = 1024;

/// Bytes of a budget left for the small per-series arrays (the bucket being filled and
/// where its extremes were); the rest is one block of exactly the same size for every
/// recorder of that budget, so the block a lab switch frees is the one the next lab reuses
/// (the page's wasm memory never shrinks: blocks of different sizes would leave holes).
const SMALL_RESERVE_BYTES: usize = 64 << 10;
/// f64 slots per bucket in the store (min, max, flags).
const BUCKET_SLOTS: usize = 3;

/// Fewest full-rate rows kept, whatever the budget.
const MIN_RECENT_ROWS: usize = 256;

/// Rows per block of the ring. Within a block each series' values are contiguous, so a
/// push writes one compact block (cache and TLB friendly) and a plot reads runs of
/// [`BLOCK`] values.
const BLOCK: usize = 64;

const FLAG_MIN_FIRST: u8 = 1;
const FLAG_GAP: u8 = 2;

/// The flags of a bucket whose minimum came first (or not), keeping the gap bit of `old`.
fn flags(min_first: bool, old: u8) -> u8 {
    (old & FLAG_GAP) | if min_first { FLAG_MIN_FIRST } else { 0 }
}

/// One bucket of one series: its extremes, the order in which they happened, and whether a
/// value was missing.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Bucket {
    min: f64,
    max: f64,
    flags: u8,
}

impl Bucket {
    const EMPTY: Bucket = Bucket {
        min: f64::INFINITY,
        max: f64::NEG_INFINITY,
        flags: FLAG_MIN_FIRST,
    };

    /// `a` followed by `b`.
    fn merge(a: Bucket, b: Bucket) -> Bucket {
        let (min_from_b, max_from_b) = (b.min < a.min, b.max > a.max);
        let min_first = match (min_from_b, max_from_b) {
            (false, false) => a.flags & FLAG_MIN_FIRST != 0,
            (true, true) => b.flags & FLAG_MIN_FIRST != 0,
            (false, true) => a.min.is_finite() || b.flags & FLAG_MIN_FIRST != 0,
            (true, false) => !a.max.is_finite() && b.flags & FLAG_MIN_FIRST != 0,
        };
        Bucket {
            min: a.min.min(b.min),
            max: a.max.max(b.max),
            flags: flags(min_first, a.flags | b.flags),
        }
    }

    fn has_values(&self) -> bool {
        self.min <= self.max
    }
}

/// Named series over the whole run, in a fixed memory budget.
#[derive(Clone, Debug)]
pub struct Recorder {
    specs: Vec<SeriesSpec>,
    /// Full-rate rows in the ring (per series), a multiple of [`BLOCK`].
    window: usize,
    /// One allocation for the ring and the older history. The ring comes first, in blocks
    /// of [`BLOCK`] rows, series-major inside a block:
    /// `recent[(slot / BLOCK) * n * BLOCK + s * BLOCK + slot % BLOCK]`; then the history,
    /// bucket `b` of series `s` at `hist0 + (s * MAX_BUCKETS + b) * BUCKET_SLOTS`.
    recent: Vec<f64>,
    /// Where the history starts in `recent` (`n * window`).
    hist0: usize,
    /// Next slot to write.
    head: usize,
    /// Rows in the ring.
    held: usize,
    /// Completed buckets.
    bucket_count: usize,
    /// Rows per completed bucket.
    bucket_rows: u64,
    /// The bucket being filled, per series, and how many rows it has.
    filling: Vec<Bucket>,
    filling_rows: u64,
    /// Where in the filling bucket the min and max were seen (row index within the bucket).
    filling_at: Vec<(u64, u64)>,
    total_rows: u64,
}

impl Recorder {
    /// A recorder for `specs` (series 0 = time) using about `budget_bytes` of memory.
    pub fn with_budget(specs: Vec<SeriesSpec>, budget_bytes: usize) -> Self {
        let n = specs.len().max(1);
        let small = n * (std::mem::size_of::<Bucket>() + 16);
        // The store's size is the same for every recorder of this budget unless the
        // series are too many for the reserve.
        let store = budget_bytes.saturating_sub(small.max(SMALL_RESERVE_BYTES)) / 8;
        let history = n * MAX_BUCKETS * BUCKET_SLOTS;
        let window = (store.saturating_sub(history) / n / BLOCK * BLOCK).max(MIN_RECENT_ROWS);
        Self::build(specs, window, store)
    }

    /// A recorder keeping `window` rows at full rate (and the min/max history before them).
    pub fn with_window(specs: Vec<SeriesSpec>, window: usize) -> Self {
        Self::build(specs, window, 0)
    }

    /// A recorder keeping `window` rows, its store allocated with room for at least
    /// `capacity` values (one block of a fixed size, see [`SMALL_RESERVE_BYTES`]).
    fn build(specs: Vec<SeriesSpec>, window: usize, capacity: usize) -> Self {
        let n = specs.len();
        let window = window.max(2).div_ceil(BLOCK) * BLOCK;
        let hist0 = n * window;
        let len = hist0 + n * MAX_BUCKETS * BUCKET_SLOTS;
        let mut recent = Vec::with_capacity(len.max(capacity));
        recent.resize(hist0, f64::NAN);
        for _ in 0..n * MAX_BUCKETS {
            recent.extend([
                Bucket::EMPTY.min,
                Bucket::EMPTY.max,
                f64::from(Bucket::EMPTY.flags),
            ]);
        }
        Self {
            recent,
            hist0,
            filling: vec![Bucket::EMPTY; n],
            filling_at: vec![(0, 0); n],
            specs,
            window,
            head: 0,
            held: 0,
            bucket_count: 0,
            bucket_rows: 1,
            filling_rows: 0,
            total_rows: 0,
        }
    }

    /// The series.
    pub fn specs(&self) -> &[SeriesSpec] {
        &self.specs
    }

    /// Index of the series named `name`.
    pub fn index_of(&self, name: &str) -> Option<usize> {
        self.specs.iter().position(|s| s.name == name)
    }

    /// Appends a row (one value per series, in spec order; missing values are NaN).
    pub fn push(&mut self, row: &[f64]) {
        debug_assert_eq!(row.len(), self.specs.len());
        if self.held == self.window {
            // The ring is full and `head` starts its oldest block: fold the whole block into
            // the history at once (series by series, contiguous), then reuse it.
            self.fold_block(self.head);
        }
        let h = self.head;
        let base = self.slot(0, h);
        for (dst, v) in self.recent[base..].iter_mut().step_by(BLOCK).zip(row) {
            *dst = *v;
        }
        self.head = (h + 1) % self.window;
        self.held += 1;
        self.total_rows += 1;
    }

    /// Index of series `s` at ring slot `slot`.
    fn slot(&self, s: usize, slot: usize) -> usize {
        (slot / BLOCK) * self.specs.len() * BLOCK + s * BLOCK + slot % BLOCK
    }

    /// Folds the [`BLOCK`] oldest rows, which start at ring slot `start`, into the history.
    fn fold_block(&mut self, start: usize) {
        // Where buckets close within the block (and whether the history halves first) is
        // the same for every series: work it out once.
        let mut events: Vec<(usize, bool, usize)> = Vec::new(); // (row, halve first, bucket)
        let (mut rows, mut count, mut per) =
            (self.filling_rows, self.bucket_count, self.bucket_rows);
        for k in 0..BLOCK {
            rows += 1;
            if rows == per {
                let halve = count == MAX_BUCKETS;
                if halve {
                    count = MAX_BUCKETS / 2;
                    per *= 2;
                }
                events.push((k, halve, count));
                count += 1;
                rows = 0;
            }
        }
        let first_row = self.filling_rows;
        for s in 0..self.specs.len() {
            let base = self.slot(s, start);
            let (mut b, mut at) = (self.filling[s], self.filling_at[s]);
            let mut n = first_row;
            let mut next_event = events.iter().peekable();
            for k in 0..BLOCK {
                let v = self.recent[base + k];
                if v.is_finite() {
                    if v < b.min {
                        b.min = v;
                        at.0 = n;
                    }
                    if v > b.max {
                        b.max = v;
                        at.1 = n;
                    }
                } else {
                    b.flags |= FLAG_GAP;
                }
                n += 1;
                if let Some(&(_, halve, j)) = next_event.next_if(|e| e.0 == k) {
                    if halve {
                        self.halve_series(s);
                    }
                    b.flags = flags(at.0 <= at.1, b.flags);
                    self.set_bucket(s * MAX_BUCKETS + j, b);
                    b = Bucket::EMPTY;
                    at = (0, 0);
                    n = 0;
                }
            }
            self.filling[s] = b;
            self.filling_at[s] = at;
        }
        self.filling_rows = rows;
        self.bucket_count = count;
        self.bucket_rows = per;
        self.held -= BLOCK;
    }

    /// Merges series `s`'s neighbouring buckets pairwise: half as many, each twice as long.
    fn halve_series(&mut self, s: usize) {
        let base = s * MAX_BUCKETS;
        for j in 0..MAX_BUCKETS / 2 {
            let merged = Bucket::merge(self.bucket(base + 2 * j), self.bucket(base + 2 * j + 1));
            self.set_bucket(base + j, merged);
        }
        for j in MAX_BUCKETS / 2..MAX_BUCKETS {
            self.set_bucket(base + j, Bucket::EMPTY);
        }
    }

    /// History bucket `i` (`s * MAX_BUCKETS + b`).
    fn bucket(&self, i: usize) -> Bucket {
        let k = self.hist0 + i * BUCKET_SLOTS;
        Bucket {
            min: self.recent[k],
            max: self.recent[k + 1],
            // Stored as a small whole number: exact.
            #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
            flags: self.recent[k + 2] as u8,
        }
    }

    /// Sets history bucket `i`.
    fn set_bucket(&mut self, i: usize, b: Bucket) {
        let k = self.hist0 + i * BUCKET_SLOTS;
        self.recent[k..k + BUCKET_SLOTS].copy_from_slice(&[b.min, b.max, f64::from(b.flags)]);
    }

    /// Rows held at full rate now (between the window less one block and the window, once
    /// the run is longer than the window).
    pub fn len(&self) -> usize {
        self.held
    }

    /// No rows at all.
    pub fn is_empty(&self) -> bool {
        self.total_rows == 0
    }

    /// Rows ever pushed.
    pub fn total_rows(&self) -> u64 {
        self.total_rows
    }

    /// Rows kept at full rate at most.
    pub fn window(&self) -> usize {
        self.window
    }

    /// Rows each bucket of the older history covers now.
    pub fn bucket_rows(&self) -> u64 {
        self.bucket_rows
    }

    /// Bytes the recorder holds (fixed at creation: it does not grow with the run).
    pub fn memory_bytes(&self) -> usize {
        self.recent.capacity() * 8
            + self.filling.len() * std::mem::size_of::<Bucket>()
            + self.filling_at.len() * 16
    }

    /// The latest value of series `index`.
    pub fn last(&self, index: usize) -> Option<f64> {
        (index < self.specs.len() && self.held > 0)
            .then(|| self.recent[self.slot(index, (self.head + self.window - 1) % self.window)])
    }

    /// The full-rate values of series `index` held now, oldest first (empty for a series
    /// that does not exist).
    pub fn recent_vec(&self, index: usize) -> Vec<f64> {
        if index >= self.specs.len() {
            return Vec::new();
        }
        let first = (self.head + self.window - self.held) % self.window;
        (0..self.held)
            .map(|k| self.recent[self.slot(index, (first + k) % self.window)])
            .collect()
    }

    /// Of the newest `rows` (at most) full-rate values of series `index`, oldest first, every
    /// `stride`-th from the oldest, where `stride` keeps about `points` of them, and always the
    /// newest: a per-frame trail that reads only the rows it keeps.
    pub fn recent_tail(&self, index: usize, rows: usize, points: usize) -> Vec<f64> {
        self.recent_tail_before(index, 0, rows, points)
    }

    /// [`Recorder::recent_tail`] ending `skipped` rows before the newest (the trail up to
    /// an earlier moment of the run: the timeline's cursor).
    pub fn recent_tail_before(
        &self,
        index: usize,
        skipped: usize,
        rows: usize,
        points: usize,
    ) -> Vec<f64> {
        if index >= self.specs.len() || skipped >= self.held {
            return Vec::new();
        }
        let take = rows.min(self.held - skipped);
        let stride = (take / points.max(1)).max(1);
        // skipped + take ≤ held ≤ window: one window added keeps it from going below 0.
        let first = (self.head + self.window - skipped - take) % self.window;
        // first < window and k < take ≤ window: one subtraction wraps the ring.
        let value = |k: usize| {
            let ring = first + k;
            let ring = if ring >= self.window {
                ring - self.window
            } else {
                ring
            };
            self.recent[self.slot(index, ring)]
        };
        let mut out: Vec<f64> = (0..take).step_by(stride).map(value).collect();
        if take > 0 && !(take - 1).is_multiple_of(stride) {
            out.push(value(take - 1));
        }
        out
    }

    /// (t, y) points of series `y` over the whole run, about `max_points` of them: the older
    /// history as bucket extremes (in the order they happened), the recent rows decimated the
    /// same way. A bucket that saw a missing value adds a `[t, NaN]` gap marker, so lines can
    /// be broken there ([`Recorder::split_at_gaps`]).
    pub fn plot_points(&self, y: usize, max_points: usize) -> Vec<[f64; 2]> {
        if y >= self.specs.len() {
            return Vec::new();
        }
        let mut old: Vec<(Bucket, Bucket)> = (0..self.bucket_count)
            .map(|j| (self.bucket(j), self.bucket(y * MAX_BUCKETS + j)))
            .collect();
        if self.filling_rows > 0 {
            let mut b = self.filling[y];
            let (at_min, at_max) = self.filling_at[y];
            b.flags = flags(at_min <= at_max, b.flags);
            old.push((self.filling[0], b));
        }
        // The recent rows are read in place (a copy of two whole windows per line per frame
        // would raise the page's memory high-water mark).
        let first = (self.head + self.window - self.held) % self.window;
        let at = |s: usize, k: usize| self.recent[self.slot(s, (first + k) % self.window)];
        // Share the points between the history and the recent rows by the rows they cover.
        let old_rows = self.total_rows - self.held as u64;
        let old_share = if self.total_rows == 0 {
            0.0
        } else {
            old_rows as f64 / self.total_rows as f64
        };
        let old_points =
            ((max_points as f64 * old_share) as usize).max(usize::from(!old.is_empty()) * 2);
        let mut out = Vec::with_capacity(max_points + 8);
        let group = old.len().div_ceil((old_points / 2).max(1)).max(1);
        for chunk in old.chunks(group) {
            let (t0, t1) = (chunk[0].0.min, chunk[chunk.len() - 1].0.max);
            let b = chunk
                .iter()
                .skip(1)
                .fold(chunk[0].1, |acc, c| Bucket::merge(acc, c.1));
            if b.has_values() {
                let (first, second) = if b.flags & FLAG_MIN_FIRST != 0 {
                    (b.min, b.max)
                } else {
                    (b.max, b.min)
                };
                out.push([t0, first]);
                out.push([t1, second]);
            }
            if b.flags & FLAG_GAP != 0 {
                out.push([t1, f64::NAN]);
            }
        }
        decimate_into(
            self.held,
            |k| at(0, k),
            |k| at(y, k),
            max_points.saturating_sub(out.len()).max(2),
            &mut out,
        );
        out
    }

    /// Splits plot points at their gap markers into drawable pieces.
    pub fn split_at_gaps(points: &[[f64; 2]]) -> Vec<Vec<[f64; 2]>> {
        points
            .split(|p| !p[1].is_finite())
            .filter(|s| !s.is_empty())
            .map(<[_]>::to_vec)
            .collect()
    }
}

/// Appends (t, y) of full-rate rows to `out`, at most about `max_points`: rows are grouped
/// into buckets and each keeps its minimum and maximum y, so spikes survive; a bucket with a
/// missing y adds a gap marker.
fn decimate_into(
    n: usize,
    t: impl Fn(usize) -> f64,
    y: impl Fn(usize) -> f64,
    max_points: usize,
    out: &mut Vec<[f64; 2]>,
) {
    let per = n.div_ceil((max_points / 2).max(1)).max(1);
    let mut start = 0;
    while start < n {
        let end = (start + per).min(n);
        // (row, value) of the bucket's minimum and maximum, and its first gap.
        let mut lo: Option<(usize, f64)> = None;
        let mut hi: Option<(usize, f64)> = None;
        let mut gap: Option<usize> = None;
        for i in start..end {
            let v = y(i);
            if !v.is_finite() {
                gap = gap.or(Some(i));
                continue;
            }
            if lo.is_none_or(|(_, m)| v < m) {
                lo = Some((i, v));
            }
            if hi.is_none_or(|(_, m)| v > m) {
                hi = Some((i, v));
            }
        }
        let mut pick: Vec<usize> = lo
            .map(|p| p.0)
            .into_iter()
            .chain(hi.map(|p| p.0))
            .chain(gap)
            .collect();
        pick.sort_unstable();
        pick.dedup();
        out.extend(pick.into_iter().map(|i| {
            let v = y(i);
            [t(i), if v.is_finite() { v } else { f64::NAN }]
        }));
        start = end;
    }
}

#[cfg(test)]
mod tests;
