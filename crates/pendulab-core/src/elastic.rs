//! The elastic pendulum, or swinging spring (docs/theory.md T-7.4): a bob of mass m on a massless spring
//! of stiffness k [N/m] and rest length l₀ \[m\] from a fixed pivot, in gravity g along −e₃:
//!
//!   r̈ = −(k/m)(|r| − l₀) r/|r| − g e₃,   equilibrium length l = l₀ + m |g|/k,
//!   E = ½m|v|² + ½k(|r| − l₀)² + m g z,   J₃ = m (x v_y − y v_x),
//!
//! both conserved; the system is not integrable. At the 1:1:2 resonance √(k/m) = 2√(g/l) energy passes
//! back and forth between bouncing and swinging and the swing plane turns in steps (Holm & Lynch
//! 2002; Lynch & Houghton 2003). The state is unconstrained (r, v) ∈ R⁶, so this model has its own
//! integrators: the Hamiltonian is separable, and Störmer–Verlet (kick–drift–kick) is symplectic,
//! order 2, and keeps J₃ exactly (the force is central about the e₃ axis plus a vertical force);
//! the triple-jump composition gives order 4 with the same properties. Units SI.

mod sensitivity;
pub use sensitivity::{
    SpringSensitivities, Tangent, MAX_DIRECTIONS, MAX_SPRING_SENSITIVITY_STEPS, SPRING_PARAMS,
};

use crate::error::{require_finite, require_positive, Error, Result};
use crate::state::State;
use glam::DVec3;

/// The swinging spring's parameters.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SwingingSpring {
    /// Stiffness per unit mass k/m [1/s²], > 0.
    pub k_over_m: f64,
    /// Rest length l₀ \[m\], > 0.
    pub rest_length: f64,
    /// Gravity g [m/s²] along −e₃ (any sign).
    pub g: f64,
    /// Mass m \[kg\], > 0 (only scales E and J₃).
    pub mass: f64,
}

impl SwingingSpring {
    /// Validated parameters: k/m > 0 [1/s²], l₀ > 0 \[m\], finite g [m/s²], m > 0 \[kg\].
    pub fn new(k_over_m: f64, rest_length: f64, g: f64, mass: f64) -> Result<Self> {
        require_positive(
            "k_over_m",
            k_over_m,
            "the stiffness per unit mass k/m must be a finite number > 0 1/s²",
        )?;
        require_positive("rest_length", rest_length, "the rest length l0 must be a finite number > 0 m")?;
        require_finite("g", g, "gravity g must be a finite number in m/s²")?;
        require_positive("mass", mass, "the mass m must be a finite number > 0 kg")?;
        Ok(Self { k_over_m, rest_length, g, mass })
    }

    /// The length l = l₀ + |g|/(k/m) \[m\] of the stable equilibrium: the bob at rest on the vertical
    /// through the pivot on the side gravity pulls it to, the spring stretched by |g|/(k/m) — below the
    /// pivot for g > 0, above it for g < 0 (the mirror image; the other rest point on the vertical,
    /// the spring compressed to l₀ − |g|/(k/m) on the far side, is unstable), l₀ for g = 0.
    pub fn equilibrium_length(&self) -> f64 {
        self.rest_length + self.g.abs() / self.k_over_m
    }

    /// The spring at the 1:1:2 resonance √(k/m) = 2√(|g|/l) for a given stable equilibrium length
    /// l \[m\]: k/m = 4|g|/l and l₀ = l − |g|/(k/m) = 3l/4. For g < 0 it is the mirror image of g > 0
    /// (the bob rests above the pivot at l); g = 0 is refused (no swing frequency, no resonance).
    pub fn resonant(equilibrium_length: f64, g: f64, mass: f64) -> Result<Self> {
        require_positive("equilibrium_length", equilibrium_length, "a length > 0 m")?;
        if !(g.is_finite() && g != 0.0) {
            return Err(Error::InvalidParameter {
                name: "g",
                value: g,
                allowed: "the resonance needs gravity: a finite g other than 0 m/s² (g < 0 rests the bob above the pivot)",
            });
        }
        Self::new(4.0 * g.abs() / equilibrium_length, 0.75 * equilibrium_length, g, mass)
    }

    /// Acceleration r̈ [m/s²].
    #[inline(always)]
    pub fn acceleration(&self, r: DVec3) -> DVec3 {
        let len = r.length();
        r * (-self.k_over_m * (len - self.rest_length) / len) - DVec3::new(0.0, 0.0, self.g)
    }

    /// Energy E \[J\].
    pub fn energy(&self, s: &State) -> f64 {
        let stretch = s.x.length() - self.rest_length;
        self.mass * (0.5 * s.v.length_squared() + 0.5 * self.k_over_m * stretch * stretch + self.g * s.x.z)
    }

    /// Vertical angular momentum J₃ [kg m²/s].
    pub fn j3(&self, s: &State) -> f64 {
        self.mass * (s.x.x * s.v.y - s.x.y * s.v.x)
    }

