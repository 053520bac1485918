//! Reading back the CSV files frictrack writes (a sweep's, a run's histories and snapshots), to draw their figures
//! again (`frictrack plot`): a header line of column names, `#` lines skipped (comments, a shard's first line, a
//! sweep's `# failed_run` lines), empty fields read as missing (NaN).

use scenario::error::{Result, invalid};

/// A table of numbers with named columns.
#[derive(Debug, Clone, PartialEq)]
pub struct Table {
    /// Column names, in order.
    pub columns: Vec<String>,
    /// Rows, each with one value per column (NaN where empty).
    pub rows: Vec<Vec<f64>>,
}

impl Table {
    /// Parse `text`, named `source` in errors: the first line that is not a comment is the header.
    pub fn parse(text: &str, source: &str) -> Result<Self> {
        let text = text.strip_prefix('\u{feff}').unwrap_or(text);
        let mut lines = text.lines().enumerate().filter(|(_, l)| !l.trim().is_empty() && !l.starts_with('#'));
        let (_, header) = lines.next().ok_or_else(|| invalid(source, "empty", "expected a CSV with a header line"))?;
        let columns: Vec<String> = header.split(',').map(|c| c.trim().to_string()).collect();
        let mut rows = Vec::new();
        for (n, line) in lines {
            let cells: Vec<&str> = line.split(',').collect();
            if cells.len() != columns.len() {
                let allowed = format!("line {}: expected {} fields, one per column", n + 1, columns.len());
                return Err(invalid(source, format!("{} fields", cells.len()), allowed));
            }
            let row = cells
                .iter()
                .map(|c| match c.trim() {
                    "" => Ok(f64::NAN),
                    t => t.parse::<f64>().map_err(|_| invalid(source, t, format!("line {}: not a number", n + 1))),
                })
                .collect::<Result<Vec<f64>>>()?;
            rows.push(row);
        }
        Ok(Self { columns, rows })
    }

    /// The index of column `name`, or an error naming the file and the columns it has.
    pub fn column(&self, name: &str, source: &str) -> Result<usize> {
        self.columns
            .iter()
            .position(|c| c == name)
            .ok_or_else(|| invalid(source, format!("no column `{name}`"), format!("has {}", self.columns.join(","))))
    }

    /// The values of column `name`, row by row.
    pub fn values(&self, name: &str, source: &str) -> Result<Vec<f64>> {
        let c = self.column(name, source)?;
        Ok(self.rows.iter().map(|r| r[c]).collect())
    }
}

#[cfg(test)]
mod tests {
    use super::Table;

    #[test]
    fn header_comments_and_missing_values() {
        let text = "# frictrack-shard 1/2 points=3\nspeed,w\n10,0.5\n20,\n# failed_run {}\n30,1e-3\n";
        let t = Table::parse(text, "sweep.csv").unwrap();
        assert_eq!(t.columns, ["speed", "w"]);
        let w = t.values("w", "sweep.csv").unwrap();
        assert_eq!((w[0], w[1].is_nan(), w[2]), (0.5, true, 1e-3));
        assert!(t.values("x", "sweep.csv").unwrap_err().to_string().contains("has speed,w"));
        assert!(Table::parse("a,b\n1\n", "bad.csv").unwrap_err().to_string().contains("line 2"));
    }
}
