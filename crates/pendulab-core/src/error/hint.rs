//! The hint of an unknown name: the nearest of the names allowed ([`did_you_mean`]), by edit distance
//! (the `strsim` crate); [`close_match`], the Python layer's rule (difflib's), which decides for the lab
//! whether a key is near one of a model's own parameters; [`Quoted`], a name in a message quoted as the
//! Python layer quotes it; and [`drift_advice`], what a step size underflow of an unprojected run says
//! to do (T-2.4).

use super::Shown;
use std::fmt;

mod close;
pub use close::close_match;

/// A name in a message, quoted as Python's `repr` quotes a string — `'x'`, or `"it's"` for a name
/// with a single quote and no double one; the quote, backslash and control characters escaped — so
/// that the core's refusals (`unknown method 'RATTLE' (did you mean 'rattle'?)`) read as the Python
/// layer's, where names are quoted `'x'` everywhere (and the CLI's usage errors, and the lab's).
#[derive(Debug, Clone, Copy)]
pub struct Quoted<'a>(pub &'a str);

impl fmt::Display for Quoted<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        use fmt::Write;
        let q = if self.0.contains('\'') && !self.0.contains('"') { '"' } else { '\'' };
        f.write_char(q)?;
        for c in self.0.chars() {
            match c {
                '\\' => f.write_str("\\\\")?,
                '\n' => f.write_str("\\n")?,
                '\r' => f.write_str("\\r")?,
                '\t' => f.write_str("\\t")?,
                c if c == q => write!(f, "\\{c}")?,
                c if c.is_control() || c == '\u{a0}' || c == '\u{ad}' => write!(f, "\\x{:02x}", c as u32)?,
                c => f.write_char(c)?,
            }
        }
        f.write_char(q)
    }
}

/// `` (did you mean 'x'?)`` (the name [`Quoted`]) for the option nearest to `name`, or `""`: an option
/// equal to it but for case first, else the one at the smallest edit distance from it in lower case if that distance is at most
/// half the longer name's length (`strsim::osa_distance`: a letter changed, added or left out, or two
/// neighbours swapped, is one edit), of equals the one more alike by `strsim::jaro_winkler` (`rattl6`:
/// `rattle6`, not `rattle`), then the first. The hint of Python's `pendulab.validate.did_you_mean`
/// (difflib's nearest) for the case and for one such slip, but for ties (`rattle46`). Only a hint: the
/// wrong case is never accepted. A name of more than 64 characters gets none (no option is near it; the
/// distance stays cheap).
pub fn did_you_mean<'a>(name: &str, options: impl IntoIterator<Item = &'a str>) -> String {
    nearest(name, options).map_or_else(String::new, |o| format!(" (did you mean {}?)", Quoted(o)))
}

/// The option [`did_you_mean`] names for `name`, or None: for a message key's value (`nearest`), which a
/// page words in its language.
pub fn nearest<'a>(name: &str, options: impl IntoIterator<Item = &'a str>) -> Option<&'a str> {
    let options: Vec<&str> = options.into_iter().collect();
    let lower = name.to_lowercase();
    let n = lower.chars().count();
    let closest = || {
        let scored = options.iter().filter(|_| n <= 64).map(|o| {
            let other = o.to_lowercase();
            let distance = strsim::osa_distance(&lower, &other);
            (o, distance, strsim::jaro_winkler(&lower, &other), 2 * distance <= n.max(other.chars().count()))
        });
        let near = scored.filter(|(.., near)| *near);
        near.min_by(|a, b| a.1.cmp(&b.1).then(b.2.total_cmp(&a.2))).map(|(o, ..)| o)
    };
    let same_but_case = options.iter().find(|o| o.to_lowercase() == lower);
    same_but_case.or_else(closest).copied()
}

/// The end of a step size underflow's message: nothing, or for an unprojected run that had left TS²
/// (`integrate::dop853_control::off_sphere`) its residuals, why, and what to do.
pub(crate) fn drift_advice(off_sphere: Option<(f64, f64)>) -> String {
    let Some((radial, tangential)) = off_sphere else { return String::new() };
    format!(
        "; the run is not projected (project=False) and had left TS² there, (|x| - l)/l = {} and \
         x·v/(l·|v|) = {}: off TS² the equations T-2.4 are unstable wherever the rod pushes (the bob \
         high and slow, near the top), so the drift grows until no step meets the tolerance; use \
         project=True (the default) or a method that keeps TS² such as 'rattle'",
        Shown(radial),
        Shown(tangential)
    )
}
