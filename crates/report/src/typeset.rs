//! Figure text as a reader expects it: `F_u`, `f_u`, `t_on`, `w_sta` drawn with real subscripts (Fᵤ, fᵤ, tₒₙ, wₛₜₐ)
//! rather than underscores. Unicode has subscript forms for the digits and for a e h i k l m n o p r s t u v x,
//! which the bundled DejaVu Sans draws; a subscript with any other letter (c, w, capitals) is left as written, so
//! labels avoid those (`φ(w)` rather than `φ_w`).

/// The subscript form of `c`, if Unicode has one the figures' font draws.
fn subscript(c: char) -> Option<char> {
    const LETTERS: [(char, char); 16] = [
        ('a', 'ₐ'),
        ('e', 'ₑ'),
        ('h', 'ₕ'),
        ('i', 'ᵢ'),
        ('k', 'ₖ'),
        ('l', 'ₗ'),
        ('m', 'ₘ'),
        ('n', 'ₙ'),
        ('o', 'ₒ'),
        ('p', 'ₚ'),
        ('r', 'ᵣ'),
        ('s', 'ₛ'),
        ('t', 'ₜ'),
        ('u', 'ᵤ'),
        ('v', 'ᵥ'),
        ('x', 'ₓ'),
    ];
    match c {
        '0'..='9' => char::from_u32('₀' as u32 + c.to_digit(10)?),
        _ => LETTERS.iter().find(|(plain, _)| *plain == c).map(|&(_, sub)| sub),
    }
}

/// `text` with every symbol's subscript written as one: `_` + a run of letters/digits after a one-letter symbol
/// (F_u, t_on, w_sta — not a word like `case_1`, which stays as written), when every character of the run has a
/// subscript form (else left as written, underscore and all).
pub fn text(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let mut chars = text.chars().peekable();
    // The last two characters written: a symbol is one letter after a non-letter (or the start).
    let (mut before, mut last) = (' ', ' ');
    while let Some(c) = chars.next() {
        let symbol = last.is_alphabetic() && !before.is_alphanumeric();
        (before, last) = (last, c);
        if c != '_' || !symbol {
            out.push(c);
            continue;
        }
        let mut run = String::new();
        while let Some(&next) = chars.peek().filter(|n| n.is_ascii_alphanumeric()) {
            run.push(next);
            chars.next();
        }
        match run.chars().map(subscript).collect::<Option<String>>() {
            Some(sub) if !run.is_empty() => out.push_str(&sub),
            _ => {
                out.push('_');
                out.push_str(&run);
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::text;

    #[test]
    fn underscores_become_subscripts_where_unicode_has_them() {
        assert_eq!(text("F_u = 50 kN, f_u = 2 kN/m"), "Fᵤ = 50 kN, fᵤ = 2 kN/m");
        assert_eq!(text("(1/t_on)∫∫|w| dx dt"), "(1/tₒₙ)∫∫|w| dx dt");
        assert_eq!(text("w/w_sta, k_1"), "w/wₛₜₐ, k₁");
        // No subscript c or w: left as written.
        assert_eq!(text("x_c, φ_w, v_cr"), "x_c, φ_w, v_cr");
        assert_eq!(text("snake_case_"), "snake_case_");
        // Words with underscores (a user's title) are no symbols.
        assert_eq!(text("case_1 of run_a"), "case_1 of run_a");
    }
}
