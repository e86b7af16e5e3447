//! Which gear of the pair, and which flank side, a member named in the case is.

use crate::config::case::Member;
use crate::geometry::flank_shape::Side;
use crate::geometry::{Gear, GearPair};

/// The gear of the pair member `m` names.
pub(crate) fn member_gear(pair: &GearPair, m: Member) -> &Gear {
    match m {
        Member::Pinion => &pair.pinion,
        Member::Gear => &pair.gear,
    }
}

/// The flank side of member `m`.
pub(crate) fn side(m: Member) -> Side {
    match m {
        Member::Pinion => Side::Pinion,
        Member::Gear => Side::Gear,
    }
}
