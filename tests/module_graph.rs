//! The crate's module graph, read from the source: no import cycles, and every import points to
//! the same or a lower layer of the list in ARCHITECTURE.md.
//!
//! How it works. Every file under `src/` that `lib.rs` or `main.rs` reaches through `mod x;`
//! declarations is one node, named by its module path (`fem::mesh`;
//! `src/lib.rs` is `crate`, `src/main.rs` is `main`, the binary's own modules `cli`, `cli::sense`).
//! Each file is lexed (comments dropped; strings kept, since serde attributes name functions in
//! them) and every path that starts at `crate::`, `super::`, `self::`, `wingbeat::` (in the
//! binary) or a child module's name is resolved to the file that defines it, following `pub use`
//! re-exports (`crate::Result` is `error`). Grouped imports (`use crate::{a::b, c}`) are expanded
//! and inline `mod x { … }` blocks are followed for `super::`. Unit-test code (`#[cfg(test)]`
//! items) is not part of the graph. An edge A -> B means "A uses B". Tarjan's algorithm finds the
//! strongly connected components; any component of two or more files is a cycle and fails the
//! test, listing its files and the edges inside it. The layer list is the fenced ```` ```layers ````
//! block of ARCHITECTURE.md (top layer first; `x::*` stands for every submodule of `x`): every
//! file must be in exactly one layer and no edge may point to a higher layer.
#![cfg(not(target_arch = "wasm32"))]

use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

/// Which crate a file belongs to: the library (`src/lib.rs` and its modules) or the binary.
#[derive(Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Debug)]
enum Krate {
    Lib,
    Bin,
}

fn key(k: Krate, segs: &[String]) -> String {
    if segs.is_empty() {
        match k {
            Krate::Lib => "crate".into(),
            Krate::Bin => "main".into(),
        }
    } else {
        segs.join("::")
    }
}

#[derive(Clone, Debug, PartialEq)]
enum Tok {
    Ident(String),
    Path, // `::`
    Open,
    Close,
    Semi,
    Other(char),
}

/// Tokens of Rust source with comments removed. String and char literals become one
/// `Other('"')` followed by the tokens of their content with braces blanked, so paths written in
/// serde attributes (`deserialize_with = "crate::error::object_only"`) are still seen.
fn lex(src: &str) -> Vec<Tok> {
    let c: Vec<char> = src.chars().collect();
    let mut out = Vec::new();
    let mut i = 0;
    let n = c.len();
    let string_body = |body: &str, out: &mut Vec<Tok>| {
        out.push(Tok::Other('"'));
        let blanked: String = body
            .chars()
            .map(|ch| {
                if matches!(ch, '{' | '}' | ';' | '"' | '\'' | '/') {
                    ' '
                } else {
                    ch
                }
            })
            .collect();
        out.extend(lex(&blanked));
        out.push(Tok::Other('"'));
    };
    while i < n {
        let ch = c[i];
        if ch == '/' && i + 1 < n && c[i + 1] == '/' {
            while i < n && c[i] != '\n' {
                i += 1;
            }
        } else if ch == '/' && i + 1 < n && c[i + 1] == '*' {
            let mut depth = 0;
            while i < n {
                if c[i] == '/' && i + 1 < n && c[i + 1] == '*' {
                    depth += 1;
                    i += 2;
                } else if c[i] == '*' && i + 1 < n && c[i + 1] == '/' {
                    depth -= 1;
                    i += 2;
                    if depth == 0 {
                        break;
                    }
                } else {
                    i += 1;
                }
            }
        } else if ch == '"' || ((ch == 'r' || ch == 'b') && raw_string_start(&c, i).is_some()) {
            // "..." with escapes, or r#"..."# / br"..." with no escapes.
            if ch == '"' {
                let start = i + 1;
                i += 1;
                while i < n && c[i] != '"' {
                    if c[i] == '\\' {
                        i += 1;
                    }
                    i += 1;
                }
                let body: String = c[start..i.min(n)].iter().collect();
                string_body(&body, &mut out);
                i += 1;
            } else {
                let (hashes, body_start) = raw_string_start(&c, i).unwrap();
                let mut j = body_start;
                loop {
                    if j >= n {
                        break;
                    }
                    if c[j] == '"' && (0..hashes).all(|h| j + 1 + h < n && c[j + 1 + h] == '#') {
                        break;
                    }
                    j += 1;
                }
                let body: String = c[body_start..j.min(n)].iter().collect();
                string_body(&body, &mut out);
                i = j + 1 + hashes;
            }
        } else if ch == '\'' {
            // A char literal ('x', '\n', '\u{..}') or a lifetime ('a).
            if i + 1 < n && c[i + 1] == '\\' {
                let mut j = i + 2;
                while j < n && c[j] != '\'' {
                    j += 1;
                }
                i = j + 1;
                out.push(Tok::Other('\''));
            } else if i + 2 < n && c[i + 2] == '\'' {
                i += 3;
                out.push(Tok::Other('\''));
            } else {
                i += 1; // a lifetime: its name follows as an identifier
                out.push(Tok::Other('\''));
            }
        } else if ch.is_alphabetic() || ch == '_' {
            let start = i;
            while i < n && (c[i].is_alphanumeric() || c[i] == '_') {
                i += 1;
            }
            out.push(Tok::Ident(c[start..i].iter().collect()));
        } else if ch.is_ascii_digit() {
            while i < n && (c[i].is_alphanumeric() || c[i] == '_' || c[i] == '.') {
                // `1.0` and `1e-3`; a trailing `.` before a method is harmless here.
                if c[i] == '.' && !(i + 1 < n && c[i + 1].is_ascii_digit()) {
                    break;
                }
                i += 1;
            }
            out.push(Tok::Other('0'));
        } else if ch == ':' && i + 1 < n && c[i + 1] == ':' {
            out.push(Tok::Path);
            i += 2;
        } else {
            match ch {
                '{' => out.push(Tok::Open),
                '}' => out.push(Tok::Close),
                ';' => out.push(Tok::Semi),
                c if c.is_whitespace() => {}
                c => out.push(Tok::Other(c)),
            }
            i += 1;
        }
    }
    out
}

