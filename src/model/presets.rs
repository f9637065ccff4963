//! Presets shipped inside the binary (stub).
