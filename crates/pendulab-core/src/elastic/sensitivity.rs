//! Forward sensitivities of the swinging spring (docs/theory.md T-7.4, T-10.8): the triple-jump (or
//! Störmer–Verlet) run of [`SwingingSpring::step`] together with its exact derivatives by any start
//! quantities and by the parameters κ = k/m [1/s²], l₀ \[m\] and g [m/s²] ([`SPRING_PARAMS`]), for the
//! Jacobian of a spring fit (`pl.fit`, docs/fit.md "Speed").
//!
//! The equation is r̈ = a(r) = −κ(|r| − l₀) r/|r| − g e₃. For a direction p with tangent
//! (X, V) = ∂(r, v)/∂p, the variational equation is Ẍ = A(r) X + ∂a/∂p with
//!
//!   A X = −κ(1 − l₀/|r|) X − κ l₀ (r·X) r/|r|³,
//!   ∂a/∂κ = −(|r| − l₀) r/|r|,  ∂a/∂l₀ = κ r/|r|,  ∂a/∂g = −e₃,
//!
//! and ∂a/∂p = 0 for a start quantity. Because the force depends on the position only, each kick
//! v ← v + (h/2) a(r) and drift r ← r + h v of a Verlet step has the derivative V ← V + (h/2)(A X + ∂a/∂p),
//! X ← X + h V: the tangent is stepped by the same composition, so it is the exact derivative of the
//! discrete run (not an approximation of the continuous one), and the states are those of
//! [`SwingingSpring::step`] to the bit. [`SwingingSpring::states_at`] is the same run without tangents,
//! keeping the states at given step numbers only (a fit's forward model). Units SI.

use super::SwingingSpring;
use crate::error::{Error, Result};
use crate::state::State;
use glam::DVec3;

/// The parameters whose derivatives follow the start quantities' ones, in this order.
pub const SPRING_PARAMS: [&str; 3] = ["k_over_m", "rest_length", "g"];

/// The most steps one run may take (its work: about (1 + directions) force evaluations per stage).
pub const MAX_SPRING_SENSITIVITY_STEPS: u64 = 1 << 26;

/// The most directions (start quantities plus [`SPRING_PARAMS`]) one run may carry.
pub const MAX_DIRECTIONS: usize = 64;

/// A tangent (X, V) = (∂r/∂p \[m/unit of p\], ∂v/∂p [m/s per unit of p]).
pub type Tangent = (DVec3, DVec3);

/// The run at the kept steps: `states[j]` after `keep[j]` steps (the request's step numbers), its tangents
/// `tangents[j * directions + d]` (the start directions first, then [`SPRING_PARAMS`]) and the
/// acceleration's derivatives there, `accelerations[j * directions + d]` = A X + ∂a/∂p.
#[derive(Debug, Clone, Default)]
pub struct SpringSensitivities {
    /// The states there.
    pub states: Vec<State>,
    /// Number of directions per state: the start tangents given, plus 3.
    pub directions: usize,
    /// The tangents, `directions` per kept state.
    pub tangents: Vec<Tangent>,
    /// ∂a/∂p (total, through the position and the parameter) [m/s² per unit], `directions` per kept
    /// state: what a cubic Hermite interpolation of the velocity needs.
    pub accelerations: Vec<DVec3>,
}

impl SwingingSpring {
    /// ∂a/∂p at `r` for the parameter directions κ, l₀, g ([`SPRING_PARAMS`]) [m/s² per unit of p].
    pub fn acceleration_by_params(&self, r: DVec3) -> [DVec3; 3] {
        let len = r.length();
        let unit = r / len;
        [unit * -(len - self.rest_length), unit * self.k_over_m, DVec3::new(0.0, 0.0, -1.0)]
    }