/// `r"`, `r#"`, `br"`, `br#"` at `i`: the number of `#` and where the body starts.
fn raw_string_start(c: &[char], i: usize) -> Option<(usize, usize)> {
    if i > 0 && (c[i - 1].is_alphanumeric() || c[i - 1] == '_') {
        return None;
    }
    let mut j = i;
    if c[j] == 'b' {
        j += 1;
    }
    if j >= c.len() || c[j] != 'r' {
        // b"..." byte strings: treated as plain strings by the caller only when they start
        // with '"', so a `b` here is just an identifier.
        return None;
    }
    j += 1;
    let mut hashes = 0;
    while j < c.len() && c[j] == '#' {
        hashes += 1;
        j += 1;
    }
    (j < c.len() && c[j] == '"').then_some((hashes, j + 1))
}

/// A module's absolute path: its crate and segments.
type ModPath = (Krate, Vec<String>);

/// One source file: its crate, module path, and the child modules it declares.
struct FileMod {
    krate: Krate,
    segs: Vec<String>,
    tokens: Vec<Tok>,
}

/// What the scan of one file found.
#[derive(Default)]
struct FileScan {
    /// Absolute paths (crate, segments) this file refers to.
    refs: Vec<(Krate, Vec<String>)>,
    /// `pub use` re-exports: exported name -> absolute path.
    reexports: BTreeMap<String, (Krate, Vec<String>)>,
    /// Child modules declared as files (`mod x;`).
    children: Vec<String>,
}

/// A scope while scanning: the file's module path plus any inline `mod x {` blocks.
struct Ctx<'a> {
    krate: Krate,
    segs: Vec<String>,
    /// Known modules of each crate (as segment paths), to tell a child module from an external
    /// crate in `use x::…` and `x::f()`.
    modules: &'a BTreeSet<(Krate, Vec<String>)>,
    /// Inline modules seen in this file (absolute).
    inline: BTreeSet<Vec<String>>,
}

