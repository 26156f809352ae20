//! The string pendulum's incremental stepper ([`StringStepper`], what the lab runs and what
//! [`super::StringRunner`] drives in chunks): taut phases with a fixed-step method that
//! keeps TS² (T-2.2), the leave event where the tension T-2.3 reaches 0 (bisection on the step
//! length), analytic free flight, the re-taut event on the exact parabola, and the snap (physics and
//! equations in [`crate::model::string`]). Its mode — taut, or slack on a given flight — is carried as state,
//! so a run cut into pieces is the same run. Times [s] lie on the grid t₀ + k·dt; SI units.

use super::{EventKind, StringEvent};
use crate::error::{Error, Result};
use crate::integrate::composition::Composition;
use crate::integrate::rattle::Rattle;
use crate::integrate::rkmk4::Rkmk4;
use crate::integrate::{FixedStep, Method, Stats};
use crate::model::string::{bisect, StringPendulum};
use crate::model::{IdealPendulum, Model};
use crate::state::{State, TS2_TOLERANCE};
use glam::DVec3;
#[derive(Debug, Clone)]
pub(super) enum Scheme {
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
    /// One step, compiled for the CPU's best instruction set ([`crate::isa`]; same numbers at every level).
    fn step(&mut self, m: &IdealPendulum, t: f64, s: &mut State, h: f64) -> Result<()> {
        crate::isa::fastest(
            #[inline(always)]
            || match self {
                Scheme::Rattle(r) => r.step(m, t, s, h),
                Scheme::Composition(c) => c.step(m, t, s, h),
                Scheme::Rkmk4(r) => r.step(m, t, s, h),
            },
        )
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
pub(super) enum Phase {
    Taut,
    /// Flying since the event at `t` from `from`; arrives on the sphere at `arrival` (∞: never).
    Slack {
        t: f64,
        from: State,
        arrival: f64,
    },
}

impl StringPendulum {
    pub(super) fn flight_from(&self, t: f64, s: State, zeros: usize) -> Phase {
        let arrival = self.flight_time(&s, zeros).map_or(f64::INFINITY, |tau| t + tau);
        Phase::Slack { t, from: s, arrival }
    }
}

/// The string pendulum stepped incrementally (what the lab runs): the hybrid run of
/// [`StringPendulum::simulate`], resumable at any time with its mode — taut, or slack with the flight
/// it is on (departure state and time, arrival) — carried as state, so that a run cut into pieces
/// is the same run: stepping to t₁ and then to t₂ gives the states of one run to t₂ when t₁ is a grid
/// point t₀ + k·dt ([`StringStepper::step`] always lands on one).
#[derive(Debug, Clone)]
pub struct StringStepper {
    model: StringPendulum,
    rod: IdealPendulum,
    scheme: Scheme,
    pub(super) t0: f64,
    pub(super) dt: f64,
    /// Time reached [s].
    pub(super) t: f64,
    /// State reached (off the sphere while slack).
    s: State,
    /// Index of the last grid point t₀ + k·dt at or before t.
    pub(super) k: u64,
    /// Grid index of the last target of [`StringStepper::step`].
    target: u64,
    on_grid: bool,
    phase: Phase,
    events: Vec<StringEvent>,
    stats: Stats,
}

impl StringStepper {
    /// A stepper from `state` at `t0` \[s\] with `method` (rattle, rattle4, rattle6, rattle8 or rkmk4)
    /// and step `dt` \[s\] in the taut phases. The start may be on the sphere (|x| = l within 1e-9
    /// relative: taut, unless T < 0 or it moves off the sphere) or inside it (slack, flying); beyond
    /// it is an error.
    pub fn new(model: StringPendulum, t0: f64, state: State, method: Method, dt: f64) -> Result<Self> {
        crate::error::require_finite("t0", t0, "the start time must be finite (s)")?;
        crate::error::require_positive("dt", dt, "the step size dt must be a finite number > 0 s")?;
        if !state.is_finite() {
            return Err(Error::Diverged { t: t0, method: "string", dt });
        }
        let l = model.params().length;
        let excess = (state.x.length() - l) / l;
        if excess > TS2_TOLERANCE {
            return Err(Error::InvalidParameter {
                name: "(|x| - l)/l",
                value: excess,
                allowed: "a string pendulum starts on the sphere |x| = l or inside it (slack), not beyond",
            });
        }
        let scheme = Scheme::new(method)?;
        let mut s = state;
        let mut events = Vec::new();
        // the start: on the sphere moving tangentially (taut unless T < 0), inward (flying) or
        // outward (a snap at once); inside the sphere, flying
        let mut phase = if excess.abs() <= TS2_TOLERANCE {
            let radial = s.x.dot(s.v) / (l * s.v.length().max(f64::MIN_POSITIVE));
            if radial.abs() <= TS2_TOLERANCE {
                s = State::projected(model.params(), s.x, s.v)?.0;
                Phase::Taut
            } else if radial < 0.0 {
                model.flight_from(t0, s, 1)
            } else {
                Phase::Slack { t: t0, from: s, arrival: t0 }
            }
        } else {
            model.flight_from(t0, s, 0)
        };
        if let Phase::Taut = phase {
            if model.tension(&s) < 0.0 {
                events.push(StringEvent {
                    t: t0,
                    kind: EventKind::Slack,
                    before: s,
                    after: s,
                    energy_lost: 0.0,
                });
                phase = model.flight_from(t0, s, 2);
            }
        }
        Ok(Self {
            model,
            rod: IdealPendulum::from_params(*model.params()),
            scheme,
            t0,
            dt,
            t: t0,
            s,
            k: 0,
            target: 0,
            on_grid: true,
            phase,
            events,
            stats: Stats::default(),
        })
    }

    /// Time reached \[s\].
    pub fn t(&self) -> f64 {
        self.t
    }

    /// State reached (x \[m\], v [m/s]); inside the sphere while slack.
    pub fn state(&self) -> State {
        self.s
    }

    /// True while the string is taut (the bob on the sphere), false while slack (in free flight).
    pub fn is_taut(&self) -> bool {
        matches!(self.phase, Phase::Taut)
    }

    /// The pendulum.
    pub fn model(&self) -> &StringPendulum {
        &self.model
    }

    /// Taut-phase steps and evaluations so far.
    pub fn stats(&self) -> Stats {
        self.stats
    }

    /// The events since the last call (or the start), in order.
    pub fn take_events(&mut self) -> Vec<StringEvent> {
        std::mem::take(&mut self.events)
    }

    /// The string's tension \[N\] at the state reached: T-2.3 while taut (≥ 0), 0 while slack.
    pub fn tension(&self) -> f64 {
        if self.is_taut() {
            self.model.tension(&self.s)
        } else {
            0.0
        }
    }

    /// The acceleration ẍ [m/s²] at the state reached: the rod's f + λx (T-2.2) while taut, gravity
    /// alone while slack.
    pub fn acceleration(&self) -> DVec3 {
        if self.is_taut() {
            crate::model::acceleration(&self.rod, self.t, self.s.x, self.s.v)
        } else {
            self.rod.applied_acceleration(self.t, self.s.x, self.s.v)
        }
    }

    /// Takes `n` steps of the grid: advances to the grid point t₀ + (K + n)·dt, K the grid index of
    /// the previous target (0 at the start); a taut step is dt, shortened at events.
    pub fn step(&mut self, n: u64) -> Result<()> {
        self.target += n;
        let t_end = self.t0 + self.target as f64 * self.dt;
        self.advance(t_end, u64::MAX, &mut |_, _, _| Ok(()))
    }

    /// Advances to `t_end` \[s\], calling `push(t, state, taut)` at every `save_every`-th grid point,
    /// after every event and at t_end; nothing when `t_end` is not after the time reached.
    pub fn advance(
        &mut self,
        t_end: f64,
        save_every: u64,
        push: &mut dyn FnMut(f64, State, bool) -> Result<()>,
    ) -> Result<()> {
        self.advance_to(t_end, true, save_every, push)
    }

    /// Advances to `t_stop` [s], calling `push` at every `save_every`-th grid point and after every
    /// event. `end`: t_stop ends the run — pushed, and a snap exactly at t_stop is left undone (the
    /// state there is the one before it), as in [`StringStepper::advance`]. Otherwise t_stop is a
    /// stop on the way (a chunk's end, a save time): pushed only when it is a `save_every`-th grid
    /// point, and a snap exactly at t_stop is done, so that the run goes on as if it had not stopped.
    pub(super) fn advance_to(
        &mut self,
        t_end: f64,
        end: bool,
        save_every: u64,
        push: &mut Push<'_>,
    ) -> Result<()> {
        let stop = Stop { t: t_end, end, save_every };
        while self.t < t_end {
            match self.phase {
                Phase::Taut => self.taut_step(stop, push)?,
                Phase::Slack { t, from, arrival } => self.fly(t, from, arrival, stop, push)?,
            }
        }
        Ok(())
    }

    /// The grid point t₀ + k·dt [s].
    #[inline]
    fn grid(&self, k: u64) -> f64 {
        self.t0 + k as f64 * self.dt
    }

    /// One taut step towards `stop.t`: to the next grid point (a full dt when on the grid) or to
    /// `stop.t`; when T < 0 at its end, the step shortened to the leave event instead ([`Self::leave`]).
    fn taut_step(&mut self, stop: Stop, push: &mut Push<'_>) -> Result<()> {
        let dt = self.dt;
        let slack_grid = 1e-9 * dt;
        // the next grid point (or t_end), reached by a full step dt when on the grid
        let next = self.grid(self.k + 1);
        let t_next = next.min(stop.t);
        let h = if self.on_grid && t_next == next { dt } else { t_next - self.t };
        // the grid index and whether on the grid once at t_next
        let (k_next, on_grid_next) = if t_next == next { (self.k + 1, true) } else { (self.k, false) };
        if h <= slack_grid {
            (self.t, self.k, self.on_grid) = (t_next, k_next, on_grid_next);
            return Ok(());
        }
        let mut trial = self.scheme.clone();
        let mut s1 = self.s;
        trial.step(&self.rod, self.t, &mut s1, h)?;
        self.stats.steps += 1;
        self.stats.rhs_evals += trial.evals();
        if self.model.tension(&s1) >= 0.0 {
            (self.scheme, self.s, self.t, self.k, self.on_grid) = (trial, s1, t_next, k_next, on_grid_next);
            if (on_grid_next && self.k.is_multiple_of(stop.save_every)) || (stop.end && self.t >= stop.t) {
                push(self.t, self.s, true)?;
            }
            return Ok(());
        }
        self.leave(h, trial.evals(), push)
    }

    /// The leave event in a taut step of `h` [s] that ends with T < 0: the step shortened to where
    /// T = 0 (bisection to round-off in h; each trial costs `evals` evaluations), the event, and the
    /// flight from there.
    fn leave(&mut self, h: f64, evals: u64, push: &mut Push<'_>) -> Result<()> {
        let trials = std::cell::Cell::new(0u64);
        let (t, s, scheme, rod) = (self.t, self.s, &self.scheme, &self.rod);
        let at = |h: f64| {
            trials.set(trials.get() + 1);
            let (mut sc, mut sh) = (scheme.clone(), s);
            sc.step(rod, t, &mut sh, h).map(|_| sh)
        };
        let h_star = bisect(0.0, h, |h| at(h).map_or(true, |sh| self.model.tension(&sh) < 0.0));
        let leave = at(h_star)?;
        self.stats.rhs_evals += trials.get() * evals;
        self.t += h_star;
        self.s = leave;
        self.on_grid = false;
        self.events.push(StringEvent {
            t: self.t,
            kind: EventKind::Slack,
            before: self.s,
            after: self.s,
            energy_lost: 0.0,
        });
        push(self.t, self.s, false)?;
        self.phase = self.model.flight_from(self.t, self.s, 2);
        Ok(())
    }

    /// Free flight on the exact parabola from `from` at `te` [s], arriving on the sphere at `arrival`
    /// [s]: the grid samples along it until the arrival or `stop.t`, then either the state at `stop.t`
    /// (the arrival is later, or exactly at the end of the run) or the snap at the arrival.
    fn fly(&mut self, te: f64, from: State, arrival: f64, stop: Stop, push: &mut Push<'_>) -> Result<()> {
        let t_end = stop.t;
        while self.grid(self.k + 1) < arrival.min(t_end) {
            self.k += 1;
            if self.k.is_multiple_of(stop.save_every) {
                let gk = self.grid(self.k);
                push(gk, self.model.flight(&from, gk - te), false)?;
            }
        }
        if arrival > t_end || (stop.end && arrival == t_end) {
            let on_grid = self.grid(self.k + 1) == t_end;
            if on_grid {
                self.k += 1;
            }
            self.s = self.model.flight(&from, t_end - te);
            self.t = t_end;
            if stop.end || (on_grid && self.k.is_multiple_of(stop.save_every)) {
                push(self.t, self.s, false)?;
            }
            return Ok(());
        }
        let before = self.model.flight(&from, arrival - te);
        self.snap(arrival, before, push)
    }

    /// The snap at `t` [s], arriving on the sphere in state `before`: the jerk (radial velocity
    /// removed or reflected), then taut, slack again at once (T < 0 after the jerk), or a rebound
    /// flight (restitution e > 0).
    fn snap(&mut self, t: f64, before: State, push: &mut Push<'_>) -> Result<()> {
        let (after, lost, taut) = self.model.snap(&before);
        self.t = t;
        self.s = after;
        self.on_grid = false;
        self.scheme.reset();
        self.events.push(StringEvent { t, kind: EventKind::Taut, before, after, energy_lost: lost });
        if taut && self.model.tension(&self.s) < 0.0 {
            self.events.push(StringEvent {
                t,
                kind: EventKind::Slack,
                before: self.s,
                after: self.s,
                energy_lost: 0.0,
            });
            self.phase = self.model.flight_from(self.t, self.s, 2);
        } else if taut {
            self.phase = Phase::Taut;
        } else {
            self.phase = self.model.flight_from(self.t, self.s, 1);
        }
        push(self.t, self.s, self.is_taut())
    }
}

/// What is called with (t [s], state, taut) for every sample kept.
pub(super) type Push<'a> = dyn FnMut(f64, State, bool) -> Result<()> + 'a;

/// Where [`StringStepper::advance_to`] stops: the time `t` [s], whether it ends the run (`end`), and
/// which grid points it reports (every `save_every`-th).
#[derive(Debug, Clone, Copy)]
struct Stop {
    t: f64,
    end: bool,
    save_every: u64,
}