    /// The two numbers of A = along·I + across·r rᵀ at `r`: −κ(1 − l₀/|r|) [1/s²], −κ l₀/|r|³ [1/(m² s²)].
    fn jacobian_coefficients(&self, r: DVec3) -> (f64, f64) {
        let len = r.length();
        (
            -self.k_over_m * (1.0 - self.rest_length / len),
            -self.k_over_m * self.rest_length / (len * len * len),
        )
    }

    /// The acceleration linearised at `r`: what A X + ∂a/∂p needs there.
    fn linearised(&self, r: DVec3) -> Linearised {
        let (along, across) = self.jacobian_coefficients(r);
        Linearised { r, along, across, by_params: self.acceleration_by_params(r) }
    }

    /// Half a kick of the tangents at `r`: V ← V + (h/2)(A X + ∂a/∂p).
    fn kick_tangents(&self, r: DVec3, tangents: &mut [Tangent], half: f64) {
        let at = self.linearised(r);
        let first_param = tangents.len() - SPRING_PARAMS.len();
        for (d, (x, v)) in tangents.iter_mut().enumerate() {
            *v += at.derivative(*x, d.checked_sub(first_param)) * half;
        }
    }

    /// One Störmer–Verlet step of `h` \[s\] of the state (exactly [`SwingingSpring::verlet`]) and its
    /// tangents (module doc).
    fn verlet_with_tangents(&self, s: &mut State, tangents: &mut [Tangent], h: f64) {
        self.kick_tangents(s.x, tangents, 0.5 * h);
        let v_half = s.v + self.acceleration(s.x) * (0.5 * h);
        s.x += v_half * h;
        for (x, v) in tangents.iter_mut() {
            *x += *v * h;
        }
        s.v = v_half + self.acceleration(s.x) * (0.5 * h);
        self.kick_tangents(s.x, tangents, 0.5 * h);
    }

    /// One step of `h` \[s\] of order 2 or 4 (as [`SwingingSpring::step`]) with the tangents.
    fn step_with_tangents(&self, s: &mut State, tangents: &mut [Tangent], h: f64, order: u32) {
        if order == 2 {
            self.verlet_with_tangents(s, tangents, h);
        } else {
            let c = 2f64.cbrt();
            let (g1, g0) = (1.0 / (2.0 - c), -c / (2.0 - c));
            self.verlet_with_tangents(s, tangents, g1 * h);
            self.verlet_with_tangents(s, tangents, g0 * h);
            self.verlet_with_tangents(s, tangents, g1 * h);
        }
    }

    /// Runs from `start` (x \[m\] away from the pivot, v [m/s]) with steps of `dt` \[s\] of `order` 2 or 4
    /// up to the last of `keep` (ascending step numbers, at most [`MAX_SPRING_SENSITIVITY_STEPS`]),
    /// carrying the tangents `start_tangents` (∂(x₀, v₀)/∂q of the caller's start quantities q) and
    /// the three of [`SPRING_PARAMS`] (zero at the start), and keeps the state and the tangents after
    /// each step number in `keep`. A state or tangent that stops being finite is [`Error::Diverged`].
    pub fn sensitivities(
        &self,
        start: State,
        start_tangents: &[Tangent],
        dt: f64,
        order: u32,
        keep: &[u64],
    ) -> Result<SpringSensitivities> {
        check_request(start_tangents, keep)?;
        let checked = super::SpringStepper::new(*self, start, 0.0, dt, order)?; // start, dt and order
        let directions = start_tangents.len() + SPRING_PARAMS.len();
        let mut tangents: Vec<Tangent> = start_tangents.to_vec();
        tangents.resize(directions, (DVec3::ZERO, DVec3::ZERO));
        let mut out = SpringSensitivities {
            states: Vec::with_capacity(keep.len()),
            directions,
            tangents: Vec::with_capacity(keep.len() * directions),
            accelerations: Vec::with_capacity(keep.len() * directions),
        };
        let mut s = checked.state();
        let mut done = 0u64;
        for &want in keep {
            while done < want {
                self.step_with_tangents(&mut s, &mut tangents, dt, order);
                done += 1;
                if !(s.is_finite() && tangents.iter().all(|(x, v)| x.is_finite() && v.is_finite())) {
                    return Err(Error::Diverged {
                        t: (done - 1) as f64 * dt,
                        method: "spring sensitivities",
                        dt,
                    });
                }
            }
            out.states.push(s);
            out.tangents.extend_from_slice(&tangents);
            let at = self.linearised(s.x);
            let first_param = directions - SPRING_PARAMS.len();
            out.accelerations.extend(
                tangents.iter().enumerate().map(|(d, (x, _))| at.derivative(*x, d.checked_sub(first_param))),
            );
        }
        Ok(out)
    }

