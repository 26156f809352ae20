//! The hint of an unknown name: the nearest of the names allowed ([`did_you_mean`]), by Levenshtein
//! distance (the `strsim` crate).

/// `` (did you mean "x"?)`` for the option nearest to `name`, or `""`: an option equal to it but for case
/// first, else the one at the smallest Levenshtein distance from it in lower case (`strsim`; the first
/// of equals) if that distance is at most half the longer name's length — the hint of Python's
/// `pendulab.validate.did_you_mean` (which takes difflib's nearest). Only a hint: the wrong case is never
/// accepted. A name of more than 64 characters gets none (no option is near it; the distance stays cheap).
pub fn did_you_mean<'a>(name: &str, options: impl IntoIterator<Item = &'a str>) -> String {
    let options: Vec<&str> = options.into_iter().collect();
    let lower = name.to_lowercase();
    let n = lower.chars().count();
    let distance = |o: &str| strsim::levenshtein(&lower, &o.to_lowercase());
    let closest = || {
        let near = |o: &&&str| n <= 64 && 2 * distance(o) <= n.max(o.chars().count());
        options.iter().filter(near).min_by_key(|o| distance(o))
    };
    let same_but_case = options.iter().find(|o| o.to_lowercase() == lower);
    same_but_case.or_else(closest).map_or_else(String::new, |o| format!(" (did you mean {o:?}?)"))
}
