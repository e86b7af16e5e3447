//! The records of a design, numbered independently of sharding.
//!
//! Physical states: condition c (slowest), trajectory state s, input speed v, load l
//! (fastest); p = ((c S + s) V + v) L + l. Each is recorded `R` times with its own noise:
//! record id = p R + r. A shard I of N takes the physical states with p mod N = I - 1
//! (round-robin, as sweeps do: neighbouring states cost alike), and all their records, so
//! a state's response is computed once. The noise seed of a record is a SplitMix64 hash
//! of (design seed, record id), cut to 53 bits (exact in every number format that reads
//! the index): independent streams for every record, the same on any machine or shard.

pub use crate::study::sweep::Shard;

use super::design::{DatasetDesign, StateChoice};

/// Where a physical state sits in the design.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct StateIndex {
    /// Condition c (0-based).
    pub condition: usize,
    /// State s along the condition's trajectory (0-based).
    pub state: usize,
    /// Input speed v (0-based, the design's order).
    pub speed: usize,
    /// Load l (0-based, the design's order).
    pub load: usize,
}

/// The sizes of the design's axes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Plan {
    /// Conditions C.
    pub conditions: usize,
    /// States S per trajectory.
    pub states: usize,
    /// Input speeds V.
    pub speeds: usize,
    /// Loads L.
    pub loads: usize,
    /// Records R per physical state (noise realisations).
    pub realisations: usize,
}

impl Plan {
    /// Physical states: C S V L.
    pub fn physical_states(&self) -> usize {
        self.conditions * self.states * self.speeds * self.loads
    }

    /// Records: C S V L R.
    pub fn records(&self) -> usize {
        self.physical_states() * self.realisations
    }

    /// Where physical state `p` (< [`Plan::physical_states`]) sits.
    pub fn state_index(&self, p: usize) -> StateIndex {
        let load = p % self.loads;
        let q = p / self.loads;
        let speed = q % self.speeds;
        let q = q / self.speeds;
        StateIndex {
            condition: q / self.states,
            state: q % self.states,
            speed,
            load,
        }
    }

    /// The physical state at `i`: p = ((c S + s) V + v) L + l.
    pub fn physical_id(&self, i: StateIndex) -> usize {
        ((i.condition * self.states + i.state) * self.speeds + i.speed) * self.loads + i.load
    }

    /// Record id of realisation `realisation` of physical state `p`: p R + r.
    pub fn record_id(&self, p: usize, realisation: usize) -> usize {
        p * self.realisations + realisation
    }

    /// The physical states of shard `shard`, ascending, listed lazily (a shard may hold
    /// more states than fit in memory as a list).
    pub fn shard_states(&self, shard: Shard) -> impl Iterator<Item = usize> + Clone {
        (shard.index.saturating_sub(1)..self.physical_states()).step_by(shard.count.max(1))
    }

    /// How many physical states shard `shard` has.
    pub fn shard_state_count(&self, shard: Shard) -> usize {
        let first = shard.index.saturating_sub(1);
        let total = self.physical_states();
        if first >= total {
            0
        } else {
            (total - first).div_ceil(shard.count.max(1))
        }
    }

    /// The conditions shard `shard` records (those with at least one of its states),
    /// found without listing the states.
    pub fn shard_conditions(&self, shard: Shard) -> Vec<usize> {
        let per = self.states * self.speeds * self.loads;
        let (i, n) = (shard.index.saturating_sub(1), shard.count.max(1));
        (0..self.conditions)
            .filter(|c| {
                let lo = c * per;
                let first = lo + (i + n - lo % n) % n;
                first < lo + per
            })
            .collect()
    }
}

/// SplitMix64 (Steele, Lea & Flood 2014): a bijective 64-bit mix.
pub fn splitmix64(mut z: u64) -> u64 {
    z = z.wrapping_add(0x9E37_79B9_7F4A_7C15);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

/// The noise seed of record `id` under the design seed (module docs).
pub fn record_seed(design_seed: u64, id: usize) -> u64 {
    splitmix64(splitmix64(design_seed) ^ id as u64) & ((1u64 << 53) - 1)
}

/// The plan's axis sizes.
pub fn plan_of(d: &DatasetDesign) -> Plan {
    Plan {
        conditions: d.conditions.len(),
        states: match &d.states {
            StateChoice::Count(n) => *n,
            StateChoice::Cycles(c) => c.len(),
        },
        speeds: d.speeds_hz.len(),
        loads: d.torques_nm.len(),
        realisations: d.noise_realisations,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ids_round_trip_and_shards_partition_the_states() {
        let plan = Plan {
            conditions: 2,
            states: 5,
            speeds: 3,
            loads: 2,
            realisations: 10,
        };
        for p in 0..plan.physical_states() {
            assert_eq!(plan.physical_id(plan.state_index(p)), p);
        }
        let mut all: Vec<usize> = (1..=3)
            .flat_map(|i| plan.shard_states(Shard { index: i, count: 3 }))
            .collect();
        for (i, n) in [(1, 3), (3, 3), (2, 7), (60, 60), (5, 100)] {
            let shard = Shard { index: i, count: n };
            let listed: Vec<usize> = shard.ids(plan.physical_states());
            assert_eq!(plan.shard_state_count(shard), listed.len(), "{i}/{n}");
            let mut conds: Vec<usize> = listed
                .iter()
                .map(|p| plan.state_index(*p).condition)
                .collect();
            conds.dedup();
            assert_eq!(plan.shard_conditions(shard), conds, "{i}/{n}");
        }
        all.sort_unstable();
        assert_eq!(all, (0..60).collect::<Vec<_>>());
        // SplitMix64's published first output for seed 0 (state advanced once).
        assert_eq!(splitmix64(0), 0xE220_A839_7B1D_CDAF);
        assert!(record_seed(7, 3) < 1 << 53);
        assert_ne!(record_seed(7, 3), record_seed(7, 4));
    }
}
