//! The wall-time budget of one tick of a live session, with the time passed in (docs/web.md, "Pacing").
//!
//! The core reads no clock (`std::time` does not exist in a browser's WebAssembly): whoever drives a
//! session hands in a [`Clock`] — seconds from any fixed origin, e.g. `performance.now()/1000` in a Web
//! Worker or a monotonic clock on a server. A [`Budget`] is a deadline on that clock; a [`Slicer`]
//! calls the steppers in slices of about [`SLICE_TIME`] seconds, sized from the steps per second it
//! measured on earlier slices, and checks the budget between slices, so a tick overruns its budget by
//! at most one slice; a small budget (a session's share of a full room) is sliced finer. The Python
//! server drives this code through the bindings (`pendulab._core.LiveSession`).
//! Units: seconds \[s\] throughout.

/// Wall-clock seconds one session may step per tick (a tick is 1/60 s ≈ 16.7 ms).
pub const TICK_BUDGET: f64 = 0.006;
/// Wall-clock seconds one call into a stepper aims at (the granularity of the budget).
pub const SLICE_TIME: f64 = 0.0005;
/// Shortest slice \[s\]: a small budget (a session's share of a full room) is spent in slices of half
/// of it, at most [`SLICE_TIME`], at least this.
pub const MIN_SLICE_TIME: f64 = 0.00002;
/// Steps of the first slice of a new stepper (before its speed is known).
pub const FIRST_SLICE: u64 = 64;
/// Most steps of one slice.
pub const MAX_SLICE: u64 = 1 << 22;

/// A source of wall-clock time \[s\] (monotonic; the origin does not matter).
pub trait Clock {
    /// Seconds since some fixed origin.
    fn now(&self) -> f64;
}

impl<F: Fn() -> f64> Clock for F {
    fn now(&self) -> f64 {
        self()
    }
}

/// A deadline on a [`Clock`]: `seconds` from when it was made, spent in slices of `slice` seconds.
pub struct Budget<'c> {
    clock: &'c dyn Clock,
    deadline: f64,
    slice: f64,
}

impl<'c> Budget<'c> {
    /// A budget of `seconds` \[s\] from now on `clock`.
    pub fn new(clock: &'c dyn Clock, seconds: f64) -> Self {
        let slice = (0.5 * seconds).clamp(MIN_SLICE_TIME, SLICE_TIME);
        Self { clock, deadline: clock.now() + seconds, slice }
    }

    /// Seconds \[s\] one slice aims at: half the budget, between [`MIN_SLICE_TIME`] and [`SLICE_TIME`].
    pub fn slice(&self) -> f64 {
        self.slice
    }

    /// True once the deadline has passed.
    pub fn spent(&self) -> bool {
        self.clock.now() >= self.deadline
    }

    /// The clock's time now \[s\].
    pub fn now(&self) -> f64 {
        self.clock.now()
    }
}

/// Calls a stepper in slices until the work is done or the budget is spent; remembers the stepper's
/// speed (steps per wall-clock second) between ticks. [`Slicer::reset`] when the stepper changes.
#[derive(Debug, Clone, Default)]
pub struct Slicer {
    rate: Option<f64>,
}

impl Slicer {
    /// A slicer that knows no speed yet.
    pub fn new() -> Self {
        Self::default()
    }

    /// Forget the measured speed (a new stepper, method or model).
    pub fn reset(&mut self) {
        self.rate = None;
    }

    fn size(&self, most: u64, budget: &Budget<'_>) -> u64 {
        let n = match self.rate {
            None => FIRST_SLICE,
            Some(r) => (r * budget.slice) as u64,
        };
        n.min(MAX_SLICE).min(most).max(1)
    }

    fn learn(&mut self, steps: u64, seconds: f64) {
        let rate = steps as f64 / seconds.max(1e-7);
        self.rate = Some(match self.rate {
            None => rate,
            Some(old) => 0.5 * (old + rate),
        });
    }

    /// Takes up to `n` steps with `step(k)` (k steps per call), at least one slice, stopping when the
    /// budget is spent; returns the steps taken (or the stepper's error).
    pub fn steps<E>(
        &mut self,
        mut step: impl FnMut(u64) -> Result<(), E>,
        n: u64,
        budget: &Budget<'_>,
    ) -> Result<u64, E> {
        let mut taken = 0;
        while taken < n {
            let k = self.size(n - taken, budget);
            let t0 = budget.now();
            step(k)?;
            self.learn(k, budget.now() - t0);
            taken += k;
            if budget.spent() {
                break;
            }
        }
        Ok(taken)
    }

    /// Calls `step_to(cap)` (at most `cap` steps towards a target; true once there) in slices, at
    /// least one, until the target is reached (true) or the budget is spent (false).
    pub fn until<E>(
        &mut self,
        mut step_to: impl FnMut(u64) -> Result<bool, E>,
        budget: &Budget<'_>,
    ) -> Result<bool, E> {
        loop {
            let k = self.size(MAX_SLICE, budget);
            let t0 = budget.now();
            let reached = step_to(k)?;
            if reached {
                return Ok(true);
            }
            self.learn(k, budget.now() - t0); // a full slice: its time measures the speed
            if budget.spent() {
                return Ok(false);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::cell::Cell;

    #[test]
    fn slices_stop_at_the_budget_and_learn_the_speed() {
        // a fake clock: every step costs 1 µs of "wall time"
        let now = Cell::new(0.0);
        let clock = || now.get();
        let budget = Budget::new(&clock, 0.006);
        let mut slicer = Slicer::new();
        let taken = slicer
            .steps(
                |k| {
                    now.set(now.get() + 1e-6 * k as f64);
                    Ok::<(), ()>(())
                },
                1_000_000,
                &budget,
            )
            .unwrap();
        // 6000 steps fit the budget; the overrun is at most one slice of SLICE_TIME (500 steps)
        assert!((6000..=6500).contains(&taken), "{taken}");
        // 1e6 steps/s × SLICE_TIME (up to the round-off of the clock's differences)
        let size = slicer.size(u64::MAX, &budget);
        assert!((499..=500).contains(&size), "{size}");
        // a small budget (a share of a full room): slices of half of it, at least MIN_SLICE_TIME
        assert_eq!(Budget::new(&clock, 1e-4).slice(), 5e-5);
        assert_eq!(Budget::new(&clock, 1e-6).slice(), MIN_SLICE_TIME);
        let small = slicer.size(u64::MAX, &Budget::new(&clock, 1e-4));
        assert!((49..=50).contains(&small), "{small}");
        // a budget already spent still takes one slice (of MIN_SLICE_TIME: 20 steps)
        let spent = Budget::new(&clock, 0.0);
        let one = slicer.steps(|_| Ok::<(), ()>(()), 10_000, &spent).unwrap();
        assert!((19..=20).contains(&one), "{one}");
    }
}
