//! Types a user can name: no public signature of a library crate names an item of another
//! registry crate (nalgebra, rand, parry2d, ...) unless the crate re-exports that item, or the
//! whole crate, so a user never needs a version-matched dependency of their own to call it.
//!
//! The sources are parsed with `syn`. Public items are read as a user meets them: functions
//! (arguments, result, bounds), struct fields, enum variants, type aliases, constants, traits
//! (every item of a public trait) and impl blocks (the trait implemented and each public
//! method). A name counts as another crate's when it is written with that crate's path
//! (`rand::Rng`) or imported from it by a `use`. Unit-test modules are left out.

mod sources;

use std::collections::{BTreeMap, BTreeSet};
use std::fs;
use std::path::{Path, PathBuf};

use syn::visit::Visit;

/// The library crates a user depends on: their folder and their `src`.
fn library_crates(root: &Path) -> Vec<PathBuf> {
    let mut dirs: Vec<PathBuf> = fs::read_dir(root.join("crates"))
        .expect("crates/")
        .map(|e| e.expect("an entry").path())
        .filter(|p| p.join("src/lib.rs").is_file())
        .collect();
    dirs.push(root.to_path_buf());
    dirs.sort();
    dirs
}

/// The names (as written in Rust) of a crate's registry dependencies, the trailmark crates left
/// out: the crates whose items a user would have to add to name them.
fn registry_dependencies(manifest: &Path) -> BTreeSet<String> {
    let text = fs::read_to_string(manifest).expect("Cargo.toml");
    let mut in_dependencies = false;
    let mut names = BTreeSet::new();
    for line in text.lines() {
        let line = line.trim();
        if line.starts_with('[') {
            in_dependencies = line == "[dependencies]";
            continue;
        }
        if !in_dependencies || line.is_empty() || line.starts_with('#') {
            continue;
        }
        let key = line.split(['=', '.', ' ']).next().unwrap_or("").trim();
        if !key.is_empty() && !key.starts_with("trailmark") {
            names.insert(key.replace('-', "_"));
        }
    }
    names
}

/// A `use` tree flattened: each name it brings in with the full path it stands for.
fn flatten_use(tree: &syn::UseTree, prefix: &mut Vec<String>, out: &mut Vec<(String, Vec<String>)>) {
    match tree {
        syn::UseTree::Path(p) => {
            prefix.push(p.ident.to_string());
            flatten_use(&p.tree, prefix, out);
            prefix.pop();
        }
        syn::UseTree::Name(n) => {
            let mut full = prefix.clone();
            full.push(n.ident.to_string());
            let name = if n.ident == "self" {
                prefix.last().cloned().unwrap_or_default()
            } else {
                n.ident.to_string()
            };
            out.push((name, full));
        }
        syn::UseTree::Rename(r) => {
            let mut full = prefix.clone();
            full.push(r.ident.to_string());
            out.push((r.rename.to_string(), full));
        }
        syn::UseTree::Glob(_) => {
            let mut full = prefix.clone();
            full.push("*".to_owned());
            out.push(("*".to_owned(), full));
        }
        syn::UseTree::Group(g) => g.items.iter().for_each(|t| flatten_use(t, prefix, out)),
    }
}

fn is_test_module(module: &syn::ItemMod) -> bool {
    module.attrs.iter().any(|a| {
        a.path().is_ident("cfg") && a.meta.require_list().is_ok_and(|l| l.tokens.to_string().contains("test"))
    })
}

fn is_public(vis: &syn::Visibility) -> bool {
    matches!(vis, syn::Visibility::Public(_))
}

/// The paths written in the public face of a file.
#[derive(Default)]
struct Face {
    paths: Vec<Vec<String>>,
    /// Inside a public signature or type (the visitor records paths only there).
    depth: usize,
}

impl Face {
    fn record<T>(&mut self, _node: &T, visit: impl FnOnce(&mut Self)) {
        self.depth += 1;
        visit(self);
        self.depth -= 1;
    }
}

impl<'a> Visit<'a> for Face {
    fn visit_path(&mut self, path: &'a syn::Path) {
        if self.depth > 0 {
            self.paths.push(path.segments.iter().map(|s| s.ident.to_string()).collect());
        }
        syn::visit::visit_path(self, path);
    }

