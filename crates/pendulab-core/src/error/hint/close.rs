//! [`close_match`]: the option the Python layer's hint names for a name (`pendulab.validate.nearest`, the
//! one rule of the parameters' hints: `pl.Pendulum`, scenario files, the server's `set_model`), computed
//! as Python computes it, so that the lab's engine decides as the Python layer whether a key is near one
//! of a model's own parameters (`live::no_parameter`: else another model's parameter is named with its
//! models). An option equal to the name but for case first (`str.casefold`'s rule, `casefold`), else
//! `difflib.get_close_matches(name[:100], options, n=1, cutoff=0.6)`: the option of the largest
//! Ratcliff–Obershelp ratio 2 M / (|a| + |b|) ≥ 0.6 (M: the characters of the matching blocks, found as
//! `difflib.SequenceMatcher` finds them, the longest common block first, then recursively left and right
//! of it), of equal ratios the greater name.

/// The option equal to `name` but for case, else the one `difflib.get_close_matches(name[:100],
/// options, n=1)` gives, else None (see the module's doc). Case-sensitive but for the first rule:
/// `AMPLITUDE` is near no parameter of `damped` (`forcing_amplitude`), `restitution` is near `friction`.
pub fn close_match<'a>(name: &str, options: impl IntoIterator<Item = &'a str>) -> Option<&'a str> {
    let options: Vec<&str> = options.into_iter().collect();
    let folded = casefold(name);
    if let Some(o) = options.iter().find(|o| casefold(o) == folded) {
        return Some(o);
    }
    let word: Vec<char> = name.chars().take(100).collect();
    let scored = options.iter().map(|o| (ratio(&o.chars().collect::<Vec<_>>(), &word), *o));
    // `heapq.nlargest(1, …)` over (ratio, option): the largest ratio, of equals the greatest option
    let best = scored.filter(|(r, _)| *r >= 0.6).fold(None, |best: Option<(f64, &str)>, (r, o)| match best {
        Some((br, bo)) if (br, bo) >= (r, o) => best,
        _ => Some((r, o)),
    });
    best.map(|(_, o)| o)
}

/// `str.casefold` as far as it can make a name equal to an ASCII option: the lower case, and the full
/// foldings that end in ASCII letters where the lower case does not (ß and ẞ → ss, ſ → s, the
/// ligatures ﬀ ﬁ ﬂ ﬃ ﬄ ﬅ ﬆ → ff fi fl ffi ffl st st; Unicode's CaseFolding.txt, status F and C). The
/// other foldings only map letters to other non-ASCII letters, which no option of the core holds.
fn casefold(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            'ß' | 'ẞ' => out.push_str("ss"),
            'ſ' => out.push('s'),
            'ﬀ' => out.push_str("ff"),
            'ﬁ' => out.push_str("fi"),
            'ﬂ' => out.push_str("fl"),
            'ﬃ' => out.push_str("ffi"),
            'ﬄ' => out.push_str("ffl"),
            'ﬅ' | 'ﬆ' => out.push_str("st"),
            _ => out.extend(c.to_lowercase()),
        }
    }
    out
}

/// A range of indices, start and end (exclusive).
type Span = (usize, usize);

/// `difflib.SequenceMatcher(None, a, b).ratio()`: 2 M / (|a| + |b|), 1 for two empty sequences.
fn ratio(a: &[char], b: &[char]) -> f64 {
    let total = a.len() + b.len();
    if total == 0 {
        return 1.0;
    }
    let mut matches = 0;
    let mut queue = vec![(0, a.len(), 0, b.len())];
    while let Some((alo, ahi, blo, bhi)) = queue.pop() {
        let (i, j, k) = longest_match(a, b, (alo, ahi), (blo, bhi));
        if k > 0 {
            matches += k;
            if alo < i && blo < j {
                queue.push((alo, i, blo, j));
            }
            if i + k < ahi && j + k < bhi {
                queue.push((i + k, ahi, j + k, bhi));
            }
        }
    }
    2.0 * matches as f64 / total as f64
}

/// `SequenceMatcher.find_longest_match` with no junk (b has fewer than 200 characters, so no popular
/// ones): the longest block a[i..i+k] == b[j..j+k] in the ranges, of equals the one ending first in a,
/// then in b (the largest k found first, row by row of a).
fn longest_match(a: &[char], b: &[char], (alo, ahi): Span, (blo, bhi): Span) -> (usize, usize, usize) {
    let (mut besti, mut bestj, mut bestsize) = (alo, blo, 0);
    let mut prev = vec![0usize; b.len() + 1]; // prev[j + 1]: the block ending at a[i - 1], b[j]
    for (i, ai) in a.iter().enumerate().take(ahi).skip(alo) {
        let mut row = vec![0usize; b.len() + 1];
        for (j, bj) in b.iter().enumerate().take(bhi).skip(blo) {
            if ai == bj {
                let k = prev[j] + 1;
                row[j + 1] = k;
                if k > bestsize {
                    (besti, bestj, bestsize) = (i + 1 - k, j + 1 - k, k);
                }
            }
        }
        prev = row;
    }
    (besti, bestj, bestsize)
}

#[cfg(test)]
mod tests {
    use super::*;

    const DAMPED: [&str; 13] = [
        "gravity_x",
        "gravity_y",
        "gravity_z",
        "damping",
        "drag",
        "friction",
        "friction_speed",
        "forcing_amplitude",
        "forcing_omega",
        "forcing_phase",
        "forcing_x",
        "forcing_y",
        "forcing_z",
    ];

    /// The hints Python's `pendulab.validate.nearest` gives (difflib, CPython 3.11) for the same names.
    #[test]
    fn the_python_layers_hint() {
        let cases = [
            ("restitution", Some("friction")),
            ("AMPLITUDE", None),
            ("amplitude", Some("forcing_amplitude")),
            ("DAMPING", Some("damping")),
            ("dampnig", Some("damping")),
            ("lenght", None),
            ("latitude", None),
            ("forcing_w", Some("forcing_z")), // of equal ratios the greater name
            ("", None),
        ];
        for (name, want) in cases {
            assert_eq!(close_match(name, DAMPED), want, "{name}");
        }
        assert_eq!(close_match("lenght", ["length", "mass", "g"]), Some("length"));
        assert_eq!(close_match("rattl6", ["rattle", "rattle6"]), Some("rattle6"));
        // equal ratios: the greater name (heapq.nlargest over (ratio, name))
        assert_eq!(close_match("ab", ["ax", "ay"]), None);
        assert_eq!(close_match("abc", ["abx", "aby"]), Some("aby"));
        assert!((ratio(&['a', 'b', 'c', 'd'], &['b', 'c', 'd', 'e']) - 0.75).abs() < 1e-15);
    }

    /// Equal but for case as Python's `str.casefold` decides it (CPython 3.11: `"MAẞ".casefold() ==
    /// "mass"`, `"ﬁnal".casefold() == "final"`, `"ſtep".casefold() == "step"`), where the lower case
    /// alone (`"maß"`) is not.
    #[test]
    fn equal_but_for_case_as_python_casefolds() {
        assert_eq!(close_match("MAẞ", ["g", "length", "mass"]), Some("mass"));
        assert_eq!(close_match("maß", ["g", "mass"]), Some("mass"));
        assert_eq!(close_match("ﬁnal", ["final", "first"]), Some("final"));
        assert_eq!(close_match("ſtep", ["step", "steps"]), Some("step"));
        assert_eq!(casefold("DaMpInG"), "damping");
        assert_eq!(casefold("Ünïcode"), "ünïcode");
    }
}