impl Ctx<'_> {
    /// The absolute start of a path whose first segment is `first`, or None for external crates,
    /// local names, `Self` and the like.
    fn start(&self, first: &str) -> Option<(Krate, Vec<String>)> {
        match first {
            "crate" => Some((self.krate, Vec::new())),
            "wingbeat" if self.krate == Krate::Bin => Some((Krate::Lib, Vec::new())),
            "self" => Some((self.krate, self.segs.clone())),
            "super" => {
                let mut s = self.segs.clone();
                s.pop()?;
                Some((self.krate, s))
            }
            name => {
                let mut s = self.segs.clone();
                s.push(name.to_string());
                (self.modules.contains(&(self.krate, s.clone())) || self.inline.contains(&s))
                    .then_some((self.krate, s))
            }
        }
    }

    /// Applies one more segment (`super` pops).
    fn extend(&self, mut at: (Krate, Vec<String>), seg: &str) -> Option<(Krate, Vec<String>)> {
        match seg {
            "super" => {
                at.1.pop()?;
            }
            "self" => {}
            s => at.1.push(s.to_string()),
        }
        Some(at)
    }
}

/// Parses a use tree starting at `i` (after `use`) into complete paths with the name each binds.
fn use_tree(
    toks: &[Tok],
    i: &mut usize,
    ctx: &Ctx<'_>,
    prefix: Option<(Krate, Vec<String>)>,
    out: &mut Vec<((Krate, Vec<String>), String)>,
) {
    let mut at = prefix;
    let mut last;
    let mut first = at.is_none();
    if toks.get(*i) == Some(&Tok::Path) {
        *i += 1; // a leading `::` names an external crate
        skip_to_end_of_tree(toks, i);
        return;
    }
    loop {
        match toks.get(*i) {
            Some(Tok::Ident(id)) => {
                if first {
                    at = ctx.start(id);
                    first = false;
                    if at.is_none() {
                        skip_to_end_of_tree(toks, i);
                        return;
                    }
                } else if id == "self" {
                    // `{self, …}`: the module itself, bound to its own name
                } else {
                    at = at.and_then(|a| ctx.extend(a, id));
                }
                last = id.clone();
                *i += 1;
                if let Some(Tok::Ident(kw)) = toks.get(*i) {
                    if kw == "as" {
                        *i += 1;
                        if let Some(Tok::Ident(alias)) = toks.get(*i) {
                            last = alias.clone();
                            *i += 1;
                        }
                    }
                }
                if toks.get(*i) == Some(&Tok::Path) {
                    *i += 1;
                    continue;
                }
                if let Some(a) = at {
                    out.push((a, last));
                }
                return;
            }
            Some(Tok::Open) => {
                *i += 1;
                while *i < toks.len() && toks[*i] != Tok::Close {
                    if toks[*i] == Tok::Other(',') {
                        *i += 1;
                        continue;
                    }
                    let before = *i;
                    use_tree(toks, i, ctx, at.clone(), out);
                    if *i == before {
                        *i += 1;
                    }
                }
                *i += 1;
                return;
            }
            Some(Tok::Other('*')) => {
                *i += 1;
                if let Some(a) = at {
                    out.push((a, "*".into()));
                }
                return;
            }
            _ => return,
        }
    }
}

fn skip_to_end_of_tree(toks: &[Tok], i: &mut usize) {
    let mut depth = 0;
    while *i < toks.len() {
        match toks[*i] {
            Tok::Open => depth += 1,
            Tok::Close | Tok::Other(',') if depth == 0 => return,
            Tok::Close => depth -= 1,
            Tok::Semi => return,
            _ => {}
        }
        *i += 1;
    }
}

