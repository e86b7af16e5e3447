//! Contact mechanics: load sharing, Hertz, kinematics, friction.