    /// The states after each step number in `keep` (ascending, at most
    /// [`MAX_SPRING_SENSITIVITY_STEPS`]) of the run from `start` with steps of `dt` \[s\] of `order` 2 or
    /// 4: the states of [`SwingingSpring::simulate`] (the same steps) without keeping every one, so
    /// that a fit's forward model holds the states around its samples only. A state that stops being
    /// finite is [`Error::Diverged`].
    pub fn states_at(&self, start: State, dt: f64, order: u32, keep: &[u64]) -> Result<Vec<State>> {
        check_request(&[], keep)?;
        let mut stepper = super::SpringStepper::new(*self, start, 0.0, dt, order)?;
        let mut done = 0u64;
        let mut out = Vec::with_capacity(keep.len());
        for &want in keep {
            stepper.step(want - done)?;
            done = want;
            out.push(stepper.state());
        }
        Ok(out)
    }
}

/// The acceleration linearised at a position `r` \[m\]: A = along·I + across·r rᵀ and ∂a/∂p of
/// [`SPRING_PARAMS`].
struct Linearised {
    r: DVec3,
    along: f64,
    across: f64,
    by_params: [DVec3; 3],
}

impl Linearised {
    /// A X + ∂a/∂p for the position tangent `x` of a start quantity (`param` None: ∂a/∂p = 0) or of
    /// the parameter `param` of [`SPRING_PARAMS`].
    #[inline(always)]
    fn derivative(&self, x: DVec3, param: Option<usize>) -> DVec3 {
        let linear = x * self.along + self.r * (self.across * self.r.dot(x));
        param.map_or(linear, |k| linear + self.by_params[k])
    }
}

/// The request's bounds: at most [`MAX_DIRECTIONS`] directions, `keep` ascending and at most
/// [`MAX_SPRING_SENSITIVITY_STEPS`], finite start tangents.
fn check_request(start_tangents: &[Tangent], keep: &[u64]) -> Result<()> {
    let directions = start_tangents.len() + SPRING_PARAMS.len();
    if directions > MAX_DIRECTIONS {
        return Err(Error::InvalidParameter {
            name: "start_tangents",
            value: start_tangents.len() as f64,
            allowed: "at most 61 start tangents (64 directions with k_over_m, rest_length, g)",
        });
    }
    if let Some(w) = keep.windows(2).find(|w| w[1] < w[0]) {
        return Err(Error::InvalidParameter {
            name: "keep",
            value: w[1] as f64,
            allowed: "step numbers in ascending order (a number may repeat)",
        });
    }
    if let Some(&last) = keep.last().filter(|&&last| last > MAX_SPRING_SENSITIVITY_STEPS) {
        return Err(Error::InvalidParameter {
            name: "keep",
            value: last as f64,
            allowed: "step numbers of at most 2^26 = 67108864 steps",
        });
    }
    for (i, (x, v)) in start_tangents.iter().enumerate() {
        if let Some(&value) = x.to_array().iter().chain(&v.to_array()).find(|c| !c.is_finite()) {
            return Err(Error::NonFinite { name: "start_tangents", index: i, value });
        }
    }
    Ok(())
}
