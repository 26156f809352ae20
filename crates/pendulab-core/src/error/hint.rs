//! The hint of an unknown name: the nearest of the names allowed ([`did_you_mean`], [`nearest`]), by
//! one rule, the Python layer's ([`close_match`], a port of difflib's `get_close_matches`), so that the
//! one-file lab (this core in WebAssembly) and the server (the Python layer) hint alike; [`Quoted`], a
//! name in a message quoted as the Python layer quotes it; and [`drift_advice`], what a step size
//! underflow of an unprojected run says to do (T-2.4).

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

/// `` (did you mean 'x'?)`` (the name [`Quoted`]) for the option [`nearest`] to `name`, or `""`. Only a
/// hint: the wrong case is never accepted.
pub fn did_you_mean<'a>(name: &str, options: impl IntoIterator<Item = &'a str>) -> String {
    nearest(name, options).map_or_else(String::new, |o| format!(" (did you mean {}?)", Quoted(o)))
}

/// The option [`did_you_mean`] names for `name`, or None (for a message key's value, which a page words
/// in its language): Python's `pendulab.validate.nearest`, [`close_match`] — an option equal to it but
/// for case first, else difflib's closest of ratio ≥ 0.6 (of the first 100 characters of `name`).
pub fn nearest<'a>(name: &str, options: impl IntoIterator<Item = &'a str>) -> Option<&'a str> {
    close_match(name, options)
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
