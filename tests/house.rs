//! The house rules of docs/architecture.md, checked on the sources: no file of a crate (or of
//! the harness) imports another that imports it back, directly or through a chain; no source
//! file grows past the size limit unless it is listed below as one concept; and the map in
//! docs/architecture.md names every module file there is.
//!
//! Imports are read from the text: `use crate::a::b`, `crate::a::b` paths, `super::` paths, and
//! names re-exported at a crate's root (`use crate::Name` counts as an import of the file that
//! defines `Name`). Unit-test modules (`#[cfg(test)] mod tests`) are left out: a test may use
//! anything.

mod sources;

use std::collections::{BTreeMap, BTreeSet};
use std::fs;
use std::path::{Path, PathBuf};

/// Lines a source file may have (its unit tests included) before it must be split or listed
/// in [`ONE_CONCEPT`].
const MAX_LINES: usize = 650;

/// Files over [`MAX_LINES`] that hold one concept, each with the reason it stays whole.
const ONE_CONCEPT: &[(&str, &str)] = &[];

/// The source folders whose files must not import each other in a circle: each crate's `src`,
/// the facade's and the harness's.
fn source_roots(root: &Path) -> Vec<PathBuf> {
    let mut roots: Vec<PathBuf> = fs::read_dir(root.join("crates"))
        .expect("crates/")
        .map(|e| e.expect("an entry").path().join("src"))
        .filter(|p| p.is_dir())
        .collect();
    roots.push(root.join("src"));
    roots.push(root.join("xtask/src"));
    roots.sort();
    roots
}

/// The module path of a file below `src` (`a/b.rs` and `a/b/mod.rs` are `a::b`; `lib.rs`,
/// `main.rs` are the root, "").
fn module_of(src: &Path, file: &Path) -> String {
    let rel = file.strip_prefix(src).expect("below src").with_extension("");
    let mut parts: Vec<String> = rel.iter().map(|p| p.to_string_lossy().into_owned()).collect();
    if matches!(parts.last().map(String::as_str), Some("mod" | "lib" | "main")) {
        parts.pop();
    }
    parts.join("::")
}

/// The text of a file without comments and without its unit-test module.
fn code_of(text: &str) -> String {
    let text = match text.find("#[cfg(test)]\nmod tests") {
        Some(i) => &text[..i],
        None => text,
    };
    text.lines().map(|l| l.split("//").next().unwrap_or("")).collect::<Vec<_>>().join("\n")
}

/// The paths a file names after `crate::` or `super::` (with `super` resolved against the
/// file's module), braces of `use` trees expanded: `use crate::{a::b, c}` gives `a::b` and `c`.
fn named_paths(code: &str, module: &str) -> Vec<Vec<String>> {
    let mut out = Vec::new();
    let bytes: Vec<char> = code.chars().collect();
    let starts = ["crate::", "super::"];
    let mut i = 0;
    while i < bytes.len() {
        let rest: String = bytes[i..bytes.len().min(i + 7)].iter().collect();
        let Some(start) = starts.iter().find(|s| rest.starts_with(**s)) else {
            i += 1;
            continue;
        };
        let preceded = i > 0 && (bytes[i - 1].is_alphanumeric() || bytes[i - 1] == '_');
        if preceded {
            i += 1;
            continue;
        }
        let mut base: Vec<String> = if *start == "crate::" {
            Vec::new()
        } else {
            let mut m: Vec<String> = module.split("::").filter(|s| !s.is_empty()).map(String::from).collect();
            m.pop();
            m
        };
        i += start.len();
        // Further `super::` segments.
        while bytes[i..].iter().collect::<String>().starts_with("super::") {
            base.pop();
            i += "super::".len();
        }
        let (tree, end) = read_tree(&bytes, i);
        for path in expand(&tree) {
            let mut full = base.clone();
            full.extend(path);
            out.push(full);
        }
        i = end.max(i + 1);
    }
    out
}