    /// One Störmer–Verlet step of `h` \[s\]: v ← v + (h/2)a(r); r ← r + h v; v ← v + (h/2)a(r).
    #[inline(always)]
    pub fn verlet(&self, s: &mut State, h: f64) {
        let v_half = s.v + self.acceleration(s.x) * (0.5 * h);
        s.x += v_half * h;
        s.v = v_half + self.acceleration(s.x) * (0.5 * h);
    }

    /// One step of `h` \[s\] from the state `s` at time `t` \[s\], of order 2 (`order` = 2, Störmer–Verlet)
    /// or 4 (triple jump of three Verlet steps). A state that is not finite after it is
    /// [`Error::Diverged`] naming `t` (the last finite state's time) and `h` (`s` is then not finite).
    pub fn step(&self, t: f64, s: &mut State, h: f64, order: u32) -> Result<()> {
        match order {
            2 => self.verlet(s, h),
            4 => {
                let c = 2f64.cbrt();
                let (g1, g0) = (1.0 / (2.0 - c), -c / (2.0 - c));
                self.verlet(s, g1 * h);
                self.verlet(s, g0 * h);
                self.verlet(s, g1 * h);
            }
            _ => {
                return Err(Error::InvalidParameter {
                    name: "order",
                    value: order as f64,
                    allowed: "2 (Störmer–Verlet) or 4 (its triple-jump composition)",
                })
            }
        }
        if s.is_finite() {
            Ok(())
        } else {
            Err(Error::Diverged { t, method: "spring verlet", dt: h })
        }
    }

    /// The spring's tension k(|r| − l₀) \[N\] (> 0 stretched and pulling, < 0 compressed and pushing).
    pub fn tension(&self, s: &State) -> f64 {
        self.mass * self.k_over_m * (s.x.length() - self.rest_length)
    }

    /// Integrates `n_steps` steps of `dt` \[s\] from `start`, keeping the start and every
    /// `save_every`-th state (and the last): returns (times \[s\], states).
    pub fn simulate(
        &self,
        start: State,
        dt: f64,
        n_steps: u64,
        save_every: u64,
        order: u32,
    ) -> Result<(Vec<f64>, Vec<State>)> {
        if save_every == 0 {
            return Err(Error::InvalidParameter {
                name: "save_every",
                value: 0.0,
                allowed: "an integer >= 1",
            });
        }
        let mut stepper = SpringStepper::new(*self, start, 0.0, dt, order)?;
        let (mut t, mut states) = (vec![0.0], vec![start]);
        for k in 1..=n_steps {
            stepper.step(1)?;
            if k % save_every == 0 || k == n_steps {
                t.push(k as f64 * dt);
                states.push(stepper.state());
            }
        }
        Ok((t, states))
    }
}

/// The swinging spring stepped incrementally (what the lab runs): whole steps of dt of one method,
/// so that stepping n₁ and then n₂ steps is the run of n₁ + n₂ steps, state for state.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpringStepper {
    spring: SwingingSpring,
    s: State,
    t0: f64,
    dt: f64,
    order: u32,
    /// Steps taken.
    k: u64,
}

impl SpringStepper {
    /// A stepper from `start` (x \[m\] away from the pivot, v [m/s]) at `t0` \[s\] with step `dt` \[s\] and
    /// `order` 2 (Störmer–Verlet) or 4 (triple jump).
    pub fn new(spring: SwingingSpring, start: State, t0: f64, dt: f64, order: u32) -> Result<Self> {
        require_finite("t0", t0, "the start time must be finite (s)")?;
        require_positive("dt", dt, "the step dt must be a finite number > 0 s")?;
        if start.x.length() == 0.0 || !start.is_finite() {
            return Err(Error::InvalidParameter {
                name: "x0",
                value: start.x.length(),
                allowed: "a finite start away from the pivot (|r| > 0 m)",
            });
        }
        crate::limits::check_limits(&crate::limits::STATE[1], start.x.length())?;
        crate::state::check_speed(start.v)?;
        let mut s = start;
        spring.step(t0, &mut s, 0.0, order)?; // a zero step: checks the order, changes nothing
        Ok(Self { spring, s: start, t0, dt, order, k: 0 })
    }

    /// Takes `n` steps of dt; on divergence the error names the last finite state's time (the start
    /// of the step that diverged) and dt, and the state stays that last finite one.
    pub fn step(&mut self, n: u64) -> Result<()> {
        for _ in 0..n {
            let mut s = self.s;
            self.spring.step(self.t(), &mut s, self.dt, self.order)?;
            self.s = s;
            self.k += 1;
        }
        Ok(())
    }

    /// Time reached t₀ + k·dt \[s\].
    pub fn t(&self) -> f64 {
        self.t0 + self.k as f64 * self.dt
    }

    /// State reached (r \[m\], v [m/s]).
    pub fn state(&self) -> State {
        self.s
    }

    /// The spring.
    pub fn spring(&self) -> &SwingingSpring {
        &self.spring
    }
}
