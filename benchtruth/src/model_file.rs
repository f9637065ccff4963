//! The user's model file of a case (spec model-format.md), written by hand: the nominal
//! driveline, without the concealed effect, in torsim's keys. TOML is written by hand so
//! that the bench shares no serialisation with torsim either.

use crate::driveline::{Driveline, Kind};
use std::fmt::Write as _;

/// `a, b, c`: a TOML array's inside.
pub(crate) fn list(xs: &[f64]) -> String {
    xs.iter()
        .map(|x| format!("{x}"))
        .collect::<Vec<_>>()
        .join(", ")
}

/// The model file of `d` (spec model-format.md).
pub fn model_toml(d: &Driveline, lo_rpm: f64, hi_rpm: f64) -> String {
    let mut s = format!(
        "format = 1\nname = \"{}\"\ndescription = \"Written by benchtruth from the bench's nominal data.\"\n",
        d.name
    );
    for n in &d.nodes {
        let _ = write!(
            s,
            "\n[[inertia]]\nname = \"{}\"\ninertia = {:e}\n",
            n.name, n.inertia_kg_m2
        );
        if n.damping_nm_s > 0.0 {
            let _ = writeln!(s, "damping = {:e}", n.damping_nm_s);
        }
    }
    for c in &d.connections {
        let (from, to) = (&d.nodes[c.from].name, &d.nodes[c.to].name);
        let _ = write!(
            s,
            "\n[[connection]]\nname = \"{}\"\nfrom = \"{from}\"\nto = \"{to}\"\n",
            c.name
        );
        let _ = match c.kind {
            Kind::Shaft { stiffness, damping } => writeln!(
                s,
                "kind = \"shaft\"\nstiffness = {stiffness:e}\ndamping = {damping:e}"
            ),
            Kind::Rubber { stiffness, psi } => writeln!(
                s,
                "kind = \"rubber\"\nstiffness = {stiffness:e}\npsi = {psi:e}"
            ),
            Kind::Gear {
                ratio,
                mesh_stiffness,
                ..
            } => writeln!(
                s,
                "kind = \"gear\"\nratio = {ratio}\nmesh_stiffness = {mesh_stiffness:e}"
            ),
        };
    }
    let e = &d.engine;
    let _ = write!(
        s,
        "\n[engine]\nat = \"{}\"\ncylinders = {}\nstrokes = 4\nfiring_angles_deg = [{}]\nbore = {}\ncrank_radius = {}\nconrod_length = {}\nreciprocating_mass = {}\npressure_by_load = [\n",
        d.nodes[e.node].name,
        e.firing_deg.len(),
        list(&e.firing_deg),
        e.bore_m,
        e.crank_radius_m,
        e.conrod_m,
        e.reciprocating_kg
    );
    for p in &e.pressure {
        let _ = writeln!(
            s,
            "  {{ load = {}, crank_angle_deg = [{}], bar = [{}] }},",
            p.load,
            list(&p.angle_deg),
            list(&p.bar)
        );
    }
    let _ = write!(
        s,
        "]\n\n[load]\nat = \"{}\"\ndamping = {:e}\n\n[operation]\nspeed_range_rpm = [{lo_rpm}, {hi_rpm}]\n",
        d.nodes[d.load_node].name, d.load_damping_nm_s
    );
    s
}