/// Scans one file's tokens: every crate-internal path it uses and its `pub use` re-exports.
fn scan(f: &FileMod, modules: &BTreeSet<(Krate, Vec<String>)>) -> FileScan {
    let toks = &f.tokens;
    let mut ctx = Ctx {
        krate: f.krate,
        segs: f.segs.clone(),
        modules,
        inline: BTreeSet::new(),
    };
    let mut out = FileScan::default();
    // Inline modules: (segments pushed, brace depth at which the block closes).
    let mut inline_stack: Vec<usize> = Vec::new();
    let mut depth = 0usize;
    let mut i = 0;
    while i < toks.len() {
        match &toks[i] {
            Tok::Other('#') => {
                // An attribute; `#[cfg(test)]` (or any cfg naming `test` without `not`) drops
                // the item it is on.
                let start = i;
                let mut j = i + 1;
                if toks.get(j) == Some(&Tok::Other('!')) {
                    j += 1;
                }
                if toks.get(j) == Some(&Tok::Other('[')) {
                    let mut bracket = 0;
                    while j < toks.len() {
                        match toks[j] {
                            Tok::Other('[') => bracket += 1,
                            Tok::Other(']') => {
                                bracket -= 1;
                                if bracket == 0 {
                                    break;
                                }
                            }
                            _ => {}
                        }
                        j += 1;
                    }
                    let attr = &toks[start..j.min(toks.len())];
                    let is_cfg = attr.get(2) == Some(&Tok::Ident("cfg".into()));
                    let names_test = attr.contains(&Tok::Ident("test".into()));
                    let negated = attr.contains(&Tok::Ident("not".into()));
                    if is_cfg
                        && names_test
                        && !negated
                        && toks.get(start + 1) != Some(&Tok::Other('!'))
                    {
                        i = skip_item(toks, j + 1);
                        continue;
                    }
                    // The attribute's own tokens (serde paths in strings) are scanned below.
                    i += 1;
                    continue;
                }
                i += 1;
            }
            Tok::Open => {
                depth += 1;
                i += 1;
            }
            Tok::Close => {
                depth = depth.saturating_sub(1);
                if inline_stack.last() == Some(&depth) {
                    inline_stack.pop();
                    ctx.segs.pop();
                }
                i += 1;
            }
            Tok::Ident(id) if id == "mod" => {
                if let (Some(Tok::Ident(name)), Some(Tok::Open)) =
                    (toks.get(i + 1), toks.get(i + 2))
                {
                    ctx.segs.push(name.clone());
                    ctx.inline.insert(ctx.segs.clone());
                    inline_stack.push(depth);
                    depth += 1;
                    i += 3;
                } else {
                    if let (Some(Tok::Ident(name)), Some(Tok::Semi)) =
                        (toks.get(i + 1), toks.get(i + 2))
                    {
                        if inline_stack.is_empty() {
                            out.children.push(name.clone());
                        }
                    }
                    i += 2;
                }
            }
            Tok::Ident(id) if id == "use" => {
                let is_pub = i > 0
                    && (toks[i - 1] == Tok::Ident("pub".into())
                        || (toks[i - 1] == Tok::Other(')')
                            && i >= 4
                            && toks[i - 4] == Tok::Ident("pub".into())));
                let mut j = i + 1;
                let mut paths = Vec::new();
                use_tree(toks, &mut j, &ctx, None, &mut paths);
                for (p, name) in paths {
                    // A re-export only names an item (references are followed through it to
                    // the file that defines it); it is not a use by this file's own code.
                    if is_pub && inline_stack.is_empty() && name != "*" {
                        out.reexports.insert(name, p);
                    } else {
                        out.refs.push(p);
                    }
                }
                while j < toks.len() && toks[j] != Tok::Semi {
                    j += 1;
                }
                i = j + 1;
            }
            Tok::Ident(id) => {
                let after_path = i > 0 && toks[i - 1] == Tok::Path;
                if !after_path && toks.get(i + 1) == Some(&Tok::Path) {
                    if let Some(mut at) = ctx.start(id) {
                        let mut j = i + 1;
                        while toks.get(j) == Some(&Tok::Path) {
                            match toks.get(j + 1) {
                                Some(Tok::Ident(seg)) => {
                                    match ctx.extend(at.clone(), seg) {
                                        Some(a) => at = a,
                                        None => break,
                                    }
                                    j += 2;
                                }
                                _ => break,
                            }
                        }
                        out.refs.push(at);
                        i = j;
                        continue;
                    }
                }
                i += 1;
            }
            _ => i += 1,
        }
    }
    out
}

/// The index just past the item that starts at `i` (ends at a `;` or a balanced `{ … }`).
fn skip_item(toks: &[Tok], mut i: usize) -> usize {
    let mut depth = 0;
    while i < toks.len() {
        match toks[i] {
            Tok::Semi if depth == 0 => return i + 1,
            Tok::Open => depth += 1,
            Tok::Close => {
                depth -= 1;
                if depth == 0 {
                    return i + 1;
                }
            }
            _ => {}
        }
        i += 1;
    }
    i
}

/// The module graph: nodes are files (by module key), edges "uses".
struct Graph {
    modules: BTreeSet<String>,
    edges: BTreeSet<(String, String)>,
}

