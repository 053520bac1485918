//! A sweep's estimate counts the runs that follow it: the refinement of its critical speed, as many as the
//! refinement then takes (the sleeper-friction study announced 90 runs and ran 162 before they were counted).

use runner::{Runner, critical_speed, finished, refinement_runs};
use scenario::Scenario;
use std::sync::Mutex;

#[test]
fn a_sweep_announces_the_refinement_that_follows_it() {
    let case = Scenario::from_toml("[mesh]\nelements = 100\n", "t.toml").unwrap().build().unwrap();
    let speeds = [150.0, 200.0, 250.0];
    let (step, tolerance) = (50.0, 1.0);
    let announced = Mutex::new(Vec::new());
    let hook = |e: &runner::cost::Estimate| announced.lock().unwrap().push(e.runs);
    let runner = Runner::new(1).unwrap().with_estimate(&hook);
    let extra = refinement_runs(step, tolerance, 0);
    let rows = runner.clone().with_refinement(extra).sweep_many_keeping(std::slice::from_ref(&case), &speeds).unwrap();
    assert_eq!(*announced.lock().unwrap(), vec![speeds.len() + extra]);
    let refined = critical_speed(&case, &finished(&rows[0]), tolerance, &runner.silent()).unwrap();
    assert_eq!(refined.evaluations.len(), extra, "the refinement ran {} runs", refined.evaluations.len());
}
