//! Links the system's IPOPT (Debian: `coinor-libipopt-dev`), found through
//! pkg-config. `cargo xtask test` installs it when it runs as root. The crate
//! is not a default member of the workspace, so `cargo build` at the root
//! needs no system library.

fn main() {
    println!("cargo:rerun-if-changed=build.rs");
    // Only libipopt itself is linked (by the `#[link]` in `src/ipopt.rs`):
    // the shared library brings its own LAPACK, BLAS and MUMPS, whose `-l`
    // flags in ipopt.pc would need their -dev packages for nothing.
    match pkg_config::Config::new()
        .atleast_version("3.11")
        .cargo_metadata(false)
        .probe("ipopt")
    {
        Ok(library) => {
            for path in library.link_paths {
                println!("cargo:rustc-link-search=native={}", path.display());
            }
        }
        Err(_) => {
            // One clear message naming the package, rather than a panic's
            // backtrace or the linker's list of undefined symbols later.
            println!(
                "cargo::error=rodyn-optimal-control needs the IPOPT library and its pkg-config file, \
                 which pkg-config does not find. On Debian or Ubuntu install them with: \
                 sudo apt-get install coinor-libipopt-dev pkg-config. \
                 The rest of the workspace builds without them (this crate is not a default member)."
            );
        }
    }
}
