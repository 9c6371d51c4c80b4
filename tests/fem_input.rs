//! Input parsing and rejection of bad input: every case is a clear error naming the field.

// Native #[test]s only (wasm32 runs just the wasm_bindgen_test suites): compiled out there,
// so `wasm-pack test` does not build this file for nothing.
#![cfg(not(target_arch = "wasm32"))]

use wingbeat::fem::*;
use wingbeat::WingbeatError;

fn small(planform: Vec<[f64; 2]>) -> FemInput {
    FemInput {
        planform_mm: planform,
        mesh_size_mm: Some(5.0),
        n_modes: 2,
        ..FemInput::default()
    }
}

fn field_of(e: &WingbeatError) -> String {
    match e {
        WingbeatError::InvalidInput { field, .. } | WingbeatError::ResourceCap { field, .. } => {
            field.clone()
        }
        other => format!("{other}"),
    }
}

#[test]
fn csv_and_json_parsing() {
    let a = parse_planform_csv("# note\nx_mm,y_mm\n0,0\n1,0\n1,1\n").unwrap();
    let b = parse_planform_csv("i,x_mm,y_mm\n0,0,0\n1,1,0\n\n2,1,1\n").unwrap();
    let c = parse_planform_json("[[0,0],[1,0],[1,1]]").unwrap();
    assert_eq!(a, vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0]]);
    assert_eq!(a, b);
    assert_eq!(a, c);
    assert!(matches!(
        parse_planform_csv("x_mm,y_mm\n0,zero\n"),
        Err(WingbeatError::Parse { .. })
    ));
    assert!(matches!(
        parse_planform_csv("foo,bar\n1,2\n"),
        Err(WingbeatError::Parse { .. })
    ));
    assert!(matches!(
        parse_planform_csv("x_mm,y_mm\n1,2,3\n"),
        Err(WingbeatError::Parse { .. })
    ));
    assert!(matches!(
        parse_planform_json("{\"a\":1}"),
        Err(WingbeatError::Parse { .. })
    ));
    let m = manduca_planform();
    assert_eq!(m.len(), 39);
    assert_eq!(m[0], [0.0, -4.0]);
    assert_eq!(*m.last().unwrap(), [0.0, 0.0]);
}

