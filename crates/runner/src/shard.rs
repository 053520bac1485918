//! Splitting a sweep over machines: shard K of N runs the points i with i mod N = K − 1 (a deterministic 1/N of
//! them, interleaved so that every shard gets low and high speeds alike) and writes them as CSV under a comment line
//! naming the shard, the number of points, the case fingerprint and a hash of the speed list. [`merge`] checks that
//! the shards belong together and are complete, and interleaves their rows back into the unsharded order, so that
//! the merged file is byte for byte what one unsharded run writes.

use scenario::error::{Result, StudyError, invalid};
use scenario::fnv1a;

/// Shard `index` (1-based) of `count`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Shard {
    /// K, 1 ≤ K ≤ N.
    pub index: usize,
    /// N ≥ 1.
    pub count: usize,
}

impl Shard {
    /// Parse `K/N` (the value of `--shard`).
    pub fn parse(text: &str) -> Result<Self> {
        let bad = || invalid("--shard", text, "must be K/N with whole numbers 1 ≤ K ≤ N, e.g. 2/3");
        let (k, n) = text.split_once('/').ok_or_else(bad)?;
        let (index, count): (usize, usize) =
            (k.trim().parse().map_err(|_| bad())?, n.trim().parse().map_err(|_| bad())?);
        if count == 0 || index == 0 || index > count {
            return Err(bad());
        }
        Ok(Self { index, count })
    }

    /// The items of this shard: those at positions i with i mod N = K − 1.
    pub fn select<T: Copy>(&self, items: &[T]) -> Vec<T> {
        items.iter().copied().skip(self.index - 1).step_by(self.count).collect()
    }

    /// The comment line heading a shard's CSV: `# frictrack-shard K/N points=… case=… speeds=…`.
    pub fn header(&self, speeds: &[f64], fingerprint: u64) -> String {
        format!(
            "# frictrack-shard {}/{} points={} case={fingerprint:016x} speeds={:016x}",
            self.index,
            self.count,
            speeds.len(),
            speeds_hash(speeds)
        )
    }
}

/// A hash of the exact speed list (shortest round-trip decimal of each).
fn speeds_hash(speeds: &[f64]) -> u64 {
    fnv1a(speeds.iter().map(|v| format!("{v},")).collect::<String>().as_bytes())
}

struct Part<'a> {
    name: &'a str,
    shard: Shard,
    points: usize,
    identity: &'a str,
    csv_header: &'a str,
    rows: Vec<&'a str>,
}

fn parse_part<'a>(name: &'a str, text: &'a str) -> Result<Part<'a>> {
    let bad = |message: String| StudyError::Io { path: name.into(), message };
    let mut lines = text.lines();
    let first = lines.next().unwrap_or("");
    let rest = first
        .strip_prefix("# frictrack-shard ")
        .ok_or_else(|| bad("not a shard output (its first line is not `# frictrack-shard K/N …`)".into()))?;
    let (shard, identity) = rest.split_once(' ').ok_or_else(|| bad(format!("malformed shard line `{first}`")))?;
    let shard = Shard::parse(shard).map_err(|_| bad(format!("malformed shard `{shard}` in `{first}`")))?;
    let points: usize = identity
        .strip_prefix("points=")
        .and_then(|r| r.split(' ').next())
        .and_then(|p| p.parse().ok())
        .ok_or_else(|| bad(format!("malformed shard line `{first}`")))?;
    let csv_header = lines.next().ok_or_else(|| bad("no CSV header after the shard line".into()))?;
    let rows: Vec<&str> = lines.collect();
    let expected = (points + shard.count - shard.index) / shard.count;
    if rows.len() != expected {
        return Err(bad(format!(
            "shard {}/{} of {points} points must hold {expected} rows, it holds {} (an unfinished shard?)",
            shard.index,
            shard.count,
            rows.len()
        )));
    }
    Ok(Part { name, shard, points, identity, csv_header, rows })
}

/// Merge shard outputs `(file name, contents)` into the CSV an unsharded sweep writes. All shards 1…N of one sweep
/// (same case, speeds and N) must be there, each once and complete.
pub fn merge(inputs: &[(String, String)]) -> Result<String> {
    if inputs.is_empty() {
        return Err(invalid("shard files", "none", "give the outputs of every shard 1/N … N/N"));
    }
    let mut parts = inputs.iter().map(|(name, text)| parse_part(name, text)).collect::<Result<Vec<_>>>()?;
    parts.sort_by_key(|p| p.shard.index);
    let first = &parts[0];
    for p in &parts[1..] {
        if p.identity != first.identity || p.shard.count != first.shard.count || p.csv_header != first.csv_header {
            return Err(invalid(
                "shard files",
                format!("{} and {}", first.name, p.name),
                "come from different sweeps (case, speeds, N or columns differ)",
            ));
        }
    }
    let n = first.shard.count;
    if parts.len() != n || parts.iter().enumerate().any(|(i, p)| p.shard.index != i + 1) {
        let have: Vec<String> = parts.iter().map(|p| format!("{}/{n}", p.shard.index)).collect();
        return Err(invalid("shard files", have.join(", "), format!("need each shard 1/{n} … {n}/{n} exactly once")));
    }
    let mut out = String::with_capacity(inputs.iter().map(|(_, t)| t.len()).sum());
    out.push_str(first.csv_header);
    out.push('\n');
    for i in 0..first.points {
        out.push_str(parts[i % n].rows[i / n]);
        out.push('\n');
    }
    Ok(out)
}