fn file_module(rel: &Path) -> (Krate, Vec<String>) {
    let parts: Vec<String> = rel
        .iter()
        .map(|p| p.to_string_lossy().into_owned())
        .collect();
    if parts == ["lib.rs"] {
        return (Krate::Lib, Vec::new());
    }
    if parts == ["main.rs"] {
        return (Krate::Bin, Vec::new());
    }
    let mut segs: Vec<String> = parts;
    let last = segs.pop().unwrap();
    if last != "mod.rs" {
        segs.push(last.trim_end_matches(".rs").to_string());
    }
    // The binary's modules are the ones main.rs declares (`cli`); everything else is the library.
    let krate = if segs.first().map(String::as_str) == Some("cli") {
        Krate::Bin
    } else {
        Krate::Lib
    };
    (krate, segs)
}

fn rust_files(dir: &Path, out: &mut Vec<std::path::PathBuf>) {
    for e in std::fs::read_dir(dir).expect("read src/") {
        let p = e.expect("dir entry").path();
        if p.is_dir() {
            rust_files(&p, out);
        } else if p.extension().is_some_and(|x| x == "rs") {
            out.push(p);
        }
    }
}

/// Builds the graph from `(file path relative to src/, source text)`.
fn build_graph(files: &[(std::path::PathBuf, String)]) -> Graph {
    let mods: Vec<FileMod> = files
        .iter()
        .map(|(rel, text)| {
            let (krate, segs) = file_module(rel);
            FileMod {
                krate,
                segs,
                tokens: lex(text),
            }
        })
        .collect();
    let known: BTreeSet<(Krate, Vec<String>)> =
        mods.iter().map(|m| (m.krate, m.segs.clone())).collect();
    let scans: Vec<FileScan> = mods.iter().map(|m| scan(m, &known)).collect();
    let reexports: BTreeMap<ModPath, &BTreeMap<String, ModPath>> = mods
        .iter()
        .zip(&scans)
        .map(|(m, s)| ((m.krate, m.segs.clone()), &s.reexports))
        .collect();
    // The file that defines an absolute path: its longest known prefix, following re-exports.
    let resolve = |mut p: (Krate, Vec<String>)| -> String {
        for _ in 0..16 {
            let mut k = p.1.len();
            while k > 0 && !known.contains(&(p.0, p.1[..k].to_vec())) {
                k -= 1;
            }
            let owner = (p.0, p.1[..k].to_vec());
            if let Some(next) = p.1.get(k).and_then(|name| reexports.get(&owner)?.get(name)) {
                let mut q = next.clone();
                q.1.extend(p.1[k + 1..].iter().cloned());
                p = q;
                continue;
            }
            return key(owner.0, &owner.1);
        }
        panic!("re-export loop at {p:?}");
    };
    // The crate's modules are the files reachable from lib.rs and main.rs through `mod x;`
    // (a stray file that nothing declares is not compiled, so it is not in the graph).
    let declared: BTreeMap<(Krate, Vec<String>), &Vec<String>> = mods
        .iter()
        .zip(&scans)
        .map(|(m, s)| ((m.krate, m.segs.clone()), &s.children))
        .collect();
    let mut reachable: BTreeSet<(Krate, Vec<String>)> = BTreeSet::new();
    let mut todo = vec![(Krate::Lib, Vec::new()), (Krate::Bin, Vec::new())];
    while let Some(m) = todo.pop() {
        if !known.contains(&m) || !reachable.insert(m.clone()) {
            continue;
        }
        for c in declared.get(&m).copied().into_iter().flatten() {
            let mut segs = m.1.clone();
            segs.push(c.clone());
            todo.push((m.0, segs));
        }
    }
    let modules: BTreeSet<String> = reachable.iter().map(|(k, s)| key(*k, s)).collect();
    let mut edges = BTreeSet::new();
    for (m, s) in mods.iter().zip(&scans) {
        if !reachable.contains(&(m.krate, m.segs.clone())) {
            continue;
        }
        let from = key(m.krate, &m.segs);
        for r in &s.refs {
            let to = resolve(r.clone());
            if to != from {
                edges.insert((from.clone(), to));
            }
        }
    }
    Graph { modules, edges }
}

