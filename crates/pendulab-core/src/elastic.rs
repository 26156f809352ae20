//! The elastic pendulum, or swinging spring (THEORY.md T-7.4): a bob of mass m on a massless spring
//! of stiffness k [N/m] and rest length l₀ [m] from a fixed pivot, in gravity g along −e₃:
//!
//!   r̈ = −(k/m)(|r| − l₀) r/|r| − g e₃,   equilibrium length l = l₀ + m g/k,
//!   E = ½m|v|² + ½k(|r| − l₀)² + m g z,   J₃ = m (x v_y − y v_x),
//!
//! both conserved; the system is not integrable. At the 1:1:2 resonance √(k/m) = 2√(g/l) energy passes
//! back and forth between bouncing and swinging and the swing plane turns in steps (Holm & Lynch
//! 2002; Lynch & Houghton 2003). The state is unconstrained (r, v) ∈ R⁶, so this model has its own
//! integrators: the Hamiltonian is separable, and Störmer–Verlet (kick–drift–kick) is symplectic,
//! order 2, and keeps J₃ exactly (the force is central about the e₃ axis plus a vertical force);
//! the triple-jump composition gives order 4 with the same properties. Units SI.

use crate::error::{require_finite, require_positive, Error, Result};
use crate::state::State;
use glam::DVec3;

/// The swinging spring's parameters.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SwingingSpring {
    /// Stiffness per unit mass k/m [1/s²], > 0.
    pub k_over_m: f64,
    /// Rest length l₀ [m], > 0.
    pub rest_length: f64,
    /// Gravity g [m/s²] along −e₃ (any sign).
    pub g: f64,
    /// Mass m [kg], > 0 (only scales E and J₃).
    pub mass: f64,
}

impl SwingingSpring {
    /// Validated parameters: k/m > 0 [1/s²], l₀ > 0 [m], finite g [m/s²], m > 0 [kg].
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

    /// The equilibrium length l = l₀ + g/(k/m) [m] (hanging at rest, g > 0).
    pub fn equilibrium_length(&self) -> f64 {
        self.rest_length + self.g / self.k_over_m
    }

    /// The spring at the 1:1:2 resonance √(k/m) = 2√(g/l) for a given equilibrium length l [m]:
    /// k/m = 4g/l and l₀ = l − g/(k/m) = 3l/4.
    pub fn resonant(equilibrium_length: f64, g: f64, mass: f64) -> Result<Self> {
        require_positive("equilibrium_length", equilibrium_length, "a length > 0 m")?;
        require_positive("g", g, "the resonance needs gravity g > 0 m/s²")?;
        Self::new(4.0 * g / equilibrium_length, 0.75 * equilibrium_length, g, mass)
    }

    /// Acceleration r̈ [m/s²].
    #[inline(always)]
    pub fn acceleration(&self, r: DVec3) -> DVec3 {
        let len = r.length();
        r * (-self.k_over_m * (len - self.rest_length) / len) - DVec3::new(0.0, 0.0, self.g)
    }

    /// Energy E [J].
    pub fn energy(&self, s: &State) -> f64 {
        let stretch = s.x.length() - self.rest_length;
        self.mass * (0.5 * s.v.length_squared() + 0.5 * self.k_over_m * stretch * stretch + self.g * s.x.z)
    }

    /// Vertical angular momentum J₃ [kg m²/s].
    pub fn j3(&self, s: &State) -> f64 {
        self.mass * (s.x.x * s.v.y - s.x.y * s.v.x)
    }

    /// One Störmer–Verlet step of `h` [s]: v ← v + (h/2)a(r); r ← r + h v; v ← v + (h/2)a(r).
    #[inline(always)]
    pub fn verlet(&self, s: &mut State, h: f64) {
        let v_half = s.v + self.acceleration(s.x) * (0.5 * h);
        s.x += v_half * h;
        s.v = v_half + self.acceleration(s.x) * (0.5 * h);
    }

    /// One step of order 2 (`order` = 2, Störmer–Verlet) or 4 (triple jump of three Verlet steps).
    pub fn step(&self, s: &mut State, h: f64, order: u32) -> Result<()> {
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
            Err(Error::Diverged { t: f64::NAN, method: "spring verlet", dt: h })
        }
    }

    /// Integrates `n_steps` steps of `dt` [s] from `start`, keeping the start and every
    /// `save_every`-th state (and the last): returns (times [s], states).
    pub fn simulate(
        &self,
        start: State,
        dt: f64,
        n_steps: u64,
        save_every: u64,
        order: u32,
    ) -> Result<(Vec<f64>, Vec<State>)> {
        require_positive("dt", dt, "the step dt must be a finite number > 0 s")?;
        if save_every == 0 {
            return Err(Error::InvalidParameter {
                name: "save_every",
                value: 0.0,
                allowed: "an integer >= 1",
            });
        }
        if start.x.length() == 0.0 || !start.is_finite() {
            return Err(Error::InvalidParameter {
                name: "x0",
                value: start.x.length(),
                allowed: "a finite start away from the pivot (|r| > 0 m)",
            });
        }
        let mut s = start;
        self.step(&mut s, 0.0, order)?; // a zero step: checks the order, changes nothing
        let (mut t, mut states) = (vec![0.0], vec![start]);
        for k in 1..=n_steps {
            self.step(&mut s, dt, order).map_err(|_| Error::Diverged {
                t: k as f64 * dt,
                method: "spring verlet",
                dt,
            })?;
            if k % save_every == 0 || k == n_steps {
                t.push(k as f64 * dt);
                states.push(s);
            }
        }
        Ok((t, states))
    }
}
