//! What the lab's "your own wing" path relies on: the node cap (checked after meshing, before
//! assembly, naming a size that fits), the automatic mesh size, the default strain point
//! (inside any valid outline) and the `wingbeat modes` document built in one place.

// Native #[test]s only (wasm32 runs just the wasm_bindgen_test suites): compiled out there,
// so `wasm-pack test` does not build this file for nothing.
#![cfg(not(target_arch = "wasm32"))]

use wingbeat::fem::*;
use wingbeat::WingbeatError;

/// A few valid outlines that are not the default one (mm): a rectangle, a clockwise
/// slender wing, a concave (notched) outline, a triangle and an outline that does not touch
/// x = 0.
fn outlines() -> Vec<(&'static str, Vec<[f64; 2]>)> {
    let mut slender = vec![
        [0.0, -8.0],
        [40.0, -6.0],
        [42.0, -2.0],
        [40.0, 0.0],
        [0.0, 0.0],
    ];
    slender.reverse();
    vec![
        ("rectangle", rectangle_planform(30.0, 10.0)),
        ("slender, clockwise", slender),
        (
            "notched",
            vec![
                [0.0, -10.0],
                [30.0, -10.0],
                [30.0, 0.0],
                [12.0, 0.0],
                [8.0, -7.0],
                [4.0, 0.0],
                [0.0, 0.0],
            ],
        ),
        ("triangle", vec![[0.0, -12.0], [25.0, 0.0], [0.0, 0.0]]),
        (
            "shifted",
            rectangle_planform(30.0, 10.0)
                .iter()
                .map(|p| [p[0] + 5.0, p[1] - 3.0])
                .collect(),
        ),
    ]
}

fn input(planform: Vec<[f64; 2]>, clamp: Clamp) -> FemInput {
    FemInput {
        planform_mm: planform,
        planform_note: "test outline".into(),
        clamp,
        n_modes: 2,
        mesh_size_mm: Some(2.5),
        ..FemInput::default()
    }
}

#[test]
fn node_cap_is_checked_after_meshing_and_names_a_size_that_fits() {
    let mut i = FemInput {
        mesh_size_mm: Some(0.5),
        max_nodes: Some(2000),
        ..FemInput::default()
    };
    let t = std::time::Instant::now();
    let e = compute_modes(&i).unwrap_err();
    let msg = e.to_string();
    println!("{msg}");
    // refused by the mesher, long before a 6 000-node solve could finish
    assert!(t.elapsed().as_secs_f64() < 5.0);
    let WingbeatError::ResourceCap {
        field,
        requested,
        cap,
        why,
    } = &e
    else {
        panic!("not a cap error: {e}")
    };
    assert_eq!(field, "mesh_size_mm");
    assert!(
        requested.contains("0.5 mm") && requested.contains("nodes"),
        "{requested}"
    );
    assert_eq!(cap, "2000 nodes");
    // the suggested size: "… a mesh size of about H mm would fit"
    let h: f64 = why
        .split("about ")
        .nth(1)
        .and_then(|s| s.split(' ').next())
        .and_then(|s| s.parse().ok())
        .unwrap_or_else(|| panic!("no size in `{why}`"));
    assert!(h > 0.5 && h < 2.0, "{h}");
    i.mesh_size_mm = Some(h);
    let (_, mesh, used) = mesh_input(&i).expect("the suggested size fits");
    assert_eq!(used, h);
    assert!(mesh.nodes.len() <= 2000 && mesh.nodes.len() > 500);
    // a size whose estimate fits but whose mesh does not (the grading toward the root adds
    // nodes; 1 653 nodes): refused by the mesher (its refinement stops at the cap)
    let j = FemInput {
        mesh_size_mm: Some(1.0),
        max_nodes: Some(1400),
        ..FemInput::default()
    };
    let e = compute_modes(&j).unwrap_err().to_string();
    assert!(
        e.contains("1 mm (more than")
            && e.contains("cap of 1400 nodes")
            && e.contains("about 1.2 mm"),
        "{e}"
    );
    // the cap itself is checked
    for bad in [0, MAX_NODES + 1] {
        i.max_nodes = Some(bad);
        let e = compute_modes(&i).unwrap_err();
        assert!(e.to_string().contains("max_nodes"), "{e}");
    }
    const { assert!(BROWSER_MAX_NODES < MAX_NODES) };
}

#[test]
fn automatic_mesh_size_follows_the_planform() {
    assert_eq!(
        default_mesh_size_mm(&manduca_planform()),
        DEFAULT_MESH_SIZE_MM
    );
    // scale invariance: the size scales with the outline (to the two digits kept)
    let r = rectangle_planform(40.0, 10.0);
    let big: Vec<[f64; 2]> = r.iter().map(|p| [p[0] * 250.0, p[1] * 250.0]).collect();
    let (h, hb) = (default_mesh_size_mm(&r), default_mesh_size_mm(&big));
    assert_eq!(h, 0.68);
    assert!((hb / h / 250.0 - 1.0).abs() < 0.01, "{h} {hb}");
    assert_eq!(
        default_mesh_size_mm(&rectangle_planform(10_000.0, 10_000.0)),
        340.0
    );
    assert!(default_mesh_size_mm(&[[0.0, 0.0], [1.0, 0.0], [2.0, 0.0]]).is_nan());
    // the node count of an automatic mesh stays near the target whatever the size
    for (name, o) in outlines() {
        let mut i = input(o, Clamp::Strip { x_mm: 6.0 });
        i.mesh_size_mm = None;
        let (_, mesh, h) = mesh_input(&i).unwrap();
        println!("{name}: auto {h} mm, {} nodes", mesh.nodes.len());
        assert!(
            mesh.nodes.len() > 800 && mesh.nodes.len() < 3000,
            "{name}: {}",
            mesh.nodes.len()
        );
    }
    // an automatic size that would exceed the cap is coarsened instead of failing
    let i = FemInput {
        max_nodes: Some(400),
        n_modes: 2,
        ..FemInput::default()
    };
    let (_, mesh, h) = mesh_input(&i).unwrap();
    assert!(h > DEFAULT_MESH_SIZE_MM && mesh.nodes.len() <= 400, "{h}");
}

