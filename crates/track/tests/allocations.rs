//! Nothing allocates inside the time loop (docs/architecture.md, one step): a counting global allocator watches 400 steps of the stepper
//! after a short warm-up, for each friction solver that runs in production (projection for devices, the windowed
//! interior point for distributed friction) and without friction. Its own test binary, so that the counting
//! allocator sees nothing else.
#![allow(unsafe_code)]

use analytic::reference::uic60_on_soft_soil;
use nscd::MoreauJean;
use nscd::solver::{SolverKind, SolverSettings};
use nscd::stepper::Integration;
use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicUsize, Ordering};
use track::MovingLoad;
use track::PlacedInteractions;
use track::system::beam_system;
use track::{BallastOnBeam, Devices, DistributedFriction};

/// The system allocator, counting allocations and reallocations.
struct Counting;

static ALLOCATIONS: AtomicUsize = AtomicUsize::new(0);

// SAFETY: forwards every call unchanged to the system allocator; only a counter is added.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        ALLOCATIONS.fetch_add(1, Ordering::Relaxed);
        // SAFETY: same contract as the caller's.
        unsafe { System.alloc(layout) }
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        // SAFETY: same contract as the caller's.
        unsafe { System.dealloc(ptr, layout) }
    }

    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        ALLOCATIONS.fetch_add(1, Ordering::Relaxed);
        // SAFETY: same contract as the caller's.
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

fn allocations_in_steps(interactions: &PlacedInteractions, kind: SolverKind) -> usize {
    let model = uic60_on_soft_soil().model().unwrap();
    let (speed, theta) = (200.0, 0.5);
    let h = 0.1 / speed;
    let system = beam_system(&model);
    let integration = Integration::theta(theta, h);
    let settings = SolverSettings { kind, ..SolverSettings::default() };
    let load = MovingLoad::new(&model, 83.4e3, speed, 0.0);
    let n = system.dofs();
    let (q0, v0) = (vec![0.0; n], vec![0.0; n]);
    let mut stepper =
        MoreauJean::build(&system, interactions.interactions().clone(), integration, &settings, q0, v0).unwrap();
    // Warm-up: the load reaches the beam's middle, so that windows of every size have been seen.
    for _ in 0..1000 {
        stepper.step(&load).unwrap();
    }
    let before = ALLOCATIONS.load(Ordering::Relaxed);
    for _ in 0..400 {
        stepper.step(&load).unwrap();
    }
    ALLOCATIONS.load(Ordering::Relaxed) - before
}

#[test]
fn the_time_loop_does_not_allocate() {
    let model = uic60_on_soft_soil().model().unwrap();
    let none = allocations_in_steps(&PlacedInteractions::new(), SolverKind::Projection);
    let devices =
        allocations_in_steps(&Devices::uniform(31, 100e3).interactions(&model).unwrap(), SolverKind::Projection);
    let distributed =
        allocations_in_steps(&DistributedFriction::new(5e3).interactions(&model).unwrap(), SolverKind::InteriorPoint);
    assert_eq!((none, devices, distributed), (0, 0, 0), "allocations in 400 steps: none / 31 devices / distributed");
}