    fn visit_item_fn(&mut self, item: &'a syn::ItemFn) {
        if is_public(&item.vis) {
            self.record(item, |f| f.visit_signature(&item.sig));
        }
    }

    fn visit_item_struct(&mut self, item: &'a syn::ItemStruct) {
        if is_public(&item.vis) {
            self.record(item, |f| {
                f.visit_generics(&item.generics);
                for field in item.fields.iter().filter(|field| is_public(&field.vis)) {
                    f.visit_type(&field.ty);
                }
            });
        }
    }

    fn visit_item_enum(&mut self, item: &'a syn::ItemEnum) {
        if is_public(&item.vis) {
            self.record(item, |f| {
                f.visit_generics(&item.generics);
                for variant in &item.variants {
                    variant.fields.iter().for_each(|field| f.visit_type(&field.ty));
                }
            });
        }
    }

    fn visit_item_type(&mut self, item: &'a syn::ItemType) {
        if is_public(&item.vis) {
            self.record(item, |f| syn::visit::visit_item_type(f, item));
        }
    }

    fn visit_item_const(&mut self, item: &'a syn::ItemConst) {
        if is_public(&item.vis) {
            self.record(item, |f| f.visit_type(&item.ty));
        }
    }

    fn visit_item_static(&mut self, item: &'a syn::ItemStatic) {
        if is_public(&item.vis) {
            self.record(item, |f| f.visit_type(&item.ty));
        }
    }

    fn visit_item_trait(&mut self, item: &'a syn::ItemTrait) {
        if is_public(&item.vis) {
            self.record(item, |f| {
                f.visit_generics(&item.generics);
                item.supertraits.iter().for_each(|b| f.visit_type_param_bound(b));
                for inner in &item.items {
                    match inner {
                        syn::TraitItem::Fn(method) => f.visit_signature(&method.sig),
                        syn::TraitItem::Type(ty) => {
                            ty.bounds.iter().for_each(|b| f.visit_type_param_bound(b))
                        }
                        syn::TraitItem::Const(c) => f.visit_type(&c.ty),
                        _ => {}
                    }
                }
            });
        }
    }

    fn visit_item_impl(&mut self, item: &'a syn::ItemImpl) {
        let of_trait = item.trait_.is_some();
        self.record(item, |f| {
            f.visit_generics(&item.generics);
            if let Some((_, path, _)) = &item.trait_ {
                f.visit_path(path);
            }
        });
        for inner in &item.items {
            match inner {
                syn::ImplItem::Fn(method) if of_trait || is_public(&method.vis) => {
                    self.record(method, |f| f.visit_signature(&method.sig));
                }
                syn::ImplItem::Type(ty) if of_trait || is_public(&ty.vis) => {
                    self.record(ty, |f| f.visit_type(&ty.ty));
                }
                syn::ImplItem::Const(c) if of_trait || is_public(&c.vis) => {
                    self.record(c, |f| f.visit_type(&c.ty));
                }
                _ => {}
            }
        }
    }

    fn visit_item_mod(&mut self, item: &'a syn::ItemMod) {
        if !is_test_module(item) {
            syn::visit::visit_item_mod(self, item);
        }
    }
}

/// The `use` items of a file outside its test modules, flattened, and whether each is `pub`.
fn imports(items: &[syn::Item], out: &mut Vec<(bool, String, Vec<String>)>) {
    for item in items {
        match item {
            syn::Item::Use(u) => {
                let mut flat = Vec::new();
                flatten_use(&u.tree, &mut Vec::new(), &mut flat);
                let public = is_public(&u.vis);
                out.extend(flat.into_iter().map(|(name, path)| (public, name, path)));
            }
            syn::Item::Mod(m) if !is_test_module(m) => {
                if let Some((_, inner)) = &m.content {
                    imports(inner, out);
                }
            }
            _ => {}
        }
    }
}

/// Crates every user of a serializable type already has, at the one major version there is:
/// serde's traits are what the derives implement on every document type, and a hand-written
/// `impl Serialize` is the same to a caller.
const USER_HAS: &[&str] = &["serde"];

