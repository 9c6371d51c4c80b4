//! The lab side of issue 14 (sensing body rotation) against the core: the lab's body-rate
//! parameter (www/state.js `BODY_RATE`, `BODY_AXIS`) has the core's range
//! (`params::BODY_RATE_RANGES`, a constant component = `mean`), and the TypeScript
//! declarations of `senseRotation` (src/wasm/types.rs) name exactly the serde keys of the core
//! types they carry (`Sensor`, `SensingOptions`, `BodyRateRange`).
#![cfg(not(target_arch = "wasm32"))]

mod ts_common;

use serde::Serialize;
use serde_json::Value;
use wingbeat::analysis::sensing::{SensingOptions, Sensor};
use wingbeat::params::{body_rate_range, BODY_RATE_RANGES};

fn keys<T: Serialize>(v: &T) -> Vec<String> {
    match serde_json::to_value(v).unwrap() {
        Value::Object(m) => m.keys().cloned().collect(),
        other => panic!("not an object: {other}"),
    }
}

/// The value of `name: <number>` in a piece of JS text.
fn num_in(line: &str, name: &str) -> f64 {
    let at = line
        .find(&format!("{name}: "))
        .unwrap_or_else(|| panic!("`{name}:` in {line}"));
    let rest = &line[at + name.len() + 2..];
    let end = rest
        .find(|c: char| !(c.is_ascii_digit() || "-+.eE".contains(c)))
        .unwrap_or(rest.len());
    rest[..end]
        .parse()
        .unwrap_or_else(|e| panic!("{name} in {line}: {e}"))
}

#[test]
fn lab_body_rate_range_is_the_cores() {
    let js = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/www/state.js"))
        .expect("www/state.js");
    // The whole statement, however the formatter lays it out over lines.
    let statement = |name: &str| -> String {
        let at = js
            .find(&format!("export const {name} = "))
            .unwrap_or_else(|| panic!("{name} in www/state.js"));
        let end = js[at..]
            .find("});")
            .unwrap_or_else(|| panic!("the end of {name}"));
        js[at..at + end].to_string()
    };
    let line = &statement("BODY_RATE");
    let mean = body_rate_range("mean");
    assert_eq!(num_in(line, "min"), mean.min, "{line}");
    assert_eq!(num_in(line, "max"), mean.max, "{line}");
    assert!(line.contains(&format!("unit: '{}'", mean.unit)), "{line}");
    let def = num_in(line, "def");
    assert!(mean.check("body_rate", def).is_ok());
    // the peak of a constant component is its magnitude: the same bound
    assert_eq!(body_rate_range("peak").max, mean.max);
    let axis = statement("BODY_AXIS");
    assert!(axis.contains("['x', 'y', 'z']"), "{axis}");
    assert_eq!(BODY_RATE_RANGES.len(), 5);
}

#[test]
fn sensing_declarations_match_serde() {
    let i = ts_common::interfaces(ts_common::declarations());
    let s = Sensor {
        rank: 1,
        node: 3,
        component: "gamma_xy".into(),
        x_mm: 1.0,
        y_mm: -2.0,
        d: 4.0,
    };
    ts_common::check(&i, "Sensor", &keys(&s));
    ts_common::check(&i, "SensingOptions", &keys(&SensingOptions::default()));
    ts_common::check(&i, "BodyRateRange", &keys(&BODY_RATE_RANGES[0]));
    for k in ["k_max", "rho", "noise", "samples_per_sensor", "point_mm"] {
        assert!(
            i["SenseOptions"].iter().any(|x| x.name == k && x.optional),
            "SenseOptions.{k}"
        );
    }
    for k in [
        "d_best", "sensors", "pd", "d_prime", "delta", "spectrum", "dq", "point_mm",
    ] {
        assert!(
            i["SensingResult"].iter().any(|x| x.name == k),
            "SensingResult.{k}"
        );
    }
}
