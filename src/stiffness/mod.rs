//! Mesh stiffness: potential energy method, fillet foundation, ISO 6336 check.
