//! The hybrid simulation of the string pendulum ([`StringPendulum`], see its module for the physics
//! and equations): taut phases with a fixed-step method that keeps TS² (T-2.2), the leave event where
//! the tension T-2.3 reaches 0 (bisection on the step length), analytic free flight, the re-taut
//! event on the exact parabola, and the snap.
//!
//! Times [s] lie on the grid t₀ + k·dt as in [`crate::Stepper`]: full steps are exactly dt, so a
//! motion that never goes slack is the rod pendulum's, bit for bit. After an event the next step is
//! shortened to land on the grid again. Samples: the start, every `save_every`-th grid point, every
//! event (the state after it) and t_end. Slack samples are the exact parabola. A short slack
//! excursion wholly inside one taut step (T < 0 only between two grid points) is not seen: dt must
//! resolve the motion.

use super::string::{bisect, StringPendulum};
use super::{IdealPendulum, Model};
use crate::error::{Error, Result};
use crate::integrate::composition::Composition;
use crate::integrate::rattle::Rattle;
use crate::integrate::rkmk4::Rkmk4;
use crate::integrate::{FixedStep, Method, Stats};
use crate::solve::BYTES_PER_SAMPLE;
use crate::state::{State, TS2_TOLERANCE};

/// What happened at an event.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum EventKind {
    /// The tension reached 0: the string goes slack, the bob flies freely.
    Slack,
    /// The bob reached |x| = l: the string snaps taut (radial velocity removed or reflected).
    Taut,
}

/// One event of a run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StringEvent {
    /// Time [s].
    pub t: f64,
    /// Leave or snap.
    pub kind: EventKind,
    /// State just before (for a leave: the state where T = 0).
    pub before: State,
    /// State just after (equal to `before` for a leave).
    pub after: State,
    /// Kinetic energy lost in the event [J] (0 for a leave; ½m(1 − e²)|u|² for a snap).
    pub energy_lost: f64,
}

/// The result of [`StringPendulum::simulate`].
#[derive(Debug, Clone, Default, PartialEq)]
pub struct StringRun {
    /// Times [s].
    pub t: Vec<f64>,
    /// States (x [m], v [m/s]); off the sphere while slack.
    pub states: Vec<State>,
    /// Whether the string is taut at each sample.
    pub taut: Vec<bool>,
    /// Every leave and snap, in order.
    pub events: Vec<StringEvent>,
    /// Taut-phase steps and evaluations.
    pub stats: Stats,
}

#[derive(Debug, Clone)]
enum Scheme {
    Rattle(Rattle),
    Composition(Composition),
    Rkmk4(Rkmk4),
}

impl Scheme {
    fn new(method: Method) -> Result<Self> {
        Ok(match method {
            Method::Rattle => Scheme::Rattle(Rattle::default()),
            Method::Rattle4 => Scheme::Composition(Composition::of_order(4)),
            Method::Rattle6 => Scheme::Composition(Composition::of_order(6)),
            Method::Rattle8 => Scheme::Composition(Composition::of_order(8)),
            Method::Rkmk4 => Scheme::Rkmk4(Rkmk4::default()),
            _ => return Err(Error::UnsupportedModel { method: method.info().name, model: "string" }),
        })
    }
    fn step(&mut self, m: &IdealPendulum, t: f64, s: &mut State, h: f64) -> Result<()> {
        match self {
            Scheme::Rattle(r) => r.step(m, t, s, h),
            Scheme::Composition(c) => c.step(m, t, s, h),
            Scheme::Rkmk4(r) => r.step(m, t, s, h),
        }
    }
    fn evals(&self) -> u64 {
        match self {
            Scheme::Rattle(r) => r.evals_per_step(),
            Scheme::Composition(c) => c.evals_per_step(),
            Scheme::Rkmk4(r) => r.evals_per_step(),
        }
    }
    fn reset(&mut self) {
        match self {
            Scheme::Rattle(r) => r.reset(),
            Scheme::Composition(c) => c.reset(),
            Scheme::Rkmk4(r) => r.reset(),
        }
    }
}

