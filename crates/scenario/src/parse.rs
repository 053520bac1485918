//! Where a TOML error is: the line and column of the offending byte, the dotted path of its key, and a "did you
//! mean" for a misspelt key or value.

/// The dotted path of the key at byte `offset`: the enclosing `[table]` header and the key on that line (or the
/// header itself when the offset is inside one). `None` for a syntax error not on a key.
pub(super) fn key_path(text: &str, offset: usize) -> Option<String> {
    let offset = offset.min(text.len());
    let line_start = text[..offset].rfind('\n').map_or(0, |i| i + 1);
    let line = text[line_start..].lines().next().unwrap_or("").trim();
    let header = |l: &str| l.trim_start_matches('[').split(']').next().map(|h| h.trim().replace(' ', ""));
    if line.starts_with('[') {
        return header(line).filter(|h| !h.is_empty());
    }
    let key = line.split_once('=')?.0.trim().trim_matches('"');
    if key.is_empty() {
        return None;
    }
    let table = text[..line_start].lines().rev().map(str::trim).find(|l| l.starts_with('[')).and_then(header);
    Some(match table {
        Some(t) if !t.is_empty() => format!("{t}.{key}"),
        _ => key.to_string(),
    })
}

/// For serde's "unknown field `x`, expected `a`, `b`…" (or variant): ", did you mean `a`?" when one of the
/// expected names is within a third of its length in edit distance, else nothing.
pub(super) fn did_you_mean(message: &str) -> String {
    let Some(rest) = message.strip_prefix("unknown field `").or_else(|| message.strip_prefix("unknown variant `"))
    else {
        return String::new();
    };
    let Some((given, expected)) = rest.split_once('`') else { return String::new() };
    let candidates = expected.split('`').skip(1).step_by(2);
    let best = candidates.map(|c| (strsim::damerau_levenshtein(given, c), c)).min();
    match best {
        Some((distance, name)) if distance <= (name.chars().count() / 3).max(1) => format!("; did you mean `{name}`?"),
        _ => String::new(),
    }
}

/// 1-based line and column of byte `offset` in `text`.
pub(super) fn line_column(text: &str, offset: usize) -> (usize, usize) {
    let before = &text[..offset.min(text.len())];
    let line = before.matches('\n').count() + 1;
    let column = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
    (line, column)
}
