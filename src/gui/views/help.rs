//! What each tab shows, in three sentences, for the "?" beside it (issue 16: the teacher's
//! question). Written for a student who knows rotating machinery but not yet torsional
//! vibration.

use crate::gui::app::Tab;

/// The explanation of `tab`.
pub fn tab_help(tab: Tab) -> &'static str {
    match tab {
        Tab::Campbell => {
            "The Campbell diagram plots each natural frequency of the driveline against \
             engine speed, with the engine orders as rays: order k is k times the \
             rotation frequency, and a four-stroke engine's cylinders fire at half orders \
             and their multiples. Where a ray meets a mode, that engine harmonic drives the \
             mode at resonance: a critical speed, bright for the major orders of the \
             firing. Click a crossing to see which mode it is and how strongly the order \
             drives it."
        }
        Tab::Modes => {
            "A mode is a way the driveline vibrates by itself at one natural frequency: \
             every inertia swings with the amplitude drawn along the shaft, in phase (same \
             sign) or against it. Where the shape crosses zero (a node) the shaft twists \
             most, and the strain-energy share names the connection that stores the mode: \
             changing that connection moves the mode most. Shapes are scaled to a largest \
             swing of 1; how large the vibration really is comes from the forced response."
        }
        Tab::Response => {
            "The steady vibration the engine's orders force at each speed, from the linear \
             model: IAS per station, torque per connection and each rubber stage's power \
             loss, order by order and summed. Peaks are the resonances of the Campbell \
             diagram, their height set by the damping. Where the twist or the IAS is large \
             the linear model is only a guide: check it in the Time traces."
        }
        Tab::Traces => {
            "The nonlinear time domain: a steady run at one speed or a run-up, with the \
             engine's crank-angle inertia, the rubber's amplitude, frequency and \
             temperature laws, and gear play. It streams in as it runs, and its orders and \
             spectrogram are taken from it the way a bench's recording is analysed. Open a \
             recording (File menu) to see measured and simulated together."
        }
        Tab::Diagnosis => {
            "Add bench recordings and press Diagnose: torsim simulates each recording's \
             regime, locates where model and bench differ, and fits the physics the model \
             may leave out. An effect is named only if it predicts recordings the fit did \
             not use (held-out χ²/N) better than a plain recalibration does. Accept puts \
             the fitted effect into the model as one undo step."
        }
    }
}
