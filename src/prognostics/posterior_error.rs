//! Why a posterior could not be computed from the observations (an input problem: the
//! observations, the prior or the sampler's settings, never a defect of the program).

/// Why no posterior could be computed. The message says what to check.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum PosteriorError {
    /// Every parameter of the prior is fixed (equal bounds): there is nothing to weigh.
    #[error("nothing to calibrate: every parameter of [calibration] is fixed (equal bounds)")]
    NothingToCalibrate,
    /// The grid posterior takes one or two free parameters.
    #[error("the grid posterior takes 1 or 2 parameters, got {free}")]
    GridDimensions {
        /// Free parameters asked for.
        free: usize,
    },
    /// Every forward run on the grid failed before the observations.
    #[error("no forward run reached the observations on the grid ({failed} of {points} failed)")]
    NoRunReached {
        /// Grid points whose forward run failed.
        failed: usize,
        /// Grid points in all.
        points: usize,
    },
    /// The observations have zero likelihood at every grid point.
    #[error(
        "the observations have zero likelihood at every one of the {points} grid points ({failed} runs failed, the others are too far from the data for their noise): check the observations' units, values and sigmas"
    )]
    ZeroLikelihood {
        /// Grid points whose forward run failed.
        failed: usize,
        /// Grid points in all.
        points: usize,
    },
    /// The ensemble sampler needs an even number of walkers, at least twice the free
    /// parameters (Goodman & Weare 2010).
    #[error(
        "the ensemble needs an even number of walkers >= 2 x {free} parameters, got {walkers}"
    )]
    Walkers {
        /// Free parameters.
        free: usize,
        /// Walkers asked for.
        walkers: usize,
    },
    /// Too few prior draws have a finite posterior to start the ensemble.
    #[error(
        "fewer than {walkers} of {draws} prior draws have a finite posterior (forward runs failed or the data exclude them): cannot start the ensemble"
    )]
    NoFiniteStart {
        /// Walkers to start.
        walkers: usize,
        /// Prior draws tried.
        draws: usize,
    },
    /// One of the above where the reference runs stop before the last observation: the
    /// cause in the terms of the data.
    #[error(
        "{cause}: the reference runs reach at most {reach_cycles:.4e} cycles (at the prior's smallest k; faster wear stops sooner: {first_failure}), but the last observation is at {last_cycles:.4e} cycles"
    )]
    BeyondReach {
        /// The error the sampler met.
        cause: Box<PosteriorError>,
        /// Largest cycle count any reference run reaches, pinion cycles.
        reach_cycles: f64,
        /// Cycle count of the last observation, pinion cycles.
        last_cycles: f64,
        /// Why the first failed reference run stopped ("no failure recorded" if none did).
        first_failure: String,
    },
}
