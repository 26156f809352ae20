//! TEMPORARY STUB (replaced by the real DOP853).
#![allow(missing_docs, unused)]
use super::Stats;
use crate::error::Result;
use crate::model::Model;
use crate::state::State;
#[derive(Debug, Clone)]
pub struct Dop853;
impl Dop853 {
    pub fn new(rtol: f64, atol: f64, project: bool, h_max: f64, h_init: Option<f64>) -> Result<Self> {
        Ok(Dop853)
    }
    pub fn step<M: Model>(
        &mut self,
        model: &M,
        t: &mut f64,
        s: &mut State,
        t_stop: f64,
        stats: &mut Stats,
    ) -> Result<()> {
        unimplemented!()
    }
    pub fn dense_output(&self, t_out: f64) -> State {
        unimplemented!()
    }
    pub fn last_step_interval(&self) -> (f64, f64) {
        unimplemented!()
    }
    pub fn reset(&mut self) {}
}
