//! How a figure's text is laid out: titles shrunk to fit their width, subtitles and legend entries wrapped at the
//! spaces a reader would break at (never between a number and its unit), one font size a legend.

use plotters::coord::Shift;
use plotters::prelude::*;

/// The font size ≤ `size` (px) at which `text` fits in `width` px: `size` scaled down by the measured overflow (text
/// width is proportional to the size), never below 60 % of it (beyond that a title must be shortened at its source).
pub(crate) fn fitting_size<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    text: &str,
    size: f64,
    width: f64,
) -> f64 {
    match area.estimate_text_size(text, &("sans-serif", size).into_font().into()) {
        Ok((measured, _)) if f64::from(measured) > width => (size * width / f64::from(measured)).max(0.6 * size),
        _ => size,
    }
}

/// The words of `text` a line may break between: split at spaces, but a number is kept with the word after it (its
/// unit: "110 m/s", "3 m", "100 kN;") and with a symbol of up to three characters before it ("Cₛ 53 m/s"), so that
/// no line ends with a number whose unit starts the next, or with a symbol whose value does.
fn words(text: &str) -> Vec<String> {
    let mut words: Vec<String> = Vec::new();
    for word in text.split(' ').filter(|w| !w.is_empty()) {
        let starts_number = word.starts_with(|c: char| c.is_ascii_digit());
        let unit = |last: &str| last.ends_with(|c: char| c.is_ascii_digit()) && !starts_number;
        let symbol = |last: &str| starts_number && !last.contains(' ') && last.chars().count() <= 3;
        match words.last_mut() {
            Some(last) if unit(last) || symbol(last) => {
                last.push(' ');
                last.push_str(word);
            }
            _ => words.push(word.to_string()),
        }
    }
    words
}

/// Font size of subtitles (px), and the most lines one takes before its last line shrinks to fit.
const SUBTITLE_SIZE: f64 = 17.0;
const SUBTITLE_LINES: usize = 3;

/// The subtitle's lines and their font sizes: wrapped at spaces into lines of at most `width` px at
/// [`SUBTITLE_SIZE`] (measured with 5 % to spare: the drawn text runs a little wider than its estimate), at most
/// [`SUBTITLE_LINES`], the last one shrinking to fit what remains.
pub(crate) fn subtitle_lines<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    text: &str,
    width: f64,
) -> Vec<(String, f64)> {
    let room = 0.95 * width;
    let fits = |line: &str| {
        area.estimate_text_size(line, &("sans-serif", SUBTITLE_SIZE).into_font().into())
            .is_ok_and(|(w, _)| f64::from(w) <= room)
    };
    let mut lines: Vec<String> = Vec::new();
    let mut words = words(text).into_iter().peekable();
    while words.peek().is_some() {
        let mut line = String::new();
        if lines.len() + 1 == SUBTITLE_LINES {
            line = words.by_ref().collect::<Vec<_>>().join(" ");
        } else {
            while let Some(word) = words.peek() {
                let longer = if line.is_empty() { word.clone() } else { format!("{line} {word}") };
                if !line.is_empty() && !fits(&longer) {
                    break;
                }
                line = longer;
                words.next();
            }
        }
        lines.push(line);
    }
    lines
        .into_iter()
        .map(|line| {
            let size = fitting_size(area, &line, SUBTITLE_SIZE, room);
            (line, size)
        })
        .collect()
}

/// Font size of the legend (px): one size for every entry, long ones wrapped onto more lines.
pub(crate) const LEGEND_SIZE: f64 = 15.0;

/// `text` wrapped at spaces into lines of at most `room` px at [`LEGEND_SIZE`] (a word longer than that alone on
/// its line).
pub(crate) fn legend_lines<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>, text: &str, room: f64) -> Vec<String> {
    let fits = |line: &str| {
        area.estimate_text_size(line, &("sans-serif", LEGEND_SIZE).into_font().into())
            .is_ok_and(|(w, _)| f64::from(w) <= room)
    };
    let mut lines: Vec<String> = Vec::new();
    for word in words(text) {
        match lines.last_mut() {
            Some(line) if fits(&format!("{line} {word}")) => {
                line.push(' ');
                line.push_str(&word);
            }
            _ => lines.push(word),
        }
    }
    lines
}

#[cfg(test)]
mod tests {
    use super::words;

    #[test]
    fn a_number_stays_with_its_unit_and_its_symbol() {
        assert_eq!(
            words("on a half-space of Cₛ 110 m/s; 2 layers"),
            ["on", "a", "half-space", "of", "Cₛ 110 m/s;", "2 layers"]
        );
        assert_eq!(words("EI = 2.000e8 N·m², 10000 kg/m"), ["EI", "= 2.000e8 N·m²,", "10000 kg/m"]);
    }
}
