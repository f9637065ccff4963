//! The artifact gains measured through the order analysis ([`super::sensor_gain`]) agree
//! with the closed form ([`super::sensor::closed_form`]) where both apply: a station
//! turning with the reference (ratio 1), whose shaft orders are engine orders.

use super::LabelledRecording;
use super::observe::observe;
use super::sensor::{ArtifactForm, closed_form};
use super::sensor_gain::unit_gains;
use super::tests::steady;
use crate::recording::{Channel, ChannelKind};

/// A clean steady run of the crank at 3000 rpm with a second station, `out`, on the same
/// shaft (no sidecar lines: both sides assume 60).
fn two_stations() -> LabelledRecording {
    let mut rec = steady("A", 3000.0, 0.0, 0.0, 0.0, 1);
    let values = rec.recording.channels[0].values.clone();
    rec.recording.channels.push(Channel {
        column: "out_rpm".into(),
        kind: ChannelKind::SpeedRpm { node: "out".into() },
        values,
    });
    rec
}

#[test]
fn analysed_gains_match_the_closed_form_on_the_reference_shaft() {
    let recordings = [two_stations()];
    let observed = observe(&recordings, 8.0).expect("observed");
    let gains = unit_gains(&recordings, &observed, 8.0);
    for form in [ArtifactForm::TapeJoint, ArtifactForm::PitchError] {
        let of_out = gains
            .iter()
            .find(|g| g.station == "out" && g.form == form)
            .expect("gains of `out`");
        let mut compared = 0;
        for (o, g) in observed.observations.iter().zip(of_out.gains.iter()) {
            if o.station != "out" {
                assert_eq!(*g, 0.0, "a gain at another station");
                continue;
            }
            let exact = closed_form(form, 1.0, o.order, o.speed_rpm, 60.0);
            // 24 whole working cycles of a pure sum of shaft orders on an exact angle: the
            // synchronous average gives them back to round-off and interpolation, 1e-3 of
            // the largest (52 rpm for 1°, 100 rpm for a joint of one pitch).
            let scale = closed_form(form, 1.0, 1.0, o.speed_rpm, 60.0);
            assert!(
                (g - exact).abs() < 1e-3 * scale,
                "{form:?} order {}: analysed {g}, closed form {exact}",
                o.order
            );
            compared += 1;
        }
        assert!(compared >= 8, "{compared} orders compared");
    }
}
