//! Every numeric option of every subcommand takes every float syntax: signs, exponents with
//! and without a sign, a leading or trailing dot, and comma-separated lists that start with a
//! negative number. clap used to answer `-1e-3`, `-.5`, `-1E+2` and `-1,2` with "unexpected
//! argument '-1'" (its negative-number test knows only `-1`, `-1.5`, `-1e5`); a value may be
//! out of range, but it must reach the option's own parser and range check.
//!
//! The options are found from `--help` (so a new option is covered without editing this
//! file) and classed by probing: an option whose parser refuses `abc` as a number is numeric.
// Runs the CLI binary: native only.
#![cfg(not(target_arch = "wasm32"))]

mod common_cli;
use common_cli::run;

/// Float syntaxes Rust's `f64` parser accepts, negative ones first.
const FLOATS: &[&str] = &[
    "-1e-3",
    "-1E+2",
    "-1e2",
    "-.5",
    "-5.",
    "-0.5",
    "-1",
    "-0",
    "+.5",
    "+1e-3",
    "1e-3",
    ".5",
    "5.",
    "1E+2",
    "2.5e-1",
    "-1.5E-300",
    "-1e308",
];
/// Lists for the comma-separated options (three entries, as `--body-rate` wants).
const LISTS: &[&str] = &[
    "-1,2,3",
    "-1e-3,-.5,-1E+2",
    "1,-2,-3",
    "-.5,+.5,5.",
    "-0,0,-0",
];
/// Integer syntaxes `usize`/`u32` parse.
const INTS: &[&str] = &["3", "+3", "07"];

/// The subcommands named in `wingbeat --help`.
fn subcommands() -> Vec<String> {
    let (_, out, _) = run(&["--help"]);
    let mut subs = Vec::new();
    let mut in_cmds = false;
    for line in out.lines() {
        if line.starts_with("Commands:") {
            in_cmds = true;
            continue;
        }
        if in_cmds {
            if !line.starts_with("  ") {
                break;
            }
            let name = line.split_whitespace().next().unwrap_or("");
            if !name.is_empty() && name != "help" {
                subs.push(name.to_string());
            }
        }
    }
    subs
}

/// The options of `wingbeat SUB` that take a value.
fn value_options(sub: &str) -> Vec<String> {
    let (_, out, _) = run(&[sub, "--help"]);
    out.lines()
        .filter_map(|l| {
            let t = l.trim_start();
            let t = t.strip_prefix("-").map_or(t, |_| {
                // `-h, --help` style: take the long name
                t.split_once(", ").map_or(t, |(_, r)| r)
            });
            let name = t.strip_prefix("--")?;
            let (name, rest) = name.split_once(' ')?;
            rest.trim_start()
                .starts_with('<')
                .then(|| format!("--{name}"))
        })
        .collect()
}

/// Arguments that make `SUB` stop right after parsing, with its own error (not clap's), so
/// that an accepted value costs no computation.
fn stop_early(sub: &str) -> Vec<&'static str> {
    match sub {
        "modes" => vec!["--material", "no-such-material"],
        "render" => vec!["--mesh", "/nonexistent/wingbeat-mesh.json"],
        "reproduce" => vec!["--format", "text"],
        _ => vec!["--preset", "no-such-preset"],
    }
}

fn args_for<'a>(sub: &'a str, opt: &'a str, v: &'a str) -> Vec<&'a str> {
    let mut a = vec![sub];
    if sub == "sweep" {
        a.push("gamma0");
    }
    a.extend([opt, v]);
    a.extend(stop_early(sub));
    a
}

/// clap's own refusals (its messages quote the value: ``invalid value 'abc' for '--x <X>'``);
/// wingbeat's say ``invalid value for `--x` ``.
fn clap_refused(err: &str, v: &str) -> bool {
    err.contains("unexpected argument")
        || err.contains(&format!("invalid value '{v}'"))
        || err.contains("a value is required")
}

#[derive(Debug, PartialEq)]
enum Kind {
    Float,
    FloatList,
    Int,
    Other,
}

fn kind_of(sub: &str, opt: &str) -> Kind {
    let (_, _, err) = run(&args_for(sub, opt, "abc"));
    if !err.contains("invalid value 'abc'") {
        return Kind::Other;
    }
    if err.contains("invalid float literal") {
        let (_, _, e2) = run(&args_for(sub, opt, "1,2,3"));
        if e2.contains("invalid value '1,2,3'") {
            Kind::Float
        } else {
            Kind::FloatList
        }
    } else if err.contains("invalid digit") {
        Kind::Int
    } else {
        Kind::Other
    }
}