/// The `use` tree (or path) starting at `i`, as text, and where it ends.
fn read_tree(bytes: &[char], mut i: usize) -> (String, usize) {
    let mut depth = 0;
    let mut tree = String::new();
    while i < bytes.len() {
        let c = bytes[i];
        match c {
            '{' => depth += 1,
            '}' if depth == 0 => break,
            '}' => depth -= 1,
            c if depth == 0 && !(c.is_alphanumeric() || c == '_' || c == ':') => break,
            _ => {}
        }
        tree.push(c);
        i += 1;
    }
    (tree, i)
}

/// The paths of a `use` tree: `a::{b, c::d}` gives `a::b` and `a::c::d`.
fn expand(tree: &str) -> Vec<Vec<String>> {
    let tree: String = tree.chars().filter(|c| !c.is_whitespace()).collect();
    let Some(open) = tree.find('{') else {
        let path: Vec<String> = tree
            .split("::")
            .filter(|s| !s.is_empty() && *s != "self" && *s != "*")
            .map(String::from)
            .collect();
        return vec![path];
    };
    let prefix: Vec<String> = tree[..open].split("::").filter(|s| !s.is_empty()).map(String::from).collect();
    let inner = &tree[open + 1..tree.rfind('}').unwrap_or(tree.len())];
    let mut parts = Vec::new();
    let (mut depth, mut from) = (0, 0);
    for (k, c) in inner.char_indices() {
        match c {
            '{' => depth += 1,
            '}' => depth -= 1,
            ',' if depth == 0 => {
                parts.push(&inner[from..k]);
                from = k + 1;
            }
            _ => {}
        }
    }
    parts.push(&inner[from..]);
    let mut out = Vec::new();
    for part in parts.into_iter().filter(|p| !p.is_empty()) {
        let part = part.split(" as ").next().unwrap_or(part);
        for mut path in expand(part) {
            let mut full = prefix.clone();
            full.append(&mut path);
            out.push(full);
        }
    }
    out
}

/// The names a crate root re-exports from its own modules, and the module each comes from.
fn root_reexports(root_code: &str, modules: &BTreeSet<String>) -> BTreeMap<String, String> {
    let mut names = BTreeMap::new();
    for statement in root_code.split(';') {
        let statement = statement.trim();
        let Some(rest) = statement.strip_prefix("pub use ") else { continue };
        for path in expand(rest) {
            let Some((name, module)) = path.split_last() else { continue };
            let module = module.join("::");
            if modules.contains(&module) {
                names.insert(name.clone(), module);
            }
        }
    }
    names
}

/// The import graph of the files below `src`: module -> the modules it imports.
fn import_graph(src: &Path) -> BTreeMap<String, BTreeSet<String>> {
    let files: BTreeMap<String, String> = sources::rust_files(src)
        .into_iter()
        .map(|f| (module_of(src, &f), code_of(&fs::read_to_string(&f).expect("a readable file"))))
        .collect();
    let modules: BTreeSet<String> = files.keys().cloned().collect();
    let reexports = root_reexports(files.get("").map_or("", String::as_str), &modules);
    let mut graph = BTreeMap::new();
    for (module, code) in &files {
        let mut imports = BTreeSet::new();
        for path in named_paths(code, module) {
            // The longest prefix that is a module, or a root re-export.
            let target = (1..=path.len())
                .rev()
                .map(|k| path[..k].join("::"))
                .find(|m| modules.contains(m))
                .or_else(|| (path.len() == 1).then(|| reexports.get(&path[0]).cloned()).flatten());
            if let Some(target) = target
                && !target.is_empty()
                && target != *module
                && !module.starts_with(&format!("{target}::"))
            {
                imports.insert(target);
            }
        }
        graph.insert(module.clone(), imports);
    }
    graph
}