/// Where the bob is between events.
#[derive(Debug, Clone, Copy)]
enum Phase {
    Taut,
    /// Flying since the event at `t` from `from`; arrives on the sphere at `arrival` (∞: never).
    Slack {
        t: f64,
        from: State,
        arrival: f64,
    },
}

struct Recorder {
    run: StringRun,
    max_samples: u64,
}

impl Recorder {
    fn push(&mut self, t: f64, s: State, taut: bool) -> Result<()> {
        if !s.is_finite() {
            return Err(Error::Diverged { t, method: "string", dt: 0.0 });
        }
        if self.run.t.last() == Some(&t) {
            // an event on a grid point: the event's state (after it) replaces the grid sample
            self.run.t.pop();
            self.run.states.pop();
            self.run.taut.pop();
        }
        if self.run.t.len() as u64 >= self.max_samples {
            let samples = self.run.t.len() as u64 + 1;
            return Err(Error::TooManySamples {
                samples,
                bytes: samples * BYTES_PER_SAMPLE,
                limit: self.max_samples * BYTES_PER_SAMPLE,
            });
        }
        self.run.t.push(t);
        self.run.states.push(s);
        self.run.taut.push(taut);
        Ok(())
    }
}

impl StringPendulum {
    /// Simulates from `state` at `t0` [s] to `t_end` [s] with `method` (rattle, rattle4, rattle6,
    /// rattle8 or rkmk4) and step `dt` [s] in the taut phases, keeping every `save_every`-th grid
    /// point, every event and t_end. The start may be on the sphere (|x| = l within 1e-9 relative) or
    /// inside it (slack); outside it is an error. `max_saved_bytes` bounds the memory of the samples.
    #[allow(clippy::too_many_arguments)]
    pub fn simulate(
        &self,
        t0: f64,
        state: State,
        t_end: f64,
        method: Method,
        dt: f64,
        save_every: u64,
        max_saved_bytes: u64,
    ) -> Result<StringRun> {
        crate::error::require_finite("t0", t0, "the start time must be finite (s)")?;
        if !(t_end.is_finite() && t_end > t0) {
            return Err(Error::InvalidParameter {
                name: "t_end",
                value: t_end,
                allowed: "the end time must be a finite number of seconds after the start time",
            });
        }
        crate::error::require_positive("dt", dt, "the step size dt must be a finite number > 0 s")?;
        if save_every == 0 {
            return Err(Error::InvalidParameter {
                name: "save_every",
                value: 0.0,
                allowed: "save_every must be an integer ≥ 1 (steps between saved samples)",
            });
        }
        if !state.is_finite() {
            return Err(Error::Diverged { t: t0, method: "string", dt });
        }
        let l = self.params().length;
        let excess = (state.x.length() - l) / l;
        if excess > TS2_TOLERANCE {
            return Err(Error::InvalidParameter {
                name: "(|x| - l)/l",
                value: excess,
                allowed: "a string pendulum starts on the sphere |x| = l or inside it (slack), not beyond",
            });
        }
        let mut scheme = Scheme::new(method)?;
        let rod = IdealPendulum::from_params(*self.params());
        let mut rec = Recorder { run: StringRun::default(), max_samples: max_saved_bytes / BYTES_PER_SAMPLE };
        let grid = |k: u64| t0 + k as f64 * dt;
        let slack_grid = 1e-9 * dt;
        let (mut t, mut s, mut k) = (t0, state, 0u64);
        let mut on_grid = true;
        // the start: on the sphere moving tangentially (taut unless T < 0), inward (flying) or
        // outward (a snap at once); inside the sphere, flying
        let mut phase = if excess.abs() <= TS2_TOLERANCE {
            let radial = s.x.dot(s.v) / (l * s.v.length().max(f64::MIN_POSITIVE));
            if radial.abs() <= TS2_TOLERANCE {
                s = State::projected(self.params(), s.x, s.v)?.0;
                Phase::Taut
            } else if radial < 0.0 {
                self.flight_from(t, s, 1)
            } else {
                Phase::Slack { t, from: s, arrival: t }
            }
        } else {
            self.flight_from(t, s, 0)
        };
        if let Phase::Taut = phase {
            if self.tension(&s) < 0.0 {
                rec.run.events.push(StringEvent {
                    t,
                    kind: EventKind::Slack,
                    before: s,
                    after: s,
                    energy_lost: 0.0,
                });
                phase = self.flight_from(t, s, 2);
            }
        }
        rec.push(t, s, matches!(phase, Phase::Taut))?;
        while t < t_end {
            match phase {
                Phase::Taut => {
                    // the next grid point (or t_end), reached by a full step dt when on the grid
                    let t_next = grid(k + 1).min(t_end);
                    let h = if on_grid && t_next == grid(k + 1) { dt } else { t_next - t };
                    if h <= slack_grid {
                        (t, k, on_grid) = (t_next, k + 1, true);
                        continue;
                    }
                    let mut trial = scheme.clone();
                    let mut s1 = s;
                    trial.step(&rod, t, &mut s1, h)?;
                    rec.run.stats.steps += 1;
                    rec.run.stats.rhs_evals += trial.evals();
                    if self.tension(&s1) >= 0.0 {
                        (scheme, s, t, k, on_grid) = (trial, s1, t_next, k + 1, true);
                        if k % save_every == 0 || t >= t_end {
                            rec.push(t, s, true)?;
                        }
                        continue;
                    }
                    // T < 0 at the end of the step: shorten it to where T = 0 (to round-off in h)
                    let trials = std::cell::Cell::new(0u64);
                    let at = |h: f64| {
                        trials.set(trials.get() + 1);
                        let (mut sc, mut sh) = (scheme.clone(), s);
                        sc.step(&rod, t, &mut sh, h).map(|_| sh)
                    };
                    let h_star = bisect(0.0, h, |h| at(h).map_or(true, |sh| self.tension(&sh) < 0.0));
                    let leave = at(h_star)?;
                    rec.run.stats.rhs_evals += trials.get() * trial.evals();
                    t += h_star;
                    s = leave;
                    on_grid = false;
                    rec.run.events.push(StringEvent {
                        t,
                        kind: EventKind::Slack,
                        before: s,
                        after: s,
                        energy_lost: 0.0,
                    });
                    rec.push(t, s, false)?;
                    phase = self.flight_from(t, s, 2);
                }
                Phase::Slack { t: te, from, arrival } => {
                    // grid samples along the exact parabola until the arrival or t_end
                    while grid(k + 1) < arrival.min(t_end) {
                        k += 1;
                        if k % save_every == 0 {
                            let gk = grid(k);
                            rec.push(gk, self.flight(&from, gk - te), false)?;
                        }
                    }
                    if arrival >= t_end {
                        s = self.flight(&from, t_end - te);
                        t = t_end;
                        rec.push(t, s, false)?;
                        break;
                    }
                    let before = self.flight(&from, arrival - te);
                    let (after, lost, taut) = self.snap(&before);
                    t = arrival;
                    s = after;
                    on_grid = false;
                    scheme.reset();
                    rec.run.events.push(StringEvent {
                        t,
                        kind: EventKind::Taut,
                        before,
                        after,
                        energy_lost: lost,
                    });
                    if taut && self.tension(&s) < 0.0 {
                        rec.run.events.push(StringEvent {
                            t,
                            kind: EventKind::Slack,
                            before: s,
                            after: s,
                            energy_lost: 0.0,
                        });
                        phase = self.flight_from(t, s, 2);
                    } else if taut {
                        phase = Phase::Taut;
                    } else {
                        phase = self.flight_from(t, s, 1);
                    }
                    rec.push(t, s, matches!(phase, Phase::Taut))?;
                }
            }
        }
        Ok(rec.run)
    }

    fn flight_from(&self, t: f64, s: State, zeros: usize) -> Phase {
        let arrival = self.flight_time(&s, zeros).map_or(f64::INFINITY, |tau| t + tau);
        Phase::Slack { t, from: s, arrival }
    }
}