fn crate_graph() -> Graph {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut paths = Vec::new();
    rust_files(&src, &mut paths);
    let files: Vec<_> = paths
        .into_iter()
        .map(|p| {
            let text = std::fs::read_to_string(&p).expect("read source");
            (p.strip_prefix(&src).unwrap().to_path_buf(), text)
        })
        .collect();
    build_graph(&files)
}

/// Tarjan's strongly connected components (iterative), each sorted; singletons included.
fn tarjan(nodes: &BTreeSet<String>, edges: &BTreeSet<(String, String)>) -> Vec<Vec<String>> {
    let names: Vec<&String> = nodes.iter().collect();
    let idx: BTreeMap<&String, usize> = names.iter().enumerate().map(|(i, n)| (*n, i)).collect();
    let n = names.len();
    let mut adj = vec![Vec::new(); n];
    for (a, b) in edges {
        if let (Some(&i), Some(&j)) = (idx.get(a), idx.get(b)) {
            adj[i].push(j);
        }
    }
    let mut index = vec![usize::MAX; n];
    let mut low = vec![0; n];
    let mut on_stack = vec![false; n];
    let mut stack = Vec::new();
    let mut next = 0;
    let mut comps = Vec::new();
    for root in 0..n {
        if index[root] != usize::MAX {
            continue;
        }
        // (node, next child position)
        let mut work = vec![(root, 0usize)];
        index[root] = next;
        low[root] = next;
        next += 1;
        stack.push(root);
        on_stack[root] = true;
        while let Some(&(v, pos)) = work.last() {
            if pos < adj[v].len() {
                let w = adj[v][pos];
                work.last_mut().unwrap().1 += 1;
                if index[w] == usize::MAX {
                    index[w] = next;
                    low[w] = next;
                    next += 1;
                    stack.push(w);
                    on_stack[w] = true;
                    work.push((w, 0));
                } else if on_stack[w] {
                    low[v] = low[v].min(index[w]);
                }
            } else {
                work.pop();
                if let Some(&(parent, _)) = work.last() {
                    low[parent] = low[parent].min(low[v]);
                }
                if low[v] == index[v] {
                    let mut comp = Vec::new();
                    loop {
                        let w = stack.pop().unwrap();
                        on_stack[w] = false;
                        comp.push(names[w].clone());
                        if w == v {
                            break;
                        }
                    }
                    comp.sort();
                    comps.push(comp);
                }
            }
        }
    }
    comps
}

/// Every cycle as a readable message: the files of each component and the edges inside it.
fn cycles(g: &Graph) -> Vec<String> {
    tarjan(&g.modules, &g.edges)
        .into_iter()
        .filter(|c| c.len() > 1)
        .map(|c| {
            let inside: Vec<String> = g
                .edges
                .iter()
                .filter(|(a, b)| c.contains(a) && c.contains(b))
                .map(|(a, b)| format!("{a} -> {b}"))
                .collect();
            format!(
                "cycle of {} files: {}\n    edges: {}",
                c.len(),
                c.join(", "),
                inside.join("; ")
            )
        })
        .collect()
}

/// The layers of ARCHITECTURE.md's ```` ```layers ```` block, top first: (name, module patterns).
fn layers() -> Vec<(String, Vec<String>)> {
    let text =
        std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("ARCHITECTURE.md"))
            .expect("read ARCHITECTURE.md");
    let mut lines = text.lines().skip_while(|l| l.trim() != "```layers");
    assert!(
        lines.next().is_some(),
        "ARCHITECTURE.md has no ```layers block"
    );
    let mut out = Vec::new();
    for l in lines.take_while(|l| l.trim() != "```") {
        let (name, mods) = l
            .split_once(':')
            .unwrap_or_else(|| panic!("layer line without ':': {l}"));
        out.push((
            name.trim().to_string(),
            mods.split(|c: char| c == ',' || c.is_whitespace())
                .filter(|s| !s.is_empty())
                .map(String::from)
                .collect(),
        ));
    }
    out
}

