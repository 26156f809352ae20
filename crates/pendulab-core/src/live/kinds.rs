//! How the lab runs each model ([`Kind`]): a rod model through the incremental [`crate::Stepper`], the
//! swinging spring (T-7.4) and the string with their own core steppers, the crane mode with the crane's
//! integrator, or not at all (`pendulab run` only). One table of every model of the registry and the
//! crane, read by every decision on a model's name in the lab (its stepper, its check, the methods it
//! runs: [`super::methods`]) through matches over [`Kind`] with no catch-all arm, so that a model added
//! to the registry does not compile until its row says how the lab runs it, and no decision can give it
//! another model's handling unseen.

use super::crane::CRANE;

/// How the lab runs a model.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Kind {
    /// A rod model on TS² through the incremental [`crate::Stepper`] (the registry's `interactive`).
    Rod,
    /// The swinging spring: [`crate::elastic::SpringStepper`].
    Spring,
    /// The string, taut and slack: [`crate::string_run::StringStepper`].
    String,
    /// The crane mode's load below the driven trolley ([`super::crane`]).
    Crane,
    /// A model of the registry that runs only in `pendulab run` / `pl.simulate` (the hoisted rope's
    /// schedule and the sampled pivot's samples are arrays a lab command does not carry).
    Offline,
}

/// Every model of the registry and the lab's crane, each with how the lab runs it. No catch-all: a model
/// added to the registry does not compile until it has its row here (the length below), and
/// `every_model_has_its_row` checks the names and that the rows agree with the registry's
/// `interactive` and [`OWN_STEPPER_MODELS`].
const MODELS: [(&str, Kind); 10] = [
    ("ideal", Kind::Rod),
    ("damped", Kind::Rod),
    ("rotating", Kind::Rod),
    ("slewing", Kind::Rod),
    ("vibrating", Kind::Rod),
    ("hoisted", Kind::Offline),
    ("sampled_pivot", Kind::Offline),
    ("spring", Kind::Spring),
    ("string", Kind::String),
    (CRANE, Kind::Crane),
];
const _: () = assert!(MODELS.len() == crate::model::registry::MODELS.len() + 1, "a model without its row");

/// The lab's models that step with their own core steppers, not [`crate::Stepper`].
pub const OWN_STEPPER_MODELS: [&str; 2] = ["spring", "string"];

/// The models a live session runs, in the registry's order: the rod models (the registry's
/// `interactive` ones), the spring and the string (not the crane mode, which a `crane` command starts).
pub fn live_models() -> Vec<&'static str> {
    let lab = |m: &&str| matches!(Kind::of(m), Some(Kind::Rod | Kind::Spring | Kind::String));
    crate::model::registry::MODELS.iter().map(|m| m.name).filter(lab).collect()
}

impl Kind {
    /// How the lab runs the model of name `model` (None: a name that is no model).
    pub(super) fn of(model: &str) -> Option<Self> {
        MODELS.iter().find(|(name, _)| *name == model).map(|(_, kind)| *kind)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The rows of [`MODELS`] are the registry's models and the crane, each once; a rod model is the
    /// registry's `interactive`, the spring and the string step on their own, the rest are offline.
    #[test]
    fn every_model_has_its_row() {
        let mut rows: Vec<&str> = MODELS.iter().map(|(name, _)| *name).collect();
        let mut models: Vec<&str> = crate::model::registry::MODELS.iter().map(|m| m.name).collect();
        models.push(CRANE);
        rows.sort_unstable();
        models.sort_unstable();
        assert_eq!(rows, models);
        for m in crate::model::registry::MODELS.iter() {
            let kind = Kind::of(m.name).unwrap();
            assert_eq!(kind == Kind::Rod, m.interactive, "{}", m.name);
            let own = matches!(kind, Kind::Spring | Kind::String);
            assert_eq!(own, OWN_STEPPER_MODELS.contains(&m.name), "{}", m.name);
        }
        let registry = crate::model::registry::MODELS.iter();
        let lab = registry.filter(|m| m.interactive || OWN_STEPPER_MODELS.contains(&m.name)).map(|m| m.name);
        assert_eq!(live_models(), lab.collect::<Vec<_>>());
        assert_eq!(Kind::of(CRANE), Some(Kind::Crane));
        assert_eq!(Kind::of("no such model"), None);
    }
}
