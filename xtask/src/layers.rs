//! `cargo xtask layers`: the core's modules stand in layers, and no file
//! imports from a file that imports it back.
//!
//! Each file of `crates/rodyn/src` is parsed (syn) and every path it names
//! inside the crate (`use` trees, paths in types and expressions, and
//! `crate::`/`super::` paths inside macro calls) is resolved to the file
//! that defines the item, following re-exports (`pub use`) and glob
//! imports, so that `crate::Scalar` counts as an import of
//! `scalar/mod.rs`, not of `lib.rs`. Doc links are documentation, not
//! imports, and are not read. Code under `#[cfg(test)]` is left out: a
//! test may check a layer with what is built on it.
//!
//! Two things fail: an import from a module of a higher layer than the
//! importing file's ([`LAYERS`]; a path through a higher module's
//! re-export counts as an import from that module), and a cycle of files that import each
//! other through more than one top-level module (reported as the files of
//! the strongly connected component with the imports that close it; the
//! layers alone would let two modules of one layer import each other). A
//! cycle among one module's own files (a `mod.rs` and the children whose
//! items it re-exports and whose shared helpers it holds) is listed, not
//! failed. `lint` runs the check.

use anyhow::{bail, Context, Result};
use proc_macro2::{TokenStream, TokenTree};
use std::collections::{BTreeMap, BTreeSet, HashMap, HashSet};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use syn::visit::Visit;

use crate::shell;

/// The core's top-level modules from the ground floor up. A file may
/// import from its own module's layer and the layers below; the crate
/// root (`lib.rs`) stands above every layer.
pub const LAYERS: &[&[&str]] = &[
    // Scalars and the build's tuning profile.
    &["scalar", "tuning"],
    // The algebra: 3-D and planar value types; the crate's errors, which
    // name only the algebra's; the traits that make the types a geometry.
    &["spatial"],
    &["planar"],
    &["error"],
    &["space"],
    // Joints, over a geometry.
    &["joint"],
    // A model: its tree, its parameters, its frames and end points, the
    // workspace its algorithms fill.
    &["topology"],
    &["model"],
    &["frame", "endpoint", "data"],
    // The algorithms over a model.
    &["algorithm"],
    // What is built on the algorithms.
    &["drive", "sensitivity", "update"],
    &["sim"],
    &["interop"],
];

/// `cargo xtask layers`: checks the core and prints its layers.
pub fn run() -> Result<()> {
    let src = shell::root().join("crates/rodyn/src");
    let graph = Graph::of_crate(&src, &|path| std::fs::read_to_string(path).ok())?;
    let report = graph.check(LAYERS);
    print!("{}", report.text);
    if !report.is_clean() {
        bail!(
            "crates/rodyn/src: {} import cycle(s) between files and {} import(s) against the \
             layer order (LAYERS in xtask/src/layers.rs)",
            report.cycles,
            report.violations
        );
    }
    Ok(())
}

/// One file's import of an item of another file.
#[derive(Debug, Clone)]
struct Import {
    line: usize,
    /// The path as written, `crate::space::Geometry`.
    path: String,
    /// The top-level modules the path passes through on its way to the
    /// item (a re-export in `joint` of an item of `space` still names
    /// `joint`).
    via: BTreeSet<String>,
}

/// The files of a crate and which imports which.
pub struct Graph {
    /// Paths relative to the crate's `src`, `lib.rs` first.
    files: Vec<PathBuf>,
    /// Each file's top-level module (`None` for the crate root).
    top_modules: Vec<Option<String>>,
    /// `(importer, imported)` with the imports, first by line.
    edges: BTreeMap<(usize, usize), Vec<Import>>,
}

/// What the check found, as printed.
pub struct Report {
    pub text: String,
    pub cycles: usize,
    pub violations: usize,
}

impl Report {
    pub fn is_clean(&self) -> bool {
        self.cycles == 0 && self.violations == 0
    }
}

/// A module: a file, or an inline `mod name { .. }` in one.
struct Module {
    file: usize,
    parent: Option<usize>,
    /// Where its `mod name;` files live.
    dir: PathBuf,
    children: HashMap<String, usize>,
    /// Names of the items defined in it (both namespaces).
    items: HashSet<String>,
    /// `use` names: the name in this module and the path it stands for.
    imports: HashMap<String, Vec<String>>,
    globs: Vec<Vec<String>>,
}