/// The layer index (0 = top) of every module; errors for modules in no layer or in two.
fn layer_of(
    modules: &BTreeSet<String>,
    layers: &[(String, Vec<String>)],
) -> (BTreeMap<String, usize>, Vec<String>) {
    let mut of = BTreeMap::new();
    let mut errors = Vec::new();
    for m in modules {
        let hits: Vec<usize> = layers
            .iter()
            .enumerate()
            .filter(|(_, (_, pats))| {
                pats.iter().any(|p| match p.strip_suffix("::*") {
                    Some(parent) => m.strip_prefix(parent).is_some_and(|r| r.starts_with("::")),
                    None => p == m,
                })
            })
            .map(|(i, _)| i)
            .collect();
        match hits.as_slice() {
            [one] => {
                of.insert(m.clone(), *one);
            }
            [] => errors.push(format!(
                "module `{m}` is in no layer of ARCHITECTURE.md's ```layers block"
            )),
            many => errors.push(format!(
                "module `{m}` is in {} layers: {}",
                many.len(),
                many.iter()
                    .map(|&i| layers[i].0.as_str())
                    .collect::<Vec<_>>()
                    .join(", ")
            )),
        }
    }
    for (name, pats) in layers {
        for p in pats {
            let parent = p.strip_suffix("::*");
            let matches = modules.iter().any(|m| match parent {
                Some(par) => m.starts_with(&format!("{par}::")),
                None => m == p,
            });
            if !matches {
                errors.push(format!(
                    "layer `{name}` lists `{p}`, which is no module of src/"
                ));
            }
        }
    }
    (of, errors)
}

fn upward_edges(
    g: &Graph,
    of: &BTreeMap<String, usize>,
    layers: &[(String, Vec<String>)],
) -> Vec<String> {
    g.edges
        .iter()
        .filter_map(|(a, b)| {
            let (la, lb) = (*of.get(a)?, *of.get(b)?);
            (lb < la).then(|| {
                format!(
                    "{a} ({}) -> {b} ({}): points to a higher layer",
                    layers[la].0, layers[lb].0
                )
            })
        })
        .collect()
}

#[test]
fn src_has_no_module_cycles() {
    let g = crate_graph();
    // Not vacuous: the scan must see the crate's files and a plausible number of imports,
    // including some that are known to exist.
    assert!(
        g.modules.len() >= 60,
        "only {} modules seen",
        g.modules.len()
    );
    assert!(g.edges.len() >= 200, "only {} edges seen", g.edges.len());
    for (a, b) in [
        ("simulate", "floquet"),
        ("floquet", "solve::propagator"),
        ("fem::mesh", "fem::geometry"),
        ("model", "kinematics"),
        ("kinematics", "error"),        // through `crate::error::…`
        ("analysis::beat", "error"),    // through `crate::Result` re-exported by lib.rs
        ("cli", "analysis::sweep"),     // the binary's `wingbeat::…` paths
        ("config", "error"),            // a serde attribute's path in a string
        ("wasm::sim", "wasm::marshal"), // `super::marshal`
    ] {
        assert!(
            g.edges.contains(&(a.to_string(), b.to_string())),
            "expected edge {a} -> {b} not seen"
        );
    }
    let c = cycles(&g);
    assert!(
        c.is_empty(),
        "import cycles among src/ files:\n  {}",
        c.join("\n  ")
    );
}

#[test]
fn imports_follow_architecture_layers() {
    let g = crate_graph();
    let layers = layers();
    assert!(
        layers.len() >= 4,
        "ARCHITECTURE.md's layer list has only {} layers",
        layers.len()
    );
    let (of, mut errors) = layer_of(&g.modules, &layers);
    errors.extend(upward_edges(&g, &of, &layers));
    assert!(
        errors.is_empty(),
        "ARCHITECTURE.md's layers do not match the code:\n  {}",
        errors.join("\n  ")
    );
    if std::env::var_os("WINGBEAT_PRINT_GRAPH").is_some() {
        println!("{} modules, {} edges", g.modules.len(), g.edges.len());
        for (name, _) in &layers {
            let ms: Vec<&String> = of
                .iter()
                .filter(|(_, &l)| layers[l].0 == *name)
                .map(|(m, _)| m)
                .collect();
            println!("{name}: {}", ms.len());
        }
    }
}

