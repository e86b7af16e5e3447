//! A second method for the linear time-periodic gear model: exponential propagation of
//! the frozen state matrix and a direct solve of the periodic boundary value problem.

use gearwear::dynamics::model::{ContactFrame, GearSystem, State, NDOF, NSTATE};
use nalgebra::{DMatrix, DVector, SMatrix};

/// Node states of the periodic solution of the linear time-periodic model over `grid`
/// (its first and last node one excitation period apart): over each interval the state
/// matrix and forcing are frozen at the interval's middle and propagated exactly
/// (exponential midpoint rule, second order), and y(end) = y(0) is solved directly for
/// the coordinates other than the held one.
pub fn linear_periodic(sys: &GearSystem, grid: &[f64], held: usize) -> Vec<State> {
    linear_periodic_with_slopes(sys, grid, held).0
}

/// [`linear_periodic`] and, per interval, the state's derivative at its start and end
/// under the interval's frozen matrix and forcing (the slopes of the interval's exact
/// frozen solution at its ends).
pub fn linear_periodic_with_slopes(
    sys: &GearSystem,
    grid: &[f64],
    held: usize,
) -> (Vec<State>, Vec<(State, State)>) {
    let y_touch = sys.static_equilibrium();
    let frozen: Vec<(DMatrix<f64>, State)> = grid
        .windows(2)
        .map(|w| {
            let t = 0.5 * (w[0] + w[1]);
            let a = sys.jacobian(ContactFrame::NATURAL, t, y_touch.as_slice());
            let b = sys
                .derivative(ContactFrame::NATURAL, t, y_touch.as_slice())
                .0
                - &a * &y_touch;
            (a, b)
        })
        .collect();
    let steps: Vec<SMatrix<f64, 17, 17>> = grid
        .windows(2)
        .zip(&frozen)
        .map(|(w, (a, b))| {
            let h = w[1] - w[0];
            let mut z = SMatrix::<f64, 17, 17>::zeros();
            z.fixed_view_mut::<16, 16>(0, 0).copy_from(a);
            z.fixed_view_mut::<16, 1>(0, 16).copy_from(b);
            (z * h).exp()
        })
        .collect();
    let monodromy = steps
        .iter()
        .fold(SMatrix::<f64, 17, 17>::identity(), |m, e| e * m);
    let free: Vec<usize> = (0..NSTATE)
        .filter(|i| *i != held && *i != NDOF + held)
        .collect();
    let n = free.len();
    let a = DMatrix::from_fn(n, n, |i, j| {
        f64::from(u8::from(i == j)) - monodromy[(free[i], free[j])]
    });
    let rhs = DVector::from_fn(n, |i, _| {
        monodromy[(free[i], 16)] + monodromy[(free[i], held)] * y_touch[held]
    });
    let x = a.lu().solve(&rhs).expect("no eigenvalue 1");
    let mut y = y_touch.clone();
    for (k, i) in free.iter().enumerate() {
        y[*i] = x[k];
    }
    y[NDOF + held] = 0.0;
    let mut out = vec![y];
    for e in &steps {
        let mut z = nalgebra::SVector::<f64, 17>::zeros();
        z.fixed_rows_mut::<16>(0).copy_from(out.last().unwrap());
        z[16] = 1.0;
        out.push(State::from_column_slice(
            (e * z).fixed_rows::<16>(0).as_slice(),
        ));
    }
    let slopes = frozen
        .iter()
        .enumerate()
        .map(|(i, (a, b))| (a * &out[i] + b, a * &out[i + 1] + b))
        .collect();
    (out, slopes)
}
