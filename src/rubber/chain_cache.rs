//! Maxwell chain fits, remembered. A fit is a non-negative least-squares problem of some
//! 100 rows; a diagnosis asks for the same few chains thousands of times (every system it
//! builds, every time-domain run), and they took a tenth of its time. A chain depends
//! only on the stage's ψ and frequency law, the band and the modes it is fitted at, so
//! those, bit for bit, are the key: a remembered chain is the very chain a new fit gives.
//!
//! Written by hand: a bounded map behind a mutex is all it needs; a caching crate would
//! add an eviction policy this use does not need.

use super::chain::{MaxwellChain, ModeTarget};
use crate::model::RubberStage;
use std::collections::HashMap;
use std::sync::{Mutex, MutexGuard, OnceLock, PoisonError};

/// Chains kept at most; the memory is emptied when it is full (a chain is ~1 kB).
const CAPACITY: usize = 4096;

/// What a fit depends on: ψ, the temperature and α_Tξ (the loss it meets), the frequency
/// law (coefficients and range), the band and the modes.
type Key = Vec<u64>;

fn key(stage: &RubberStage, band_hz: [f64; 2], modes: &[ModeTarget]) -> Key {
    let mut key = vec![
        stage.psi.to_bits(),
        band_hz[0].to_bits(),
        band_hz[1].to_bits(),
        stage.temperature_c.to_bits(),
    ];
    if let Some(p) = &stage.temperature_damping_poly {
        key.push(u64::MAX - 2);
        key.extend(p.coeffs.iter().map(|c| c.to_bits()));
        if let Some(range) = p.range {
            key.extend(range.iter().map(|r| r.to_bits()));
        }
    }
    if let Some(law) = &stage.frequency_zener {
        key.push(u64::MAX - 3);
        key.extend([law.delta, law.alpha, law.relax_hz, law.reference_hz].map(f64::to_bits));
    }
    if let Some(law) = &stage.frequency_power_law {
        key.extend([u64::MAX, law.exponent.to_bits(), law.reference_hz.to_bits()]);
    }
    if let Some(p) = &stage.frequency_poly {
        key.extend(p.coeffs.iter().map(|c| c.to_bits()));
        if let Some(range) = p.range {
            key.extend(range.iter().map(|r| r.to_bits()));
        }
    }
    key.push(u64::MAX - 1);
    for m in modes {
        key.extend([m.frequency_hz.to_bits(), m.energy_share.to_bits()]);
    }
    key
}

/// The remembered chains, locked. A poisoned lock only means another thread panicked
/// while holding it; the map itself is always whole.
fn memory() -> MutexGuard<'static, HashMap<Key, MaxwellChain>> {
    static MEMORY: OnceLock<Mutex<HashMap<Key, MaxwellChain>>> = OnceLock::new();
    MEMORY
        .get_or_init(|| Mutex::new(HashMap::new()))
        .lock()
        .unwrap_or_else(PoisonError::into_inner)
}

impl MaxwellChain {
    /// Fits the chain to `stage`'s α_f and ψ over `band_hz = [lo, hi]` (lo > 0) alone, with
    /// no mode rows ([`MaxwellChain::fit_at_modes`]).
    pub fn fit(stage: &RubberStage, band_hz: [f64; 2]) -> Self {
        Self::fit_at_modes(stage, band_hz, &[])
    }

    /// Fits the chain to `stage`'s α_f and ψ over `band_hz = [lo, hi]` (lo > 0) and at
    /// `modes`, or gives back the chain fitted before to the same ψ, law, band and modes.
    pub fn fit_at_modes(stage: &RubberStage, band_hz: [f64; 2], modes: &[ModeTarget]) -> Self {
        let key = key(stage, band_hz, modes);
        let remembered = memory().get(&key).cloned();
        if let Some(chain) = remembered {
            return chain;
        }
        // Fitted outside the lock, so other threads' look-ups do not wait for it.
        let chain = Self::fit_uncached(stage, band_hz, modes);
        let mut map = memory();
        if map.len() >= CAPACITY {
            map.clear();
        }
        map.insert(key, chain.clone());
        chain
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{Poly, RubberStiffness};

    fn stage(psi: f64, a2: f64) -> RubberStage {
        RubberStage {
            stiffness: RubberStiffness::Direct(1.0e4),
            psi,
            temperature_c: 25.0,
            amplitude_poly: None,
            amplitude_saturation: None,
            amplitude_form: Default::default(),
            frequency_poly: Some(Poly {
                coeffs: [a2, 0.0, 1.0],
                range: None,
            }),
            frequency_power_law: None,
            frequency_zener: None,
            temperature_stiffness_poly: None,
            temperature_damping_poly: None,
            thermal: None,
            rating: None,
        }
    }

    #[test]
    fn a_remembered_chain_is_the_fitted_one() {
        let band = [2.0, 3600.0];
        for (psi, a2) in [(1.0, 1e-7), (0.9, 1e-7), (1.0, 2e-7)] {
            let s = stage(psi, a2);
            let fresh = MaxwellChain::fit_uncached(&s, band, &[]);
            assert_eq!(MaxwellChain::fit(&s, band), fresh);
            assert_eq!(MaxwellChain::fit(&s, band), fresh);
        }
        // Another band is another chain.
        let s = stage(1.0, 1e-7);
        assert_eq!(
            MaxwellChain::fit(&s, [2.0, 1800.0]),
            MaxwellChain::fit_uncached(&s, [2.0, 1800.0], &[])
        );
        assert_ne!(
            MaxwellChain::fit(&s, [2.0, 1800.0]),
            MaxwellChain::fit(&s, band)
        );
    }
}