/// Prints the graph (`WINGBEAT_PRINT_GRAPH=1 cargo test --test module_graph -- --nocapture`).
#[test]
fn graph_listing_when_asked() {
    if std::env::var_os("WINGBEAT_PRINT_GRAPH").is_none() {
        return;
    }
    let g = crate_graph();
    for (a, b) in &g.edges {
        println!("EDGE {a} -> {b}");
    }
    for c in cycles(&g) {
        println!("{c}");
    }
}

fn synthetic(files: &[(&str, &str)]) -> Graph {
    let files: Vec<_> = files
        .iter()
        .map(|(p, t)| (std::path::PathBuf::from(p), t.to_string()))
        .collect();
    build_graph(&files)
}

#[test]
fn detects_a_cycle_in_a_small_graph() {
    let g = synthetic(&[
        (
            "lib.rs",
            "pub mod a; pub mod b; pub mod c; pub mod d; pub use d::Err;",
        ),
        ("a.rs", "use crate::b::thing;\nfn f() -> crate::Err { }"),
        ("b.rs", "pub fn thing() { crate::c::other() }"),
        // c reaches back to a through a grouped import: a -> b -> c -> a.
        ("c.rs", "use crate::{d, a::{self, X}};\npub fn other() {}"),
        ("d.rs", "pub struct Err;"),
        // not declared by any module: not compiled, not in the graph
        ("stray.rs", "use crate::a::X;"),
    ]);
    assert_eq!(g.modules.len(), 5);
    assert!(
        g.edges.contains(&("a".into(), "d".into())),
        "crate::Err resolves through lib.rs's re-export"
    );
    let c = cycles(&g);
    assert_eq!(c.len(), 1, "{c:?}");
    assert!(c[0].contains("cycle of 3 files: a, b, c"), "{}", c[0]);
    assert!(c[0].contains("c -> a"), "{}", c[0]);
}

#[test]
fn ignores_comments_tests_and_external_crates() {
    let g = synthetic(&[
        ("lib.rs", "pub mod a; pub mod b; pub mod x;"),
        (
            "x/mod.rs",
            "pub mod y; pub use y::Thing; fn f() { y::g(); }",
        ),
        // `super::Thing` resolves through x's re-export to x::y, and y -> x would only be via
        // the doc comment, so there is no cycle x <-> x::y.
        (
            "x/y.rs",
            "/// uses [`super::f`]\npub struct Thing;\npub fn g() {}",
        ),
        (
            "a.rs",
            "// crate::b::h()\n/* crate::b::h() */ use serde::Serialize; use std::fmt;\n\
                  fn f() -> crate::x::Thing { let s = \"{}\"; }\n\
                  #[cfg(test)]\nmod tests { use crate::b; }",
        ),
        ("b.rs", "use crate::a; mod inner { use super::super::x; }"),
    ]);
    assert!(
        !g.edges.contains(&("a".into(), "b".into())),
        "comments and test modules are not edges"
    );
    assert!(g.edges.contains(&("a".into(), "x::y".into())));
    assert!(g.edges.contains(&("x".into(), "x::y".into())));
    assert!(!g.edges.contains(&("x::y".into(), "x".into())));
    assert!(
        g.edges.contains(&("b".into(), "x".into())),
        "super::super:: from an inline module"
    );
    assert!(g.edges.contains(&("b".into(), "a".into())));
    assert!(cycles(&g).is_empty());
}

#[test]
fn layer_check_flags_upward_edges_and_unlisted_modules() {
    let g = synthetic(&[
        ("lib.rs", "pub mod low; pub mod high; pub mod extra;"),
        ("low.rs", "use crate::high::f;"),
        ("high.rs", "pub fn f() {}"),
        ("extra.rs", ""),
    ]);
    let layers = vec![
        (
            "top".to_string(),
            vec!["crate".to_string(), "high".to_string()],
        ),
        (
            "bottom".to_string(),
            vec!["low".to_string(), "gone".to_string()],
        ),
    ];
    let (of, errors) = layer_of(&g.modules, &layers);
    assert!(
        errors.iter().any(|e| e.contains("`extra` is in no layer")),
        "{errors:?}"
    );
    assert!(
        errors
            .iter()
            .any(|e| e.contains("`gone`, which is no module")),
        "{errors:?}"
    );
    let up = upward_edges(&g, &of, &layers);
    assert_eq!(
        up,
        vec!["low (bottom) -> high (top): points to a higher layer".to_string()]
    );
}