/// What a path names.
#[derive(Clone, Copy, PartialEq, Debug)]
enum Target {
    Module(usize),
    /// An item defined in this module.
    Item(usize),
}

/// A path a file names, to resolve once every module is known.
struct Reference {
    module: usize,
    line: usize,
    segments: Vec<String>,
}

/// Resolution gives up past this many re-exports (a `use` cycle).
const MAX_DEPTH: usize = 32;

impl Graph {
    /// Parses the crate whose root is `src/lib.rs`, reading files through
    /// `read` (`None`: no such file).
    pub fn of_crate(src: &Path, read: &dyn Fn(&Path) -> Option<String>) -> Result<Graph> {
        let mut crate_ = Crate {
            files: Vec::new(),
            modules: Vec::new(),
            references: Vec::new(),
        };
        let root_file = src.join("lib.rs");
        crate_.files.push(PathBuf::from("lib.rs"));
        crate_.modules.push(Module::new(0, None, src.to_path_buf()));
        let mut queue = vec![(root_file, 0usize)];
        while let Some((path, module)) = queue.pop() {
            let text = read(&path).with_context(|| format!("reading {}", path.display()))?;
            let ast = syn::parse_file(&text)
                .with_context(|| format!("parsing {} (syn)", path.display()))?;
            let mut visitor = Collector {
                crate_: &mut crate_,
                stack: vec![module],
                block_depth: 0,
                file_modules: Vec::new(),
            };
            visitor.visit_file(&ast);
            for (child, name) in visitor.file_modules {
                let dir = crate_.modules[child].dir.clone();
                let parent_dir = dir.parent().expect("a module's folder has a parent");
                let flat = parent_dir.join(format!("{name}.rs"));
                let nested = dir.join("mod.rs");
                let file = if read(&flat).is_some() {
                    flat
                } else if read(&nested).is_some() {
                    nested
                } else {
                    bail!(
                        "{}: `mod {name};` has neither {} nor {}",
                        path.display(),
                        flat.display(),
                        nested.display()
                    );
                };
                crate_.modules[child].file = crate_.files.len();
                crate_
                    .files
                    .push(file.strip_prefix(src).unwrap_or(&file).to_path_buf());
                queue.push((file, child));
            }
        }
        Ok(crate_.graph())
    }