#[test]
fn every_numeric_option_takes_every_float_syntax() {
    let subs = subcommands();
    for s in ["simulate", "psd", "sweep", "modes", "sense"] {
        assert!(subs.iter().any(|x| x == s), "{s} missing from {subs:?}");
    }
    let (mut floats, mut lists, mut ints, mut runs) = (0, 0, 0, 0);
    let mut failures = Vec::new();
    for sub in &subs {
        for opt in value_options(sub) {
            let kind = kind_of(sub, &opt);
            let (values, must_accept): (Vec<&str>, bool) = match kind {
                Kind::Float => {
                    floats += 1;
                    (FLOATS.to_vec(), true)
                }
                Kind::FloatList => {
                    lists += 1;
                    (FLOATS.iter().chain(LISTS).copied().collect(), true)
                }
                // integers: negative and fractional syntaxes reach the integer parser, which
                // refuses them naming the option (or accepts `-0`), never as an unexpected
                // argument
                Kind::Int => {
                    ints += 1;
                    for v in FLOATS.iter().chain(LISTS) {
                        let (_, _, err) = run(&args_for(sub, &opt, v));
                        runs += 1;
                        let parser_refused = err.contains(&format!("invalid value '{v}'"));
                        if err.contains("unexpected argument")
                            || (parser_refused && !err.contains(&opt))
                        {
                            failures.push(format!("{sub} {opt} {v}: {err}"));
                        }
                    }
                    (INTS.to_vec(), true)
                }
                Kind::Other => continue,
            };
            for v in values {
                let a = args_for(sub, &opt, v);
                let (code, _, err) = run(&a);
                runs += 1;
                if must_accept && clap_refused(&err, v) {
                    failures.push(format!("{a:?} (exit {code}): {err}"));
                }
                // `--opt=value` is the same value
                let eq = format!("{opt}={v}");
                let mut a2 = vec![sub.as_str()];
                if sub == "sweep" {
                    a2.push("gamma0");
                }
                a2.push(&eq);
                a2.extend(stop_early(sub));
                let (_, _, err2) = run(&a2);
                runs += 1;
                if clap_refused(&err2, v) {
                    failures.push(format!("{a2:?}: {err2}"));
                }
            }
        }
    }
    // the options this crate has today (a lower bound, so that the discovery cannot silently
    // find nothing): simulate's alpha0 … sample_rate, psd's overlap, sweep's from/to, modes'
    // camber … mesh_size_mm, sense's noise/rho; lists: body_rate, q0, qdot0
    assert!(floats >= 25, "found {floats} float options");
    assert!(lists >= 12, "found {lists} list options");
    assert!(ints >= 10, "found {ints} integer options");
    assert!(
        failures.is_empty(),
        "{} of {runs} runs refused by the parser:\n{}",
        failures.len(),
        failures.join("\n")
    );
}

/// The options whose value is text with numbers inside (`--points X,Y;…`, `--point NAME:X,Y`,
/// `--clamp strip:X`): negative and exponent forms reach their own parsers too.
#[test]
fn text_options_with_numbers_take_negative_and_exponent_forms() {
    for (a, field) in [
        (
            vec![
                "sense",
                "--points",
                "-1e-3,-.5;3,-6",
                "--preset",
                "no-such-preset",
            ],
            "--preset",
        ),
        (
            vec!["sense", "--points", "-1,2", "--noise", "-1E+2"],
            "--noise",
        ),
        (
            vec!["modes", "--point", "-P:-1e-3,-.5", "--material", "nope"],
            "--material",
        ),
        (
            vec!["modes", "--clamp", "-1E+2", "--material", "nope"],
            "--clamp",
        ),
    ] {
        let (code, _, err) = run(&a);
        assert_eq!(code, 2, "{a:?}: {err}");
        assert!(!err.contains("unexpected argument"), "{a:?}: {err}");
        assert!(
            err.contains(field),
            "{a:?} should be refused naming {field}: {err}"
        );
    }
}

/// A valid negative value in exponent form is used, not only parsed: `--zeta -1e-3` gets the
/// range error of ζ (≥ 0), `--q0 -1e-3,-2E-3` runs and starts both modes there.
#[test]
fn negative_exponent_values_reach_the_run() {
    let (code, _, err) = run(&["simulate", "--zeta", "-1e-3"]);
    assert_eq!(code, 2);
    assert!(err.contains("zeta") && err.contains("allowed"), "{err}");
    let (code, out, err) = run(&[
        "simulate",
        "--q0",
        "-1e-3,-2E-3",
        "--duration",
        "1e-2",
        "--format",
        "csv",
    ]);
    assert_eq!(code, 0, "{err}");
    let row: Vec<f64> = out
        .lines()
        .nth(1)
        .unwrap()
        .split(',')
        .map(|v| v.parse().unwrap())
        .collect();
    // columns: t, then per mode euler, centrifugal, coriolis, free, total, qdot
    assert!((row[4] - -1e-3).abs() < 1e-15, "{row:?}");
    assert!((row[10] - -2e-3).abs() < 1e-15, "{row:?}");
}
