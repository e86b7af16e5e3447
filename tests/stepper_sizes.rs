//! The period stepper on stack vectors (`Const<N>`, the sizes `period::period_stepper`
//! lists) against the same stepper on heap vectors (`Dyn`): the same steps and the same
//! state, bit for bit, on the two-stage reducer of the examples (28 states). A second
//! method for the monomorphised stepper: nalgebra runs the same loops in the same order
//! on both dimension types, so any difference is a bug of the sized path.

use gearwear::config::load_case;
use gearwear::dynamics::excitation::ExternalError;
use gearwear::dynamics::grid::train_nodes;
use gearwear::dynamics::period::{PeriodIntegrator, PeriodStepper};
use gearwear::study::Model;
use gearwear::wear::WearState;
use nalgebra::{Const, Dyn};

#[test]
fn a_two_stage_period_on_the_stack_is_the_heap_period_bit_for_bit() {
    let text = include_str!("../examples/two_stage_reducer.toml");
    let model = Model::from_case(&load_case(text, &[]).expect("valid case")).expect("a train");
    let wear = WearState::new(model.grid.len());
    let gap = model.wear_gap(&wear);
    let none = ExternalError::none();
    let sys = model.system(&gap, &none, model.roughness_for(&wear));
    assert_eq!(
        sys.states(),
        28,
        "the example's size is one of the listed ones"
    );
    let settings = &model.settings;
    let start = sys.static_equilibrium();
    let nodes = train_nodes(&sys, settings.steps_per_mesh_period).expect("a base period");
    // A part of the base period (a whole one takes long in a debug build): its first 300
    // node intervals from the static equilibrium, with the events, rejected steps and
    // refactorisations the error control meets there.
    let until = nodes[300.min(nodes.len() - 1)];
    let tol = settings.integration_tolerance;
    let mut on_stack = PeriodStepper::new(&sys, Const::<28>, nodes.clone(), tol).expect("stepper");
    let mut on_heap = PeriodStepper::new(&sys, Dyn(28), nodes, tol).expect("stepper");
    let (mut a, mut b) = (start.as_slice().to_vec(), start.as_slice().to_vec());
    on_stack
        .integrate_part(0.0, &mut a, &mut (), until)
        .expect("steps");
    on_heap
        .integrate_part(0.0, &mut b, &mut (), until)
        .expect("steps");
    assert!(on_stack.counts().accepted > 300, "{:?}", on_stack.counts());
    assert_eq!(on_stack.counts(), on_heap.counts());
    assert_eq!(on_stack.integrator_stats(), on_heap.integrator_stats());
    for (i, (x, y)) in a.iter().zip(&b).enumerate() {
        assert_eq!(
            x.to_bits(),
            y.to_bits(),
            "state {i}: {x:e} on the stack, {y:e} on the heap"
        );
    }
    assert!(a != start.as_slice(), "the state moved");
}