/// The cycles of a graph: its strongly connected components of more than one node.
fn cycles(graph: &BTreeMap<String, BTreeSet<String>>) -> Vec<Vec<String>> {
    // Kosaraju: finishing order on the graph, then components on the reversed graph.
    fn visit<'a>(
        n: &'a str,
        graph: &'a BTreeMap<String, BTreeSet<String>>,
        seen: &mut BTreeSet<&'a str>,
        order: &mut Vec<&'a str>,
    ) {
        if !seen.insert(n) {
            return;
        }
        for m in graph.get(n).into_iter().flatten() {
            visit(m, graph, seen, order);
        }
        order.push(n);
    }
    let mut reversed: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    for (a, targets) in graph {
        for b in targets {
            reversed.entry(b.clone()).or_default().insert(a.clone());
        }
    }
    let (mut seen, mut order) = (BTreeSet::new(), Vec::new());
    for n in graph.keys() {
        visit(n, graph, &mut seen, &mut order);
    }
    let mut assigned = BTreeSet::new();
    let mut out = Vec::new();
    for &n in order.iter().rev() {
        let (mut component, mut members) = (BTreeSet::new(), Vec::new());
        visit(n, &reversed, &mut component, &mut members);
        let members: Vec<String> =
            members.into_iter().filter(|m| assigned.insert(m.to_string())).map(String::from).collect();
        if members.len() > 1 {
            out.push(members);
        }
    }
    out
}

fn workspace() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

#[test]
fn no_file_imports_one_that_imports_it_back() {
    let mut found = Vec::new();
    for src in source_roots(&workspace()) {
        for cycle in cycles(&import_graph(&src)) {
            found.push(format!("{}: {}", src.display(), cycle.join(" -> ")));
        }
    }
    assert!(found.is_empty(), "circular imports:\n{}", found.join("\n"));
}

#[test]
fn the_reader_sees_a_cycle_when_there_is_one() {
    let dir = std::env::temp_dir().join(format!("trailmark-house-{}", std::process::id()));
    let src = dir.join("src");
    fs::create_dir_all(src.join("family")).unwrap();
    fs::write(src.join("lib.rs"), "mod a;\nmod family;\npub use family::b::Thing;\n").unwrap();
    fs::write(src.join("a.rs"), "use crate::Thing;\npub struct A;\n").unwrap();
    fs::write(src.join("family/mod.rs"), "pub mod b;\n").unwrap();
    fs::write(src.join("family/b.rs"), "use crate::{a::A, family};\npub struct Thing;\n").unwrap();
    let graph = import_graph(&src);
    assert_eq!(graph["a"], BTreeSet::from(["family::b".to_string()]));
    let mut found = cycles(&graph);
    found.iter_mut().for_each(|c| c.sort());
    assert_eq!(found, vec![vec!["a".to_string(), "family::b".to_string()]]);
    fs::write(src.join("family/b.rs"), "// crate::a::A is not imported here\npub struct Thing;\n").unwrap();
    assert!(cycles(&import_graph(&src)).is_empty());
    fs::remove_dir_all(dir).unwrap();
}

#[test]
fn files_stay_small_or_are_one_concept() {
    let root = workspace();
    let mut over = Vec::new();
    for src in source_roots(&root) {
        for file in sources::rust_files(&src) {
            let lines = fs::read_to_string(&file).expect("a readable file").lines().count();
            let name =
                file.strip_prefix(&root).expect("in the workspace").to_string_lossy().replace('\\', "/");
            let listed = ONE_CONCEPT.iter().any(|(f, _)| *f == name);
            if lines > MAX_LINES && !listed {
                over.push(format!("{name}: {lines} lines"));
            }
        }
    }
    assert!(
        over.is_empty(),
        "files over {MAX_LINES} lines: split them by concept, or list them in ONE_CONCEPT with the reason:\n{}",
        over.join("\n")
    );
}

#[test]
fn the_map_names_every_module_file() {
    let root = workspace();
    let map = fs::read_to_string(root.join("docs/architecture.md")).expect("docs/architecture.md");
    let mut missing = Vec::new();
    for src in source_roots(&root) {
        for file in sources::rust_files(&src) {
            let name = file.strip_prefix(&src).expect("below src").to_string_lossy().replace('\\', "/");
            if matches!(name.as_str(), "lib.rs" | "main.rs") || name.ends_with("tests.rs") {
                continue;
            }
            // A folder's files may be named by the folder (`prm/`).
            let folder = name.rsplit_once('/').map(|(dir, _)| format!("{dir}/"));
            if !map.contains(&name) && !folder.is_some_and(|f| map.contains(&f)) {
                missing.push(file.strip_prefix(&root).expect("in the workspace").display().to_string());
            }
        }
    }
    assert!(missing.is_empty(), "docs/architecture.md does not name:\n{}", missing.join("\n"));
}
