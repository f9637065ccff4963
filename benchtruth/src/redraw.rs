//! A seed's case is one a bench could record. A drawn truth whose friction state
//! diverges, or whose engine or brake would turn backwards through a resonance, is no
//! campaign a test engineer could hand over: the engine would stall, the run would be
//! stopped. Such a draw is set aside and the seed drawn again on fresh random streams
//! ([`crate::draw::stream`]); draw 0 is the case every earlier build drew, so a seed that
//! ran before gives the same case. The set-aside draws and why are kept in `truth.toml`
//! (`draw`, `redrawn_because`), and `results.csv` has the draw per case.
//!
//! Published runs 5–12 lost 1–3 of every 110 cases this way as "bench errors" (the
//! twelfth: 101117's Dahl truth diverged; in 101132 and 101161 the crank turned
//! backwards): cases of the bench, not of the diagnosis.
//!
//! A draw whose campaign cannot show its effect is drawn again too (from 2026-12-05):
//! no order amplitude of any recording moves by [`MIN_VISIBLE_Z`] of its uncertainty
//! when the effect is taken out of the truth ([`crate::visibility`]). No diagnosis can
//! name what the recordings do not hold; such a case measured the bench, not the
//! diagnosis. The last draw of a seed is kept whatever its visibility, with it written
//! in `truth.toml`, so that every seed still gives a case.

use crate::draw::draw_attempt;
use crate::visibility::MIN_VISIBLE_Z;
use crate::write::{CaseFiles, WriteError, simulate_case, write_simulated};
use std::path::Path;

/// How many draws of a seed [`write_case`] tries before the seed counts as a bench error.
pub const MAX_DRAWS: u64 = 4;

/// Draws the case of `seed` (class forced or `seed mod 11`) and writes it into `dir`; a
/// draw no bench could run, or whose campaign cannot show its effect, is drawn again, up
/// to [`MAX_DRAWS`] times. Nothing is written for a draw set aside, nor when every draw
/// fails.
pub fn write_case(seed: u64, class: Option<&str>, dir: &Path) -> Result<CaseFiles, WriteError> {
    let mut unusable: Vec<String> = Vec::new();
    for attempt in 0..MAX_DRAWS {
        let case = draw_attempt(seed, class, attempt).map_err(WriteError::Draw)?;
        match simulate_case(&case) {
            Ok(simulated) => {
                let meters: Vec<_> = simulated.iter().map(|s| s.orders.clone()).collect();
                let visibility = crate::visibility::measure(&case, &meters);
                if let Some(v) = &visibility
                    && v.z_max < MIN_VISIBLE_Z
                    && attempt + 1 < MAX_DRAWS
                {
                    unusable.push(format!(
                        "seed {seed} draw {attempt}: the campaign cannot show its effect (largest \
                         change of an order amplitude z = {:.2} < {MIN_VISIBLE_Z}, at {})",
                        v.z_max, v.at
                    ));
                    continue;
                }
                return write_simulated(&case, simulated, visibility, &unusable, dir);
            }
            Err(WriteError::Unusable(why)) => unusable.push(why),
            Err(e) => return Err(e),
        }
    }
    Err(WriteError::Draw(format!(
        "seed {seed}: no bench could run any of its {MAX_DRAWS} draws ({}); the case counts \
         as a bench error",
        unusable.join("; ")
    )))
}

#[cfg(test)]
mod tests {
    use crate::draw::{draw_attempt, draw_case};

    /// Draw 0 is the case every earlier build drew; a redraw is another case of the same
    /// class on other streams.
    #[test]
    fn draw_zero_is_the_old_case_and_a_redraw_is_another() {
        for seed in [2000_u64, 2010, 2017] {
            let old = draw_case(seed, None).expect("draw 0");
            let zero = draw_attempt(seed, None, 0).expect("draw 0 again");
            let one = draw_attempt(seed, None, 1).expect("draw 1");
            assert_eq!(format!("{old:?}"), format!("{zero:?}"));
            assert_eq!(one.class, old.class);
            assert_eq!(one.attempt, 1);
            assert_ne!(format!("{:?}", one.truth), format!("{:?}", old.truth));
        }
    }
}