    /// Cycles between files and imports against `layers`, as a report.
    pub fn check(&self, layers: &[&[&str]]) -> Report {
        let mut text = String::new();
        let imports: usize = self.edges.values().map(Vec::len).sum();
        let _ = writeln!(
            text,
            "layers: {} files, {} imports of another file's items",
            self.files.len(),
            imports
        );
        // A module's own files may import each other (its `mod.rs` and
        // their shared items); a cycle through two modules may not.
        let (across, within): (Vec<Vec<usize>>, Vec<Vec<usize>>) =
            self.cycles().into_iter().partition(|component| {
                let modules: BTreeSet<&Option<String>> =
                    component.iter().map(|&f| &self.top_modules[f]).collect();
                modules.len() > 1
            });
        for component in &across {
            let _ = writeln!(
                text,
                "layers: import cycle of {} files across modules: {}",
                component.len(),
                component
                    .iter()
                    .map(|&f| self.name(f))
                    .collect::<Vec<_>>()
                    .join(", ")
            );
            let members: BTreeSet<usize> = component.iter().copied().collect();
            for ((from, to), list) in &self.edges {
                if members.contains(from) && members.contains(to) {
                    let first = &list[0];
                    let _ = writeln!(
                        text,
                        "  {}:{} -> {} ({}{})",
                        self.name(*from),
                        first.line,
                        self.name(*to),
                        first.path,
                        more(list.len())
                    );
                }
            }
        }
        if !within.is_empty() {
            let list: Vec<String> = within
                .iter()
                .map(|component| {
                    let dir = self.files[component[0]]
                        .parent()
                        .map_or_else(String::new, |d| d.display().to_string());
                    format!("{dir}/ ({} files)", component.len())
                })
                .collect();
            let _ = writeln!(
                text,
                "layers: {} cycle(s) within one module's files, allowed: {}",
                within.len(),
                list.join(", ")
            );
        }
        let layer_of = |module: &Option<String>| -> Option<usize> {
            let name = module.as_deref()?;
            layers.iter().position(|layer| layer.contains(&name))
        };
        let mut violations = 0;
        let mut undeclared = BTreeSet::new();
        for (file, module) in self.top_modules.iter().enumerate() {
            if module.is_some() && layer_of(module).is_none() {
                undeclared.insert((module.clone().unwrap_or_default(), file));
            }
        }
        for (module, file) in &undeclared {
            violations += 1;
            let _ = writeln!(
                text,
                "layers: module `{module}` ({}) is in no layer: add it to LAYERS in xtask/src/layers.rs",
                self.name(*file)
            );
        }
        for ((from, to), list) in &self.edges {
            let Some(low) = layer_of(&self.top_modules[*from]) else {
                continue;
            };
            // The highest module an import names: the item's own, or one
            // it is re-exported through.
            let highest = |import: &Import| -> Option<(usize, String)> {
                let own = self.top_modules[*to].iter();
                own.chain(import.via.iter())
                    .filter_map(|m| {
                        Some((
                            layers.iter().position(|l| l.contains(&m.as_str()))?,
                            m.clone(),
                        ))
                    })
                    .max()
            };
            let upward: Vec<(&Import, (usize, String))> = list
                .iter()
                .filter_map(|import| Some((import, highest(import)?)))
                .filter(|(_, (high, _))| *high > low)
                .collect();
            let Some((first, (high, module))) = upward.first() else {
                continue;
            };
            violations += upward.len();
            let others: Vec<String> = upward[1..]
                .iter()
                .map(|(i, _)| i.line.to_string())
                .collect();
            let _ = writeln!(
                text,
                "layers: {}:{} imports {} from {} through `{}` (layer {}) above its own `{}` (layer {}){}",
                self.name(*from),
                first.line,
                first.path,
                self.name(*to),
                module,
                high,
                self.top_modules[*from].as_deref().unwrap_or("crate"),
                low,
                if others.is_empty() {
                    String::new()
                } else {
                    format!("; also on line(s) {}", others.join(", "))
                }
            );
        }
        if across.is_empty() && violations == 0 {
            let order: Vec<String> = layers.iter().map(|layer| layer.join(" ")).collect();
            let _ = writeln!(
                text,
                "layers: no import cycle; every import points down: {}",
                order.join(" < ")
            );
        }
        Report {
            text,
            cycles: across.len(),
            violations,
        }
    }

    fn name(&self, file: usize) -> String {
        self.files[file].display().to_string()
    }

    /// The strongly connected components of more than one file (Tarjan),
    /// each sorted by file name.
    fn cycles(&self) -> Vec<Vec<usize>> {
        let n = self.files.len();
        let mut next: Vec<Vec<usize>> = vec![Vec::new(); n];
        for &(from, to) in self.edges.keys() {
            next[from].push(to);
        }
        struct Tarjan<'a> {
            next: &'a [Vec<usize>],
            index: Vec<Option<usize>>,
            low: Vec<usize>,
            on_stack: Vec<bool>,
            stack: Vec<usize>,
            counter: usize,
            out: Vec<Vec<usize>>,
        }
        impl Tarjan<'_> {
            fn visit(&mut self, v: usize) {
                self.index[v] = Some(self.counter);
                self.low[v] = self.counter;
                self.counter += 1;
                self.stack.push(v);
                self.on_stack[v] = true;
                for i in 0..self.next[v].len() {
                    let w = self.next[v][i];
                    match self.index[w] {
                        None => {
                            self.visit(w);
                            self.low[v] = self.low[v].min(self.low[w]);
                        }
                        Some(index) if self.on_stack[w] => self.low[v] = self.low[v].min(index),
                        Some(_) => {}
                    }
                }
                if Some(self.low[v]) == self.index[v] {
                    let mut component = Vec::new();
                    while let Some(w) = self.stack.pop() {
                        self.on_stack[w] = false;
                        component.push(w);
                        if w == v {
                            break;
                        }
                    }
                    if component.len() > 1 {
                        self.out.push(component);
                    }
                }
            }
        }
        let mut tarjan = Tarjan {
            next: &next,
            index: vec![None; n],
            low: vec![0; n],
            on_stack: vec![false; n],
            stack: Vec::new(),
            counter: 0,
            out: Vec::new(),
        };
        for v in 0..n {
            if tarjan.index[v].is_none() {
                tarjan.visit(v);
            }
        }
        let mut out = tarjan.out;
        for component in &mut out {
            component.sort_by_key(|&f| self.files[f].clone());
        }
        out.sort();
        out
    }
}

