//! The refusal of a parameter a lab model does not have (docs/web.md, "Languages"), in the words of the
//! Python layer (`pendulab.model.registry.elsewhere` and its `Elsewhere`: `pl.Pendulum`, scenario files,
//! the server's `set_model`), so that the server's sessions and the in-page engine (the one-file lab has
//! no server) say the same: a key that is another lab model's parameter names the models that have it
//! (`parameter_of_other_model`, `parameter_of_other_models`); any other the model's own parameters
//! (`unknown_parameter`, or `no_parameters` for a model with none besides length, mass, g).

use super::crane::CRANE;
use super::kinds::live_models;
use crate::error::{close_match, Error, Quoted};
use crate::model::registry::spec;

/// The refusal of a parameter `key` that `model` does not have (`own`: the parameters it has besides
/// length, mass, g): another lab model's ([`elsewhere`]), else keyed `unknown_parameter`
/// (`no_parameters` when it has none of its own).
pub(super) fn no_parameter(model: &'static str, key: &str, own: &[&str]) -> Error {
    if let Some(refusal) = elsewhere(model, key, own) {
        return refusal;
    }
    let name = if model == CRANE { "the crane".to_string() } else { format!("the {} model", Quoted(model)) };
    let mut values = vec![("model", model.to_string()), ("name", key.to_string())];
    if own.is_empty() {
        return Error::RefusedKeyed {
            words: format!("{name} has no parameter {}; it has none besides length, mass, g", Quoted(key)),
            key: "no_parameters",
            values,
        };
    }
    values.push(("available", own.join(", ")));
    Error::RefusedKeyed {
        words: format!("{name} has no parameter {}; its parameters: {}", Quoted(key), own.join(", ")),
        key: "unknown_parameter",
        values,
    }
}

/// The refusal of `key` for the lab model `model` (own parameters `own`) when `key` is, the same but for
/// case, a parameter of other lab models and near none of `own` by the Python layer's rule
/// ([`crate::error::close_match`], as `registry.elsewhere` decides with `validate.did_you_mean`: so
/// `restitution` on `damped` is near `friction`, and `AMPLITUDE` near none, the vibrating pendulum's):
/// `damping is a parameter of model 'damped' (and 'rotating', …), not of 'ideal'; its parameters:
/// length, mass, g`, after `the 'ideal' model has no parameter 'DAMPING' (did you mean
/// 'damping'?); ` for a key in another case. Keyed `parameter_of_other_model` (one model has it) or
/// `parameter_of_other_models` (values model, name: the parameter's own name, owner: the first model in
/// the registry's order, others: the further ones, available: every parameter of `model`). None for the
/// crane (its parameters are no model's) and for any other key.
fn elsewhere(model: &'static str, key: &str, own: &[&str]) -> Option<Error> {
    if model == CRANE || close_match(key, own.iter().copied()).is_some() {
        return None;
    }
    let lab: Vec<_> = live_models().into_iter().filter_map(|m| spec(m).ok()).collect();
    let fold = key.to_lowercase();
    let name = lab.iter().flat_map(|m| m.params).map(|p| p.name).find(|n| n.to_lowercase() == fold)?;
    let owners: Vec<&str> = lab
        .iter()
        .filter(|m| m.name != model && m.params.iter().any(|p| p.name == name))
        .map(|m| m.name)
        .collect();
    let (owner, others) = owners.split_first()?;
    let quoted: Vec<String> = others.iter().map(|m| Quoted(m).to_string()).collect();
    let also = if others.is_empty() { String::new() } else { format!(" (and {})", quoted.join(", ")) };
    let mut words =
        format!("{name} is a parameter of model {}{also}, not of {}", Quoted(owner), Quoted(model));
    if key != name {
        words = format!(
            "the {} model has no parameter {} (did you mean {}?); {words}",
            Quoted(model),
            Quoted(key),
            Quoted(name)
        );
    }
    let available = ["length", "mass", "g"].iter().chain(own).copied().collect::<Vec<_>>().join(", ");
    let mut values = vec![
        ("model", model.to_string()),
        ("name", name.to_string()),
        ("owner", owner.to_string()),
        ("available", available.clone()),
    ];
    if !others.is_empty() {
        values.push(("others", others.join(", ")));
    }
    Some(Error::RefusedKeyed {
        words: format!("{words}; its parameters: {available}"),
        key: if others.is_empty() { "parameter_of_other_model" } else { "parameter_of_other_models" },
        values,
    })
}
