//! A small reader of the wasm API's TypeScript declarations (`TS_TYPES` in src/wasm/types.rs):
//! the top-level keys of each `export interface`, for the drift tests (tests/ts_types.rs
//! natively against the serde types, tests/wasm_common against the objects the API returns).
#![allow(dead_code)]

use std::collections::BTreeMap;

/// The TypeScript text of `TS_TYPES` in src/wasm/types.rs (the raw string literal).
pub fn declarations() -> &'static str {
    let file = include_str!("../../src/wasm/types.rs");
    let start = file.find("r#\"").expect("TS_TYPES raw string") + 3;
    let len = file[start..].find("\"#").expect("end of TS_TYPES");
    &file[start..start + len]
}

/// One declared key: its name and whether it is optional (`key?:`).
#[derive(Debug, Clone, PartialEq, Eq, PartialOrd, Ord)]
pub struct Key {
    /// The key.
    pub name: String,
    /// Declared with `?:`.
    pub optional: bool,
}

fn strip_comments(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let mut rest = text;
    while let Some(i) = rest.find("/*") {
        out.push_str(&rest[..i]);
        match rest[i..].find("*/") {
            Some(j) => rest = &rest[i + j + 2..],
            None => {
                rest = "";
                break;
            }
        }
    }
    out.push_str(rest);
    out.lines()
        .map(|l| match l.find("//") {
            Some(i) => &l[..i],
            None => l,
        })
        .collect::<Vec<_>>()
        .join("\n")
}

/// `interface name → its top-level keys`, for every `export interface` in `ts`.
pub fn interfaces(ts: &str) -> BTreeMap<String, Vec<Key>> {
    let text = strip_comments(ts);
    let mut out = BTreeMap::new();
    let mut rest = text.as_str();
    while let Some(i) = rest.find("export interface ") {
        rest = &rest[i + "export interface ".len()..];
        let name: String = rest
            .chars()
            .take_while(|c| c.is_alphanumeric() || *c == '_')
            .collect();
        let open = rest.find('{').expect("interface body");
        let body_start = open + 1;
        let mut depth = 1;
        let mut end = body_start;
        for (k, c) in rest[body_start..].char_indices() {
            match c {
                '{' | '[' | '(' => depth += 1,
                '}' | ']' | ')' => {
                    depth -= 1;
                    if depth == 0 {
                        end = body_start + k;
                        break;
                    }
                }
                _ => {}
            }
        }
        out.insert(name, top_level_keys(&rest[body_start..end]));
        rest = &rest[end..];
    }
    out
}

/// Keys at depth 0 of an interface body: `ident:` or `ident?:` after `{`, `;`, `,` or a
/// line start.
fn top_level_keys(body: &str) -> Vec<Key> {
    let mut keys = Vec::new();
    let mut depth = 0;
    let mut in_str = false;
    let mut expect_key = true;
    let chars: Vec<char> = body.chars().collect();
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        if in_str {
            if c == '"' {
                in_str = false;
            }
            i += 1;
            continue;
        }
        match c {
            '"' => in_str = true,
            '{' | '[' | '(' | '<' => depth += 1,
            '}' | ']' | ')' | '>' => depth -= 1,
            ';' | '\n' if depth == 0 => expect_key = true,
            c if depth == 0 && expect_key && (c.is_alphabetic() || c == '_') => {
                let start = i;
                while i < chars.len() && (chars[i].is_alphanumeric() || chars[i] == '_') {
                    i += 1;
                }
                let name: String = chars[start..i].iter().collect();
                let optional = chars.get(i) == Some(&'?');
                if optional {
                    i += 1;
                }
                if chars.get(i) == Some(&':') {
                    keys.push(Key { name, optional });
                }
                expect_key = false;
                continue;
            }
            _ => {}
        }
        i += 1;
    }
    keys
}

/// Checks that the keys an object actually has (`present`) agree with interface `name`:
/// every present key is declared, every required declared key is present. Panics with both
/// lists otherwise.
pub fn check(ifaces: &BTreeMap<String, Vec<Key>>, name: &str, present: &[String]) {
    let declared = ifaces
        .get(name)
        .unwrap_or_else(|| panic!("no `export interface {name}` in the TS declarations"));
    let undeclared: Vec<&String> = present
        .iter()
        .filter(|p| !declared.iter().any(|k| &k.name == *p))
        .collect();
    let missing: Vec<&str> = declared
        .iter()
        .filter(|k| !k.optional && !present.contains(&k.name))
        .map(|k| k.name.as_str())
        .collect();
    assert!(
        undeclared.is_empty() && missing.is_empty(),
        "TS `{name}` drifted: keys not declared {undeclared:?}, declared keys missing {missing:?} \
         (declared {declared:?}, present {present:?})"
    );
}