fn more(count: usize) -> String {
    if count > 1 {
        format!(" and {} more", count - 1)
    } else {
        String::new()
    }
}

impl Module {
    fn new(file: usize, parent: Option<usize>, dir: PathBuf) -> Module {
        Module {
            file,
            parent,
            dir,
            children: HashMap::new(),
            items: HashSet::new(),
            imports: HashMap::new(),
            globs: Vec::new(),
        }
    }
}

/// The modules and references found so far.
struct Crate {
    files: Vec<PathBuf>,
    modules: Vec<Module>,
    references: Vec<Reference>,
}

impl Crate {
    fn graph(&self) -> Graph {
        let mut edges: BTreeMap<(usize, usize), Vec<Import>> = BTreeMap::new();
        for reference in &self.references {
            let mut via = Vec::new();
            let Some(Target::Item(module)) =
                self.resolve(reference.module, &reference.segments, 0, &mut via)
            else {
                continue;
            };
            let (from, to) = (
                self.modules[reference.module].file,
                self.modules[module].file,
            );
            if from != to {
                edges.entry((from, to)).or_default().push(Import {
                    line: reference.line,
                    path: reference.segments.join("::"),
                    via: via.iter().filter_map(|&m| self.top_module(m)).collect(),
                });
            }
        }
        for list in edges.values_mut() {
            list.sort_by_key(|import| import.line);
        }
        let top_modules = (0..self.files.len())
            .map(|file| {
                let module = self.modules.iter().position(|m| m.file == file)?;
                self.top_module(module)
            })
            .collect();
        Graph {
            files: self.files.clone(),
            top_modules,
            edges,
        }
    }

    /// The name under the crate root of the module holding `module`.
    fn top_module(&self, mut module: usize) -> Option<String> {
        loop {
            let parent = self.modules[module].parent?;
            if parent == 0 {
                let (name, _) = self.modules[0]
                    .children
                    .iter()
                    .find(|(_, &child)| child == module)?;
                return Some(name.clone());
            }
            module = parent;
        }
    }

    /// What `path`, written in `module`, names; `None` outside the crate.
    /// Each module the path enters or re-exports through goes to `via`.
    fn resolve(
        &self,
        module: usize,
        path: &[String],
        depth: usize,
        via: &mut Vec<usize>,
    ) -> Option<Target> {
        if depth > MAX_DEPTH || path.is_empty() {
            return None;
        }
        let mut rest = path;
        let mut current = match path[0].as_str() {
            "crate" => {
                rest = &path[1..];
                0
            }
            "self" => {
                rest = &path[1..];
                module
            }
            "super" => {
                let mut m = module;
                while rest.first().map(String::as_str) == Some("super") {
                    m = self.modules[m].parent?;
                    rest = &rest[1..];
                }
                m
            }
            _ => module,
        };
        for (i, segment) in rest.iter().enumerate() {
            match self.lookup(current, segment, depth + 1, via) {
                Some(Target::Module(m)) => {
                    via.push(m);
                    current = m;
                }
                Some(item) => return Some(item),
                // Unknown in the first place: another crate, the prelude
                // or a local name. Further in: something the resolver
                // does not follow (a macro's item): the module holds it.
                None if i == 0 && !matches!(path[0].as_str(), "crate" | "self" | "super") => {
                    return None
                }
                None => return Some(Target::Item(current)),
            }
        }
        Some(Target::Module(current))
    }

    /// The name `name` in `module`'s scope.
    fn lookup(
        &self,
        module: usize,
        name: &str,
        depth: usize,
        via: &mut Vec<usize>,
    ) -> Option<Target> {
        if depth > MAX_DEPTH {
            return None;
        }
        let m = &self.modules[module];
        if let Some(&child) = m.children.get(name) {
            return Some(Target::Module(child));
        }
        if m.items.contains(name) {
            return Some(Target::Item(module));
        }
        if let Some(path) = m.imports.get(name) {
            via.push(module);
            return self.resolve(module, path, depth + 1, via);
        }
        for glob in &m.globs {
            if let Some(Target::Module(g)) = self.resolve(module, glob, depth + 1, &mut Vec::new())
            {
                if g != module {
                    let mut through = vec![g];
                    if let Some(found) = self.lookup(g, name, depth + 1, &mut through) {
                        via.extend(through);
                        return Some(found);
                    }
                }
            }
        }
        None
    }
}