#[test]
fn default_strain_point_is_p_on_the_default_outline_and_inside_any_other() {
    assert_eq!(
        default_strain_point_mm(&manduca_planform()),
        STRAIN_POINT_P_MM
    );
    assert_eq!(strain_point_for(&FemInput::default()), STRAIN_POINT_P_MM);
    for (name, o) in outlines() {
        let touches_root = o.iter().filter(|p| p[0] == 0.0).count() >= 2;
        let clamps = if touches_root {
            vec![Clamp::Root, Clamp::Strip { x_mm: 4.0 }]
        } else {
            vec![Clamp::Strip { x_mm: 9.0 }]
        };
        for clamp in clamps {
            let i = input(o.clone(), clamp);
            let (x, y) = strain_point_for(&i);
            let fe = compute_modes(&i).unwrap();
            let e = fe.strain_at(0, x, y);
            println!("{name} {clamp:?}: P = ({x:.3}, {y:.3}) mm, {e:?}");
            let e = e.unwrap_or_else(|err| panic!("{name} {clamp:?}: {err}"));
            // off the clamped strip: the point strains
            if let Clamp::Strip { x_mm } = clamp {
                assert!(x > x_mm, "{name}: {x}");
            }
            assert!(e.iter().any(|v| v.abs() > 0.0));
            fe.model_modes(0.0, &[("P".into(), x, y)], "point").unwrap();
        }
        let (x, y) = default_strain_point_mm(&o);
        assert!(
            compute_modes(&input(o.clone(), Clamp::Free))
                .map(|fe| fe.strain_at(0, x, y).is_ok())
                .unwrap_or(true),
            "{name}"
        );
    }
}

#[test]
fn modes_document_carries_the_modes_and_the_mesh_size() {
    let i = FemInput {
        n_modes: 2,
        mesh_size_mm: Some(3.0),
        ..FemInput::default()
    };
    let fe = compute_modes(&i).unwrap();
    assert_eq!(fe.mesh_size_mm, 3.0);
    let (x, y) = strain_point_for(&i);
    let modes = fe
        .model_modes(0.02, &[("P".into(), x, y)], "point")
        .unwrap();
    let doc = modes_document(&fe, &modes).unwrap();
    let v: serde_json::Value = serde_json::from_str(&doc).unwrap();
    assert_eq!(v["mesh_size_mm"], 3.0);
    assert_eq!(v["units"]["mesh_size_mm"], "mm");
    // (serde_json reads floats back to within an ulp)
    let back: Vec<wingbeat::model::Mode> = serde_json::from_value(v["modes"].clone()).unwrap();
    assert_eq!(back.len(), modes.len());
    for (b, m) in back.iter().zip(&modes) {
        assert_eq!(b.name, m.name);
        assert!((b.freq_hz / m.freq_hz - 1.0).abs() < 1e-15);
        assert!((b.a[0] - m.a[0]).abs() <= 1e-15 * m.a[0].abs());
        assert!(
            (b.strains[0].eps_x - m.strains[0].eps_x).abs() <= 1e-14 * m.strains[0].eps_x.abs()
        );
    }
    let fe_back: FemModes = serde_json::from_value(v).unwrap();
    assert_eq!(fe_back.freq_hz, fe.freq_hz);
}

/// The mesh of an outline whose boundary points spade's constrained bulk loader inserts in one
/// pass (the default wing, with and without a strip line, and a notched outline) is the same
/// call after call. KNOWN OPEN BUG (docs/fem.md, "Pipeline"): an outline with several boundary
/// points at the same angle from the loader's starting centre (the straight edges of
/// www/examples/planform-tapered.csv) is not repeatable — spade 2.15.1 re-inserts those
/// skipped points in hash-set order (1585–1634 nodes over identical runs at the automatic
/// size, f1 within 0.05 %) — so it is not among these cases.
#[test]
fn meshing_the_same_outline_twice_gives_the_same_mesh() {
    let cases = [
        ("default wing", manduca_planform(), Some(1.0), Clamp::Root),
        (
            "default wing, strip",
            manduca_planform(),
            Some(1.0),
            Clamp::Strip { x_mm: 3.0 },
        ),
        ("notched", outlines()[2].1.clone(), None, Clamp::Root),
    ];
    let builtins = geometry::builtin_planforms()
        .into_iter()
        .map(|b| (b.id, b.points_mm, None, Clamp::Root));
    let cases: Vec<_> = cases.into_iter().chain(builtins).collect();
    for (name, planform, h, clamp) in cases {
        let input = FemInput {
            planform_mm: planform,
            mesh_size_mm: h,
            clamp,
            ..FemInput::default()
        };
        let (_, first, _) = mesh_input(&input).unwrap();
        for _ in 0..4 {
            let (_, again, _) = mesh_input(&input).unwrap();
            assert_eq!(again.nodes.len(), first.nodes.len(), "{name}");
            assert!(again.nodes == first.nodes, "{name}: node positions differ");
            assert!(
                again.triangles == first.triangles,
                "{name}: triangles differ"
            );
        }
        println!("{name}: {} nodes, repeatable", first.nodes.len());
    }
}
