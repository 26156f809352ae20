//! Which methods a lab model runs, and the keyed refusal of the others (docs/web.md, "Languages").
//! Matched over every [`Restricted`] model: a model added there must say which methods it runs and
//! why not the others, at compile time; and a model added to the registry must say how the lab runs
//! it ([`Kind`]), and so whether it is one.

use super::kinds::Kind;
use crate::error::Error;

/// The spring's methods and their orders: Störmer–Verlet (2) and its triple jump (4).
pub const SPRING_ORDERS: [(&str, u32); 2] = [("rattle", 2), ("rattle4", 4)];
/// The string's methods: fixed step and keeping TS² in the taut phases.
pub const STRING_METHODS: [&str; 5] = ["rattle", "rattle4", "rattle6", "rattle8", "rkmk4"];

/// A lab model that runs only some of the methods: which ones ([`Restricted::methods`]) and why not
/// the others ([`method_refused`]), both matched over every variant, so that a model added here cannot
/// be given another model's reason (a catch-all arm gave any model but the spring and the crane the
/// string's).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Restricted {
    Spring,
    String,
    Crane,
}

impl Restricted {
    /// The model of name `model` if it runs only some methods (None: a rod model, which runs every
    /// method of [`crate::Stepper`], a model that runs in no lab, or a name that is no model), by how the
    /// lab runs it ([`Kind`]: every model of the registry and the crane, no catch-all).
    pub(super) fn of(model: &str) -> Option<Self> {
        match Kind::of(model)? {
            Kind::Rod | Kind::Offline => None,
            Kind::Spring => Some(Self::Spring),
            Kind::String => Some(Self::String),
            Kind::Crane => Some(Self::Crane),
        }
    }

    /// The methods it runs, by registry name.
    pub(super) fn methods(self) -> Vec<&'static str> {
        match self {
            Self::Spring => SPRING_ORDERS.iter().map(|(m, _)| *m).collect(),
            Self::String => STRING_METHODS.to_vec(),
            Self::Crane => vec!["dop853"],
        }
    }
}

/// The methods that can run `model` in the lab (None: every method of [`crate::Stepper`]).
pub fn methods_for(model: &str) -> Option<Vec<&'static str>> {
    Restricted::of(model).map(Restricted::methods)
}

/// The refusal of `method` for `model` ([`Restricted`] `which`), which runs only the methods `allowed`
/// in the lab, keyed by why (messages.json: `method_not_for_spring`, `method_not_for_string`,
/// `method_not_for_crane`; values method, model, available), so that a page words the reason in its
/// language too.
pub(super) fn method_refused(
    which: Restricted,
    model: &'static str,
    method: &str,
    allowed: &[&str],
) -> Error {
    let (key, what, use_) = match which {
        Restricted::Spring => (
            "method_not_for_spring",
            "it leaves the sphere: rattle runs Störmer–Verlet (order 2), rattle4 its triple jump (order 4)",
            "use one of",
        ),
        Restricted::String => {
            ("method_not_for_string", "its taut phases need a fixed-step method that keeps TS²", "use one of")
        }
        Restricted::Crane => (
            "method_not_for_crane",
            "the crane mode steps its load with the crane integrator, adaptive DOP853 with projection onto \
             the rope",
            "use",
        ),
    };
    let available = allowed.join(", ");
    Error::RefusedKeyed {
        words: format!("method {method:?} cannot run the {model:?} model ({what}); {use_} {available}"),
        key,
        values: vec![("method", method.to_string()), ("model", model.to_string()), ("available", available)],
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The spring, the string and the crane run some methods; the rod models, the offline ones and a
    /// name that is no model are not restricted.
    #[test]
    fn restricted_models() {
        assert_eq!(Restricted::of("spring"), Some(Restricted::Spring));
        assert_eq!(Restricted::of("string"), Some(Restricted::String));
        assert_eq!(Restricted::of(super::super::crane::CRANE), Some(Restricted::Crane));
        for model in ["ideal", "damped", "hoisted", "no such model"] {
            assert_eq!(Restricted::of(model), None, "{model}");
        }
    }
}