/// Walks one file's syntax tree.
struct Collector<'a> {
    crate_: &'a mut Crate,
    /// The module being read, innermost last.
    stack: Vec<usize>,
    /// Inside a function body: items there are not the module's.
    block_depth: usize,
    /// `mod name;` declarations found: (module, name).
    file_modules: Vec<(usize, String)>,
}

impl Collector<'_> {
    fn module(&self) -> usize {
        *self.stack.last().expect("a module")
    }

    fn define(&mut self, name: String) {
        if self.block_depth == 0 {
            let module = self.module();
            self.crate_.modules[module].items.insert(name);
        }
    }

    fn refer(&mut self, line: usize, segments: Vec<String>) {
        let module = self.module();
        self.crate_.references.push(Reference {
            module,
            line,
            segments,
        });
    }

    fn use_tree(&mut self, prefix: &mut Vec<String>, tree: &syn::UseTree) {
        let line = line_of(tree);
        let module = self.module();
        match tree {
            syn::UseTree::Path(p) => {
                prefix.push(p.ident.to_string());
                self.use_tree(prefix, &p.tree);
                prefix.pop();
            }
            syn::UseTree::Name(n) => {
                let name = n.ident.to_string();
                let (alias, path) = if name == "self" {
                    (prefix.last().cloned().unwrap_or_default(), prefix.clone())
                } else {
                    let mut path = prefix.clone();
                    path.push(name.clone());
                    (name, path)
                };
                self.refer(line, path.clone());
                self.crate_.modules[module].imports.insert(alias, path);
            }
            syn::UseTree::Rename(r) => {
                let mut path = prefix.clone();
                path.push(r.ident.to_string());
                self.refer(line, path.clone());
                self.crate_.modules[module]
                    .imports
                    .insert(r.rename.to_string(), path);
            }
            syn::UseTree::Glob(_) => {
                self.crate_.modules[module].globs.push(prefix.clone());
            }
            syn::UseTree::Group(g) => {
                for tree in &g.items {
                    self.use_tree(prefix, tree);
                }
            }
        }
    }

    /// `crate::a::b`, `super::c` and `$crate::d` inside a macro call's tokens.
    fn macro_tokens(&mut self, tokens: TokenStream) {
        let trees: Vec<TokenTree> = tokens.into_iter().collect();
        let mut i = 0;
        while i < trees.len() {
            if let TokenTree::Group(group) = &trees[i] {
                self.macro_tokens(group.stream());
            }
            let starts =
                matches!(&trees[i], TokenTree::Ident(id) if id == "crate" || id == "super");
            if starts && path_separator(&trees, i + 1) {
                let line = trees[i].span().start().line;
                let mut segments = vec![trees[i].to_string()];
                let mut j = i + 1;
                while path_separator(&trees, j) {
                    match trees.get(j + 2) {
                        Some(TokenTree::Ident(id)) => segments.push(id.to_string()),
                        _ => break,
                    }
                    j += 3;
                }
                self.refer(line, segments);
                i = j;
                continue;
            }
            i += 1;
        }
    }
}

/// Whether `trees[at..]` starts with `::`.
fn path_separator(trees: &[TokenTree], at: usize) -> bool {
    matches!(
        (trees.get(at), trees.get(at + 1)),
        (Some(TokenTree::Punct(a)), Some(TokenTree::Punct(b))) if a.as_char() == ':' && b.as_char() == ':'
    )
}

fn line_of(node: &impl syn::spanned::Spanned) -> usize {
    node.span().start().line
}

/// `#[cfg(test)]` or `#[cfg(all(test, ..))]`.
fn test_only(attrs: &[syn::Attribute]) -> bool {
    attrs.iter().any(|attr| {
        attr.path().is_ident("cfg")
            && attr.meta.require_list().is_ok_and(|list| {
                let text: String = list.tokens.to_string().split_whitespace().collect();
                text == "test" || text.starts_with("all(test,")
            })
    })
}

