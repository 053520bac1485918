//! Probe: the undamped reference track with ballast friction over a speed range, each speed from the last one's wave
//! on the domain it grew to (as the stationary-wave study sweeps), with each speed's Newton iterations and time.
//! `cargo run --release -p stationary --example friction_curve -- FROM TO STEP F_U [halved]`; with `halved` each
//! speed's error estimate too (its wave solved again on elements half as long, as the CLI does), timed apart.

use analytic::reference::uic60_on_soft_soil;
use fem_beam::{DistributedFriction, Foundation, FoundationLaw};
use stationary::{ContactGuess, Control, Domain, StationaryProblem, solve_halved, solve_within};

fn main() {
    let halved = std::env::args().nth(5).is_some_and(|a| a == "halved");
    let args: Vec<f64> = std::env::args().skip(1).take(4).map(|a| a.parse().expect("a number")).collect();
    let [from, to, step, friction] = args[..] else { panic!("FROM TO STEP F_U [halved]") };
    let mut estimates = std::time::Duration::ZERO;
    let case = uic60_on_soft_soil();
    let mut domain = Domain::default();
    let mut guess = ContactGuess::default();
    let (mut total, mut iterations) = (std::time::Duration::ZERO, 0);
    let count = ((to - from) / step + 1e-9).floor() as usize + 1;
    for speed in (0..count).map(|i| from + i as f64 * step) {
        let problem = StationaryProblem {
            beam: case.beam,
            foundation: Foundation { law: FoundationLaw::Linear, ..case.foundation },
            load: 83.4e3,
            speed,
            self_weight: false,
            friction: DistributedFriction::new(friction),
            domain,
        };
        let start = std::time::Instant::now();
        let wave = solve_within(&problem, &mut guess, &Control::new(None)).expect("a wave");
        let spent = start.elapsed();
        if wave.convergence.is_converged() {
            (domain.behind, domain.ahead) = (-wave.s[0], *wave.s.last().expect("nodes"));
        }
        total += spent;
        if halved && wave.convergence.is_converged() {
            let start = std::time::Instant::now();
            let finer = solve_halved(&problem, &wave, &Control::new(None)).expect("a halved wave");
            estimates += start.elapsed();
            println!(
                "          halved: {} its {:8.1} ms peak {:.6} mm {:?}",
                finer.convergence.iterations(),
                start.elapsed().as_secs_f64() * 1e3,
                finer.max_downward().value * 1e3,
                finer.convergence.is_converged()
            );
        }
        iterations += wave.convergence.iterations();
        println!(
            "{speed:7.1} m/s  {:>5} its  {:8.1} ms  peak {:.6} mm  domain {}:{}  {:?}",
            wave.convergence.iterations(),
            spent.as_secs_f64() * 1e3,
            wave.max_downward().value * 1e3,
            domain.behind,
            domain.ahead,
            wave.convergence.is_converged()
        );
    }
    println!(
        "total {:.2} s, {iterations} iterations; error estimates {:.2} s",
        total.as_secs_f64(),
        estimates.as_secs_f64()
    );
}