#[test]
fn input_json_round_trip_and_clamp_parse() {
    let d = FemInput::default();
    let s = serde_json::to_string(&d).unwrap();
    let back: FemInput = serde_json::from_str(&s).unwrap();
    assert_eq!(back, d);
    let partial: FemInput =
        serde_json::from_str(r#"{"n_modes": 3, "clamp": {"strip": {"x_mm": 2.5}}}"#).unwrap();
    assert_eq!(partial.n_modes, 3);
    assert_eq!(partial.clamp, Clamp::Strip { x_mm: 2.5 });
    assert_eq!(Clamp::parse("root").unwrap(), Clamp::Root);
    assert_eq!(Clamp::parse("strip:3").unwrap(), Clamp::Strip { x_mm: 3.0 });
    assert!(Clamp::parse("pinned").is_err());
    assert!(Clamp::parse("strip:abc").is_err());
}

/// Issue 13: an unknown field inside the clamp (or anywhere in the FE input) is refused, not
/// ignored.
#[test]
fn unknown_clamp_and_input_fields_are_refused() {
    for bad in [
        r#"{"clamp": {"strip": {"x_mm": 1.0, "extra": 2}}}"#,
        r#"{"clamp": {"strip": {"x": 1.0}}}"#,
        r#"{"clamp": "pinned"}"#,
        r#"{"material": {"e_pa": 1e9, "youngs": 1}}"#,
        r#"{"camber": 0.1, "chamber": 0.2}"#,
    ] {
        let e = serde_json::from_str::<FemInput>(bad).expect_err(bad);
        assert!(e.to_string().contains("unknown"), "{bad}: {e}");
    }
}

#[test]
fn bad_outlines_are_rejected() {
    let bowtie = vec![[0.0, 0.0], [10.0, -10.0], [10.0, 0.0], [0.0, -10.0]];
    assert!(matches!(
        compute_modes(&small(bowtie)),
        Err(WingbeatError::Geometry(_))
    ));
    let two = vec![[0.0, 0.0], [10.0, 0.0]];
    assert_eq!(
        field_of(&compute_modes(&small(two)).unwrap_err()),
        "planform"
    );
    let dup = vec![[0.0, 0.0], [0.0, 0.0], [0.0, 0.0]];
    assert_eq!(
        field_of(&compute_modes(&small(dup)).unwrap_err()),
        "planform"
    );
    let collinear = vec![[0.0, 0.0], [5.0, 0.0], [10.0, 0.0]];
    assert!(compute_modes(&small(collinear)).is_err());
    let nan = vec![[0.0, 0.0], [f64::NAN, -10.0], [10.0, 0.0]];
    assert_eq!(
        field_of(&compute_modes(&small(nan)).unwrap_err()),
        "planform[1][0]"
    );
    // outline not touching x = 0: Root clamp impossible, a strip still works
    let shifted: Vec<[f64; 2]> = rectangle_planform(30.0, 10.0)
        .iter()
        .map(|p| [p[0] + 5.0, p[1]])
        .collect();
    assert_eq!(
        field_of(&compute_modes(&small(shifted.clone())).unwrap_err()),
        "clamp"
    );
    let mut s = small(shifted);
    s.clamp = Clamp::Strip { x_mm: 8.0 };
    assert!(compute_modes(&s).is_ok());
    s.clamp = Clamp::Strip { x_mm: 1.0 };
    assert_eq!(field_of(&compute_modes(&s).unwrap_err()), "clamp.x_mm");
    s.clamp = Clamp::Strip { x_mm: 100.0 };
    assert_eq!(field_of(&compute_modes(&s).unwrap_err()), "clamp.x_mm");
    // a closing duplicate point and clockwise order are accepted
    let mut cw = rectangle_planform(30.0, 10.0);
    cw.reverse();
    cw.push(cw[0]);
    assert!(compute_modes(&small(cw)).is_ok());
}

/// A change applied to a valid input.
type Edit = Box<dyn Fn(&mut FemInput)>;

#[test]
fn bad_material_and_sizes_are_rejected() {
    let base = small(rectangle_planform(30.0, 10.0));
    let cases: Vec<(&str, Edit)> = vec![
        (
            "material.thickness_m",
            Box::new(|i| i.material.thickness_m = 0.0),
        ),
        ("material.e_pa", Box::new(|i| i.material.e_pa = -1.0)),
        (
            "material.rho_kg_m3",
            Box::new(|i| i.material.rho_kg_m3 = f64::INFINITY),
        ),
        ("material.nu", Box::new(|i| i.material.nu = 0.5)),
        ("material.nu", Box::new(|i| i.material.nu = -1.0)),
        ("camber", Box::new(|i| i.camber = -0.1)),
        ("n_modes", Box::new(|i| i.n_modes = 0)),
        ("n_modes", Box::new(|i| i.n_modes = 1000)),
        ("mesh_size_mm", Box::new(|i| i.mesh_size_mm = Some(0.0))),
        (
            "mesh_size_mm",
            Box::new(|i| i.mesh_size_mm = Some(f64::NAN)),
        ),
        // would need ≈ 7 million nodes: refused before meshing, quickly
        ("mesh_size_mm", Box::new(|i| i.mesh_size_mm = Some(0.01))),
    ];
    for (field, f) in cases {
        let mut i = base.clone();
        f(&mut i);
        let t = std::time::Instant::now();
        let e = compute_modes(&i).unwrap_err();
        assert_eq!(field_of(&e), field, "{e}");
        assert!(t.elapsed().as_secs_f64() < 1.0);
    }
}