fn item_attrs(item: &syn::Item) -> &[syn::Attribute] {
    use syn::Item;
    match item {
        Item::Const(i) => &i.attrs,
        Item::Enum(i) => &i.attrs,
        Item::ExternCrate(i) => &i.attrs,
        Item::Fn(i) => &i.attrs,
        Item::ForeignMod(i) => &i.attrs,
        Item::Impl(i) => &i.attrs,
        Item::Macro(i) => &i.attrs,
        Item::Mod(i) => &i.attrs,
        Item::Static(i) => &i.attrs,
        Item::Struct(i) => &i.attrs,
        Item::Trait(i) => &i.attrs,
        Item::TraitAlias(i) => &i.attrs,
        Item::Type(i) => &i.attrs,
        Item::Union(i) => &i.attrs,
        Item::Use(i) => &i.attrs,
        _ => &[],
    }
}

impl<'ast> Visit<'ast> for Collector<'_> {
    fn visit_item(&mut self, item: &'ast syn::Item) {
        if test_only(item_attrs(item)) {
            return;
        }
        use syn::Item;
        let name = match item {
            Item::Const(i) => Some(&i.ident),
            Item::Enum(i) => Some(&i.ident),
            Item::Fn(i) => Some(&i.sig.ident),
            Item::Static(i) => Some(&i.ident),
            Item::Struct(i) => Some(&i.ident),
            Item::Trait(i) => Some(&i.ident),
            Item::TraitAlias(i) => Some(&i.ident),
            Item::Type(i) => Some(&i.ident),
            Item::Union(i) => Some(&i.ident),
            Item::Macro(i) => i.ident.as_ref(),
            _ => None,
        };
        if let Some(name) = name {
            self.define(name.to_string());
        }
        syn::visit::visit_item(self, item);
    }

    fn visit_item_mod(&mut self, item: &'ast syn::ItemMod) {
        let parent = self.module();
        let name = item.ident.to_string();
        let dir = self.crate_.modules[parent].dir.join(&name);
        let file = self.crate_.modules[parent].file;
        let id = self.crate_.modules.len();
        self.crate_
            .modules
            .push(Module::new(file, Some(parent), dir));
        self.crate_.modules[parent]
            .children
            .insert(name.clone(), id);
        match &item.content {
            Some((_, items)) => {
                let depth = std::mem::replace(&mut self.block_depth, 0);
                self.stack.push(id);
                for inner in items {
                    self.visit_item(inner);
                }
                self.stack.pop();
                self.block_depth = depth;
            }
            None => self.file_modules.push((id, name)),
        }
    }

    fn visit_item_use(&mut self, item: &'ast syn::ItemUse) {
        let mut prefix = Vec::new();
        if item.leading_colon.is_none() {
            self.use_tree(&mut prefix, &item.tree);
        }
    }

    fn visit_block(&mut self, block: &'ast syn::Block) {
        self.block_depth += 1;
        syn::visit::visit_block(self, block);
        self.block_depth -= 1;
    }

    fn visit_path(&mut self, path: &'ast syn::Path) {
        if path.leading_colon.is_none() {
            let segments = path.segments.iter().map(|s| s.ident.to_string()).collect();
            self.refer(line_of(path), segments);
        }
        syn::visit::visit_path(self, path);
    }

    fn visit_macro(&mut self, mac: &'ast syn::Macro) {
        self.macro_tokens(mac.tokens.clone());
        syn::visit::visit_macro(self, mac);
    }

    fn visit_attribute(&mut self, _: &'ast syn::Attribute) {
        // Attributes (docs, cfg, derives) name nothing of the crate.
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn graph(files: &[(&str, &str)]) -> Graph {
        let files: HashMap<PathBuf, String> = files
            .iter()
            .map(|(path, text)| (Path::new("/src").join(path), text.to_string()))
            .collect();
        Graph::of_crate(Path::new("/src"), &|path| files.get(path).cloned()).unwrap()
    }

    fn edges(graph: &Graph) -> Vec<(String, String)> {
        graph
            .edges
            .keys()
            .map(|&(a, b)| (graph.name(a), graph.name(b)))
            .collect()
    }

    #[test]
    fn imports_resolve_through_re_exports_to_the_defining_file() {
        let g = graph(&[
            ("lib.rs", "pub mod low; pub mod high; pub use low::Thing;"),
            ("low/mod.rs", "mod thing; pub use thing::Thing;"),
            ("low/thing.rs", "pub struct Thing;"),
            (
                "high.rs",
                "use crate::Thing; pub fn f() -> crate::low::Thing { Thing }",
            ),
        ]);
        let e = edges(&g);
        assert!(
            e.contains(&("high.rs".into(), "low/thing.rs".into())),
            "{e:?}"
        );
        assert!(!e
            .iter()
            .any(|(from, to)| from == "high.rs" && to == "lib.rs"));
        assert!(!e
            .iter()
            .any(|(from, to)| from == "high.rs" && to == "low/mod.rs"));
        let report = g.check(&[&["low"], &["high"]]);
        assert!(report.is_clean(), "{}", report.text);
    }

    #[test]
    fn a_cycle_and_an_upward_import_are_reported_with_their_lines() {
        let g = graph(&[
            ("lib.rs", "pub mod low;\npub mod high;"),
            (
                "low.rs",
                "pub struct A;\npub fn f() {\n    crate::high::g();\n}",
            ),
            ("high.rs", "use super::low::A;\npub fn g() -> A { A }"),
        ]);
        let report = g.check(&[&["low"], &["high"]]);
        assert_eq!(
            (report.cycles, report.violations),
            (1, 1),
            "{}",
            report.text
        );
        assert!(report
            .text
            .contains("import cycle of 2 files across modules: high.rs, low.rs"));
        assert!(report
            .text
            .contains("low.rs:3 imports crate::high::g from high.rs"));
    }

    #[test]
    fn test_code_and_other_crates_are_not_imports() {
        let g = graph(&[
            ("lib.rs", "pub mod low;\npub mod high;"),
            (
                "low.rs",
                "use core::fmt::Debug;\npub struct A;\n#[cfg(test)]\nmod tests { use crate::high::B; }",
            ),
            ("high.rs", "pub struct B;\npub fn g() -> crate::low::A { crate::low::A }"),
        ]);
        assert_eq!(edges(&g), [("high.rs".to_string(), "low.rs".to_string())]);
    }

    #[test]
    fn paths_in_macro_calls_count() {
        let g = graph(&[
            ("lib.rs", "pub mod low;\npub mod high;"),
            ("low.rs", "pub const C: u8 = 1;"),
            ("high.rs", "pub fn g() { assert_eq!(crate::low::C, 1); }"),
        ]);
        assert_eq!(edges(&g), [("high.rs".to_string(), "low.rs".to_string())]);
    }

    #[test]
    fn a_module_in_no_layer_is_named() {
        let g = graph(&[("lib.rs", "pub mod stray;"), ("stray.rs", "")]);
        let report = g.check(&[&["low"]]);
        assert_eq!(report.violations, 1);
        assert!(report
            .text
            .contains("module `stray` (stray.rs) is in no layer"));
    }

    #[test]
    fn a_cycle_within_one_module_is_listed_not_failed() {
        let g = graph(&[
            ("lib.rs", "pub mod low;"),
            (
                "low/mod.rs",
                "mod a;\npub use a::A;\npub(crate) fn helper() {}",
            ),
            ("low/a.rs", "pub struct A;\nfn f() { super::helper() }"),
        ]);
        let report = g.check(&[&["low"]]);
        assert!(report.is_clean(), "{}", report.text);
        assert!(report
            .text
            .contains("1 cycle(s) within one module's files, allowed: low/ (2 files)"));
    }

    #[test]
    fn a_path_through_a_higher_module_counts_as_an_import_from_it() {
        let g = graph(&[
            ("lib.rs", "pub mod low;\npub mod high;"),
            ("low/mod.rs", "mod a;\nmod b;"),
            ("low/a.rs", "pub struct A;"),
            ("low/b.rs", "use crate::high::A;\npub fn f(_: A) {}"),
            ("high.rs", "pub use crate::low::a::A;"),
        ]);
        let report = g.check(&[&["low"], &["high"]]);
        // The `use` and the use of its name.
        assert_eq!(report.violations, 2, "{}", report.text);
        assert!(
            report.text.contains(
                "low/b.rs:1 imports crate::high::A from low/a.rs through `high` (layer 1) above \
                 its own `low` (layer 0); also on line(s) 2"
            ),
            "{}",
            report.text
        );
    }

    /// The check `lint` runs, also under `cargo test`.
    #[test]
    fn the_core_keeps_its_layers() {
        let src = shell::root().join("crates/rodyn/src");
        let graph = Graph::of_crate(&src, &|path| std::fs::read_to_string(path).ok()).unwrap();
        let report = graph.check(LAYERS);
        assert!(report.is_clean(), "{}", report.text);
    }
}