/// What a crate re-exports from other crates: whole crates (`pub use rand;`, a glob of one), and
/// items by their full path.
#[derive(Default)]
struct Reexports {
    whole: BTreeSet<String>,
    items: BTreeSet<String>,
}

impl Reexports {
    fn of(files: &[Source]) -> Self {
        let mut reexports = Self::default();
        for source in files {
            for (_, _, path) in source.uses.iter().filter(|(public, ..)| *public) {
                if path.len() == 1 || path.len() == 2 && path[1] == "*" {
                    reexports.whole.insert(path[0].clone());
                }
                reexports.items.insert(path.join("::"));
            }
        }
        reexports
    }

    /// Whether a user can name the item at `full` through this crate.
    fn names(&self, full: &[String]) -> bool {
        USER_HAS.contains(&full[0].as_str())
            || self.whole.contains(&full[0])
            || (1..=full.len()).any(|k| self.items.contains(&full[..k].join("::")))
            || self.items.contains(&format!("{}::*", full[..full.len() - 1].join("::")))
    }
}

/// A source file of a library crate: its path, its syntax tree and its `use` items.
struct Source {
    file: PathBuf,
    parsed: syn::File,
    uses: Vec<(bool, String, Vec<String>)>,
}

impl Source {
    fn read(file: PathBuf) -> Self {
        let text = fs::read_to_string(&file).expect("a source file");
        let parsed = syn::parse_file(&text).unwrap_or_else(|e| panic!("{}: {e}", file.display()));
        let mut uses = Vec::new();
        imports(&parsed.items, &mut uses);
        Source { file, parsed, uses }
    }
}

/// The full paths of the other crates' items that the public face of `source` names, and the
/// number of paths read.
fn foreign_items(source: &Source, dependencies: &BTreeSet<String>) -> (Vec<Vec<String>>, usize) {
    let from_other_crates: BTreeMap<&String, &Vec<String>> = source
        .uses
        .iter()
        .filter(|(_, _, path)| dependencies.contains(&path[0]))
        .map(|(_, name, path)| (name, path))
        .collect();
    let mut face = Face::default();
    face.visit_file(&source.parsed);
    let read = face.paths.len();
    let foreign = face
        .paths
        .into_iter()
        .filter_map(|segments| {
            if dependencies.contains(&segments[0]) && segments.len() > 1 {
                Some(segments)
            } else {
                let path = from_other_crates.get(&segments[0])?;
                Some(path.iter().chain(&segments[1..]).cloned().collect())
            }
        })
        .collect();
    (foreign, read)
}

#[test]
fn public_signatures_name_only_items_a_user_can_name() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut unnamed: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    let mut read = 0;
    let mut seen = BTreeSet::new();
    for dir in library_crates(root) {
        let dependencies = registry_dependencies(&dir.join("Cargo.toml"));
        let files: Vec<Source> =
            sources::rust_files(&dir.join("src")).into_iter().map(Source::read).collect();
        let reexports = Reexports::of(&files);
        for source in &files {
            let file = &source.file;
            let (foreign, paths) = foreign_items(source, &dependencies);
            read += paths;
            for full in foreign {
                if !reexports.names(&full) {
                    let at = file.strip_prefix(root).unwrap_or(file).display().to_string();
                    unnamed.entry(full.join("::")).or_default().insert(at);
                }
                seen.insert(full.join("::"));
            }
        }
    }
    assert!(read > 1000, "only {read} paths read: the parser missed the public items");
    // The check is not empty: the public face does name other crates' items, re-exported.
    for expected in ["rand_chacha::ChaCha8Rng", "nalgebra::Point2", "serde_json::Value"] {
        assert!(seen.contains(expected), "{expected} not found among {seen:?}");
    }
    assert!(
        unnamed.is_empty(),
        "public signatures name items of other crates that their crate does not re-export:\n{}",
        unnamed
            .iter()
            .map(|(item, at)| format!("  {item}: {}", at.iter().cloned().collect::<Vec<_>>().join(", ")))
            .collect::<Vec<_>>()
            .join("\n")
    );
}
